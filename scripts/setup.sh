#!/usr/bin/env bash
# Installs exactly the Debian packages lac uses. Idempotent: quick when all are present.
set -euo pipefail
packages=(
  g++ cmake ninja-build                   # toolchain
  libboost-dev                            # Boost.Math, Odeint, Multiprecision (header-only)
  libeigen3-dev libceres-dev              # linear algebra, nonlinear least squares
  libcerf-dev                             # erfi, Dawson, erfcx
  libcli11-dev nlohmann-json3-dev         # CLI parsing, JSON output
  libtbb-dev                              # parallel sweeps
  libgtest-dev libbenchmark-dev           # tests, benchmarks
  clang libclang-rt-14-dev                # libFuzzer targets and sanitizer runtimes
  python3 python3-mpmath python3-numpy python3-matplotlib  # reference generators, figures
  python3-dev pybind11-dev python3-pybind11 python3-pytest python3-distributed  # Python module lac, its tests, Dask sweeps
  libocct-data-exchange-dev libocct-modeling-algorithms-dev  # STEP/IGES export (optional lac::export)
  python3-ezdxf                           # reads the exported DXF back in the tests
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
echo "setup: all packages present" >&2

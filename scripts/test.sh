#!/usr/bin/env bash
# Quick start #2: set up, build what the suite runs (target test_deps: the tests, the lac tool, the
# Python module and the experiments the tests call; not the benchmarks), run the GoogleTest and
# pytest suites (ctest). Exit status is ctest's.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_TARGET=test_deps bash scripts/build.sh
ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j "$(nproc)"

#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer (gcc, LAC_SANITIZE=ON)
# in build-asan/ and runs ctest there. Any sanitizer report stops the test that raised it
# (halt_on_error) and fails the run; leaks are checked where LeakSanitizer works (not under
# ptrace). Quiet on success apart from ctest's summary. Exit status: ctest's.
#
# Usage: scripts/sanitize.sh   (JOBS=n: build/test parallelism, default nproc; LAC_DETECT_LEAKS=0: no leak checks)
# Budget: under 30 min on 2 cores (build ~15 min from scratch at -O1, tests under 10 min).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build-asan}
JOBS=${JOBS:-$(nproc)}
bash scripts/setup.sh 2>/dev/null

log=$(mktemp)
trap 'rm -f "$log"' EXIT
# -O1 instead of Release's -O3: the instrumented build is most of this script's time, and -O1 halves
# it (a CLI translation unit: 49 s -> 23 s) for somewhat slower tests; sanitizer checks are the same.
if ! cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
      -DLAC_SANITIZE=ON -DLAC_BENCHMARKS=OFF -DLAC_FUZZERS=OFF -DLAC_INSTALL=OFF >"$log" 2>&1; then
  cat "$log" >&2
  exit 1
fi

# Only what ctest runs: target test_deps (CMakeLists.txt).
if ! cmake --build "$BUILD_DIR" -j "$JOBS" --target test_deps >"$log" 2>&1; then
  grep -E "error|Error|undefined reference|FAILED" "$log" | head -40 >&2 || tail -40 "$log" >&2
  exit 1
fi

# LeakSanitizer cannot run under ptrace (some containers, debuggers): probe once.
# LAC_DETECT_LEAKS=0 switches leak checks off explicitly.
leaks=${LAC_DETECT_LEAKS:-1}
probe=$(ASAN_OPTIONS=detect_leaks=1 "$BUILD_DIR/lac" --help 2>&1 >/dev/null || true)
if grep -q "LeakSanitizer does not work" <<<"$probe"; then
  leaks=0
  echo "sanitize: LeakSanitizer unavailable here (ptrace); leak checks off" >&2
fi
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=$leaks"
# Leaks inside OpenCASCADE (static registries of its STEP/IGES toolkits) are not lac's: suppressed by library.
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan_suppressions.txt:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

status=0
ctest --test-dir "$BUILD_DIR" -j "$JOBS" --output-on-failure --timeout 1500 >"$log" 2>&1 || status=$?
# Summary line(s) always; failure details only when something failed.
if [ "$status" -ne 0 ]; then
  cat "$log"
else
  sed -n '/tests passed/,$p' "$log"
fi
exit "$status"

#!/usr/bin/env bash
# Installs the packages (scripts/setup.sh), configures and builds everything in build/.
# Usage: scripts/build.sh [extra cmake args]   (BUILD_DIR overrides build/; BUILD_TARGET builds one
#        target instead of everything, e.g. test_deps)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD_DIR=${BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$BUILD_DIR" -j "$(nproc)" ${BUILD_TARGET:+--target "$BUILD_TARGET"}

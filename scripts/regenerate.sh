#!/usr/bin/env bash
# Quick start #1 (the main job): set up, build, and regenerate results/ with default settings.
# Runs every experiment executable (build/exp_*), then every figure script
# (experiments/figures/*.py), then writes the index results/README.md.
# Usage: scripts/regenerate.sh [--only NAME_SUBSTRING]
set -euo pipefail
cd "$(dirname "$0")/.."
only=""
if [ "${1:-}" = "--only" ]; then only="${2:-}"; fi
bash scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
mkdir -p results/figures
for exe in "$BUILD_DIR"/exp_*; do
  name=$(basename "$exe")
  [ -n "$only" ] && [[ "$name" != *"$only"* ]] && continue
  echo "== $name" >&2
  start=$(date +%s)
  "$exe" --out results
  echo "   $name: $(( $(date +%s) - start )) s" >&2
done
for fig in experiments/figures/*.py; do
  [ -e "$fig" ] || continue
  [ -n "$only" ] && [[ "$(basename "$fig")" != *"$only"* ]] && continue
  echo "== $fig" >&2
  MPLBACKEND=Agg /usr/bin/python3 "$fig" results
done
/usr/bin/python3 scripts/index_results.py results
echo "results/ regenerated; see results/README.md" >&2

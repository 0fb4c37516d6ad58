#!/usr/bin/env bash
# The long oracle campaign (docs/robustness.md, "Long campaign"): 10^6 problems (or COUNT) per
# construction named, each checked by the long-double oracle, written to
# results/oracle_long_<construction>.md and summarized in results/robustness_oracle_long.md.
# Runs on the committed code only (the rows name the commit): a dirty work tree is refused.
# One slice of problems first … first + N − 1 with --first (default 0); --max-evaluations caps the
# integrand evaluations of each g2, scurve and compound solve.
#   scripts/oracle_long.sh [--count N] [--first F] [--threads T] [--max-evaluations M] construction...
set -euo pipefail
cd "$(dirname "$0")/.."
count=1000000 threads=2 first=0 budget=()
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --count) count=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --first) first=$2; shift 2 ;;
    --max-evaluations) budget=(--max-evaluations "$2"); shift 2 ;;
    *) echo "oracle_long.sh: unknown option $1 (--count N, --first F, --threads T, --max-evaluations M)" >&2; exit 2 ;;
  esac
done
[[ $# -gt 0 ]] || { echo "oracle_long.sh: name constructions (g1 g2 scurve chain compound quadratic eval space)" >&2; exit 2; }
if [[ -n $(git status --porcelain --untracked-files=no) ]]; then
  echo "oracle_long.sh: the work tree has uncommitted changes; commit first (rows name the commit)" >&2; exit 2
fi
rev=$(git rev-parse --short=12 HEAD)
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD}
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
ninja -C build exp_oracle_campaign >/dev/null
for c in "$@"; do
  build/exp_oracle_campaign --long --revision "$rev" --construction "$c" --first "$first" --count "$count" --seed 1 \
    --threads "$threads" "${budget[@]}" --out results
done
/usr/bin/python3 scripts/index_results.py results

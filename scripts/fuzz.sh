#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, build-fuzz/, library instrumented with
# -fsanitize=fuzzer-no-link,address,undefined, no comparison tracing) and runs each for a number of executions, then
# writes results/robustness.{md,csv}: per target executions, crashes, hangs and NaN results
# (distinct findings) with notes. See docs/robustness.md.
#
# Usage: scripts/fuzz.sh [--short] [--runs N] [--max-time S] [--seed N] [--targets "cli la_curve ..."]
#                        [--jobs N] [--no-build] [--report-only] [--out DIR] [--findings DIR]
#   default      10^6 executions per target (-runs=1000000), at most 3 h each, libFuzzer fork mode
#                (a crash does not end the run), random seed, corpus kept in build-fuzz/fuzz-corpus/
#   --short      the test / CI run: deterministic and bounded. Per target about 60 s of executions at
#                the measured rate (short_runs below), at most 120 s each, one target per core side by
#                side (FUZZ_PARALLEL=n to change; 8 targets on 2 cores: at most 8 min plus replays),
#                in-process (no fork), -seed=1, a fresh corpus from the
#                committed seeds (fuzz/corpus/<target>/, and the saved finding inputs
#                fuzz/findings/fuzz_<target>/ as a regression corpus)
#   --max-time   wall-clock cap per target in seconds (the table reports executions reached)
#   --seed       libFuzzer -seed (default: 1 with --short, random otherwise)
#   --jobs       fork-mode workers per target (default 1; not with --short)
#   --findings   where this run saves finding inputs (default fuzz/findings; CI: a temp dir)
#   --report-only  rewrite the results from the last run's build-fuzz/fuzz-summary.tsv (same options)
# Findings: libFuzzer's crash/timeout/oom inputs and the harness's property violations (one input
# per distinct message, LAC_FUZZ_CONTINUE mode) are saved under <findings>/fuzz_<target>/. Only
# inputs saved during this run are counted: the saved inputs of earlier runs are replayed as seeds,
# and one that still fails is saved (rewritten) again, so it counts; one that no longer fails does not.
# Exit status 0 when no target has a finding, 3 otherwise (1 on build errors).
set -euo pipefail
cd "$(dirname "$0")/.."
# --short: executions per target, ~60 % of the 120 s cap at the rates measured on a
# 2-core machine (docs/robustness.md; executions/s in-process under the sanitizers, over
# the whole run: the first executions are cheaper), so that the run ends by its count
# (deterministic), not by the cap.
short_runs() {
  case "$1" in
    cli) echo 25000 ;;              # ~360/s
    g1_hermite) echo 18000 ;;       # ~275/s over a whole run (G2 chains cost most)
    hermite) echo 6000 ;;           # ~85/s
    la_curve) echo 12000 ;;         # ~170/s over a whole run (budget-bound inputs take ~0.3 s)
    planar_segments) echo 25000 ;;  # ~370/s
    quadratic) echo 5000 ;;         # ~75/s over a whole run
    space) echo 1000 ;;             # ~20/s (solver calls of ~0.3 s)
    special) echo 500000 ;;         # ~30000/s
    *) echo 3000 ;;
  esac
}
SHORT_MAX_TIME=120
RUNS=1000000
MAX_TIME=10800
SEED=""
TARGETS=""
FORK_JOBS=1
BUILD=1
OUT=results
FINDINGS=fuzz/findings
MODE=full
REPORT_ONLY=0
RUNS_GIVEN=0
MAX_TIME_GIVEN=0
while (($#)); do
  case "$1" in
    --short) MODE=short ;;
    --runs) RUNS=$2; RUNS_GIVEN=1; shift ;;
    --max-time) MAX_TIME=$2; MAX_TIME_GIVEN=1; shift ;;
    --seed) SEED=$2; shift ;;
    --targets) TARGETS=$2; shift ;;
    --jobs) FORK_JOBS=$2; shift ;;
    --no-build) BUILD=0 ;;
    --report-only) REPORT_ONLY=1; BUILD=0 ;;
    --out) OUT=$2; shift ;;
    --findings) FINDINGS=$2; shift ;;
    *) echo "fuzz.sh: unknown argument $1 (see the header of scripts/fuzz.sh)" >&2; exit 2 ;;
  esac
  shift
done
[ "$MODE" = short ] && [ -z "$SEED" ] && SEED=1
COMMAND="scripts/fuzz.sh"
[ "$MODE" = short ] && COMMAND+=" --short"
# --runs / --max-time override the mode's settings in any order
[ "$MODE" = short ] && ((RUNS_GIVEN == 0)) && RUNS=short
[ "$MODE" = short ] && ((MAX_TIME_GIVEN == 0)) && MAX_TIME=$SHORT_MAX_TIME
((RUNS_GIVEN)) && COMMAND+=" --runs $RUNS"
((MAX_TIME_GIVEN)) && COMMAND+=" --max-time $MAX_TIME"
[ "$FORK_JOBS" != 1 ] && COMMAND+=" --jobs $FORK_JOBS"
[ -n "$SEED" ] && [ "$MODE" != short -o "$SEED" != 1 ] && COMMAND+=" --seed $SEED"
BUILD_DIR=${BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}

log=$(mktemp)
trap 'rm -f "$log"' EXIT
if ((BUILD)); then
  bash scripts/setup.sh 2>/dev/null
  # No comparison tracing (-fno-sanitize-coverage=trace-cmp): in the Eigen and integrator inner
  # loops it took two thirds of fuzz_space's time (perf); edge coverage, the CLI dictionary and
  # libFuzzer's memcmp/strcmp hooks still guide the search.
  flags="-g -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-coverage=trace-cmp"
  flags+=" -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
  if ! CC=clang CXX=clang++ cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release -DLAC_FUZZERS=ON \
        -DLAC_BENCHMARKS=OFF -DLAC_SANITIZE=OFF -DLAC_INSTALL=OFF "-DCMAKE_CXX_FLAGS=$flags" >"$log" 2>&1 ||
     ! cmake --build "$BUILD_DIR" -j "$JOBS" --target lac_fuzzers >"$log" 2>&1; then
    grep -E "error" "$log" | head -40 >&2 || tail -40 "$log" >&2
    exit 1
  fi
fi
if [ -z "$TARGETS" ]; then
  TARGETS=$(for f in fuzz/fuzz_*.cpp; do basename "$f" .cpp | sed 's/^fuzz_//'; done | tr '\n' ' ')
fi

# The CLI target's dictionary: every option and subcommand name in the cli/ sources (a call may
# span lines: the sources are joined first) and the --format values.
dict="$BUILD_DIR/fuzz-cli.dict"
{
  grep -ohE '"--?[a-z][a-z0-9-]*"' cli/*.cpp
  cat cli/*.cpp | tr '\n' ' ' | grep -oE '(add_subcommand|parent_command)\( *(app, *)?"[a-z0-9-]+"' | grep -oE '"[a-z0-9-]+"'
  printf '"%s"\n' json csv svg
} | sort -u >"$dict"

export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=0:allocator_may_return_null=1:symbolize=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LAC_FUZZ_CONTINUE=1
summary="$BUILD_DIR/fuzz-summary.tsv"
((REPORT_ONLY)) && TARGETS=""
((REPORT_ONLY)) || : >"$summary"
status=0
replay_limit=120
[ "$MODE" = short ] && replay_limit=30
# One target: run, classify the inputs it saved, write its summary row to $BUILD_DIR/fuzz-<t>.row.
fuzz_target() {
  local t=$1 bin findings corpus runs marker args seeds runlog start seconds execs sigs path f line row
  bin="$BUILD_DIR/fuzz/fuzz_$t"
  [ -x "$bin" ] || { echo "fuzz.sh: no target $bin" >&2; exit 1; }
  findings="$FINDINGS/fuzz_$t"
  if [ "$MODE" = short ]; then  # deterministic: start from the committed seeds only
    corpus="$BUILD_DIR/fuzz-short-corpus/$t"
    rm -rf "$corpus"
  else
    corpus="$BUILD_DIR/fuzz-corpus/$t"
  fi
  mkdir -p "$findings" "$corpus"
  runs=$RUNS
  [ "$runs" = short ] && runs=$(short_runs "$t")
  marker="$BUILD_DIR/fuzz-$t.start"
  touch "$marker"
  sleep 1
  args=("-runs=$runs" "-max_total_time=$MAX_TIME" -timeout=20 -rss_limit_mb=2560 -max_len=512
        "-artifact_prefix=$findings/" -print_final_stats=1)
  # Fork mode keeps going after a crash; the short run stays in one process (deterministic for a
  # given seed; a crash ends that target's run, which is a finding anyway).
  # -len_control=0: inputs up to -max_len from the start; libFuzzer's default length growth keeps
  # a few-thousand-execution run at ~17 bytes, too short to reach the solvers (about 3 doubles).
  if [ "$MODE" = short ]; then
    args+=(-len_control=0)
  else
    args+=("-fork=$FORK_JOBS" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  fi
  [ -n "$SEED" ] && args+=("-seed=$SEED")
  [ "$t" = cli ] && [ -s "$dict" ] && args+=("-dict=$dict")
  seeds=()
  [ -d "fuzz/corpus/$t" ] && seeds+=("fuzz/corpus/$t")
  # Saved inputs of earlier findings (fixed or open) are a regression corpus.
  [ -d "fuzz/findings/fuzz_$t" ] && [ "fuzz/findings/fuzz_$t" != "$corpus" ] && seeds+=("fuzz/findings/fuzz_$t")
  runlog="$BUILD_DIR/fuzz-$t.log"
  start=$(date +%s)
  LAC_FUZZ_FINDINGS_DIR="$findings" "$bin" "${args[@]}" "$corpus" "${seeds[@]}" >"$runlog" 2>&1 || true
  seconds=$(($(date +%s) - start))
  # Executions: the largest "#N:" progress count of the fork-mode driver.
  execs=$(grep -oE '^#[0-9]+' "$runlog" | tr -d '#' | sort -n | tail -1)
  execs=${execs:-0}
  # Classify every input saved during this run by replaying it once (without continue mode the
  # harness aborts at its first finding and prints it): libFuzzer's crash-/oom-/timeout- files
  # and the harness's <KIND>-<hash> files (one per distinct message).
  sigs="$BUILD_DIR/fuzz-$t.signatures"
  : >"$sigs"
  for path in $(find "$findings" -type f -newer "$marker" | sort); do
    f=$(basename "$path")
    case "$f" in
      timeout-*) echo "TIMEOUT: libFuzzer -timeout=20 exceeded [$f]" >>"$sigs"; continue ;;
      crash-*|oom-*|leak-*|[A-Z]*-*) ;;
      *) continue ;;
    esac
    line=$(LAC_FUZZ_CONTINUE=0 timeout "$replay_limit" "$bin" "$path" 2>&1 |
           grep -m1 -E 'LAC_FUZZ_[A-Z_]+:|ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:' || true)
    case "$line" in
      LAC_FUZZ_*) echo "${line#*LAC_FUZZ_}" | sed 's/^/LAC_FUZZ_/' >>"$sigs" ;;
      *) [[ "$f" == oom-* ]] && line="out of memory ${line}"
         echo "SANITIZER_CRASH: ${line:-no longer reproduces} [$f]" >>"$sigs" ;;
    esac
  done
  row="$BUILD_DIR/fuzz-$t.row"
  : >"$row"
  python3 - "$t" "$execs" "$seconds" "$sigs" "$row" "$runs" "$MAX_TIME" <<'PY'
import re, sys
target, execs, seconds, sigs_path, summary, runs, max_time = sys.argv[1:]
def strip(s):  # one signature per kind of failure, not per input
    s = re.sub(r"==\d+==|0x[0-9a-fA-F]+|\[(crash|oom|leak|timeout)-[0-9a-f]+\]", "", s)
    return re.sub(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?|[-+]?\b(nan|inf)\b|\[crash-[0-9a-f]+\]|\[oom-[0-9a-f]+\]", "#", s)[:140]
kinds = {"crash": set(), "hang": set(), "nan": set()}
examples = {}
for line in open(sigs_path, errors="replace"):
    line = line.strip()
    kind_name = line.split(":", 1)[0]
    if kind_name in ("LAC_FUZZ_HANG", "TIMEOUT"): k = "hang"
    elif kind_name == "LAC_FUZZ_NAN": k = "nan"
    else: k = "crash"
    sig = strip(line)
    if sig not in kinds[k]:
        kinds[k].add(sig)
        examples.setdefault(k, []).append(line[:160])
notes = "; ".join(e.replace("|", "/") for k in ("crash", "hang", "nan") for e in examples.get(k, [])[:3]) or "none"
with open(summary, "a") as f:
    f.write("\t".join([target, runs, max_time, execs, seconds, str(len(kinds["crash"])), str(len(kinds["hang"])), str(len(kinds["nan"])), notes]) + "\n")
PY
  line=$(tail -1 "$row")
  IFS=$'\t' read -r _ _ _ _ _ nc nh nn _ <<<"$line"
  echo "fuzz_$t: $execs executions in ${seconds}s ($((execs / (seconds > 0 ? seconds : 1))) per s), crashes $nc, hangs $nh, NaN $nn" >&2
}
# --short runs the targets side by side, one per core (each in one process, deterministic for its
# seed: the run ends by its execution count, and a target's rate is that of one core); the full
# campaign runs one target at a time (fork mode has its own workers).
parallel=1
[ "$MODE" = short ] && parallel=${FUZZ_PARALLEL:-$(nproc)}
for t in $TARGETS; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  rm -f "$BUILD_DIR/fuzz-$t.row"
  fuzz_target "$t" &
done
wait
for t in $TARGETS; do
  row="$BUILD_DIR/fuzz-$t.row"
  [ -s "$row" ] || { echo "fuzz.sh: fuzz_$t wrote no summary row" >&2; exit 1; }
  cat "$row" >>"$summary"
  IFS=$'\t' read -r _ _ _ _ _ nc nh nn _ <"$row"
  ((nc + nh + nn == 0)) || status=3
done

# --report-only: LAC_FUZZ_COMMAND may name the invocations that produced the summary rows.
COMMAND=${LAC_FUZZ_COMMAND:-$COMMAND}
python3 - "$summary" "$OUT" "$COMMAND" "$(clang++ --version 2>/dev/null | head -1 || echo clang++)" <<'PY'
import csv, os, re, sys
summary, out, command, compiler = sys.argv[1:]
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "unknown CPU")
machine = f"{cpu}, {os.cpu_count()} logical CPUs; {compiler}, Release (-O3 -DNDEBUG) with -fsanitize=fuzzer-no-link,address,undefined (scripts/fuzz.sh)"
rows = [l.rstrip("\n").split("\t") for l in open(summary) if l.strip()]
os.makedirs(out, exist_ok=True)
cols = ["target", "runs_asked", "max_seconds", "executions", "seconds", "crashes", "hangs", "nan_results", "notes"]
with open(os.path.join(out, "robustness.csv"), "w", newline="") as f:
    f.write(f"# written by: {command}\n")
    w = csv.writer(f)
    w.writerow(cols)
    w.writerows(rows)
# The oracle section (written by exp_oracle_campaign between its markers) is kept as it is.
oracle_section = ""
md_path = os.path.join(out, "robustness.md")
if os.path.exists(md_path):
    old = open(md_path).read()
    a = old.find("<!-- oracle campaign: begin")
    b = old.find("<!-- oracle campaign: end -->")
    if a >= 0 and b > a:
        oracle_section = old[a:b + len("<!-- oracle campaign: end -->")] + "\n"
with open(md_path, "w") as f:
    f.write("# Robustness: libFuzzer targets\n\n")
    f.write(f"Written by `{command}` — do not edit by hand; rerun the command.\n\n")
    f.write(f"Machine: {machine}. Executions and seconds are this machine's; they vary from run to run.\n\n")
    f.write(f"Each target ran under AddressSanitizer + UndefinedBehaviorSanitizer (clang 14, libFuzzer edge coverage, fork mode unless --short) for "
            "-runs=`runs_asked` executions or at most `max_seconds` s, whichever came first; `executions` is what it reached. "
            "crashes = distinct sanitizer reports, unexpected exception types, errors without a parameter name, "
            "CLI exit status 1; hangs = calls over the per-call CPU-time bound (LAC_FUZZ_CALL_SECONDS, default 1 s) or "
            "inputs over libFuzzer's -timeout=20; nan_results = NaN/inf in a successful result. Counts are distinct "
            "findings (messages compared with their numbers removed); inputs are in fuzz/findings/<target>/. "
            "Properties and findings: docs/robustness.md.\n\n")
    f.write("| " + " | ".join(cols) + " |\n|" + "---|" * len(cols) + "\n")
    for r in rows:
        f.write("| " + " | ".join(c.replace("|", "/") for c in r) + " |\n")
    # The fixes: fuzz/fixes.tsv names each finding's regression tests; each must exist under tests/.
    tests = set()
    for root, _, files in os.walk("tests"):
        for name in files:
            if name.endswith(".cpp"):
                text = open(os.path.join(root, name), errors="replace").read()
                tests.update(f"{a}.{b}" for a, b in re.findall(r"^TEST(?:_F|_P)?\((\w+),\s*(\w+)\)", text, re.M))
    fixes = [l.rstrip("\n").split("\t") for l in open("fuzz/fixes.tsv") if l.strip() and not l.startswith("#")]
    missing = []
    f.write("\n## Findings and their fixes\n\nFrom `fuzz/fixes.tsv` (details in docs/robustness.md). Every regression "
            "test named here exists under tests/ (checked when this table was written) and runs in the test suite, "
            "plain and under the sanitizers.\n\n")
    f.write("| " + " | ".join(fixes[0]) + " |\n|" + "---|" * len(fixes[0]) + "\n")
    for r in fixes[1:]:
        named = r[-1].split()
        missing += [t for t in named if t not in tests]
        r = r[:-1] + [", ".join(f"`{t}`" if t in tests else f"`{t}` (MISSING)" for t in named)]
        f.write("| " + " | ".join(c.replace("|", "/") for c in r) + " |\n")
    if oracle_section:
        f.write("\n" + oracle_section)
if missing:
    sys.exit("fuzz.sh: fuzz/fixes.tsv names regression tests that do not exist: " + " ".join(missing))
PY
echo "fuzz.sh: wrote $OUT/robustness.md and $OUT/robustness.csv" >&2
if ((status)); then  # the notes name each finding's call; its input is in the findings folder
  awk -F'\t' '$6 + $7 + $8 > 0 { print "fuzz.sh: fuzz_" $1 ": " $9 }' "$summary" >&2
  echo "fuzz.sh: finding inputs saved in $FINDINGS/fuzz_<target>/ (replay: $BUILD_DIR/fuzz/fuzz_<target> <file>)" >&2
fi
exit "$status"

#!/usr/bin/env bash
# Builds the Clothoids library (github.com/ebertolazzi/Clothoids, the peer) OUTSIDE this repository
# from a checkout the caller provides, then lac's bench_peer_speed against it, and runs it pinned
# to CPU 0, writing results/peer_speed.{md,csv}. Downloads nothing. docs/peer_speed.md.
#
# Usage: scripts/peer_speed.sh PEER_SRC [PEER_OUT] [BUILD_DIR]
#   PEER_SRC   a Clothoids checkout with its submodules (UtilsLite, GenericContainer,
#              quarticRootsFlocke) under submodules/; its commit is `git rev-parse HEAD` there, or
#              the first line of PEER_SRC/COMMIT for an exported tree
#   PEER_OUT   where the peer's static library goes (default: PEER_SRC/../clothoids-peer), must be
#              outside this repository; holds lib/libclothoids_peer.a and COMMIT
#   BUILD_DIR  lac's CMake build folder (default: build)
# PEER_SKIP_RUN=1 stops after building; JOBS (default 2) parallel peer compilations.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 1 ] || { sed -n 2,14p "$0" >&2; exit 2; }
src=$(cd "$1" && pwd)
out=${2:-$src/../clothoids-peer}
build=${3:-$root/build}
mkdir -p "$out/lib" "$out/obj"
out=$(cd "$out" && pwd)
case "$out/" in "$root"/*) echo "peer_speed.sh: PEER_OUT must be outside the repository" >&2; exit 2 ;; esac

if git -C "$src" rev-parse HEAD >/dev/null 2>&1; then
  commit=$(git -C "$src" rev-parse HEAD)
elif [ -f "$src/COMMIT" ]; then
  commit=$(head -n1 "$src/COMMIT")
else
  echo "peer_speed.sh: no commit id for $src (not a git checkout, no COMMIT file)" >&2; exit 2
fi
sub=$src/submodules
for d in "$src/src" "$sub/UtilsLite/src" "$sub/GenericContainer/include" "$sub/quarticRootsFlocke/src"; do
  [ -d "$d" ] || { echo "peer_speed.sh: $d missing (submodules not checked out?)" >&2; exit 2; }
done

# The peer's sources with the flags of lac's Release build (-O3 -DNDEBUG, no -march), C++17 as the
# peer's own build. Only the members the adapter needs are linked (ld -r pulls them from the archive).
cxx=${CXX:-g++}
flags=(-std=c++17 -O3 -DNDEBUG -fPIC -fno-gnu-unique -w -include utility -I"$src/src" -I"$sub/UtilsLite/src" -I"$sub/GenericContainer/include"
       -I"$sub/GenericContainer/src" -I"$sub/quarticRootsFlocke/src")
sources=("$src"/src/*.cc "$sub"/GenericContainer/src/*.cc "$sub"/quarticRootsFlocke/src/*.cc "$sub/UtilsLite/src/Utils_fmt.cc")
objs=()
for f in "${sources[@]}"; do
  o="$out/obj/$(basename "$(dirname "$(dirname "$f")")")_$(basename "$f" .cc).o"
  objs+=("$o")
  [ -f "$o" ] && [ "$o" -nt "$f" ] && continue
  while [ "$(jobs -rp | wc -l)" -ge "${JOBS:-2}" ]; do wait -n; done
  echo "compiling $f" >&2
  "$cxx" "${flags[@]}" -c "$f" -o "$o" &
done
while [ "$(jobs -rp | wc -l)" -gt 0 ]; do wait -n; done
rm -f "$out/obj/peer_raw.a"
ar rcs "$out/obj/peer_raw.a" "${objs[@]}"
"$cxx" "${flags[@]}" -c "$root/bench/peer/clothoids_adapter.cpp" -o "$out/obj/adapter.o"
# One relocatable object, section groups dissolved, every symbol but the adapter's made local
# (-fno-gnu-unique above makes the statics of inline functions weak, so they are localized too):
# the peer's Eigen 5 and lac's Eigen 3 instantiations cannot be merged by the final link.
ld -r --force-group-allocation -o "$out/obj/peer_all.o" "$out/obj/adapter.o" "$out/obj/peer_raw.a"
objcopy --wildcard --keep-global-symbol='_ZN8lac_peer*' "$out/obj/peer_all.o" "$out/obj/peer_local.o"
rm -f "$out/lib/libclothoids_peer.a"
ar rcs "$out/lib/libclothoids_peer.a" "$out/obj/peer_local.o"
echo "$commit" > "$out/COMMIT"
echo "peer library: $out/lib/libclothoids_peer.a (Clothoids $commit)" >&2

[ "${PEER_SKIP_RUN:-0}" = 1 ] && exit 0
cmake -S "$root" -B "$build" -DLAC_PEER_CLOTHOIDS_DIR="$out" >/dev/null
ninja -C "$build" bench_peer_speed
cd "$root" && taskset -c 0 "$build/bench_peer_speed" --out-dir results

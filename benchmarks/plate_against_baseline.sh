#!/bin/bash
# Part 3 side by side against an earlier commit: build/benchmark_plate_rod_growth
# of this tree and of the baseline commit (built once, in its own worktree
# and build directory), run alternately, first lines (the sector at 4
# refinements: flat state to the located first threshold) compared.
#
#   bash benchmarks/plate_against_baseline.sh [build = build] [baseline = 079b84b] [repeats = 3]
#
# 079b84b is the code of the issue's "today" for part 3 (5.26 s on the
# development machine, benchmarks/README.md): before KINSOL's J p from the
# solve, the plate's chain rule and the predictor step.
set -euo pipefail
REPO=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$REPO/build}" && pwd)
BASE=${2:-079b84b}
REPEATS=${3:-3}
WORK=$REPO/build-baseline-$BASE
if [ ! -x "$WORK/build/benchmark_plate_rod_growth" ]; then
  echo "building the baseline $BASE in $WORK (once)"
  [ -d "$WORK/src" ] || git -C "$REPO" worktree add --detach "$WORK/src" "$BASE" >/dev/null
  args=(-S "$WORK/src" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release)
  command -v ccache >/dev/null && args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake "${args[@]}" >/dev/null
  cmake --build "$WORK/build" -j2 --target benchmark_plate_rod_growth >/dev/null
fi

# The first result line and its phases: the sector, Newton location, 4 refinements.
run() {
  (cd "$1" && timeout 600 ./benchmark_plate_rod_growth 4 2>&1 | sed -n '2,3p;3q') || true # (the benchmark ends on SIGPIPE after them)
}
declare -a tb tn
for k in $(seq "$REPEATS"); do
  b=$(run "$WORK/build"); n=$(run "$BUILD")
  tb+=("$(echo "$b" | head -1 | awk '{print $9}')")
  tn+=("$(echo "$n" | head -1 | awk '{print $9}')")
  echo "run $k  baseline: $(echo "$b" | head -1)"
  echo "       phases:   $(echo "$b" | tail -1)"
  echo "       this tree: $(echo "$n" | head -1)"
  echo "       phases:   $(echo "$n" | tail -1)"
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
mb=$(median "${tb[@]}"); mn=$(median "${tn[@]}")
awk -v b="$mb" -v n="$mn" 'BEGIN {printf "sector to its first threshold (median of runs): baseline %.2f s, this tree %.2f s: %.2fx\n", b, n, b / n}'

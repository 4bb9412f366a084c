#!/usr/bin/env bash
# Strong scaling of the distributed drivers (io/ranks.h, doc/parallel-runs.md)
# on this machine: the same run on one process (all cores as threads), on
# one process with one thread, and on 1..P MPI ranks of one thread each.
#
#  - table: parameter_files/strip/ribbon_comparison.prm (a constitutive
#    table, 21 x 11 points, 40 cells: 405 field DoFs), with its grid
#    refined to N1 x 11 points;
#  - curve: parameter_files/plate_rod/studies/critical_curve_mode_change_planar_lobes.prm
#    (a critical curve of 6 values on 4 902 DoFs).
#
# Prints, per run: wall seconds (whole process, median of REPEATS) and the
# speed-up against one process on all cores (threads) and against one
# process on one thread (the parallel efficiency of the ranks is the
# latter divided by their number).
#
# usage: benchmarks/mpi_scaling.sh [build dir = build] [max ranks = 2] [N1 = 21] [repeats = 3] [scratch]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") P=${2:-2} N1=${3:-21} R=${4:-3}
dir=$(realpath -m "${5:-/tmp/cosmo_mpi_scaling}")
rm -rf "$dir" && mkdir -p "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
cores=$(nproc)
time_of() { # median wall seconds of R runs of "$@" (the last argument: the prm's output directory)
  local out=${@: -1}; set -- "${@:1:$#-1}"
  for _ in $(seq 1 "$R"); do
    rm -rf "$out"; local t0=$(date +%s.%N)
    "$@" > "$out.txt" 2>&1 || { echo "failed: $*" >&2; cat "$out.txt" >&2; exit 1; }
    python3 -c "import time; print(time.time() - $t0)"
  done | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'
}
row() { # label seconds reference(all threads) reference(one thread)
  python3 -c "print('| %-34s | %7.2f | %5.2fx | %5.2fx |' % ('$1', $2, $3 / $2, $4 / $2))"
}
for case in table curve; do
  case $case in
    table) exe=$build/strip prm=$REPO/parameter_files/strip/ribbon_comparison.prm
           edit="s|^\( *set First range *=\).*|\1 0, 1, $N1|" ;;
    curve) exe=$build/plate_rod prm=$REPO/parameter_files/plate_rod/studies/critical_curve_mode_change_planar_lobes.prm
           edit="s|^x||" ;;
  esac
  sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$case|" -e "$edit" "$prm" > "$dir/$case.prm"
  echo
  echo "$case: $(basename "$prm") ($cores cores)"
  echo "| run                                | seconds | against 1 process, $cores threads | against 1 thread |"
  echo "|---|---:|---:|---:|"
  ref=$(time_of "$exe" --quiet "$dir/$case.prm" "$dir/$case")
  one=$(DEAL_II_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 time_of "$exe" --quiet "$dir/$case.prm" "$dir/$case")
  row "1 process, $cores threads" "$ref" "$ref" "$one"
  row "1 process, 1 thread" "$one" "$ref" "$one"
  for p in $(seq 2 "$P"); do
    t=$(time_of mpirun -np "$p" "$exe" --quiet "$dir/$case.prm" "$dir/$case")
    row "mpirun -np $p (1 thread each)" "$t" "$ref" "$one"
  done
done

#!/usr/bin/env bash
# A constitutive table spread over 2 MPI ranks (mpirun -np 2, io/ranks.h)
# writes the table of one process: tests/compare_tables.py checks
#  - rank 0's block (the first half of the serpentine) bitwise against one
#    process on one thread (the same operations in the same order);
#  - every number against one process to 10x the larger of the round-off
#    resolution R of the table itself (the largest difference between one
#    process on one thread and on two: sums and BLAS in another order,
#    measured 1.3e-11 of a column's scale) and Newton's tolerance 1e-10:
#    rank 1 reaches its first point by another path, so its states agree to
#    Newton's stopping test (measured 1.9e-10);
#  - table.h5 (written collectively) against its table.csv, with the same
#    attributes and dimension scales as one process's;
# and that no rank directory is left. Then a table interrupted by SIGTERM
# under mpirun is resumed by 2 ranks from their checkpoints (the table of
# the uninterrupted 2-rank run, bitwise), and resuming it with another
# number of ranks is refused (exit 1) naming the number it was begun with.
# usage: mpi_table.sh <strip> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
# What running as root and on a machine with fewer cores than ranks needs.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mpi() { timeout 300 mpirun -np "$@"; }
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }
table_of() {
  sed -e "s|^\( *set Output directory *=\).*|\1 $1|" -e "s|^\( *set First range *=\).*|\1 0, 1, ${2:-9}|" \
      -e "s|^\( *set Second range *=\).*|\1 0, 0.2, 5|" -e "s|^\( *set Number of cells *=\).*|\1 ${3:-20}|" \
      "$here/../parameter_files/strip/ribbon_comparison.prm"
}
for run in one_thread two_threads two_ranks; do table_of $run > $run.prm; done
DEAL_II_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 timeout 300 "$exe" --quiet one_thread.prm > one_thread.txt 2>&1 ||
  { bad "one process, one thread failed"; cat one_thread.txt; }
DEAL_II_NUM_THREADS=2 OPENBLAS_NUM_THREADS=2 timeout 300 "$exe" --quiet two_threads.prm > two_threads.txt 2>&1 ||
  { bad "one process, two threads failed"; cat two_threads.txt; }
mpi 2 "$exe" two_ranks.prm > two_ranks.txt 2>&1; s=$?
if [ $s -eq 0 ] && grep -q "on 2 MPI ranks" two_ranks/log.txt && [ ! -e two_ranks/rank-1 ]; then
  ok "mpirun -np 2: exit 0, '2 MPI ranks' in the log, no rank directory left"
else bad "mpirun -np 2: exit $s"; cat two_ranks.txt; fi
/usr/bin/python3 "$here/compare_tables.py" one_thread two_threads two_ranks || fail=1

# Interrupted under mpirun (SIGTERM to mpirun, which passes it to the
# ranks), resumed by 2 ranks; refused with 1.
table_of stopped 65 40 > stopped.prm
table_of whole 65 40 > whole.prm
mpi 2 "$exe" --quiet whole.prm > whole.txt 2>&1 || { bad "the uninterrupted 2-rank table failed"; cat whole.txt; }
mpirun -np 2 "$exe" --quiet stopped.prm > stopped-0.txt 2>&1 & pid=$!
for _ in $(seq 1 600); do
  [ -f stopped/checkpoint.cosmo ] && [ -f stopped/rank-1/checkpoint.cosmo ] && break; sleep 0.1; done
kill -TERM $pid; wait $pid 2>/dev/null; s1=$?
rows=$(($(wc -l < stopped/table.csv) - 1))
mpi 1 "$exe" --quiet --resume stopped > refused.txt 2>&1; s0=$?
if [ $s0 -eq 1 ] && grep -q "number of MPI ranks" refused.txt && grep -q "2 ranks" refused.txt; then
  ok "resuming a 2-rank table on 1 rank is refused (exit 1, the number of ranks named)"
else bad "resume on 1 rank: exit $s0"; cat refused.txt; fi
mpi 2 "$exe" --quiet --resume stopped > stopped-1.txt 2>&1; s2=$?
if [ $s1 -ne 0 ] && [ $rows -ge 1 ] && [ $s2 -eq 0 ] && cmp -s whole/table.csv stopped/table.csv &&
   [ -f stopped/table.h5 ] && [ ! -e stopped/checkpoint.cosmo ] && [ ! -e stopped/rank-1 ]; then
  ok "a 2-rank table stopped by SIGTERM (exit $s1, $rows rows on rank 0) and resumed on 2 ranks: the uninterrupted table.csv"
else bad "2-rank resume: exits $s1 $s2, $rows rows"; cat stopped-1.txt; diff whole/table.csv stopped/table.csv | head -4; fi
exit $fail

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
# that no rank directory is left, and that the seam check (rank 0 continues
# one point into rank 1's block and compares) finds the two paths' states
# equal to 1e-6 of their scales (the same branch: Newton's 1e-10 apart).
# Then a table interrupted by SIGTERM under mpirun is resumed: on 2 ranks
# from their checkpoints (the table of the uninterrupted 2-rank run,
# bitwise), and begun on 2 and resumed on 1, begun on 1 and resumed on 2
# (each point taken from the checkpoint of the rank that did it, the rest
# solved: the uninterrupted table to the tolerance above).
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
seam=$(sed -n 's/.*seam before point [0-9]*: .* agree to \([^ ]*\) .*/\1/p' two_ranks/log.txt)
if [ $s -eq 0 ] && grep -q "on 2 MPI ranks" two_ranks/log.txt && [ ! -e two_ranks/rank-1 ] &&
   [ -n "$seam" ] && python3 -c "import sys; sys.exit(not float('$seam') <= 1e-6)" && ! grep -q WARNING two_ranks/log.txt &&
   python3 -c "import json, sys; sys.exit(json.load(open('two_ranks/summary.json')).get('mpi_ranks') != 2)"; then
  ok "mpirun -np 2: exit 0, '2 MPI ranks' in the log and mpi_ranks = 2 in summary.json, no rank directory left; the seam between the blocks checked: $seam (a warning above 1e-6)"
else bad "mpirun -np 2: exit $s"; cat two_ranks.txt; fi
/usr/bin/python3 "$here/compare_tables.py" one_thread two_threads two_ranks || fail=1

# Interrupted under mpirun (SIGTERM to mpirun, which passes it to the
# ranks) and resumed: on 2 ranks, the uninterrupted 2-rank table bitwise
# (each rank goes on from its own checkpoint); on 1 rank and, begun on 1,
# on 2 ranks, each point from the checkpoint of the rank that solved it or
# solved from where an earlier rank stopped: the table of one process to
# the tolerance above.
table_of whole 97 40 > whole.prm
mpi 2 "$exe" --quiet whole.prm > whole.txt 2>&1 || { bad "the uninterrupted 2-rank table failed"; cat whole.txt; }
for case in 2:2 2:1 1:2; do
  from=${case%:*} to=${case#*:} d=stopped_$from-$to
  table_of $d 97 40 > $d.prm
  mpirun -np $from "$exe" --quiet $d.prm > $d-0.txt 2>&1 & pid=$!
  for _ in $(seq 1 600); do
    [ -f $d/checkpoint.cosmo ] && { [ $from = 1 ] || [ -f $d/rank-1/checkpoint.cosmo ]; } && break; sleep 0.02; done
  kill -TERM $pid; wait $pid 2>/dev/null; s1=$?
  rows=$(($(wc -l < $d/table.csv) - 1))
  mpi $to "$exe" --quiet --resume $d > $d-1.txt 2>&1; s2=$?
  if [ $s1 -ne 0 ] && [ $rows -ge 1 ] && [ $rows -lt 485 ] && [ $s2 -eq 0 ] && [ -f $d/table.h5 ] &&
     [ ! -e $d/checkpoint.cosmo ] && [ ! -e $d/rank-1 ] && grep -q "going on\|resumed on" $d/log.txt; then
    ok "a table on $from rank(s) stopped by SIGTERM (exit $s1, $rows rows on rank 0), resumed on $to: exit 0, no checkpoint or rank directory left"
  else bad "$from-rank table resumed on $to: exits $s1 $s2, $rows rows"; cat $d-1.txt; fi
  if [ $case = 2:2 ]; then
    cmp -s whole/table.csv $d/table.csv && ok "  ... its table.csv is the uninterrupted one, bitwise" ||
      { bad "  ... its table.csv differs from the uninterrupted one"; diff whole/table.csv $d/table.csv | head -4; }
  else
    # Against the uninterrupted 2-rank table, to 10x Newton's tolerance (R,
    # the round-off between thread counts, is not measured for this table).
    /usr/bin/python3 "$here/compare_tables.py" whole whole $d --resumed || fail=1
  fi
done
exit $fail

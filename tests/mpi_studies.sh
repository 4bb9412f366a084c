#!/usr/bin/env bash
# Parameter studies spread over 2 MPI ranks (mpirun -np 2, io/ranks.h)
# against one process:
#  - rod_cross_section's sweep curvature_vs_differential_growth: the points
#    are independent runs, so sweep.csv is the one process's to 1e-12
#    (tests/compare_runs.py; measured: bitwise);
#  - plate_rod's critical curve critical_curve_mode_change_planar_lobes
#    (6 values, blocks of 3): each block's first value is an independent
#    run instead of a continued one, so the critical loads agree to the
#    event location's resolution (the t_resolution column, ~1e-12; here
#    10x it), the modes and the converged flags exactly, and the change of
#    the critical mode (n = 16 to 14 between the 3rd and 4th value, on the
#    seam between the ranks' blocks) is still found and flagged;
# every point directory in the run's directory and no rank directory left;
# a 2-rank curve interrupted and resumed on one process; and a single path
# (strip twisting.prm) under mpirun: rank 0 alone, the result of one process.
# usage: mpi_studies.sh <rod_cross_section> <plate_rod> <strip> <scratch dir> [curve dir]
# (curve dir: the same curve already run by one process, e.g. by the test
# validation.plate_rod_critical_curve_mode_change; else it is run here)
set -uo pipefail
rod=$(realpath "$1") plate=$(realpath "$2") strip=$(realpath "$3") dir=$4 done_curve=${5:-}
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }
as() { sed "s|^\( *set Output directory *=\).*|\1 $2|" "$here/../parameter_files/$1"; }
as rod_cross_section/studies/curvature_vs_differential_growth.prm sweep_one > sweep_one.prm
as rod_cross_section/studies/curvature_vs_differential_growth.prm sweep_two > sweep_two.prm
as plate_rod/studies/critical_curve_mode_change_planar_lobes.prm curve_one > curve_one.prm
as plate_rod/studies/critical_curve_mode_change_planar_lobes.prm curve_two > curve_two.prm
timeout 600 "$rod" --quiet sweep_one.prm > sweep_one.txt 2>&1 || { bad "sweep, one process"; cat sweep_one.txt; }
timeout 600 mpirun -np 2 "$rod" --quiet sweep_two.prm > sweep_two.txt 2>&1 || { bad "sweep, 2 ranks"; cat sweep_two.txt; }
if /usr/bin/python3 "$here/compare_runs.py" sweep_one sweep_two sweep.csv; then
  ok "rod_cross_section sweep on 2 ranks: sweep.csv of one process (1e-12)"
else bad "rod_cross_section sweep on 2 ranks differs"; fi
if [ -n "$done_curve" ] && [ -f "$done_curve/sweep.csv" ]; then
  cp -r "$done_curve" curve_one
else
  timeout 900 "$plate" --quiet curve_one.prm > curve_one.txt 2>&1 || { bad "curve, one process"; cat curve_one.txt; }
fi
timeout 900 mpirun -np 2 "$plate" --quiet curve_two.prm > curve_two.txt 2>&1 || { bad "curve, 2 ranks"; cat curve_two.txt; }
same_curve() {
/usr/bin/python3 - "$1" "$2" <<'PY' || fail=1
import csv, math, sys
a, b = [list(csv.DictReader(open(d + "/sweep.csv"))) for d in sys.argv[1:3]]
key = lambda r, n: next(v for k, v in r.items() if k.split(" ")[0] == n)
bad = []
if len(a) != len(b) or len(a) != 6:
    bad.append("%d against %d values" % (len(a), len(b)))
worst = 0
for ra, rb in zip(a, b):
    for n in ("value", "converged", "mode_number", "mode_out_of_plane", "mode_change"):
        if key(ra, n) != key(rb, n):
            bad.append("%s: %s against %s at value %s" % (n, key(ra, n), key(rb, n), key(ra, "value")))
    ta, tb = float(key(ra, "t_critical")), float(key(rb, "t_critical"))
    res = max(float(key(ra, "t_resolution")), float(key(rb, "t_resolution")))
    worst = max(worst, abs(ta - tb) / res)
    if not abs(ta - tb) <= 10 * res:
        bad.append("t_critical %r against %r (resolution %.2g)" % (ta, tb, res))
changes = [key(r, "value") for r in b if key(r, "mode_change") == "1"]
for m in bad:
    print("  FAIL  " + m)
if not bad:
    print("  ok    critical curve %s: the same modes, converged flags and mode change (at %s), "
          "t_critical within %.2g of its resolution (tolerance 10)" % (sys.argv[2], changes, worst))
sys.exit(1 if bad else 0)
PY
}
same_curve curve_one curve_two
n=$(ls -d curve_two/point-0? 2>/dev/null | wc -l)
if [ "$n" -eq 6 ] && [ ! -e curve_two/rank-1 ] && [ ! -e sweep_two/rank-1 ] && grep -q "on different ranks" curve_two/sweep-log.txt; then
  ok "6 point directories in the run's directory, no rank directory left, the seam's mode change logged"
else bad "point directories: $n; rank-1 left: $(ls -d */rank-1 2>/dev/null)"; fi
# A single path has nothing to spread: rank 0 follows it (on all the
# cores); the other ranks would take part in its factorizations of 20000
# unknowns or more (tests/mpi_path.sh), none here: the result is one
# process's.
as strip/twisting.prm path_one > path_one.prm
as strip/twisting.prm path_two > path_two.prm
timeout 300 "$strip" --quiet path_one.prm > path_one.txt 2>&1 || { bad "path, one process"; cat path_one.txt; }
timeout 300 mpirun -np 2 "$strip" path_two.prm > path_two.txt 2>&1; s=$?
if [ $s -eq 0 ] && grep -q "which rank 0 follows" path_two.txt && [ ! -e path_two/rank-1 ] &&
   /usr/bin/python3 "$here/compare_runs.py" path_one path_two steps.csv; then
  ok "a single path under mpirun -np 2: rank 0's (said so), steps.csv of one process (1e-12)"
else bad "a single path under mpirun: exit $s"; cat path_two.txt; fi

# A curve on 2 ranks stopped (SIGTERM) after rank 0's first value, resumed
# on one process: the earlier value taken from rank 0's checkpoint, the
# others run; the same curve as above.
as plate_rod/studies/critical_curve_mode_change_planar_lobes.prm curve_stopped > curve_stopped.prm
# The ranks are stopped (SIGSTOP) as soon as rank 0's first checkpoint is
# there and sent SIGTERM (as SLURM signals every task), so that it reaches
# them in the middle of rank 0's block however fast the machine (a value
# takes 0.3 s here, the poll 0.01 s); they take it when continued.
mpirun -np 2 "$plate" --quiet curve_stopped.prm > curve_stopped-0.txt 2>&1 & pid=$!
for _ in $(seq 1 12000); do [ -f curve_stopped/checkpoint.cosmo ] && break; sleep 0.01; done
pkill -STOP -P $pid; pkill -TERM -P $pid; pkill -CONT -P $pid
wait $pid 2>/dev/null; s1=$?
timeout 900 "$plate" --quiet --resume curve_stopped > curve_stopped-1.txt 2>&1; s2=$?
if [ $s1 -ne 0 ] && [ $s2 -eq 0 ] && grep -q "resumed on 1 ranks a study begun on 2" curve_stopped/sweep-log.txt &&
   grep -q "done before the resume" curve_stopped/sweep-log.txt && [ ! -e curve_stopped/rank-1 ] &&
   [ ! -e curve_stopped/checkpoint.cosmo ]; then
  ok "a 2-rank curve stopped part-way (exit $s1) and resumed on one process: exit 0, the values done taken as they were"
else bad "2-rank curve resumed on 1: exits $s1 $s2"; cat curve_stopped-1.txt; tail -5 curve_stopped/sweep-log.txt; fi
same_curve curve_one curve_stopped
exit $fail

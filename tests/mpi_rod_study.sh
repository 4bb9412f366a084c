#!/usr/bin/env bash
# The rod's critical curve (parameter_files/rod/studies/euler_vs_length.prm,
# 6 lengths) on 2 MPI ranks (blocks of 3) against one process: each block's
# first value is an independent run instead of a continued one, so the
# critical loads agree to the event location's resolution (the t_resolution
# column, ~5e-14; here 100x it), the modes and the converged flags exactly;
# every point directory in the run's directory.
# usage: mpi_rod_study.sh <rod> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
as() { sed "s|^\( *set Output directory *=\).*|\1 $1|" "$here/../parameter_files/rod/studies/euler_vs_length.prm"; }
as one > one.prm && as two > two.prm
timeout 300 "$exe" --quiet one.prm > one.txt 2>&1 || { echo "  FAIL  the one-process study failed"; exit 1; }
timeout 300 mpirun -np 2 "$exe" --quiet two.prm > two.txt 2>&1 || { echo "  FAIL  the 2-rank study failed"; cat two.txt; exit 1; }
python3 - one/sweep.csv two/sweep.csv <<'PY'
import csv, sys
one, two = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
col = lambda r, n: next(v for k, v in r.items() if k.split(" [")[0] == n)
assert len(one) == len(two) == 6, "%d and %d points" % (len(one), len(two))
for a, b in zip(one, two):
    res = max(float(col(a, "t_resolution")), float(col(b, "t_resolution")))
    d = abs(float(col(a, "t_critical")) - float(col(b, "t_critical")))
    assert d <= 100 * res, "value %s: t differs by %g (resolution %g)" % (col(a, "value"), d, res)
    for n in ("converged", "mode_direction"):
        assert col(a, n) == col(b, n), "value %s: %s %s against %s" % (col(a, "value"), n, col(a, n), col(b, n))
print("  ok    6 points on 2 ranks: the critical loads within 100x their resolution, modes and flags equal")
PY
status=$?
n=$(ls -d two/point-* 2>/dev/null | wc -l)
if [ "$n" = 6 ]; then echo "  ok    every point directory in the run's directory"; else echo "  FAIL  $n point directories"; status=1; fi
exit $status

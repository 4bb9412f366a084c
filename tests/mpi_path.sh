#!/usr/bin/env bash
# A run of one path under `mpirun -np 2` (doc/parallel-runs.md): rank 0
# follows it, rank 1 takes part in its MUMPS factorizations and solves
# (solvers::factorization_ranks; COSMO_PARALLEL_FACTORIZATION_MIN=0 shares
# every matrix, which the default keeps to 20000 unknowns and more). The
# parallel LDL^T pivots and sums in another order than one process's, so
# the runs agree to round-off, not bitwise. Checked against one process:
#  - plate_rod, the dome past its first branch point onto the bifurcated
#    branch: every MUMPS phase shared (mumps_phases_on_all_ranks > 0), the
#    same events with the same inertia counts (INFOG(12) with ICNTL(13) = 1
#    is the exact inertia in parallel: a wrong count moves or loses an
#    event), the located loads equal to their resolution (summary.json
#    location.resolution, the round-off bound of the test function,
#    6.6e-9 here; measured differences 4e-11 to 6e-10), and the same stability count
#    and dome height at every step (to 1e-6 of the largest: the states
#    agree to Newton's stopping test, amplified on the branch just past
#    the bifurcation; measured 2.3e-9);
#  - rod_cross_section, the natural shape of a growing disc: the same
#    Newton iterations' result, strains and 6x6 stiffness to 1e-10 of their
#    scale (Newton's stopping test; measured 1.4e-16), the same inertia.
# usage: mpi_path.sh <plate_rod> <rod_cross_section> <scratch dir>
set -uo pipefail
plate=$(realpath "$1") section=$(realpath "$2") dir=$3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export COSMO_PARALLEL_FACTORIZATION_MIN=0
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }

for run in one two; do
  sed -e "s|^\( *set Output directory *=\).*|\1 dome_$run|" \
      -e "s|^\( *set Parameter range *=\).*|\1 0, 0.16|" \
      -e "s|^\( *set Maximum number of branches *=\).*|\1 2|" \
      "$here/../parameter_files/plate_rod/dome.prm" > dome_$run.prm
  sed -e "s|^\( *set Global refinements *=\).*|\1 3|" -e "s|^\( *set Output directory *=\).*|\1 disc_$run|" \
      "$here/../benchmarks/growing_disc.prm" > disc_$run.prm
done
for app in "$plate dome" "$section disc"; do
  exe=${app% *} name=${app#* }
  timeout 300 "$exe" --quiet ${name}_one.prm > ${name}_one.txt 2>&1 || { bad "$name: one process failed"; cat ${name}_one.txt; }
  timeout 300 mpirun -np 2 "$exe" --quiet ${name}_two.prm > ${name}_two.txt 2>&1 || { bad "$name: mpirun -np 2 failed"; cat ${name}_two.txt; }
done
/usr/bin/python3 - "$here" <<'PY' || fail=1
import csv, sys
sys.path.insert(0, sys.argv[1])
from mpi_checks import check, load, same_events, same_section_state
import mpi_checks
one, two = load("dome_one"), load("dome_two")
check(two.get("mpi_ranks") == 2 and two.get("mumps_phases_on_all_ranks", 0) > 0,
      f"dome: {two.get('mumps_phases_on_all_ranks')} MUMPS phases on both ranks")
same_events("dome", one, two)
s1, s2 = (list(csv.DictReader(open(f"dome_{r}/steps.csv"))) for r in ("one", "two"))
check(len(s1) == len(s2) and all(a["n_negative_eigenvalues"] == b["n_negative_eigenvalues"] and a["branch"] == b["branch"] for a, b in zip(s1, s2)),
      f"dome: {len(s1)} and {len(s2)} steps, the same branches and stability counts")
scale = max(abs(float(a["dome_height"])) for a in s1)
d = max(abs(float(a["dome_height"]) - float(b["dome_height"])) for a, b in zip(s1, s2)) / scale
check(scale > 1e-3 and d <= 1e-6, f"dome: dome height (largest {scale:.3g}, on the bifurcated branch) the same to {d:.1e} <= 1e-6")
one, two = load("disc_one"), load("disc_two")
check(two.get("mumps_phases_on_all_ranks", 0) > 0, f"disc: {two.get('mumps_phases_on_all_ranks')} MUMPS phases on both ranks")
same_section_state("disc", one, two)
sys.exit(mpi_checks.failures > 0)
PY
exit $fail

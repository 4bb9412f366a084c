#!/usr/bin/env bash
# rod_cross_section on a mesh distributed over the MPI ranks ('Finite
# element / Distributed', doc/parallel-runs.md "Distributed meshes"): each
# rank assembles its own cells into its rows of the bordered system's sparse
# block, MUMPS factorizes it with distributed input, the border (the six
# strains, the six gauge multipliers: whole on every rank) is condensed on
# every rank alike. The ranks' partial sums are added in another order than
# one process's, so the runs agree to round-off, not bitwise. Checked
# against one process on a serial mesh:
#  - the natural shape of a growing disc at np = 1 and 2: the strains and the
#    6x6 stiffness to 1e-10 of their scale (Newton's stopping test, as for one
#    path on several ranks; measured 5.6e-17 and 6.6e-16), the same inertia,
#    the same mesh; the .pvtu records list one piece per rank, all present,
#    and VTK reads the section and the rod piece with the serial VTUs' cells
#    and largest |position| and |displacement| (Float32: to 1e-6 of it);
#  - a section with surface growth whose Hessian has 43 negative
#    eigenvalues (the exact inertia of MUMPS in parallel) and a gmsh
#    section (every gmsh cell a coarse cell of the distributed mesh): the
#    same inertia and stiffness to 1e-10 (measured 6.1e-15, 5.5e-13);
#  - the twist buckling of a thin strip's section (arclength, stop at the
#    first event): the same branch point with the same inertia counts, at
#    the same load to its resolution (5.4e-13; measured 5e-15). Both runs
#    take the second-order estimate's products by differences of residuals
#    (COSMO_ESTIMATE_BY_RESIDUALS=1 for the serial run; a distributed
#    problem stores no Jacobian copies): so both locate the point from the
#    same estimate, to round-off. (With stored Jacobians, and the estimate's
#    mode converged to 1e-4 as it then was, the serial estimate was another,
#    0.4707611 against 0.4707338, and Newton from it located the point
#    1.3e-12 = 2.4 resolutions away; the mode is converged to 1e-8 since,
#    doc/theory-continuation.md 10.)
# usage: mpi_distributed_section.sh <rod_cross_section> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
examples="$here/../parameter_files/rod_cross_section"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail=0
bad() { echo "  FAIL  $1"; fail=1; }
distributed='subsection Finite element\n  set Distributed = true\nend\n'

# name, source, sed script, extra lines (the runs start in the repository: the gmsh files' paths)
make_prm() { sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$1|" -e "$3" "$2" > $1.prm; printf "$4" >> $1.prm; }
disc='s|^\( *set Global refinements *=\).*|\1 3|
s|List of postprocessors = steps table$|List of postprocessors = steps table, fields\n  subsection fields\n    set Steps between outputs = 0\n  end|'
for r in serial np1 np2; do
  extra=""; [ $r != serial ] && extra="$distributed"
  make_prm disc_$r "$here/../benchmarks/growing_disc.prm" "$disc" "$extra"
  make_prm surface_$r "$examples/surface_growth.prm" "" "$extra"
  make_prm channel_$r "$examples/channel_twist.prm" "" "$extra"
  python3 - "$examples/studies/critical_twist_vs_axial_growth.prm" twist_$r "$dir" "$extra" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
s = re.sub(r"subsection Parameter sweep.*?\nend\n", "", s, flags=re.S)
s = re.sub(r"(set Output directory *=).*", r"\1 " + sys.argv[3] + "/" + sys.argv[2], s)
open(sys.argv[2] + ".prm", "w").write(s + sys.argv[4].replace("\\n", "\n"))
PY
done
run() { # name, ranks (0: one process, no mpirun)
  if [ $2 -eq 0 ]; then (cd "$here/.." && timeout 300 "$exe" --quiet "$dir/$1.prm") > $1.txt 2>&1
  else (cd "$here/.." && timeout 300 mpirun -np $2 "$exe" --quiet "$dir/$1.prm") > $1.txt 2>&1; fi ||
    { bad "$1 failed"; tail -n 5 $1.txt; }
}
run disc_serial 0; run disc_np1 1; run disc_np2 2
for c in surface channel; do run ${c}_serial 0; run ${c}_np2 2; done
COSMO_ESTIMATE_BY_RESIDUALS=1 run twist_serial 0; run twist_np2 2

/usr/bin/python3 - "$here" <<'PY' || fail=1
import os, sys
sys.path.insert(0, sys.argv[1])
from mpi_checks import check, load, same_events, same_section_state, pieces_present, same_as_serial_vtu
import mpi_checks
def same_state(name, a, b, ranks):
    check(b.get("distributed_mesh_ranks") == ranks and a["mesh"]["cells"] == b["mesh"]["cells"] and
          a["mesh"]["field_dofs"] == b["mesh"]["field_dofs"] and a["status"] == b["status"] == "converged",
          f"{name}: the mesh over {b.get('distributed_mesh_ranks')} rank(s), {b['mesh']['cells']} cells, {b['mesh']['field_dofs']} field DoFs, converged")
    same_section_state(name, a, b)
serial = load("disc_serial")
same_state("growing disc, 1 rank", serial, load("disc_np1"), 1)
same_state("growing disc, 2 ranks", serial, load("disc_np2"), 2)
same_state("surface growth, 2 ranks", load("surface_serial"), load("surface_np2"), 2)
same_state("gmsh channel, 2 ranks", load("channel_serial"), load("channel_np2"), 2)
same_events("twist", load("twist_serial"), load("twist_np2"))
# (the section's displacement of a natural shape is zero to round-off: its deformed position)
for stem, field in (("solution-0001", "position"), ("rod-0001", "displacement")):
    check(pieces_present("disc_np2", stem, 2), f"{stem}.pvtu: the pieces of both ranks, present")
    same_as_serial_vtu("disc_serial", "disc_np2", stem, field)
check("solution-0001.pvtu" in open("disc_np2/solution.pvd").read(), "solution.pvd names the .pvtu record")
sys.exit(mpi_checks.failures > 0)
PY
exit $fail

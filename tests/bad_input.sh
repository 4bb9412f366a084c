#!/usr/bin/env bash
# Bad input ends with a clear message naming the file/entry/allowed values
# and exit status 1 -- never an abort, a hang or a silent answer.
# usage: bad_input.sh <rod_cross_section> <scratch dir>
set -uo pipefail
exe=$1 dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
source "$here/expect.sh"
base() { cat <<PRM
subsection Cross-section
  set Shape = circle
  set Global refinements = 1
end
subsection Output
  set Output directory = out
end
subsection Postprocess
  set List of postprocessors = steps table
end
PRM
}
expect "missing file" "cannot open the parameter file 'nope.prm'" nope.prm
{ base; echo "include self.prm"; } > self.prm
expect "a parameter file that includes itself" "include cycle in parameter files: 'self.prm' includes 'self.prm' again" self.prm
{ base; echo "include b.prm"; } > a.prm; echo "include a.prm" > b.prm
expect "an include cycle through two files" "'a.prm' includes 'b.prm' includes 'a.prm' again" a.prm
mkdir -p a_directory.prm
expect "a directory as the parameter file" "'a_directory.prm' is not a regular file (a directory)" a_directory.prm
{ base; echo "include ."; } > include_dir.prm
expect "an include of a directory" "'.' (included from 'include_dir.prm') is not a regular file" include_dir.prm
printf '{"Output": {"Output directory"' > truncated.json
expect "a truncated JSON parameter file (file and line named)" "in parameter file 'truncated.json': The provided JSON file is not valid. Boost aborted with the following assert message: line 1: expected ':'" truncated.json
printf '<?xml version="1.0"?>\n<ParameterHandler><Output><Output_20directory>x</Output' > truncated.xml
expect "a truncated XML parameter file (file and line named)" "in parameter file 'truncated.xml': line 2: expected > (the file is not complete XML)" truncated.xml
{ base; echo "set Undeclared entry = 3"; } > undeclared.prm
expect "undeclared entry" "Undeclared entry" undeclared.prm
{ base; printf 'subsection Cross-section\n set Shape = hexagon\nend\n'; } > shape.prm
expect "value outside its pattern (names the allowed values)" "circle|ellipse" shape.prm
{ base; printf 'subsection Material 1\n set Poisson'"'"'s ratio = 0.7\nend\n'; } > poisson.prm
expect "Poisson ratio out of range" "Poisson's ratio" poisson.prm
{ base; printf 'subsection Material 1\n set Growth kind = axial\n set Growth factor = 1 + 0.3*z\nend\n'; } > expr.prm
expect "growth expression that does not parse" "Growth factor" expr.prm
{ base; printf 'subsection Material 1\n set Growth kind = none\n set Growth factor = 1 + 0.3*z\nend\n'; } > unused_expr.prm
expect "an unused growth expression that does not parse (Growth kind = none)" "unused with Growth kind = none, still checked', entry 'Growth factor'" unused_expr.prm
{ base; printf 'subsection Material 1\n set Growth kind = isotropic\n set Growth factor = 0.5 - x\nend\n'; } > detfg.prm
expect "growth with det Fg <= 0" "det Fg" detfg.prm
{ base; printf 'subsection Cross-section\n set Shape = bilayer\nend\n'; } > region.prm
expect "region without a material" "no material covers region 2" region.prm
{ base; printf 'subsection Cross-section\n set Shape = gmsh\n set Mesh file = missing.msh\nend\n'; } > msh.prm
expect "gmsh mesh file missing" "Mesh file" msh.prm
{ base; printf 'subsection Cross-section\n set Shape = gmsh\n set Mesh file = missing.geo\nend\n'; } > geo.prm
expect "gmsh .geo file missing" "'Mesh file' = 'missing.geo'" geo.prm
printf 'Point(1) = {0, 0, 0 0.1};\n' > syntax.geo
{ base; printf 'subsection Cross-section\n set Shape = gmsh\n set Mesh file = syntax.geo\nend\n'; } > geo_syntax.prm
expect "gmsh .geo with a syntax error (gmsh's message)" "'Mesh file' = 'syntax.geo': gmsh failed" geo_syntax.prm
printf 'Point(1) = {0,0,0,0.2}; Point(2) = {1,0,0,0.2}; Point(3) = {1,1,0,0.2};\nLine(1) = {1,2}; Line(2) = {2,3};\nCurve Loop(1) = {1,2}; Plane Surface(1) = {1};\n' > open.geo
{ base; printf 'subsection Cross-section\n set Shape = gmsh\n set Mesh file = open.geo\nend\n'; } > geo_open.prm
expect "gmsh .geo with an open curve loop" "'Mesh file' = 'open.geo'" geo_open.prm
{ base; printf 'subsection Material 1\n set Regions = section, core\nend\n'; } > region_name.prm
expect "unknown region name (lists the names)" "'Regions' = 'section, core': unknown region 'core'; this section has: section (1)" region_name.prm
{ base; printf 'subsection Surface layer 1\n set Boundary parts = outer, lumen\nend\n'; } > part.prm
expect "unknown boundary part (lists the parts)" "unknown boundary part 'lumen'; this section has: outer" part.prm
{ base; printf 'subsection Surface layer 1\n set Boundary parts = arc 200 100\nend\n'; } > arc.prm
expect "arc with A >= B" "needs A < B" arc.prm
{ base; printf 'subsection Surface layer 1\n set Boundary parts = all\n set Growth kind = isotropic\n set Growth factor = 1 + q\nend\n'; } > sexpr.prm
expect "surface growth expression that does not parse" "'Surface layer 1', entry 'Growth factor'" sexpr.prm
{ base; printf 'subsection Surface layer 1\n set Boundary parts = all\n set Growth kind = tangential and axial\n set Growth factor = 1.1\nend\n'; } > stwo.prm
expect "surface growth with one factor for two" "expected 2 expression(s)" stwo.prm
{ base; printf 'subsection Surface layer 1\n set Boundary parts = all\n set Growth kind = isotropic\n set Growth factor = x\nend\n'; } > sneg.prm
expect "surface growth factor <= 0 somewhere (names the point)" "each surface factor (gT, g3) = -0.707107 at (-0.707107, -0.707107)" sneg.prm
{ base; printf 'subsection Material 1\n set Growth kind = isotropic\n set Growth factor = 1 + 1e300*1e300*x*x\nend\n'; } > ginf.prm
expect "a growth factor that is infinite on part of the section" "growth must be finite and keep det Fg > 0" ginf.prm
{ base; printf 'subsection Cross-section\n set Global refinements = 10\nend\nsubsection Finite element\n set Polynomial degree = 4\nend\n'; } > huge.prm
expect "a mesh far larger than memory (refused before refining, ~200 GB estimated)" "fits in this machine's memory" huge.prm
{ base; printf 'subsection Surface layer 1\n set Boundary parts = all\n set Surface Lame modulus = -1\n set Surface shear modulus = 0.5\nend\n'; } > slame.prm
expect "surface moduli with a negative areal modulus" "lambda_s + mu_s must be >= 0" slame.prm
{ base; printf 'subsection Parameter sweep\n set Entry = Material 1/Youngs modulus\nend\n'; } > sweep_entry.prm
expect "sweep of an entry that does not exist" "'Parameter sweep', entry 'Entry'" sweep_entry.prm
{ base; printf 'subsection Parameter sweep\n set Entry = Material 1/Poisson'"'"'s ratio\n set Values = 0.3, 0.6\nend\n'; } > sweep_value.prm
expect "sweep value outside the entry's range" "accepts '0.6'" sweep_value.prm
{ base; printf 'subsection Parameter sweep\n set Entry = Material 1/Growth factor\n set Template = 1 + x\nend\n'; } > sweep_template.prm
expect "sweep template without {}" "Template" sweep_template.prm
{ base; printf 'subsection Material 1\n set Growth kind = isotropic\nend\nsubsection Parameter sweep\n set Entry = Material 1/Growth factor\n set Template = 1 + {}*x\n set Values = 0.2, 1.5, 0.4\nend\n'; } > sweep_reject.prm
expect "sweep point rejected by the problem (names it)" "1 of 3 values were rejected by the problem: '1 + 1.5\*x'" sweep_reject.prm
if [ "$(grep -c '^[0-9]' out/sweep.csv)" = 3 ] && grep -q '^2,0.4,1,' out/sweep.csv; then
  echo "  ok    the other sweep points ran (sweep.csv has 3 rows, point 2 converged)"
else
  echo "  FAIL  after a rejected point the sweep must go on:"; cat out/sweep.csv; fail=1
fi
{ base; printf 'subsection Rod strains\n set Strains = 0, 0, 1\nend\n'; } > strains.prm
expect "wrong number of strains" "Strains" strains.prm
expect "unknown option" "unknown option" --frobnicate
expect "--print-parameters with an unknown format" "takes prm, json or xml (then, optionally, a parameter file), not 'yaml'" --print-parameters yaml
expect "--print-parameters of a missing file" "cannot open the parameter file 'nope.prm'" --print-parameters json nope.prm
{ base; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Strains = 0, 0, 1, 0, 0, 0.25\nend\n'; } > given.prm
if timeout 60 "$exe" --print-parameters json given.prm | python3 -c 'import json, sys; d = json.load(sys.stdin); sys.exit(0 if d["Rod strains"]["Strains"]["value"] == "0, 0, 1, 0, 0, 0.25" and d["Cross-section"]["Global refinements"]["value"] == "1" else 1)'; then
  echo "  ok    --print-parameters json FILE prints the file's values"
else echo "  FAIL  --print-parameters json FILE does not print the file's values"; fail=1; fi
{ base; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Free strains = kappa3\nend\nsubsection Constitutive table\n set Enabled = true\nend\n'; } > tablefree.prm
expect "a table axis that is a free strain" "entry 'Second strain' = 'kappa3': a prescribed strain: this one is free" tablefree.prm
{ base; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Free strains = nu3\n set Resultants = 0, 0, 1, 1, 0, 0\nend\n'; } > moment.prm
expect "a moment target for a prescribed curvature" "m1 = 1 for the prescribed kappa1: a resultant can only be prescribed for a strain in 'Free strains'" moment.prm
distributed='subsection Finite element\n set Distributed = true\nend\n'
{ base; printf "$distributed"'subsection Nonlinear solver\n set Linear solver = UMFPACK\nend\n'; } > distributed_umfpack.prm
expect "a distributed mesh with UMFPACK" "entry 'Linear solver' = 'UMFPACK': a distributed mesh ('Finite element / Distributed = true') is factorized by MUMPS" distributed_umfpack.prm
{ base; printf "$distributed"'subsection Rod strains\n set Mode = prescribed strains\n set Free strains = nu3\nend\nsubsection Constitutive table\n set Enabled = true\nend\n'; } > distributed_table.prm
expect "a distributed mesh with a constitutive table" "entry 'Distributed' = 'true': a constitutive table spreads its points over the MPI ranks" distributed_table.prm
{ base; printf "$distributed"'subsection Parameter sweep\n set Entry = Material 1/Growth factor\n set Values = 1, 1.1\nend\n'; } > distributed_sweep.prm
expect "a distributed mesh with a parameter study" "entry 'Distributed' = 'true': a parameter study spreads its values over the MPI ranks" distributed_sweep.prm
exit $fail

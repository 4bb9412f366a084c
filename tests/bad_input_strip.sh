#!/usr/bin/env bash
# Bad input of the strip application: a clear message naming the entry and
# exit status 1. usage: bad_input_strip.sh <strip> <scratch dir>
set -uo pipefail
exe=$1 dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
source "$here/expect.sh"
strip() { printf 'subsection Strip\n%s\nend\nsubsection Output\n set Output directory = out\nend\n' "$1"; }
strip ' set Width = -1' > width.prm
expect "negative width" "Width" width.prm
strip ' set Width = 0.1
 set Thickness = 0.2' > thick.prm
expect "thickness larger than the width" "must be smaller than the width" thick.prm
strip ' set Mesh = chebyshev' > mesh.prm
expect "unknown mesh kind (names the allowed values)" "graded|uniform" mesh.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Strains = 0, 0, 1, 0\nend\n'; } > strains.prm
expect "wrong number of strains" "Strains" strains.prm
{ strip ' set Width = 1'; printf 'subsection Plate material\n set Young'"'"'s modulus = 0\nend\n'; } > young.prm
expect "zero Young's modulus" "Young's modulus" young.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Free strains = nu3\n set Path = 0, 0, 1.1, 0, 0, 0\nend\n'; } > twice.prm
expect "a path that asks for a strain twice (free and prescribed)" "either prescribed or free" twice.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Path = 0, 0, 1; 1\nend\n'; } > path.prm
expect "a path waypoint that is not six numbers" "not six numbers" path.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Path = 0, 0, 1, nan, 0, 0\nend\n'; } > nan_path.prm
expect "a NaN in a path waypoint" "six finite numbers" nan_path.prm
{ strip ' set Width = 1'; printf 'subsection Constitutive table\n set Enabled = true\n set First strain = kappa3\n set Second strain = kappa3\nend\n'; } > table.prm
expect "a table that asks for a strain twice" "a strain other than the first" table.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Free strains = kappa3\nend\nsubsection Constitutive table\n set Enabled = true\nend\n'; } > tablefree.prm
expect "a table axis that is a free strain" "a prescribed strain: this one is free" tablefree.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Strains = 0, 0, 1.1, 0, 0, 0.2\n set Free strains = nu3\nend\n'; } > strainfree.prm
expect "a strain both free and set in Strains" "is in 'Free strains' and set here" strainfree.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Strains = 0, 0, 1, 1e300, 0, 0\nend\n'; } > huge_kappa.prm
expect "a curvature no rod has (kappa1 = 1e300; it made Newton wander)" "kappa1 = 1e+300 is not" huge_kappa.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = natural shape\n set Free strains = nu3\nend\n'; } > ignored.prm
expect "an entry the natural-shape mode ignores (Free strains)" "entry 'Free strains' = 'nu3': nothing in 'Mode = natural shape'" ignored.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = prescribed strains\n set Free strains = nu3\n set Resultants = 0, 0, 0.1, 0, 0, 0.01\nend\n'; } > torque_prescribed.prm
expect "a resultant target for a prescribed strain (m3 with kappa3 prescribed)" "entry 'Resultants' = '0, 0, 0.1, 0, 0, 0.01': m3 = 0.01 for the prescribed kappa3: a resultant can only be prescribed for a strain in 'Free strains'" torque_prescribed.prm
{ strip ' set Width = 1'; printf 'subsection Rod strains\n set Mode = natural shape\n set Resultants = 0, 0, 0.1, 0, 0, 0\nend\n'; } > natural_loaded.prm
expect "a resultant target in natural-shape mode" "entry 'Resultants' = '0, 0, 0.1, 0, 0, 0': nothing in 'Mode = natural shape'" natural_loaded.prm
strip ' set Width = 1
 set Natural curvature = 0; 0; t*' > kbar_parse.prm
expect "a natural curvature that does not parse" "3 muparser expressions of eta and t" kbar_parse.prm
strip ' set Width = 1
 set Natural curvature = 0; 0; 1 + t' > kbar_start.prm
expect "a natural curvature not zero at t = 0" "zero at t = 0 (the path starts at the flat strip)" kbar_start.prm
strip ' set Width = 1
 set Natural curvature = 0; 0; t/eta' > kbar_inf.prm
expect "a natural curvature infinite at the centre line" "finite across the width" kbar_inf.prm
exit $fail

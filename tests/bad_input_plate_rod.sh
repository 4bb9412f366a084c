#!/usr/bin/env bash
# Bad input of the plate_rod application: a clear message naming the entry
# and exit status 1. usage: bad_input_plate_rod.sh <plate_rod> <scratch dir>
set -uo pipefail
exe=$1 dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
source "$here/expect.sh"
base() { printf 'subsection Mesh\n set Global refinements = 1\nend\nsubsection Output\n set Output directory = out\nend\n'; }
{ base; printf 'subsection Mesh\n set Domain = sector\n set Sector angle = 50\nend\n'; } > sector.prm
expect "a sector angle that is not 180/n degrees" "180/n degrees for an integer n" sector.prm
{ base; printf 'subsection Rim rod\n set Stiffnesses = 1, 1, 1e12, 1, 1, 1\nend\n'; } > stiff.prm
expect "a rod stiffer than representable" "stiffer than representable" stiff.prm
{ base; printf 'subsection Rim rod\n set Stiffnesses = 1, 1, 0, 1, 1, 1\nend\n'; } > zero.prm
expect "a rod stiffness of zero" "must be positive" zero.prm
{ base; printf 'subsection Rim rod\n set Stiffnesses = 1, 1, 1\nend\n'; } > three.prm
expect "three stiffnesses instead of six" "Stiffnesses" three.prm
{ base; printf 'subsection Plate growth\n set Kind = isotropic\n set Radial growth factor = 1.001\nend\nsubsection Rim rod\n set Stiffnesses = 1, 1, 1, 1e-5, 1e-5, 1e-5\nend\nsubsection Growth path\n set Start = 0.8\nend\n'; } > start.prm
expect "a path that starts past the threshold" "already unstable" start.prm
{ base; printf 'subsection Plate growth\n set Kind = isotropic\n set Radial growth factor = 1 - 2*r\nend\n'; } > negative.prm
expect "a growth factor that is negative somewhere (names the point and the load)" "entry .Radial growth factor. = .1 - 2\*r.: the radial growth factor = .* at load t = " negative.prm
{ base; printf 'subsection Plate\n set Thickness = 2\nend\n'; } > thick.prm
expect "a plate thicker than its radius" "smaller than the radius" thick.prm
{ base; printf 'subsection Model\n set Model = reissner\nend\n'; } > model.prm
expect "an unknown model (names the allowed values)" "cosserat|kirchhoff|von karman" model.prm
{ base; printf 'subsection Rim rod\n set Stiffness file = no-such-summary.json\nend\n'; } > file.prm
expect "a stiffness file that does not exist" "cannot open it" file.prm
printf '{"stiffness": [[1, 0], [0, 1]]}\n' > small.json
{ base; printf 'subsection Rim rod\n set Stiffness file = small.json\nend\n'; } > small.prm
expect "a stiffness file without a 6x6 stiffness" "found 4 numbers" small.prm
printf '{"stiffness": [[1, 0], [0, 1]\n' > broken.json
{ base; printf 'subsection Rim rod\n set Stiffness file = broken.json\nend\n'; } > broken.prm
expect "a stiffness file that is not JSON (names where)" "not JSON at character" broken.prm
{ base; printf 'subsection Plate\n set Thickness profile = 1 - 2*r^2\nend\n'; } > profile.prm
expect "a thickness profile negative near the rim" "the thickness must be positive and finite at the quadrature points" profile.prm
{ base; printf 'subsection Plate\n set Thickness profile = 1 + q\nend\n'; } > profile_parse.prm
expect "a thickness profile that does not parse (names the entry)" "Thickness profile" profile_parse.prm
{ base; printf 'subsection Plate growth\n set Natural curvature = 0.1; sqrt(0.3 - r); 0\nend\n'; } > curvature.prm
expect "a natural curvature that is NaN on part of the plate" "must be finite on the plate" curvature.prm
{ base; printf 'subsection Plate growth\n set Natural curvature = 0.1; 0.1\nend\n'; } > curvature2.prm
expect "two natural curvature components instead of three" "3 muparser expression(s)" curvature2.prm
{ base; printf 'subsection Rim rod\n set Natural curvature = 0.1, nan, 0\nend\n'; } > rimcurv.prm
expect "a NaN in the rim's natural curvature" "Natural curvature" rimcurv.prm
{ base; printf 'subsection Mesh\n set Global refinements = 8\n set Polynomial degree = 4\nend\n'; } > huge.prm
expect "a mesh far larger than memory (refused before refining, ~500 GB estimated)" "fits in this machine's memory" huge.prm
{ base; printf 'subsection Plate\n set Thickness = 1e-300\nend\n'; } > thin.prm
expect "a plate too thin for double precision (names the thickness)" "entry 'Thickness' = '1e-300': h/R >= 1e-5" thin.prm
{ base; printf 'subsection Plate growth\n set Kind = none\n set Radial growth factor = 1 + zz\nend\n'; } > unused.prm
expect "an unused plate growth expression that does not parse (Kind = none)" "entry 'Radial growth factor (unused with Kind = none, still checked)' = '1 + zz'" unused.prm
printf '{"stiffness": [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,-1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]}\n' > negative.json
{ base; printf 'subsection Rim rod\n set Stiffness file = negative.json\nend\n'; } > negative.prm
expect "a stiffness file with a negative EA (names the file, not the unused Stiffnesses)" "entry 'Stiffness file' = 'negative.json': every stiffness must be positive (EA = -1 is not)" negative.prm
printf '{"stiffness": [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,2,0,0],[0,0,2,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]}\n' > indefinite.json
{ base; printf 'subsection Rim rod\n set Stiffness file = indefinite.json\nend\n'; } > indefinite.prm
expect "a stiffness file with positive diagonal but indefinite (coupling 2 > sqrt(1 x 1))" "entry 'Stiffness file' = 'indefinite.json': a positive definite 6x6 stiffness (its leading 4x4 block is not)" indefinite.prm
printf '{"stiffness": [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0.5,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]}\n' > asymmetric.json
{ base; printf 'subsection Rim rod\n set Stiffness file = asymmetric.json\nend\n'; } > asymmetric.prm
expect "an asymmetric stiffness file" "entry 'Stiffness file' = 'asymmetric.json': a symmetric 6x6 stiffness (max |K_ab - K_ba| = 0.5)" asymmetric.prm
{ base; printf 'subsection Mesh\n set Distributed = true\nend\nsubsection Parameter sweep\n set Entry = Plate/Thickness\n set Values = 0.01, 0.02\nend\n'; } > distributed_study.prm
expect "a distributed mesh with a parameter study (which spreads its values over the ranks)" "entry 'Distributed' = 'true': a parameter study spreads its values" distributed_study.prm
printf 'subsection Output\n set Output directory = ab\000cd\nend\n' > nul.prm
expect "a NUL byte in the output directory (shown, its position named)" "a path without control characters (character 3 is 0x00" nul.prm
exit $fail

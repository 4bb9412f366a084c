#!/usr/bin/env bash
# Bad input of the rod application: a clear message naming the entry and
# exit status 1; a start the element cannot represent is refused, not
# followed. usage: bad_input_rod.sh <rod> <scratch dir>
set -uo pipefail
exe=$1 dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
source "$here/expect.sh"
rod() { printf 'subsection Rod\n%s\nend\n%s\nsubsection Output\n set Output directory = out\nend\n' "$1" "${2:-}"; }
rod ' set Length = -1' > length.prm
expect "negative length" "Length" length.prm
rod ' set Natural strains = 0; 0; 1; 0; 0' > strains.prm
expect "five natural strains for six" "6 muparser expression" strains.prm
rod ' set Natural strains = 0; 0; 1; 0; sin(; 0' > parse.prm
expect "an expression that does not parse" "Natural strains" parse.prm
rod ' set Shape = spiral' > shape.prm
expect "unknown shape (names the allowed values)" "straight|natural|ring" shape.prm
rod '' 'subsection End A
 set Support = free
end' > free.prm
expect "both ends free (rigid motions not held)" "supports that hold the rod" free.prm
rod '' 'subsection End A
 set Support = pinned
end' > pinned_free.prm
expect "a pin and a free end (the rod turns about the pin)" "supports that hold the rod" pinned_free.prm
rod '' 'subsection End B
 set Support = clamped
 set Force = 0; 0; t
end' > force.prm
expect "a dead force on a clamped end" "a force there does no work" force.prm
rod ' subsection Material
  set Law = cubic
 end' > law.prm
expect "an unknown rod law" "quadratic" law.prm
rod ' set Shape = ring
 set Number of elements = 2' > ring.prm
expect "a ring of two elements" "at least 3 for a ring" ring.prm
rod ' set Number of elements = 2
 set Natural strains = 0; 0; 1; 0; 8; 0
 set Shape = natural' > coarse.prm
expect "an element of the start turned by 229 degrees (too coarse a mesh)" "use at least 4 elements" coarse.prm
# The law of part-1 sections: a missing file, a file that is not a result,
# a sweep without its columns, a part-1 parameter file with bad input of
# its own, natural strains given beside the section's.
# section_law FILE [ROD ENTRIES]: a rod on 'Law = section' with 'Section file = FILE'.
section_law() { rod "${2:-}
 subsection Material
  set Law = section
  set Section file = $1
 end"; }
section_law nowhere/summary.json > section_missing.prm
expect "a section file that does not exist" "Section file" section_missing.prm
printf '{"status": "converged", "strains": {}}' > not_a_section.json
section_law not_a_section.json > section_broken.prm
expect "a summary.json without a stiffness" "6x6" section_broken.prm
printf 'point,value [x],converged,nu1 [1]\n0,0,1,0\n' > short_sweep.csv
section_law short_sweep.csv > section_columns.prm
expect "a sweep.csv without the stiffness columns" "no column" section_columns.prm
printf 'subsection Cross-section\n set Shape = spiral\nend\n' > bad_section.prm
section_law bad_section.prm > section_nested.prm
expect "a part-1 file with bad input of its own" "bad_section.prm" section_nested.prm
printf '{"status": "converged", "strains": {"nu1": 0, "nu2": 0, "nu3": 1, "kappa1": 0, "kappa2": -0.3, "kappa3": 0}, "resultants": {"n1": 0, "n2": 0, "n3": 0, "m1": 0, "m2": 0, "m3": 0}, "stiffness": [[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,3,0,0,0],[0,0,0,0.8,0,0],[0,0,0,0,0.8,0],[0,0,0,0,0,0.6]]}' > one_section.json
section_law one_section.json ' set Natural strains = 0; 0; 1; 0; 1; 0' > section_twice.prm
expect "natural strains given beside a section's" "Natural strains" section_twice.prm
rod ' set Natural strain imperfection = 0; 0.1*s' > imperfection.prm
expect "an imperfection of two strains for six" "Natural strain imperfection" imperfection.prm
# Self-contact: a radius the nodes cannot integrate (the default 40
# elements on L = 1 need a >= 0.05), a contact without stiffness.
rod ' subsection Contact
  set Radius = 0.03
 end' > contact_coarse.prm
expect "a contact radius below twice the element length" "at least twice the element length" contact_coarse.prm
rod ' subsection Contact
  set Radius = 0.1
  set Stiffness = 0
 end' > contact_stiffness.prm
expect "a contact without stiffness" "positive with a contact radius" contact_stiffness.prm
# Stiffness factors: non-positive at the start (refused, exit 1); falling
# to zero along the path (the path stops where it would, exit 2, the entry
# and the point named).
rod ' set Stiffness factors = 1; 1; 1; 1; 1; 0' > factors.prm
expect "a zero stiffness factor at the start" "Stiffness factors" factors.prm
rod ' set Stiffness factors = 1; 1; 1; 1; 1' > factors_five.prm
expect "five stiffness factors for six" "Stiffness factors" factors_five.prm
rod ' set Stiffness factors = 1; 1; 1; 1; 1 - 2*t; 1' 'subsection End B
 set Force = 0; 0; -0.01*t
end' > factors_path.prm
timeout 60 "$exe" factors_path.prm > out.txt 2>&1; status=$?
if [ $status -eq 2 ] && grep -q "Stiffness factors" out.txt; then
  echo "  ok    a factor falling to zero on the path (status 2: $(grep -m1 'Stiffness factors' out.txt | cut -c1-150))"
else
  echo "  FAIL  a factor falling to zero on the path: status $status (expected 2), output:"; cat out.txt; fail=1
fi
exit $fail

#!/usr/bin/env bash
# Part 1 and 2 paths killed and resumed (--resume): the strip's twist
# buckling (arclength, events, switched branches) stopped by SIGTERM at step
# 20 and SIGKILL at step 50, and a section's natural-parameter growth path
# stopped by SIGKILL after step 2, and a sweep of a section over a parameter
# killed after its third point, and a section's constitutive table killed
# half-way, each resumed to the end, reach the uninterrupted run's tables
# and summary.json (tests/compare_runs.py; the table's table.csv byte for
# byte and table.h5's data), and the strip's postprocessors (unknowns.csv,
# the PVD collections) their files byte for byte.
# usage: robustness_paths.sh <strip> <rod_cross_section> <scratch dir>
set -uo pipefail
strip=$(realpath "$1") rod=$(realpath "$2") dir=$3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }
wait_for() { for _ in $(seq 1 1200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.05; done; return 1; }
with_output() { sed -e "s|^\( *set Output directory *=\).*|\1 $2|" "$1"; }
# resume_case <exe> <example> <name> <signal:step-pattern>...
resume_case() {
  local exe=$1 prm=$2 name=$3; shift 3
  with_output "$prm" "$name-whole" > "$name-whole.prm"
  timeout 300 "$exe" --quiet "$name-whole.prm" > "$name-whole.txt" 2>&1 || { bad "$name: the uninterrupted run failed"; return; }
  with_output "$prm" "$name" > "$name.prm"
  local args=("$name.prm") exits=""
  for stop in "$@"; do
    "$exe" --quiet "${args[@]}" > "$name-$stop.txt" 2>&1 & local pid=$!
    wait_for "$name/log.txt" "^step *${stop#*:} "; kill -"${stop%%:*}" $pid; wait $pid 2>/dev/null
    exits="$exits $?"; args=(--resume "$name")
  done
  timeout 300 "$exe" --quiet --resume "$name" > "$name-last.txt" 2>&1; exits="$exits $?"
  local why; why=$(python3 "$here/compare_runs.py" "$name-whole" "$name" steps.csv)
  local want=""; for stop in "$@"; do want="$want $([ "${stop%%:*}" = KILL ] && echo 137 || echo 143)"; done
  local resumed; resumed=$(grep -c "going on after step" "$name/log.txt")
  if [ "$exits" = "$want 0" ] && [ -z "$why" ] && [ ! -f "$name/checkpoint.cosmo" ] && [ "$resumed" = $# ]; then
    ok "$name stopped at $* and resumed: the uninterrupted steps.csv and summary.json"
  else bad "$name: exits$exits (expected$want 0), $resumed resumes; $why"; tail -3 "$name-last.txt"; fi
}
# (the twist buckling example on 16 cells: 73 steps on five branches in ~5 s)
sed -e "s|^\( *set Number of cells *=\).*|\1 16|" "$here/../parameter_files/strip/twist_buckling.prm" > twist_buckling_16.prm
printf 'subsection Postprocess\n  set List of postprocessors = steps table, fields, unknowns\nend\n' >> twist_buckling_16.prm
resume_case "$strip" twist_buckling_16.prm twist_buckling TERM:20 KILL:50
# The postprocessors' state is in the checkpoints: their files of the
# resumed run are the uninterrupted run's, byte for byte (the states are).
for f in unknowns.csv strip.pvd section-branch-0.pvd; do
  if cmp -s "twist_buckling-whole/$f" "twist_buckling/$f"; then ok "twist_buckling resumed: $f the uninterrupted run's"
  else bad "twist_buckling resumed: $f differs from the uninterrupted run's"; fi
done
resume_case "$rod" "$here/../parameter_files/rod_cross_section/surface_growth.prm" surface_growth KILL:2
# A section's sweep (one run per value) killed after its third point and resumed.
with_output "$here/../parameter_files/rod_cross_section/studies/twist_vs_fibre_angle.prm" sweep-whole > sweep-whole.prm
timeout 300 "$rod" --quiet sweep-whole.prm > sweep-whole.txt 2>&1 || bad "the uninterrupted sweep failed"
with_output "$here/../parameter_files/rod_cross_section/studies/twist_vs_fibre_angle.prm" sweep > sweep.prm
"$rod" --quiet sweep.prm > sweep-0.txt 2>&1 & pid=$!
wait_for sweep/sweep-log.txt "^point 3/"; kill -KILL $pid; wait $pid 2>/dev/null; s1=$?
timeout 300 "$rod" --quiet --resume sweep > sweep-1.txt 2>&1; s2=$?
why=$(python3 "$here/compare_runs.py" sweep-whole sweep sweep.csv)
if [ $s1 -eq 137 ] && [ $s2 -eq 0 ] && [ -z "$why" ] && grep -q "resumed from the checkpoint: [1-8] of 9" sweep/sweep-log.txt &&
   [ ! -f sweep/checkpoint.cosmo ]; then
  ok "a section sweep killed after point 3 and resumed: the uninterrupted sweep.csv"
else bad "section sweep: exits $s1 $s2; $why"; cat sweep-1.txt; fi
# A section's constitutive table (12 x 12) killed after its 40th point and resumed.
table_prm() { sed -e "s/-0.2, 0.2, 5/-0.2, 0.2, 12/g" "$here/../parameter_files/rod_cross_section/table_bending_twist.prm" | with_output /dev/stdin "$1"; }
table_prm table-whole > table-whole.prm; table_prm table > table.prm
timeout 300 "$rod" --quiet table-whole.prm > table-whole.txt 2>&1 || bad "the uninterrupted table failed"
"$rod" --quiet table.prm > table-0.txt 2>&1 & pid=$!
for _ in $(seq 1 1200); do [ "$(wc -l < table/table.csv 2>/dev/null || echo 0)" -ge 41 ] && break; sleep 0.05; done
kill -KILL $pid; wait $pid 2>/dev/null; s1=$?
timeout 300 "$rod" --quiet --resume table > table-1.txt 2>&1; s2=$?
same=$(/usr/bin/python3 - <<'PY'
import h5py, numpy as np
a, b = h5py.File("table-whole/table.h5"), h5py.File("table/table.h5")
print(all(np.array_equal(a[k][()], b[k][()], equal_nan=True) for k in ("energy", "resultants", "stiffness", "converged")))
PY
)
if [ $s1 -eq 137 ] && [ $s2 -eq 0 ] && cmp -s table-whole/table.csv table/table.csv && [ "$same" = True ] &&
   grep -q "going on after" table/log.txt && [ ! -f table/checkpoint.cosmo ]; then
  ok "a section table killed after 40 points and resumed: the uninterrupted table.csv and table.h5"
else bad "section table: exits $s1 $s2, h5 equal: $same"; tail -3 table-1.txt; fi
exit $fail

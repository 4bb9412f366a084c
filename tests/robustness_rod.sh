#!/usr/bin/env bash
# The rod's path killed and resumed (--resume): the clamped Euler example
# (arclength, three located events, a switched branch) stopped by SIGTERM at
# step 5 and SIGKILL at step 11 (on the buckled branch), then resumed to the end, reaches the
# uninterrupted run's steps.csv and summary.json (tests/compare_runs.py), and
# its PVD collection byte for byte.
# usage: robustness_rod.sh <rod> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
wait_for() { for _ in $(seq 1 1200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.05; done; return 1; }
with_output() { sed -e "s|^\( *set Output directory *=\).*|\1 $2|" "$1"; }
# On 2000 elements (a few seconds) so that the signals land mid-path.
sed -e "s/^\( *set Number of elements *=\).*/\1 2000/" "$here/../parameter_files/rod/euler_clamped.prm" > euler_2000.prm
prm=euler_2000.prm
with_output "$prm" whole > whole.prm
timeout 300 "$exe" --quiet whole.prm > whole.txt 2>&1 || { echo "  FAIL  the uninterrupted run failed"; exit 1; }
with_output "$prm" run > run.prm
"$exe" --quiet run.prm > run-1.txt 2>&1 & pid=$!
wait_for run/log.txt "^step *5 "; kill -TERM $pid; wait $pid; s1=$?
"$exe" --quiet --resume run > run-2.txt 2>&1 & pid=$!
wait_for run/log.txt "^step *11 "; kill -KILL $pid; wait $pid 2>/dev/null; s2=$?
timeout 300 "$exe" --quiet --resume run > run-3.txt 2>&1; s3=$?
why=$(python3 "$here/compare_runs.py" whole run steps.csv)
resumed=$(grep -c "going on after step" run/log.txt)
if [ "$s1 $s2 $s3" = "143 137 0" ] && [ -z "$why" ] && [ "$resumed" = 2 ] && [ ! -f run/checkpoint.cosmo ]; then
  echo "  ok    stopped by TERM at step 5 and KILL at step 11, resumed twice: the uninterrupted steps.csv and summary.json"
else
  echo "  FAIL  exits $s1 $s2 $s3 (expected 143 137 0), $resumed resumes; $why"; tail -3 run-3.txt; fail=1
fi
if cmp -s whole/rod.pvd run/rod.pvd; then echo "  ok    rod.pvd the uninterrupted run's"
else echo "  FAIL  rod.pvd differs from the uninterrupted run's"; fail=1; fi
# With self-contact: the tendril's perversion stopped by TERM at step 38,
# just before its turns touch (step 40), resumed: the contact's pattern is
# made in the resumed process as it was in the uninterrupted one, and the
# runs agree (contact_gap, contact_pairs and contact_force included).
# (its section file named from the repository's root, where examples run)
sed -e "s|= parameter_files/|= $(realpath "$here/..")/parameter_files/|" \
  "$here/../parameter_files/rod/tendril_perversion.prm" > tendril.prm
tendril=tendril.prm
with_output "$tendril" tendril_whole > tendril_whole.prm
timeout 300 "$exe" --quiet tendril_whole.prm > tendril_whole.txt 2>&1 || { echo "  FAIL  the uninterrupted tendril failed"; exit 1; }
with_output "$tendril" tendril_run > tendril_run.prm
"$exe" --quiet tendril_run.prm > tendril-1.txt 2>&1 & pid=$!
wait_for tendril_run/log.txt "^step *38 "; kill -TERM $pid; wait $pid; t1=$?
timeout 300 "$exe" --quiet --resume tendril_run > tendril-2.txt 2>&1; t2=$?
why=$(python3 "$here/compare_runs.py" tendril_whole tendril_run steps.csv)
pairs=$(python3 -c "import json; print(json.load(open('tendril_run/summary.json'))['last_state']['contact_pairs'])")
if [ "$t1 $t2" = "143 0" ] && [ -z "$why" ] && [ "$pairs" -gt 0 ]; then
  echo "  ok    the tendril with self-contact stopped at step 38 and resumed: the uninterrupted steps.csv and summary.json ($pairs pairs touching at the end)"
else
  echo "  FAIL  tendril: exits $t1 $t2 (expected 143 0), $pairs pairs at the end; $why"; tail -3 tendril-2.txt; fail=1
fi
exit $fail

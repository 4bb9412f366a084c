#!/usr/bin/env bash
# The first event from one eigenproblem ('Arclength continuation / First
# event by estimate', doc/theory-continuation.md 10) against the path
# followed to it: studies of critical points (each point 'Stop at first
# event') run again with the estimate reach the references of the followed
# paths -- their located loads within twice their round-off resolution
# (plate_rod) or 1e-6 relative (strip, rod_cross_section), and their
# '# check' and '# sweep check' lines. The estimate is used at every point
# of the plate's studies (flat starts) and at the first of the strip's (a
# critical curve continues the others), and the path is followed where the
# estimate's guess does not converge (the
# section's twist, whose estimate from the untwisted start is a quarter of
# the load: the twisted state is far from linear in t).
# usage: first_event_by_estimate.sh <build dir> <scratch dir>
set -uo pipefail
build=$(realpath "$1") dir=$(realpath -m "$2")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir"
fail=0
# <runner> <application> <example> <reference> <points from the estimate: all | any>
check_study() {
  local runner=$1 app=$2 prm=$3 ref=$4 expect=$5 name
  name=$(basename "$prm" .prm)
  sed -e '/^ *subsection Arclength continuation/a\  set First event by estimate = true' \
    "$here/../parameter_files/$prm" > "$dir/$name.prm"
  if ! "$here/$runner" "$build/$app" "$dir/$name.prm" "$here/reference/$ref" "$dir/$name" > "$dir/$name.txt" 2>&1; then
    echo "  FAIL  $name: against the followed paths' reference"; tail -5 "$dir/$name.txt"; fail=1; return
  fi
  local points used
  points=$(ls -d "$dir/$name"/out/point-* | wc -l)
  used=$(cat "$dir/$name"/out/point-*/log.txt | grep -c "from the estimate")
  if [ "$expect" = any ] || [ "$used" = "$points" ]; then
    echo "  ok    $name: the reference of the followed paths; $used of $points points from the estimate"
  else
    echo "  FAIL  $name: $used of $points points from the estimate (expected $expect)"; fail=1
  fi
}
check_study run_plate_rod_example.sh plate_rod plate_rod/studies/critical_growth_vs_rim_stiffness_von_karman.prm \
  plate_rod_critical_growth_vs_rim_stiffness_von_karman.output all
check_study run_plate_rod_example.sh plate_rod plate_rod/studies/critical_growth_vs_thickness_cosserat.prm \
  plate_rod_critical_growth_vs_thickness_cosserat.output all
check_study run_example.sh strip strip/studies/seed_pod_critical_width.prm strip_seed_pod_critical_width.output any
check_study run_example.sh rod_cross_section rod_cross_section/studies/critical_twist_vs_axial_growth.prm \
  critical_twist_vs_axial_growth.output any
exit $fail

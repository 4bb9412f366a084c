#!/usr/bin/env bash
# The first event from one eigenproblem ('Arclength continuation / First
# event by estimate', doc/theory-continuation.md 10, the default) against
# the path followed to it ('First event by estimate = false'): studies of
# critical points (each point 'Stop at first event') run both ways reach the
# same references -- their located loads within twice their round-off
# resolution (plate_rod) or 1e-6 relative (strip, rod_cross_section), and
# their '# check' and '# sweep check' lines. With the estimate, every point
# of the plate's studies (flat starts) is located from it; the strip's and
# the section's twisted starts, whose estimates come in clusters (the next
# critical load less than twice as far as the first), follow the path, as
# they do with the setting off; no point says "from the estimate" then.
# usage: first_event_by_estimate.sh <build dir> <scratch dir>
set -uo pipefail
build=$(realpath "$1") dir=$(realpath -m "$2")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir"
fail=0
# <runner> <application> <example> <reference> <points from the estimate: all | none>
check_study() {
  local runner=$1 app=$2 prm=$3 ref=$4 expect=$5 name estimate points used
  for estimate in default false; do
    name=$(basename "$prm" .prm)-$estimate
    if [ $estimate = default ]; then
      cp "$here/../parameter_files/$prm" "$dir/$name.prm"
    else
      sed -e '/^ *subsection Arclength continuation/a\  set First event by estimate = false' \
        "$here/../parameter_files/$prm" > "$dir/$name.prm"
    fi
    if ! "$here/$runner" "$build/$app" "$dir/$name.prm" "$here/reference/$ref" "$dir/$name" > "$dir/$name.txt" 2>&1; then
      echo "  FAIL  $name: against the reference"; tail -5 "$dir/$name.txt"; fail=1; continue
    fi
    points=$(ls -d "$dir/$name"/out/point-* | wc -l)
    used=$(cat "$dir/$name"/out/point-*/log.txt | grep -c "from the estimate")
    local want=$expect
    [ $estimate = false ] && want=none
    if { [ "$want" = all ] && [ "$used" = "$points" ]; } || { [ "$want" = none ] && [ "$used" = 0 ]; }; then
      echo "  ok    $name: the reference; $used of $points points from the estimate"
    else
      echo "  FAIL  $name: $used of $points points from the estimate (expected $want)"; fail=1
    fi
  done
}
check_study run_plate_rod_example.sh plate_rod plate_rod/studies/critical_growth_vs_rim_stiffness_von_karman.prm \
  plate_rod_critical_growth_vs_rim_stiffness_von_karman.output all
check_study run_plate_rod_example.sh plate_rod plate_rod/studies/critical_growth_vs_thickness_cosserat.prm \
  plate_rod_critical_growth_vs_thickness_cosserat.output all
check_study run_example.sh strip strip/studies/seed_pod_critical_width.prm strip_seed_pod_critical_width.output none
check_study run_example.sh rod_cross_section rod_cross_section/studies/critical_twist_vs_axial_growth.prm \
  critical_twist_vs_axial_growth.output none
exit $fail

#!/usr/bin/env bash
# The first event from one eigenproblem ('Arclength continuation / First
# event by estimate', doc/theory-continuation.md 10, the default) against
# the path followed to it ('First event by estimate = false'): studies of
# critical points (each point 'Stop at first event') run both ways reach the
# same references -- their located loads within twice their round-off
# resolution (plate_rod) or 1e-6 relative (strip, rod_cross_section), and
# their '# check' and '# sweep check' lines. With the estimate, every point
# of the plate's studies (flat starts) is located from it. The strip's and
# the section's twisted starts, whose linear estimates come in clusters (the
# next critical load less than twice as far as the first), take the
# second-order estimate, on the field and the free strains (the strains
# the energy is minimized over besides): the first point of each study is
# located from it (the seed pod's in 3 factorizations since the start,
# against 31 along the path; the section's in 7, against 26), the later
# points start from their predecessor's located point, as with the setting
# off. The first point's count is bounded with one Newton iteration of
# margin (another CPU's round-off may take one more).
# A plate point from the estimate costs 3 factorizations (bounded: median 3, most 4): the
# start's (its stability check and the driver's tangent share it) and one
# per Newton iteration on the augmented system from the prediction (2; the
# thickest Cosserat plates, whose linear estimates are 0.8 % and 1.9 % off,
# take the second-order model where the linear one's defect at its
# prediction exceeds 5e-3, and took 3 before); converging the guess onto
# the path first, or factorizing the start twice, took 5-6.
# usage: first_event_by_estimate.sh <build dir> <scratch dir>
set -uo pipefail
build=$(realpath "$1") dir=$(realpath -m "$2")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir"
fail=0
# <runner> <application> <example> <reference> <points from the estimate: all | first:<most factorizations> | none> [via_path | separate]
# via_path: once more with COSMO_ESTIMATE_VIA_PATH=1, the guess converged onto
# the path before Newton on the augmented system (the fallback where Newton
# from the prediction does not converge, which no study here needs).
# separate: once more with 'Critical curve = false', every point from its own
# start and all from the estimate: the section's later points, whose Newton
# from the second-order estimate (0.1-7.4 % high) fails, are located from a state
# converged short of it (0.7 of the way) and estimated again from there.
check_study() {
  local runner=$1 app=$2 prm=$3 ref=$4 expect=$5 name estimate points used
  for estimate in default false ${6:-}; do
    name=$(basename "$prm" .prm)-$estimate
    if [ $estimate = separate ]; then
      sed -e 's|^\( *set Critical curve *=\).*|\1 false|' "$here/../parameter_files/$prm" > "$dir/$name.prm"
    elif [ $estimate != false ]; then
      cp "$here/../parameter_files/$prm" "$dir/$name.prm"
    else
      sed -e '/^ *subsection Arclength continuation/a\  set First event by estimate = false' \
        "$here/../parameter_files/$prm" > "$dir/$name.prm"
    fi
    if ! env $([ $estimate = via_path ] && echo COSMO_ESTIMATE_VIA_PATH=1) \
      "$here/$runner" "$build/$app" "$dir/$name.prm" "$here/reference/$ref" "$dir/$name" > "$dir/$name.txt" 2>&1; then
      echo "  FAIL  $name: against the reference"; tail -5 "$dir/$name.txt"; fail=1; continue
    fi
    points=$(ls -d "$dir/$name"/out/point-* | wc -l)
    used=$(cat "$dir/$name"/out/point-*/log.txt | grep -c "from the estimate")
    local want=${expect%%:*} first_most=${expect#*:}
    [ $estimate = false ] && want=none
    [ $estimate = separate ] && want=all
    if { [ "$want" = all ] && [ "$used" = "$points" ]; } || { [ "$want" = none ] && [ "$used" = 0 ]; } ||
       { [ "$want" = first ] && [ "$used" = 1 ] && grep -q "from the estimate" "$dir/$name"/out/point-00/log.txt; }; then
      echo "  ok    $name: the reference; $used of $points points from the estimate"
    else
      echo "  FAIL  $name: $used of $points points from the estimate (expected $want)"; fail=1
    fi
    if [ $estimate = separate ]; then
      local short
      short=$(cat "$dir/$name"/out/point-*/log.txt | grep -c "estimating again from there")
      if [ "$short" -gt 0 ]; then
        echo "  ok    $name: $short points estimated again from a state short of the estimate"
      else
        echo "  FAIL  $name: no point estimated again from a state short of the estimate"; fail=1
      fi
    fi
    if [ "$want" = first ] && [ $estimate = default ]; then
      local first_count
      first_count=$(python3 -c 'import csv, sys
print(int(float(next(csv.DictReader(open(sys.argv[1])))["factorizations"])))' "$dir/$name/out/sweep.csv")
      if [ "$first_count" -le "$first_most" ]; then
        echo "  ok    $name: the first point in $first_count factorizations (bound $first_most)"
      else
        echo "  FAIL  $name: the first point in $first_count factorizations (bound $first_most)"; fail=1
      fi
    fi
    if [ "$want" = all ] && [ $estimate = default ]; then
      local most
      # the median at most 3 (before: 5-6), and no point above 4: one Newton
      # iteration of margin where an update sits at the acceptance threshold
      # (another CPU's round-off may take one more)
      local counts
      counts=$(python3 -c 'import csv, statistics, sys
f = [int(float(r["factorizations"])) for r in csv.DictReader(open(sys.argv[1]))]
print(statistics.median(f), max(f))' "$dir/$name/out/sweep.csv")
      if python3 -c 'import sys; m, x = map(float, sys.argv[1:]); sys.exit(0 if m <= 3 and x <= 4 else 1)' $counts; then
        echo "  ok    $name: factorizations a point, median and most: $counts (bounds 3, 4)"
      else
        echo "  FAIL  $name: factorizations a point, median and most: $counts (bounds 3, 4)"; fail=1
      fi
    fi
  done
}
check_study run_plate_rod_example.sh plate_rod plate_rod/studies/critical_growth_vs_rim_stiffness_von_karman.prm \
  plate_rod_critical_growth_vs_rim_stiffness_von_karman.output all via_path
check_study run_plate_rod_example.sh plate_rod plate_rod/studies/critical_growth_vs_thickness_cosserat.prm \
  plate_rod_critical_growth_vs_thickness_cosserat.output all
# The thickest Cosserat plates' linear models fail their check (defect 1.2e-2
# and 2.7e-2 at the prediction, above 5e-3): the second-order model is solved
# and the points still take at most the bounds above.
# (two on the machine measured; one exercises the route)
defects=0
for log in "$dir"/critical_growth_vs_thickness_cosserat-default/out/point-*/log.txt; do
  # (solved, and kept: not the fallback to the linear estimate)
  grep -q "defect at its prediction" "$log" && grep -q "(second order:" "$log" &&
    ! grep -q "; the linear estimate$" "$log" && defects=$((defects + 1))
done
if [ "$defects" -ge 1 ]; then
  echo "  ok    critical_growth_vs_thickness_cosserat-default: $defects points from the second-order model (the linear model's defect)"
else
  echo "  FAIL  critical_growth_vs_thickness_cosserat-default: no point took the second-order model for the linear model's defect"; fail=1
fi
check_study run_example.sh strip strip/studies/seed_pod_critical_width.prm strip_seed_pod_critical_width.output first:4
check_study run_example.sh rod_cross_section rod_cross_section/studies/critical_twist_vs_axial_growth.prm \
  critical_twist_vs_axial_growth.output first:8 separate
# The second-order estimate refined with the start's factorization alone
# ('Refine estimate = true', doc/theory-continuation.md 10): the twisted
# strip's and the section's thresholds, every point from its own start,
# against the same study unrefined: each located load within twice its
# resolution (measured at most 0.27, and 0.44 under a 1e-14 change of the
# width or Poisson's ratio), every point refined and located
# from the estimate, in at most 3 factorizations (median; most 4: one
# Newton iteration of margin) -- unrefined 6-7 (strip) and 7-12 (section).
check_refined() {
  local app=$1 prm=$2 name mode base
  base=$(basename "$prm" .prm)
  for mode in plain refined; do
    name=$base-$mode
    sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$name|" -e 's|^\( *set Critical curve *=\).*|\1 false|' \
      -e "/^ *subsection Arclength continuation/a\\  set Refine estimate = $([ $mode = refined ] && echo true || echo false)" \
      "$here/../parameter_files/$prm" > "$dir/$name.prm"
    if ! (cd "$here/.." && "$build/$app" --quiet "$dir/$name.prm" > "$dir/$name.txt" 2>&1); then
      echo "  FAIL  $name: the run"; tail -5 "$dir/$name.txt"; fail=1; return
    fi
  done
  # (points refined and located from the estimate; a point may refine twice)
  local refined=0 log
  for log in "$dir/$base-refined"/point-*/log.txt; do
    grep -q "refined with the start's factorization: t =" "$log" && grep -q "from the estimate" "$log" &&
      refined=$((refined + 1))
  done
  if python3 - "$dir/$base-plain/sweep.csv" "$dir/$base-refined/sweep.csv" "$refined" <<'PY'
import csv, statistics, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
refined = int(sys.argv[3])
ok = len(a) == len(b) and refined == len(b) and all(int(r["converged"]) == 1 for r in a + b)
worst = max(abs(float(x["t_critical"]) - float(y["t_critical"])) / float(x["t_resolution"]) for x, y in zip(a, b))
f = [int(float(r["factorizations"])) for r in b]
ok = ok and worst <= 2 and statistics.median(f) <= 3 and max(f) <= 4
print("    %d of %d points refined; largest difference %.2f resolutions (bound 2); factorizations %s, unrefined %s (bounds: median 3, most 4)"
      % (refined, len(b), worst, f, [int(float(r["factorizations"])) for r in a]))
sys.exit(0 if ok else 1)
PY
  then
    echo "  ok    $base refined"
  else
    echo "  FAIL  $base refined"; fail=1
  fi
}
check_refined strip strip/studies/critical_twist_vs_thickness.prm
check_refined rod_cross_section rod_cross_section/studies/critical_twist_vs_axial_growth.prm
exit $fail

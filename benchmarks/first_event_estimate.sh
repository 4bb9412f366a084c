#!/usr/bin/env bash
# The first threshold from one eigenproblem against the path followed to it
# (doc/theory-continuation.md 10, benchmarks/README.md): studies of critical
# points, each point a run to its first event ('Stop at first event'), once
# following the path and once with 'First event by estimate = true'
# ('Critical curve = false': every point from its own start). Prints per
# study the points, factorizations, whole-process seconds (median of
# `repeats`) and the largest difference of t_critical over its resolution.
# usage: benchmarks/first_event_estimate.sh [build dir = build] [repeats = 3] [scratch = /tmp/cosmo_first_event]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") repeats=${2:-3} dir=$(realpath -m "${3:-/tmp/cosmo_first_event}")
rm -rf "$dir" && mkdir -p "$dir"
cd "$REPO"
studies="plate_rod:plate_rod/studies/critical_growth_vs_rim_stiffness_von_karman.prm
plate_rod:plate_rod/studies/critical_growth_vs_rim_stiffness_kirchhoff.prm
plate_rod:plate_rod/studies/critical_growth_vs_thickness_cosserat.prm
strip:strip/studies/seed_pod_critical_width.prm
strip:strip/studies/critical_twist_vs_thickness.prm
rod_cross_section:rod_cross_section/studies/critical_twist_vs_axial_growth.prm"
echo "| study | points | DoFs | followed: factorizations | followed: s | estimate: factorizations | estimate: s | from the estimate | ratio s | max abs(diff t)/resolution |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
while IFS=: read -r app prm; do
  name=$(basename "$prm" .prm)
  for mode in followed estimate; do
    estimate=$([[ $mode = estimate ]] && echo true || echo false)
    sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$name-$mode|" \
        -e "s|^\( *set Critical curve *=\).*|\1 false|" \
        -e "/^ *subsection Arclength continuation/a\  set First event by estimate = $estimate" \
        "parameter_files/$prm" > "$dir/$name-$mode.prm"
    for r in $(seq "$repeats"); do
      start=$EPOCHREALTIME
      "$build/$app" --quiet "$dir/$name-$mode.prm" > /dev/null
      awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f\n", b - a }'
    done | sort -n | awk '{ a[NR] = $0 } END { print a[int((NR + 1) / 2)] }' > "$dir/$name-$mode.seconds"
  done
  python3 - "$dir" "$name" <<'PY'
import csv, glob, os, sys
d, name = sys.argv[1], sys.argv[2]
rows = {m: list(csv.DictReader(open(os.path.join(d, "%s-%s" % (name, m), "sweep.csv")))) for m in ("followed", "estimate")}
sec = {m: float(open(os.path.join(d, "%s-%s.seconds" % (name, m))).read()) for m in rows}
fac = {m: sum(float(r["factorizations"]) for r in rows[m]) for m in rows}
used = sum(open(f).read().count("from the estimate") for f in glob.glob(os.path.join(d, name + "-estimate", "point-*", "log.txt")))
worst = max(abs(float(a["t_critical"]) - float(b["t_critical"])) / float(a["t_resolution"])
            for a, b in zip(rows["followed"], rows["estimate"]))
print("| %s | %d | %s | %d | %.2f | %d | %.2f | %d | %.2f | %.2f |" % (
    name, len(rows["followed"]), rows["followed"][0].get("dofs", "-"), fac["followed"], sec["followed"],
    fac["estimate"], sec["estimate"], used, sec["followed"] / sec["estimate"], worst))
PY
done <<< "$studies"

#!/usr/bin/env bash
# The second-order estimate refined with the start's factorization alone
# ('Arclength continuation / Refine estimate', doc/theory-continuation.md 10)
# against the default (Newton on the augmented system from the estimate):
# the twisted strip's and the section's studies, every point from its own
# start ('Critical curve = false'), and the section's first point on finer
# meshes ('Global refinements' 0-3). Prints the DoFs, the factorizations,
# the computing seconds (the points' own, median of `repeats` runs) and the
# largest difference of t_critical over its resolution.
# usage: benchmarks/refined_estimate.sh [build dir = build] [repeats = 3] [scratch = /tmp/cosmo_refined_estimate]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") repeats=${2:-3} dir=$(realpath -m "${3:-/tmp/cosmo_refined_estimate}")
rm -rf "$dir" && mkdir -p "$dir"
cd "$REPO"
# <application> <study> <label> [sed expression]
cases="strip|strip/studies/critical_twist_vs_thickness.prm|twisted strip, 7 thicknesses|
rod_cross_section|rod_cross_section/studies/critical_twist_vs_axial_growth.prm|section, 5 growths|
rod_cross_section|rod_cross_section/studies/critical_twist_vs_axial_growth.prm|section, growth 1, 1 refinement|s/^\( *set Global refinements *=\).*/\1 1/;s/^\( *set Values *=\).*/\1 1/
rod_cross_section|rod_cross_section/studies/critical_twist_vs_axial_growth.prm|section, growth 1, 2 refinements|s/^\( *set Global refinements *=\).*/\1 2/;s/^\( *set Values *=\).*/\1 1/
rod_cross_section|rod_cross_section/studies/critical_twist_vs_axial_growth.prm|section, growth 1, 3 refinements|s/^\( *set Global refinements *=\).*/\1 3/;s/^\( *set Values *=\).*/\1 1/"
echo "| case | DoFs | default: factorizations | default: s | refined: factorizations | refined: s | ratio s | max abs(diff t)/resolution |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
n=0
while IFS='|' read -r app prm label extra; do
  n=$((n + 1))
  for mode in false true; do
    sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$n-$mode|" \
        -e "s|^\( *set Critical curve *=\).*|\1 false|" \
        -e "/^ *subsection Arclength continuation/a\  set Refine estimate = $mode" \
        -e "${extra:-b}" "parameter_files/$prm" > "$dir/$n-$mode.prm"
    for r in $(seq "$repeats"); do
      "$build/$app" --quiet "$dir/$n-$mode.prm" > /dev/null
      python3 -c 'import csv, sys
print("%.3f" % sum(float(r["seconds"]) for r in csv.DictReader(open(sys.argv[1]))))' "$dir/$n-$mode/sweep.csv"
    done | sort -n | awk '{ a[NR] = $0 } END { print a[int((NR + 1) / 2)] }' > "$dir/$n-$mode.seconds"
  done
  python3 - "$dir" "$n" "$label" <<'PY'
import csv, os, sys
d, n, label = sys.argv[1:]
rows = {m: list(csv.DictReader(open(os.path.join(d, "%s-%s" % (n, m), "sweep.csv")))) for m in ("false", "true")}
sec = {m: float(open(os.path.join(d, "%s-%s.seconds" % (n, m))).read()) for m in rows}
fac = {m: sum(int(float(r["factorizations"])) for r in rows[m]) for m in rows}
worst = max(abs(float(a["t_critical"]) - float(b["t_critical"])) / float(a["t_resolution"]) for a, b in zip(rows["false"], rows["true"]))
print("| %s | %s | %d | %.2f | %d | %.2f | %.2f | %.2f |" % (label, rows["false"][0]["dofs"], fac["false"], sec["false"],
      fac["true"], sec["true"], sec["true"] / sec["false"], worst))
PY
done <<< "$cases"

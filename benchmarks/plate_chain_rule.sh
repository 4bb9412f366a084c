#!/usr/bin/env bash
# The plate's Jacobian and residual by the Cosserat model's chain rule
# (kinematics/plate_measures.h, source/kinematics/plate_models/
# cosserat_derivatives.cc) against nested AD of the plate energy
# (COSMO_PLATE_NESTED_AD=1, what the assembly did before): the dome of
# parameter_files/plate_rod/dome.prm (the assumed shear, the default) on
# the quarter disc at REF global refinements (4: 19 014 DoFs) from the flat
# state to its first event ('Stop at first event'), whole process, median
# of REPEATS paired runs; the phases and the located threshold of each.
#
# usage: benchmarks/plate_chain_rule.sh [build dir = build] [REF = 4] [repeats = 3]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") REF=${2:-4} R=${3:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sed -e "s|^\( *set Global refinements *=\).*|\1 $REF|" \
    -e "s|^\( *set Event tolerance *=.*\)|\1\n  set Stop at first event = true|" \
    -e "s|^\( *set Output directory *=\).*|\1 $dir/run|" "$REPO/parameter_files/plate_rod/dome.prm" > "$dir/dome.prm"
for k in $(seq 1 "$R"); do
  for variant in nested chain; do
    if [ $variant = nested ]; then export COSMO_PLATE_NESTED_AD=1; else unset COSMO_PLATE_NESTED_AD; fi
    t0=$(date +%s.%N)
    "$build/plate_rod" --quiet "$dir/dome.prm" > "$dir/out.txt" 2>&1 || { cat "$dir/out.txt"; exit 1; }
    t1=$(date +%s.%N)
    /usr/bin/python3 - "$dir/run/summary.json" $variant "$(echo "$t1 - $t0" | bc -l)" <<'PY' >> "$dir/rows.txt"
import json, sys
j = json.load(open(sys.argv[1])); t = j["timings"]
e = j["events"][0]
print(sys.argv[2], sys.argv[3], t["assembly (Jacobian)"]["seconds"], t["assembly (Jacobian)"]["calls"],
      t["assembly (residual)"]["seconds"], t["assembly (residual)"]["calls"], repr(e["t"]),
      e["location"]["resolution"], j["dofs"])
PY
  done
done
unset COSMO_PLATE_NESTED_AD
/usr/bin/python3 - "$dir/rows.txt" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print(f"dome to its first event, {rows[0][8]} DoFs, median of {len(rows) // 2} paired runs")
print("| variant | whole process [s] | Jacobian [s] (calls) | per Jacobian [s] | residual [s] (calls) | threshold t | resolution |")
print("|---|---:|---:|---:|---:|---:|---:|")
med = {}
for v, label in (("nested", "nested AD of the energy"), ("chain", "chain rule (default)")):
    sel = [r for r in rows if r[0] == v]
    m = lambda i: statistics.median(float(r[i]) for r in sel)
    med[v] = (m(1), m(2) / float(sel[0][3]))
    print(f"| {label} | {m(1):.2f} | {m(2):.3f} ({sel[0][3]}) | {m(2) / float(sel[0][3]):.4f} | {m(4):.3f} ({sel[0][5]}) | {float(sel[0][6]):.12f} | {float(sel[0][7]):.1e} |")
print(f"chain rule against nested AD: whole process {med['nested'][0] / med['chain'][0]:.2f}x, per Jacobian {med['nested'][1] / med['chain'][1]:.2f}x")
PY

#!/usr/bin/env bash
# Convergence and cost of the plate's transverse shear treatments (part 3):
# the first threshold of an example ('Stop at first event', event tolerance
# 1e-10) on refinements 1 .. max of its mesh, for each 'Shear integration',
# with the DoFs, the wall time to the located threshold, the threshold, its
# difference from the finest assumed-strain value and the ratio of
# successive differences (4 per refinement is second order, 16 fourth).
#
# usage (from the repository root, after scripts/setup.sh):
#   bash benchmarks/plate_shear_convergence.sh [example.prm] [model] [max refinement] [thickness]
# defaults: parameter_files/plate_rod/dome.prm cosserat 4 (the example's thickness)
set -euo pipefail
prm=${1:-parameter_files/plate_rod/dome.prm}
model=${2:-cosserat}
max=${3:-4}
thickness=${4:-}
exe=build/plate_rod
[ -x "$exe" ] || { echo "build the suite first (bash scripts/setup.sh)"; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
results=$dir/results.txt
for shear in "assumed strain" "interior tying" "stabilized" "reduced"; do
  for r in $(seq 1 "$max"); do
    out=$dir/run
    rm -rf "$out"
    {
      cat "$prm"
      printf 'subsection Model\n set Model = %s\n set Shear integration = %s\nend\n' "$model" "$shear"
      printf 'subsection Mesh\n set Global refinements = %s\nend\n' "$r"
      [ -n "$thickness" ] && printf 'subsection Plate\n set Thickness = %s\nend\n' "$thickness"
      printf 'subsection Growth path\n set Stop at first event = true\nend\n'
      printf 'subsection Arclength continuation\n set Event tolerance = 1e-10\nend\n'
      printf 'subsection Output\n set Output directory = %s\nend\n' "$out"
    } > "$dir/in.prm"
    start=$(date +%s.%N)
    "$exe" --quiet "$dir/in.prm" > "$dir/log" 2>&1 || true
    end=$(date +%s.%N)
    python3 - "$out/summary.json" "$shear" "$r" "$start" "$end" >> "$results" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
e = s["events"][0] if s.get("events") else None
t = e["t"] if e else float("nan")
res = e["location"]["resolution"] if e and "location" in e else float("nan")
print("%s|%s|%d|%.16g|%.3g|%.2f|%s" % (sys.argv[2], sys.argv[3], s["dofs"], t, res,
      float(sys.argv[5]) - float(sys.argv[4]), e["mode_number"] if e else "-"))
PY
  done
done
python3 - "$results" "$prm" "$model" <<'PY'
import sys
rows = [l.strip().split("|") for l in open(sys.argv[1])]
best = [float(r[3]) for r in rows if r[0] == "assumed strain"][-1]
print("example %s, model %s; differences from the finest assumed-strain threshold t = %.12g"
      % (sys.argv[2], sys.argv[3], best))
print("| shear | refinements | DoFs | threshold t | resolution | t/t_ref - 1 | ratio | mode | time to threshold [s] |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
previous = {}
for shear, r, dofs, t, res, wall, mode in rows:
    t = float(t)
    d = t / best - 1
    p = previous.get(shear)
    ratio = "" if p is None or d == 0 else "%.1f" % abs(p / d)
    previous[shear] = d
    print("| %s | %s | %s | %.10f | %s | %+.2e | %s | %s | %s |" % (shear, r, dofs, t, res, d, ratio, mode, wall))
PY

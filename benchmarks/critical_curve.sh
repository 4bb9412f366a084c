#!/usr/bin/env bash
# Cost of a critical curve against the study of independent runs at the same
# values (doc/theory-continuation.md 7, benchmarks/README.md).
#
# The setting of parameter_files/plate_rod/studies/critical_curve_vs_rim_stiffness_cosserat.prm
# (critical growth of the Cosserat plate against the rim's EI1), at a given
# refinement and number of values of EI1 (log-spaced over 1e-9 .. 1e-4):
# once as independent runs (path from t = 0 to the first instability), once
# as a critical curve. Prints DoFs, factorizations and seconds of each and
# their ratios, and the largest relative difference of t_critical.
#
# usage: benchmarks/critical_curve.sh [build dir = build] [refinements = 3] [values = 16] [scratch = /tmp/cosmo_critical_curve]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") refinements=${2:-3} n=${3:-16}
dir=$(realpath -m "${4:-/tmp/cosmo_critical_curve}")
rm -rf "$dir" && mkdir -p "$dir"
values=$(python3 -c "n=$n; print(', '.join('%.6g' % (10 ** (-9 + 5 * k / (n - 1))) for k in range(n)))")
for name in independent curve; do
  curve=$([[ $name = curve ]] && echo true || echo false)
  sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$name|" \
      -e "s|^\( *set Global refinements *=\).*|\1 $refinements|" \
      -e "s|^\( *set Values *=\).*|\1 $values|" \
      -e "s|^\( *set Critical curve *=\).*|\1 $curve|" \
      "$REPO/parameter_files/plate_rod/studies/critical_curve_vs_rim_stiffness_cosserat.prm" \
      > "$dir/$name.prm"
  python3 - "$build/plate_rod" "$dir/$name" <<'PY'
import subprocess, sys, time
start = time.time()
with open(sys.argv[2] + ".log", "w") as log:
    subprocess.run([sys.argv[1], "--quiet", sys.argv[2] + ".prm"], stdout=log, stderr=log, check=True)
open(sys.argv[2] + ".seconds", "w").write("%.3f" % (time.time() - start))
PY
done
python3 - "$dir" <<'PY'
import csv, sys, os
d = sys.argv[1]
rows = {k: list(csv.DictReader(open(os.path.join(d, k, "sweep.csv")))) for k in ("independent", "curve")}
sec = {k: float(open(os.path.join(d, k + ".seconds")).read()) for k in rows}
fac = {k: sum(float(r["factorizations"]) for r in rows[k]) for k in rows}
diff = max(abs(float(a["t_critical"]) / float(b["t_critical"]) - 1)
           for a, b in zip(rows["independent"], rows["curve"]))
cont = [r for r in rows["curve"] if r["continued"] == "1"]
print("| values | DoFs | study: factorizations | study: s | curve: factorizations | curve: s | "
      "per continued point | ratio factorizations | ratio time | max rel. diff of t |")
print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
print("| %d | %s | %d | %.1f | %d | %.1f | %.2f | %.1f | %.1f | %.1e |" % (
    len(rows["curve"]), rows["curve"][0]["dofs"], fac["independent"], sec["independent"],
    fac["curve"], sec["curve"], sum(float(r["factorizations"]) for r in cont) / max(1, len(cont)),
    fac["independent"] / fac["curve"], sec["independent"] / sec["curve"], diff))
PY

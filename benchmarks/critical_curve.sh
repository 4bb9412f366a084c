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
# With APP=strip: parameter_files/strip/studies/critical_twist_vs_thickness.prm
# (critical twist of the strip against h/w, log-spaced over 0.005 .. 0.04),
# "refinements" then being the number of cells across the width.
#
# usage: [APP=strip] benchmarks/critical_curve.sh [build dir = build] [refinements = 3 | 40] [values = 16] [scratch = /tmp/cosmo_critical_curve]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
app=${APP:-plate_rod}
case $app in
  plate_rod)
    prm=parameter_files/plate_rod/studies/critical_curve_vs_rim_stiffness_cosserat.prm
    mesh_entry="Global refinements" from=-9 to=-4 default_refinements=3 ;;
  strip)
    prm=parameter_files/strip/studies/critical_twist_vs_thickness.prm
    mesh_entry="Number of cells" from=-2.30103 to=-1.39794 default_refinements=40 ;;
  *) echo "APP must be plate_rod or strip" >&2; exit 1 ;;
esac
build=$(realpath "${1:-$REPO/build}") refinements=${2:-$default_refinements} n=${3:-16}
dir=$(realpath -m "${4:-/tmp/cosmo_critical_curve}")
rm -rf "$dir" && mkdir -p "$dir"
values=$(python3 -c "n=$n; print(', '.join('%.6g' % (10 ** ($from + ($to - $from) * k / (n - 1))) for k in range(n)))")
for name in independent curve; do
  curve=$([[ $name = curve ]] && echo true || echo false)
  sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$name|" \
      -e "s|^\( *set $mesh_entry *=\).*|\1 $refinements|" \
      -e "s|^\( *set Values *=\).*|\1 $values|" \
      -e "s|^\( *set Critical curve *=\).*|\1 $curve|" \
      "$REPO/$prm" > "$dir/$name.prm"
  python3 - "$build/$app" "$dir/$name" <<'PY'
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

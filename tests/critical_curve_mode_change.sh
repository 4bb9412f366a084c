#!/usr/bin/env bash
# A change of the critical mode along a critical curve (codimension-2 point):
# the curve's estimate (codim2_value, codim2_t: the two critical curves'
# secants intersected) is checked by an independent run at codim2_value,
# whose first instability must lie at codim2_t within the secants' own
# error bound. At the estimate both secants give codim2_t, so the first
# instability there, the lower of the two true curves, is within the larger
# of the two secants' interpolation errors of it: at most h^2/8 max|t''|
# with h the step in x = log(value) (the secants are in log of the value),
# and t'' estimated for each of the two modes by the second divided
# difference of t_critical in x over three consecutive values of that mode
# (the larger); a factor 2 covers the change of t'' between the intervals it
# is estimated on and the one it is used on.
# The mode found there must be one of the two. Every point's event files
# are the ones its summary.json names.
# usage: critical_curve_mode_change.sh <plate_rod> <curve.prm> <scratch dir>
set -euo pipefail
exe=$(realpath "$1") prm=$(realpath "$2") dir=$(realpath -m "$3")
rm -rf "$dir" && mkdir -p "$dir"
sed -e "s|^\( *set Output directory *=\).*|\1 $dir/curve|" "$prm" > "$dir/curve.prm"
"$exe" --quiet "$dir/curve.prm" > "$dir/curve.log" 2>&1 || { tail -5 "$dir/curve.log"; exit 1; }
# A point whose continued critical point failed is run again independently:
# its event files are that run's, the ones its summary.json names, and no
# others (the failed attempt's are written over, not numbered on); the run
# that continues a new mode back (point-K/back) writes the files its
# summary.json names too.
python3 - "$dir/curve" <<'PY'
import glob, json, os, sys
for d in sorted(glob.glob(sys.argv[1] + "/point-*") + glob.glob(sys.argv[1] + "/point-*/back")):
    events = json.load(open(d + "/summary.json")).get("events", [])
    named = {e[k] for e in events for k in ("state_vtu", "mode_vtu") if k in e}
    files = {os.path.basename(f) for f in glob.glob(d + "/event-*.*vtu")}
    assert files == named, "%s: event files %s, summary.json names %s" % (d, sorted(files), sorted(named))
print("every point's event files are those its summary.json names")
PY
read -r value t_star n_before n_after bound < <(python3 - "$dir/curve/critical_curve.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
key = next(k for k in rows[0] if k.startswith("value"))
changes = [i for i, r in enumerate(rows) if r["mode_change"] == "1"]
assert len(changes) == 1, "expected one change of the critical mode, found %d" % len(changes)
k = changes[0]
assert math.isfinite(float(rows[k]["codim2_value"])), "no codimension-2 estimate"
x = [math.log(float(r[key])) for r in rows]
t = [float(r["t_critical"]) for r in rows]
curvature = {}  # max |t''| in x of each mode, over its triples of consecutive values
for i in range(1, len(rows) - 1):
    n = rows[i]["mode_number"]
    if rows[i - 1]["mode_number"] == n == rows[i + 1]["mode_number"]:
        s1 = (t[i] - t[i - 1]) / (x[i] - x[i - 1])
        s2 = (t[i + 1] - t[i]) / (x[i + 1] - x[i])
        curvature[n] = max(curvature.get(n, 0.0), abs(2 * (s2 - s1) / (x[i + 1] - x[i - 1])))
modes = (rows[k - 1]["mode_number"], rows[k]["mode_number"])
assert all(n in curvature for n in modes), \
    "each of the two modes needs three consecutive values to estimate its t'' (have %s)" % curvature
h = x[k] - x[k - 1]
print(rows[k]["codim2_value"], rows[k]["codim2_t"], modes[0], modes[1],
      2 * h * h / 8 * max(curvature[n] for n in modes))
PY
)
echo "codimension-2 estimate: value $value, t $t_star (modes $n_before -> $n_after), secant error bound $bound"
# The independent run at the estimated value: no sweep, no curve; the swept
# entry (Rim rod/Stiffnesses) set by the study's template.
template=$(sed -n 's|^ *set Template *= *||p' "$prm")
sed -e "s|^\( *set Output directory *=\).*|\1 $dir/check|" \
    -e "s|^\( *set Entry *=\).*|\1|" \
    -e "s|^\( *set Critical curve *=\).*|\1 false|" \
    -e "s|^\( *set Stiffnesses *=\).*|\1 ${template//\{\}/$value}|" \
    "$prm" > "$dir/check.prm"
"$exe" --quiet "$dir/check.prm" > "$dir/check.log" 2>&1 || { tail -5 "$dir/check.log"; exit 1; }
python3 - "$dir/check/summary.json" "$t_star" "$n_before" "$n_after" "$bound" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t_star, n0, n1, bound = float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
e = s["events"][0]
print("independent run there: first instability at t = %.8g, mode %d; |t - t*| = %.3g, bound %.3g"
      % (e["t"], e["mode_number"], abs(e["t"] - t_star), bound))
assert e["mode_number"] in (n0, n1), "the mode there is neither of the two"
assert abs(e["t"] - t_star) <= bound, "the codimension-2 estimate is off by more than its bound"
PY

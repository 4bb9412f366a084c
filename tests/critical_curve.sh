#!/usr/bin/env bash
# A critical curve (Parameter sweep / Critical curve = true) against the study of
# independent runs at the same values: every continued point must agree in
# t_critical within max(1e-7 t, 2 x the stated resolution), with the same
# critical mode, and must have cost
# fewer factorizations than the independent run of that value; prints the
# ratio of the factorizations of the whole study to the curve's. The
# independent runs follow their paths ('First event by estimate = false'):
# from the estimate (the default) an independent plate point costs 3-4
# factorizations, as much as a continued point at these decade-spaced
# values, and the estimate has its own test (first_event_by_estimate.sh).
# usage: critical_curve.sh <application> <independent study.prm> <curve.prm> <scratch dir>
set -euo pipefail
exe=$(realpath "$1") independent=$(realpath "$2") curve=$(realpath "$3") dir=$(realpath -m "$4")
rm -rf "$dir" && mkdir -p "$dir"
for name in independent curve; do
  prm=${!name}
  [[ $name == curve ]] && flag=true || flag=false
  sed -e "s|^\( *set Output directory *=\).*|\1 $dir/$name|" \
      -e "s|^\( *set Critical curve *=\).*|\1 $flag|" \
      -e "/^ *subsection Arclength continuation/a\  set First event by estimate = false" "$prm" > "$dir/$name.prm"
  "$exe" --quiet "$dir/$name.prm" > "$dir/$name.log" 2>&1 || { tail -5 "$dir/$name.log"; exit 1; }
done
python3 - "$dir/independent/sweep.csv" "$dir/curve/critical_curve.csv" <<'PY'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(b) and a, "the two tables differ in length"
bad = 0
fa = fb = 0.0
for x, y in zip(a, b):
    ta, tb = float(x["t_critical"]), float(y["t_critical"])
    # the independent run's resolution; the curve's must not be 4x worse,
    # beyond the 1e-10 (|t| + 1e-2 |t|) to which a curve locates its points
    # where that is above R/10 (solvers/critical_point_study.h; a point
    # accepted at R/10 states R): the resolution column includes the Newton
    # precision
    ra, rb = float(x["t_resolution"]), float(y["t_resolution"])
    tol = max(1e-7 * abs(ta), 2 * ra)
    fa += float(x["factorizations"]); fb += float(y["factorizations"])
    ok = abs(ta - tb) <= tol and rb <= max(4 * ra, 1.01e-10 * abs(tb)) and (y["continued"] == "0" or float(y["factorizations"]) < float(x["factorizations"]))
    # the same critical mode (a continued point must not be another mode's):
    # every mode classification column (mode_number, mode_symmetry, ...)
    modes = [c for c in x if c.startswith("mode_") and c != "mode_change"]
    ok = ok and all(x[c] == y[c] for c in modes)
    # and a classified one: the mesh of each study is symmetric, and the
    # eigenvector of a simple critical eigenvalue of a symmetric problem is
    # symmetric or antisymmetric under each symmetry (+1 or -1; 0 = mixed or
    # nan = not classifiable would be a wrong mode or a broken classifier)
    ok = ok and all(x[c] in ("1", "-1") for c in modes if "symmetry" in c)
    bad += not ok
    print("value %s: t %.12g (independent, %s factorizations) vs %.12g (%s, %s factorizations): "
          "|diff| %.2e relative, tolerance %.2e%s" % (
        list(x.values())[0], ta, x["factorizations"], tb,
        "continued" if y["continued"] == "1" else "independent", y["factorizations"],
        abs(ta - tb) / abs(ta), tol / abs(ta), "" if ok else "  <-- FAILS"))
assert any(y["continued"] == "1" for y in b), "no point was continued"
print("factorizations: independent study %d, critical curve %d (ratio %.2f)" % (fa, fb, fa / fb))
sys.exit(1 if bad else 0)
PY

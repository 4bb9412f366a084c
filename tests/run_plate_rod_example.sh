#!/usr/bin/env bash
# Regression test of one plate_rod example: run it (output into a scratch
# directory), check its '# check:' lines, then compare its key numbers with
# the stored reference (tests/compare_key_numbers.py: a located load within
# twice its round-off resolution, which summary.json states per event; the
# kind, branch, stability counts and mode number of each event exactly). The
# state at the end of a branch is not a key: where a branch leaves the
# parameter range depends on the step sequence, not on the physics.
#   # check: <json path> = <number or json path> +- <absolute tolerance>
#   # check rel: <json path> = <number or json path> +- <relative tolerance>
# A json path is dotted, list entries by index: events.0.t,
# closed_form.axisymmetric.mismatch. A study (sweep.csv) is checked row by
# row with '# sweep check: <python expression of the columns>'.
# usage: run_plate_rod_example.sh <plate_rod or rod> <file.prm> <reference.output> <scratch dir>
set -euo pipefail
exe=$(realpath "$1") prm=$(realpath "$2") ref=$(realpath -m "$3") dir=$(realpath -m "$4")
rm -rf "$dir" && mkdir -p "$dir"
sed -e "s|^\( *set Output directory *=\).*|\1 $dir/out|" "$prm" > "$dir/run.prm"
cd "$(dirname "${BASH_SOURCE[0]}")/.."
"$exe" --quiet "$dir/run.prm"
python3 - "$dir/out" "$prm" > "$dir/key_numbers.output" <<'PY'
import csv, json, math, os, re, sys
out, prm = sys.argv[1], sys.argv[2]
lines = open(prm).read().splitlines()
if os.path.exists(os.path.join(out, "sweep.csv")):
    rows = list(csv.DictReader(open(os.path.join(out, "sweep.csv"))))
    checks = [m.group(1) for m in (re.match(r"#\s*sweep check:\s*(.+)", l) for l in lines) if m]
    assert rows and checks, "a study states at least one '# sweep check:'"
    for r in rows:
        env = {k.split(" [")[0]: float(v) for k, v in r.items()}
        assert env["converged"] == 1, "point at value %g did not converge" % env["value"]
        env.update(abs=abs, math=math)
        for c in checks:
            assert eval(c, {}, env), "value %g: '%s' fails" % (env["value"], c)
    print("%d points, %d sweep checks hold at each" % (len(rows), len(checks)), file=sys.stderr)
    for r in rows:
        t, res, D = float(r["t_critical"]), float(r["t_resolution"]), float(r["mismatch_critical"])
        print("value", r[next(k for k in r if k.startswith("value"))], "%r~%.3g" % (t, res),
              "%r~%.3g" % (D, res * abs(D / t)), r["mode_number"])
    sys.exit(0)
s = json.load(open(os.path.join(out, "summary.json")))
assert s["status"] == "converged", s["message"]
def get(path):
    x = s
    for p in path.split("."):
        x = x[int(p)] if isinstance(x, list) else x[p]
    return x
def value(text):
    try:
        return float(text)
    except ValueError:
        return get(text)
n = 0
for line in lines:
    m = re.match(r"#\s*check( rel)?:\s*([\w.]+)\s*=\s*(\S+)\s*\+-\s*(\S+)", line)
    if m:
        rel, got, want, tol = m.group(1), get(m.group(2)), value(m.group(3)), float(m.group(4))
        bound = tol * abs(want) if rel else tol
        assert abs(got - want) <= bound, "%s = %r, expected %r +- %g%s" % (
            m.group(2), got, want, tol, " (relative)" if rel else "")
        print("checked %s = %r (expected %r +- %g%s)" % (m.group(2), got, want, tol,
              " relative" if rel else ""), file=sys.stderr)
        n += 1
assert n > 0, "an example states at least one '# check:'"
# A mode's number is a key number only where the classification is clear:
# a mode whose type measures (or two largest rim amplitudes) are within a
# factor 2 is a mix, typically of a near-double eigenvalue, and its number
# can flip under round-off; it is written as "mixed".
def mode_key(e):
    if "mode_number" not in e:
        return -1
    if max(e.get("mode_type_margin", 0), e.get("mode_number_margin", 0)) > 0.5:
        return "mixed"
    return e["mode_number"]
for e in s["events"]:
    print(e["kind"].replace(" ", "_"), e["branch"], "%r~%.3g" % (e["t"], e["location"]["resolution"]),
          e["n_negative_before"], e["n_negative_after"], mode_key(e))
PY
if [ ! -f "$ref" ]; then
  echo "no reference $ref; produced $dir/key_numbers.output"; cat "$dir/key_numbers.output"; exit 1
fi
python3 tests/compare_key_numbers.py "$ref" "$dir/key_numbers.output" || exit 1
echo "key numbers match $ref"

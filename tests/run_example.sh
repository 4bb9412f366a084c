#!/usr/bin/env bash
# Regression test of one example: run it (output into a scratch directory),
# check what is known independently of the code -- a natural state has zero
# resultants and zero multipliers; lines '# check: <key> = <value> +- <tol>'
# in the .prm state closed-form values (a key is a path in summary.json,
# list items by 0-based index: stiffness.5.5) -- then compare its key numbers from
# summary.json with the stored reference with numdiff (relative 1e-6,
# absolute 1e-9: far above the Newton tolerance, far below any physical change).
# A parameter sweep (sweep.csv) is checked row by row instead: lines
# '# sweep check: <python expression of the columns>' must hold at every
# point, e.g. 'abs(kappa2 + value) < 1e-10', and '# sweep check all: ...'
# over the whole columns (lists), e.g. odd symmetry of the twist in the
# fibre angle: 'all(abs(a + b) < 1e-9 for a, b in zip(kappa3, kappa3[::-1]))'.
# Its key numbers are the strains
# and diagonal stiffnesses of every point.
# The strip's examples are guarded the same way (their summary.json has no
# helix; their located events' loads are key numbers too).
# usage: run_example.sh <rod_cross_section | strip> <file.prm> <reference.output> <scratch dir>
set -euo pipefail
exe=$(realpath "$1") prm=$(realpath "$2") ref=$(realpath -m "$3") dir=$(realpath -m "$4")
rm -rf "$dir" && mkdir -p "$dir"
# Redirect the example's output directory into the scratch directory.
sed -e "s|^\( *set Output directory *=\).*|\1 $dir/out|" "$prm" > "$dir/run.prm"
# Mesh files in the examples are relative to the repository root.
cd "$(dirname "${BASH_SOURCE[0]}")/.."
"$exe" --quiet "$dir/run.prm"
if [ -f "$dir/out/sweep.csv" ]; then
python3 - "$dir/out/sweep.csv" "$prm" > "$dir/key_numbers.output" <<'PY'
import csv, math, re, sys
rows = list(csv.DictReader(open(sys.argv[1])))
lines = open(sys.argv[2]).read().splitlines()
checks = [m.group(1) for m in (re.match(r"#\s*sweep check:\s*(.+)", l) for l in lines) if m]
table_checks = [m.group(1) for m in (re.match(r"#\s*sweep check all:\s*(.+)", l) for l in lines) if m]
assert rows, "empty sweep"
assert checks or table_checks, "a sweep example states at least one '# sweep check:'"
columns = {}
for r in rows:
    for k, v in r.items():
        columns.setdefault(k.split(" [")[0], []).append(float(v))
for c in table_checks:
    # Columns as globals: a generator expression sees only globals.
    assert eval(c, {"abs": abs, "all": all, "zip": zip, "math": math, "len": len, **columns}), "'%s' fails" % c
for k, r in enumerate(rows):
    env = {k.split(" [")[0]: float(v) for k, v in r.items()}
    assert env["converged"] == 1, "point %d did not converge" % k
    env.update(abs=abs, math=math)
    for c in checks:
        assert eval(c, {}, env), "point %d (value %g): '%s' fails" % (k, env["value"], c)
print("%d points, %d sweep checks hold at each, %d over the table" % (len(rows), len(checks), len(table_checks)), file=sys.stderr)
strains = ("nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3")
for r in rows:
    env = {k.split(" [")[0]: v for k, v in r.items()}
    if "t_critical" in env:
        # A study of critical points: the critical load and the strains
        # there (resolved to t_resolution ~ 1e-11, far below numdiff's 1e-6).
        print("value", env["value"], "t_critical", env["t_critical"])
        print("strains", *[env[s + "_critical"] for s in strains])
        continue
    print("value", env["value"], *[env[s] for s in strains])
    print("K", *[env["K_%s_%s" % (s, s)] for s in strains])
PY
else
python3 - "$dir/out/summary.json" "$prm" > "$dir/key_numbers.output" <<'PY'
import json, re, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "converged", s["message"]
# Independent checks (to stderr, so that the key numbers stay clean).
if s.get("mode") == "natural shape":
    # Moduli and lengths of the examples are O(1): absolute 1e-8.
    worst = max(abs(v) for v in s["resultants"].values())
    assert worst < 1e-8, "natural state with a resultant of %g" % worst
    worst = max(abs(v) for v in s["multipliers"])
    assert worst < 1e-8, "natural state with a multiplier of %g" % worst
    print("natural state: resultants and multipliers vanish", file=sys.stderr)
for line in open(sys.argv[2]):
    m = re.match(r"#\s*check:\s*([\w.]+)\s*=\s*(\S+)\s*\+-\s*(\S+)", line)
    if m:
        name, value, tol = m.group(1), float(m.group(2)), float(m.group(3))
        got = s
        for part in name.split("."):
            got = got[int(part)] if isinstance(got, list) else got[part]
        assert abs(got - value) <= tol, "%s = %r, expected %r +- %g" % (name, got, value, tol)
        print("checked %s = %r (expected %r +- %g)" % (name, got, value, tol), file=sys.stderr)
print("energy", s["energy"])
for k, v in s["strains"].items(): print(k, v)
for k, v in s["resultants"].items(): print(k, v)
for i, row in enumerate(s["stiffness"]):
    print("K%d" % (i + 1), *row)
if "helix" in s:
    print("helix_radius", s["helix"]["radius"])
    print("handedness", s["helix"]["handedness"])
# Located events (strip): their load, resolved to ~1e-11 (the events'
# "resolution" in summary.json), far below numdiff's 1e-6.
for e in s.get("events", []):
    print("event", e["kind"], "branch", e["branch"], "lambda", e["t"])
PY
fi
if [ ! -f "$ref" ]; then
  echo "no reference $ref; produced $dir/key_numbers.output"; cat "$dir/key_numbers.output"; exit 1
fi
numdiff -q -r 1e-6 -a 1e-9 "$ref" "$dir/key_numbers.output" || {
  numdiff -r 1e-6 -a 1e-9 "$ref" "$dir/key_numbers.output"; exit 1; }
echo "key numbers match $ref"

#!/usr/bin/env bash
# Regression test of one example: run it (output into a scratch directory),
# check what is known independently of the code -- a natural state has zero
# resultants and zero multipliers; lines '# check: <key> = <value> +- <tol>'
# in the .prm state closed-form values -- then compare its key numbers from
# summary.json with the stored reference with numdiff (relative 1e-6,
# absolute 1e-9: far above the Newton tolerance, far below any physical change).
# usage: run_example.sh <rod_cross_section> <file.prm> <reference.output> <scratch dir>
set -euo pipefail
exe=$1 prm=$2 ref=$3 dir=$4
rm -rf "$dir" && mkdir -p "$dir"
# Redirect the example's output directory into the scratch directory.
sed -e "s|^\( *set Output directory *=\).*|\1 $dir/out|" "$prm" > "$dir/run.prm"
"$exe" --quiet "$dir/run.prm"
python3 - "$dir/out/summary.json" "$prm" > "$dir/key_numbers.output" <<'PY'
import json, re, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "converged", s["message"]
# Independent checks (to stderr, so that the key numbers stay clean).
if s["mode"] == "natural shape":
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
            got = got[part]
        assert abs(got - value) <= tol, "%s = %r, expected %r +- %g" % (name, got, value, tol)
        print("checked %s = %r (expected %r +- %g)" % (name, got, value, tol), file=sys.stderr)
print("energy", s["energy"])
for k, v in s["strains"].items(): print(k, v)
for k, v in s["resultants"].items(): print(k, v)
for i, row in enumerate(s["stiffness"]):
    print("K%d" % (i + 1), *row)
print("helix_radius", s["helix"]["radius"])
print("handedness", s["helix"]["handedness"])
PY
if [ ! -f "$ref" ]; then
  echo "no reference $ref; produced $dir/key_numbers.output"; cat "$dir/key_numbers.output"; exit 1
fi
numdiff -q -r 1e-6 -a 1e-9 "$ref" "$dir/key_numbers.output" || {
  numdiff -r 1e-6 -a 1e-9 "$ref" "$dir/key_numbers.output"; exit 1; }
echo "key numbers match $ref"

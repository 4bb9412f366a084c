#!/usr/bin/env bash
# Regression test of one example: run it (output into a scratch directory),
# extract its key numbers from summary.json and compare them with the stored
# reference with numdiff (relative 1e-6, absolute 1e-9: far above the Newton
# tolerance, far below any physical change).
# usage: run_example.sh <rod_cross_section> <file.prm> <reference.output> <scratch dir>
set -euo pipefail
exe=$1 prm=$2 ref=$3 dir=$4
rm -rf "$dir" && mkdir -p "$dir"
# Redirect the example's output directory into the scratch directory.
sed -e "s|^\( *set Output directory *=\).*|\1 $dir/out|" "$prm" > "$dir/run.prm"
"$exe" --quiet "$dir/run.prm"
python3 - "$dir/out/summary.json" > "$dir/key_numbers.output" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "converged", s["message"]
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

#!/usr/bin/env bash
# A cookbook extension (doc/cookbook.md) appears and runs: the executable
# built with the extension's one file lists its name among the values of the
# entry it extends, the application without it does not, and the example
# that uses it reproduces its closed form ('# check:' lines, run_example.sh or
# run_plate_rod_example.sh)
# and its reference key numbers.
# usage: cookbook.sh <executable with the extension> <application> <entry> <name> <file.prm> <reference.output> <scratch dir>
set -euo pipefail
with=$(realpath "$1") without=$(realpath "$2") entry=$3 name=$4 prm=$5 ref=$6 dir=$(realpath -m "$7")
listed() {
  "$1" --print-parameters json | python3 -c '
import json, re, sys
entry, name = sys.argv[1], sys.argv[2]
found = []
def walk(d):
    for k, v in d.items():
        if isinstance(v, dict):
            if k == entry and "pattern_description" in v:
                sel = re.match(r"\[Selection (.*) \]", v["pattern_description"])
                found.append(bool(sel) and name in sel.group(1).split("|"))
            else:
                walk(v)
walk(json.load(sys.stdin))
sys.exit(0 if any(found) else 1)' "$entry" "$name"
}
listed "$with" || { echo "'$name' is not a value of '$entry' in $(basename "$with")"; exit 1; }
if listed "$without"; then echo "'$name' is a value of '$entry' without the extension"; exit 1; fi
echo "'$name' is a value of '$entry' with the extension's file only"
runner=run_example.sh
[[ $(basename "$without") == plate_rod ]] && runner=run_plate_rod_example.sh
exec "$(dirname "${BASH_SOURCE[0]}")/$runner" "$with" "$prm" "$ref" "$dir"

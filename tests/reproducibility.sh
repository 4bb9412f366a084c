#!/usr/bin/env bash
# Reproducibility of located critical points: run one input four times --
# with 1 and with 2 BLAS threads (OPENBLAS_NUM_THREADS; MUMPS' kernels round
# differently), and with the entry named on its '# perturb:' line multiplied
# by 1 + 1e-14 and 1 - 1e-14 (of a growth factor g that moves the mismatch
# g - 1 it drives by 1e-14 g/(g - 1): 1e-11 for g = 1.001) -- and require
# every located event's load to agree with the first run's within
# max(1e-9 |lambda|, R), R the round-off resolution the first run reports for
# it (summary.json: events.*.location.resolution, the larger of
# eps |v|.|J||v| / |dg/dlambda| and the Newton iteration's precision;
# doc/theory-continuation.md 4), with every rerun's R at most 4 times it.
# Prints the measured spread against both.
# usage: reproducibility.sh <application> <input.prm> <scratch dir>
set -euo pipefail
exe=$(realpath "$1") prm=$(realpath "$2") dir=$(realpath -m "$3")
rm -rf "$dir" && mkdir -p "$dir"
entry=$(sed -n 's/^# perturb: *//p' "$prm")
[ -n "$entry" ] || { echo "$prm names no '# perturb:' entry"; exit 1; }
run() { # name threads factor
  local out="$dir/$1"
  python3 - "$prm" "$entry" "$3" "$out" > "$dir/$1.prm" <<'PY'
import re, sys
prm, entry, factor, out = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
for line in open(prm).read().splitlines():
    m = re.match(r"(\s*set\s+%s\s*=\s*)(\S+)\s*$" % re.escape(entry), line)
    if m and factor != 1:
        line = m.group(1) + repr(float(m.group(2)) * factor)
    line = re.sub(r"^(\s*set Output directory\s*=).*", r"\1 " + out, line)
    print(line)
PY
  OPENBLAS_NUM_THREADS=$2 "$exe" --quiet "$dir/$1.prm" > "$dir/$1.log" 2>&1 ||
    { echo "run $1 failed:"; tail -5 "$dir/$1.log"; exit 1; }
}
run threads1 1 1
run threads2 2 1
run plus 1 1.00000000000001
run minus 1 0.99999999999999
python3 - "$dir" <<'PY'
import json, os, sys
d = sys.argv[1]
runs = {}
for name in ("threads1", "threads2", "plus", "minus"):
    s = json.load(open(os.path.join(d, name, "summary.json")))
    assert s["status"] == "converged", (name, s.get("message"))
    runs[name] = s["events"]
ref = runs["threads1"]
assert ref, "no event located"
bad = 0
for name, ev in runs.items():
    assert len(ev) == len(ref), "%s: %d events, threads1: %d" % (name, len(ev), len(ref))
    for k, (a, b) in enumerate(zip(ref, ev)):
        la, lb = a["t"], b["t"]
        assert a["kind"] == b["kind"] and a["branch"] == b["branch"], (name, k)
        # the tolerance is the reference run's resolution; a rerun that
        # resolves its load more than 4x worse is itself a failure
        res = a["location"]["resolution"]
        tol = max(1e-9 * abs(la), res)
        ok = abs(la - lb) <= tol and b["location"]["resolution"] <= 4 * res
        bad += not ok
        print("%-8s event %d (%s, branch %d, %s): %.15g vs %.15g: |diff| %.2e = %.2e relative, "
              "%.2f of the resolution %.2e%s" % (name, k, a["kind"], a["branch"],
              a["location"]["method"].split()[0], la, lb, abs(la - lb), abs(la - lb) / abs(la),
              abs(la - lb) / res if res > 0 else 0, res, "" if ok else "  <-- FAILS"))
sys.exit(1 if bad else 0)
PY

#!/usr/bin/env bash
# Faults a run must survive (issue: nothing lost, nothing silently wrong):
# a path that cannot reach its target, a default parameter file, SIGTERM
# and SIGINT mid-run and mid-study, two runs into one directory, a rerun
# into an old directory, bad input into an existing directory. Each case
# asserts the exit status, summary.json's status and what the directory
# holds. usage: robustness.sh <plate_rod> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
examples="$here/../parameter_files/plate_rod"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }
status_of() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['status'])" "$1" 2>/dev/null; }
# No temporary file anywhere below a directory, every VTU/PVD well-formed XML,
# every PVD listing only files that exist, every CSV rectangular.
complete_files() {
  python3 - "$1" <<'PY'
import csv, os, sys, xml.etree.ElementTree as ET
bad = []
for root, _, files in os.walk(sys.argv[1]):
    for f in files:
        p = os.path.join(root, f)
        if ".tmp" in f:
            bad.append("temporary file " + p)
        elif f.endswith((".vtu", ".pvd")):
            try:
                t = ET.parse(p)
            except ET.ParseError as e:
                bad.append("malformed %s: %s" % (p, e))
                continue
            if f.endswith(".pvd"):
                for d in t.iter("DataSet"):
                    if not os.path.exists(os.path.join(root, d.get("file"))):
                        bad.append("%s lists the missing %s" % (p, d.get("file")))
        elif f.endswith(".csv"):
            rows = list(csv.reader(open(p)))
            if rows and any(len(r) != len(rows[0]) for r in rows):
                bad.append("ragged " + p)
print("; ".join(bad))
sys.exit(1 if bad else 0)
PY
}
with_output() { sed -e "s|^\( *set Output directory *=\).*|\1 $2|" "$1"; }

# 1. Every step fails from t = 0: exit 2, "failed", never "converged".
printf 'subsection Mesh\n set Global refinements = 1\nend\nsubsection Plate growth\n set Kind = isotropic\n set Radial growth factor = 1e6\nend\nsubsection Output\n set Output directory = stuck\nend\n' > stuck.prm
timeout 120 "$exe" --quiet stuck.prm > stuck.txt 2>&1; s=$?
if [ $s -eq 2 ] && [ "$(status_of stuck/summary.json)" = failed ] && grep -q "did not reach its target" stuck.txt; then
  ok "a path whose every step fails: exit 2, status failed"
else bad "a path whose every step fails: exit $s, status $(status_of stuck/summary.json)"; cat stuck.txt; fi

# 2. A parameter file that sets nothing (but where to write): a bounded job.
printf 'subsection Output\n set Output directory = defaults\nend\n' > defaults.prm
timeout 120 "$exe" --quiet defaults.prm > defaults.txt 2>&1; s=$?
if [ $s -eq 0 ] && [ "$(status_of defaults/summary.json)" = converged ]; then
  ok "the default parameters: a bounded run, exit 0"
else bad "the default parameters: exit $s"; cat defaults.txt; fi

# 3. SIGTERM and SIGINT mid-run: 143 / 130, "interrupted", complete files.
for sig in TERM INT; do
  with_output "$examples/dome.prm" "sig$sig" > "sig$sig.prm"
  "$exe" --quiet "sig$sig.prm" > "sig$sig.txt" 2>&1 & pid=$!
  for _ in $(seq 1 100); do [ -f "sig$sig/steps.csv" ] && break; sleep 0.1; done
  sleep 1; kill -$sig $pid; wait $pid; s=$?
  want=$([ $sig = TERM ] && echo 143 || echo 130)
  why=$(complete_files "sig$sig")
  if [ $s -eq "$want" ] && [ "$(status_of sig$sig/summary.json)" = interrupted ] && [ -z "$why" ]; then
    ok "SIG$sig mid-run: exit $s, status interrupted, files complete"
  else bad "SIG$sig mid-run: exit $s (expected $want), status $(status_of sig$sig/summary.json); $why"; cat "sig$sig.txt"; fi
done

# 4. SIGTERM mid-study: the points done are in sweep.csv, nothing partial.
with_output "$examples/studies/critical_growth_vs_rim_stiffness_cosserat.prm" study > study.prm
"$exe" --quiet study.prm > study.txt 2>&1 & pid=$!
for _ in $(seq 1 300); do [ -f study/sweep.csv ] && break; sleep 0.1; done
kill -TERM $pid; wait $pid; s=$?
why=$(complete_files study)
rows=$(($(wc -l < study/sweep.csv) - 1))
if [ $s -eq 143 ] && [ -z "$why" ] && [ $rows -ge 1 ]; then
  ok "SIGTERM mid-study: exit 143, sweep.csv with the $rows point(s) done, files complete"
else bad "SIGTERM mid-study: exit $s, $rows rows; $why"; cat study.txt; fi

# 5. Two runs into one directory: the second exits 1 at once naming the first's pid.
with_output "$examples/dome.prm" shared > shared.prm
"$exe" --quiet shared.prm > first.txt 2>&1 & pid=$!
for _ in $(seq 1 100); do [ -f shared/summary.json ] && break; sleep 0.1; done
timeout 20 "$exe" --quiet shared.prm > second.txt 2>&1; s=$?
kill -TERM $pid; wait $pid
if [ $s -eq 1 ] && grep -q "pid $pid" second.txt; then
  ok "a second run into a directory in use: exit 1 naming pid $pid"
else bad "a second run into a directory in use: exit $s"; cat second.txt; fi

# 6. A shorter run into an old directory: the old run's files go to previous/.
sed -e "s|^\( *set Parameter range *=\).*|\1 0, 0.05|" shared.prm > short.prm
timeout 120 "$exe" --quiet short.prm > short.txt 2>&1; s=$?
stale=$(python3 - <<'PY'
import os
listed = set(l.strip() for l in open("shared/.cosmo-files"))
print(" ".join(f for f in os.listdir("shared") if f not in listed and not f.startswith(".") and f != "previous"))
PY
)
why=$(complete_files shared)
if [ $s -eq 0 ] && [ -z "$stale" ] && [ -z "$why" ] && [ -f shared/previous/summary.json ]; then
  ok "a rerun into an old directory: only its own files, the old run in previous/"
else bad "a rerun into an old directory: exit $s, stale: $stale; $why"; fi

# 7. Bad input into that directory leaves it as it was.
before=$(cd shared && find . -type f -exec md5sum {} + | sort | md5sum)
{ cat short.prm; printf 'subsection Plate\n set Thickness profile = 1 - 2*r^2\nend\n'; } > rejected.prm
timeout 60 "$exe" --quiet rejected.prm > rejected.txt 2>&1; s=$?
after=$(cd shared && find . -type f -exec md5sum {} + | sort | md5sum)
if [ $s -eq 1 ] && [ "$before" = "$after" ]; then
  ok "bad input into an existing directory: exit 1, the directory untouched"
else bad "bad input into an existing directory: exit $s, changed: $([ "$before" = "$after" ] && echo no || echo yes)"; cat rejected.txt; fi
exit $fail

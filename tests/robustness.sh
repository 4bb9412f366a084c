#!/usr/bin/env bash
# Faults a run must survive (issue: nothing lost, nothing silently wrong):
# a path that cannot reach its target, a default parameter file, SIGTERM
# and SIGINT mid-run and mid-study, two runs into one directory, a rerun
# into an old directory, bad input into an existing directory, a run and a
# study killed (SIGTERM, SIGKILL) at several points and resumed (--resume),
# and the resumes that must be refused. Each case asserts the exit status,
# summary.json's status and what the directory holds; a resumed run must
# reach the uninterrupted run's result (events and tables to 1e-12).
# usage: robustness.sh <plate_rod> <scratch dir>
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
# Wait until the log has a line matching $2 (at most 120 s).
wait_for() { for _ in $(seq 1 1200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.1; done; return 1; }
# The same result: every number of the tables and the events of summary.json
# to 1e-12 relative (of the column's largest value); wall times excepted.
same_result() {
  python3 - "$1" "$2" "$3" <<'PY'
import csv, json, math, sys
a, b, table = sys.argv[1:4]
bad = []
def close(x, y, scale):
    return x == y or (math.isnan(x) and math.isnan(y)) or abs(x - y) <= 1e-12 * max(scale, 1e-300)
ra, rb = list(csv.reader(open(a + "/" + table))), list(csv.reader(open(b + "/" + table)))
if ra[0] != rb[0] or len(ra) != len(rb):
    bad.append("%s: %d against %d rows" % (table, len(ra), len(rb)))
else:
    for c, name in enumerate(ra[0]):
        if name == "seconds":
            continue
        col = [(float(x[c]), float(y[c])) for x, y in zip(ra[1:], rb[1:])]
        scale = max([abs(x) for x, _ in col if not math.isnan(x)] + [0])
        bad += ["%s column %s row %d: %r against %r" % (table, name, k, x, y)
                for k, (x, y) in enumerate(col) if not close(x, y, scale)][:2]
try:
    ea, eb = json.load(open(a + "/summary.json"))["events"], json.load(open(b + "/summary.json"))["events"]
    if len(ea) != len(eb):
        bad.append("%d against %d events" % (len(ea), len(eb)))
    for x, y in zip(ea, eb):
        for k in ("kind", "branch", "n_negative_before", "n_negative_after", "mode_number"):
            if x.get(k) != y.get(k):
                bad.append("event %s: %r against %r" % (k, x.get(k), y.get(k)))
        if not close(x["t"], y["t"], abs(x["t"])):
            bad.append("event t %r against %r" % (x["t"], y["t"]))
    if json.load(open(b + "/summary.json"))["status"] != "converged":
        bad.append("the resumed run is not converged")
except FileNotFoundError:
    pass  # a study: its table is its result
print("; ".join(bad))
sys.exit(1 if bad else 0)
PY
}

# 8. A run killed three times (SIGTERM on the first branch, SIGKILL on the
#    second, SIGTERM on the third) and resumed each time reaches the
#    uninterrupted run's result; no checkpoint is left at the end.
# (the dome on its coarsest mesh up to t = 0.6: 28 steps on three branches in ~4 s)
coarse() { with_output "$examples/dome.prm" "$1" | sed -e "s|^\( *set Global refinements *=\).*|\1 1|" \
  -e "s|^\( *set Parameter range *=\).*|\1 0, 0.6|"; }
coarse whole > whole.prm
timeout 300 "$exe" --quiet whole.prm > whole.txt 2>&1 || { bad "the uninterrupted run failed"; cat whole.txt; }
coarse killed > killed.prm
"$exe" --quiet killed.prm > killed-0.txt 2>&1 & pid=$!
wait_for killed/log.txt "^step   4 "; kill -TERM $pid; wait $pid; s1=$?
"$exe" --quiet --resume killed > killed-1.txt 2>&1 & pid=$!
wait_for killed/log.txt "^step  13 "; kill -KILL $pid; wait $pid 2>/dev/null; s2=$?
"$exe" --quiet --resume killed > killed-2.txt 2>&1 & pid=$!
wait_for killed/log.txt "^step  24 "; kill -TERM $pid; wait $pid; s3=$?
timeout 300 "$exe" --quiet --resume killed > killed-3.txt 2>&1; s4=$?
why=$(same_result whole killed steps.csv; complete_files killed)
if [ $s1 -eq 143 ] && [ $s2 -eq 137 ] && [ $s3 -eq 143 ] && [ $s4 -eq 0 ] && [ -z "$why" ] &&
   [ ! -f killed/checkpoint.cosmo ] && [ "$(grep -c 'resumed from the checkpoint' killed/log.txt)" = 3 ]; then
  ok "killed at steps 4 (TERM, branch 0), 13 (KILL, branch 1), 24 (TERM, branch 2) and resumed: the uninterrupted result"
else bad "kill and resume: exits $s1 $s2 $s3 $s4; $why"; tail -5 killed-*.txt; fi

# 9. Resumes that must be refused (exit 1, the directory untouched): a
#    finished run, a checkpoint whose parameters were changed (named), a
#    directory that is not a run's, a parameter file that differs.
"$exe" --quiet --resume whole > finished.txt 2>&1; s1=$?
coarse edited > edited.prm
"$exe" --quiet edited.prm > edited-0.txt 2>&1 & pid=$!
wait_for edited/log.txt "^step   3 "; kill -TERM $pid; wait $pid
sed -i -e "s|^\( *set Thickness *=\).*|\1 0.02|" edited/parameters.prm
before=$(cd edited && find . -type f -exec md5sum {} + | sort | md5sum)
"$exe" --quiet --resume edited > edited-1.txt 2>&1; s2=$?
after=$(cd edited && find . -type f -exec md5sum {} + | sort | md5sum)
mkdir -p empty; "$exe" --quiet --resume empty > empty.txt 2>&1; s3=$?
coarse edited | sed -e "s|^\( *set Thickness *=\).*|\1 0.03|" > other.prm
"$exe" --quiet other.prm --resume edited > other.txt 2>&1; s4=$?
if [ $s1 -eq 1 ] && grep -q "checkpoint" finished.txt && [ $s2 -eq 1 ] &&
   grep -q "Plate/Thickness' was '0.01' and is now '0.02'" edited-1.txt && [ "$before" = "$after" ] &&
   [ $s3 -eq 1 ] && grep -q "no parameters.prm" empty.txt && [ $s4 -eq 1 ] && grep -q "Plate/Thickness" other.txt; then
  ok "resume refused (exit 1, naming why): a finished run, changed parameters, no run directory"
else bad "refused resumes: exits $s1 $s2 $s3 $s4"; cat finished.txt edited-1.txt empty.txt other.txt; fi

# 10. A study (critical curve) killed after its first point and resumed:
#     the same sweep.csv as the uninterrupted study (but the times).
study_of() { with_output "$examples/studies/critical_growth_vs_rim_stiffness_kirchhoff.prm" "$1" |
  sed -e "s|^\( *set Global refinements *=\).*|\1 2|"; }
study_of study_whole > study_whole.prm
timeout 300 "$exe" --quiet study_whole.prm > study_whole.txt 2>&1 || { bad "the uninterrupted study failed"; cat study_whole.txt; }
study_of study_killed > study_killed.prm
"$exe" --quiet study_killed.prm > study_killed-0.txt 2>&1 & pid=$!
# (after the first value, the slowest: the other five are continued from it)
for _ in $(seq 1 3000); do grep -q "= 1e-09: critical" study_killed/sweep-log.txt 2>/dev/null && break; sleep 0.02; done
kill -KILL $pid; wait $pid 2>/dev/null
timeout 300 "$exe" --quiet --resume study_killed > study_killed-1.txt 2>&1; s=$?
why=$(same_result study_whole study_killed sweep.csv; complete_files study_killed)
if [ $s -eq 0 ] && [ -z "$why" ] && grep -q "resumed from the checkpoint: [1-5] of 6" study_killed/sweep-log.txt &&
   [ ! -f study_killed/checkpoint.cosmo ]; then
  ok "a study killed (KILL) after a point and resumed: the uninterrupted sweep.csv"
else bad "study kill and resume: exit $s; $why"; cat study_killed-1.txt; tail -3 study_killed/sweep-log.txt; fi
exit $fail

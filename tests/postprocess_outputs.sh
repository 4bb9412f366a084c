#!/usr/bin/env bash
# The run's outputs are postprocessors (io/postprocessors.h): steps.csv is
# 'steps table', the VTU files and their collections 'fields'. What the list
# and 'Steps between outputs' select is what is written, and nothing else:
#  1. Steps between outputs = 3 on a path of 11 states (steps 0 .. 10): the
#     VTU files of steps 0, 3, 6, 9 and of the last state, 10, each listed
#     once in solution.pvd (path order) and solution-branch-0.pvd, while
#     steps.csv has every state;
#  2. only 'steps table': steps.csv and no VTU or PVD file;
#  3. only 'fields': every state's VTU and no steps.csv;
#  4. a run that fails (exit 2: 'Maximum number of steps' = 5 before its
#     target) with Steps between outputs = 0 still writes its last converged
#     state, step 5, and only it;
#  5. a strip twisted past its first branch point ('Stop at first event'):
#     'fields' writes the event's state and mode (event-01.vtu,
#     event-01-mode.vtu) with no converged state's VTU (Steps between
#     outputs = 0 and the run stops at the event); without 'fields', no
#     event file;
#  6. 'Steps between outputs' left at auto: the same strip stopping at its
#     event writes the event's files and no converged state's; followed
#     past it (no stop), every converged state's VTU, as with 1.
# usage: postprocess_outputs.sh <rod_cross_section> <strip> <scratch dir>
set -uo pipefail
exe=$(realpath "$1") strip=$(realpath "$2") dir=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
prm() { # name, list, interval
  cat <<PRM
subsection Cross-section
  set Shape = circle
  set Global refinements = 1
end
subsection Material 1
  set Growth kind = isotropic
  set Growth factor = 1 + 0.1*x
end
subsection Continuation
  set Initial step = 0.1
  set Maximum step = 0.1
  set Minimum step = 0.1
  set Maximum number of steps = ${4:-200}
end
subsection Output
  set Output directory = $1
  set Stiffness at every step = false
end
subsection Postprocess
  set List of postprocessors = $2
  subsection fields
    set Steps between outputs = $3
  end
end
PRM
}
fail=0
strip_prm() { # name, list, interval (auto: the entry left out), stop at the first event
  cat <<PRM
subsection Strip
  set Width = 1
  set Thickness = 0.02
  set Number of cells = 10
end
subsection Rod strains
  set Mode = prescribed strains
  set Strains = 0, 0, 1, 0, 0, 2
  set Free strains = nu3
end
subsection Path following
  set Method = arclength
end
subsection Arclength continuation
  set Parameter range = 0, 0.8
  set Initial step = 0.05
  set Maximum step = 0.1
  set Stop at first event = $4
  set Maximum number of branches = 1
end
subsection Output
  set Output directory = $1
end
subsection Postprocess
  set List of postprocessors = $2
  subsection fields
$([[ $3 == auto ]] || echo "    set Steps between outputs = $3")
  end
end
PRM
}
for run in "every3|steps table, fields|3" "table_only|steps table|1" "fields_only|fields|1"; do
  IFS='|' read -r name list interval <<< "$run"
  prm "$name" "$list" "$interval" > "$name.prm"
  timeout 300 "$exe" --quiet "$name.prm" > "$name.txt" 2>&1 || { echo "  FAIL  $name: status $?"; cat "$name.txt"; fail=1; }
done
prm stalled "steps table, fields" 0 5 > stalled.prm
timeout 300 "$exe" --quiet stalled.prm > stalled.txt 2>&1
status=$?
[[ $status == 2 ]] && echo "  ok    stalled: exit status 2 (target not reached)" ||
  { echo "  FAIL  stalled: status $status, not 2"; cat stalled.txt; fail=1; }
for run in "events|steps table, fields|0|true" "no_events|steps table|0|true" \
  "auto_stop|steps table, fields|auto|true" "auto_path|steps table, fields|auto|false"; do
  IFS='|' read -r name list interval stop <<< "$run"
  strip_prm "$name" "$list" "$interval" "$stop" > "$name.prm"
  timeout 300 "$strip" --quiet "$name.prm" > "$name.txt" 2>&1 || { echo "  FAIL  $name: status $?"; cat "$name.txt"; fail=1; }
done
python3 - <<'PY' || fail=1
import csv, glob, os, sys
import xml.etree.ElementTree as ET
ok = True
def check(what, cond, detail=""):
    global ok
    print(("  ok    " if cond else "  FAIL  ") + what + ("" if cond else ": " + str(detail)))
    ok = ok and cond
def steps(d):
    with open(d + "/steps.csv") as f:
        return [int(float(r[0])) for r in list(csv.reader(f))[1:]]
def listed(pvd):
    return [e.get("file") for e in ET.parse(pvd).getroot().iter("DataSet")]

s = steps("every3")
check("every3: steps.csv has the 11 states of the path", s == list(range(11)), s)
want = ["solution-%04d.vtu" % k for k in (0, 3, 6, 9, 10)]
check("every3: solution.pvd lists steps 0, 3, 6, 9 and the last", listed("every3/solution.pvd") == want,
      listed("every3/solution.pvd"))
check("every3: solution-branch-0.pvd the same", listed("every3/solution-branch-0.pvd") == want)
check("every3: rod.pvd the same states", listed("every3/rod.pvd") == [w.replace("solution", "rod") for w in want])
check("every3: exactly those VTU files", sorted(os.path.basename(f) for f in glob.glob("every3/solution-*.vtu")) == want)
check("table_only: steps.csv has every state", steps("table_only") == list(range(11)))
check("table_only: no VTU or PVD file", not glob.glob("table_only/*.vtu") + glob.glob("table_only/*.pvd"),
      glob.glob("table_only/*.*vt*"))
check("fields_only: no steps.csv", not os.path.exists("fields_only/steps.csv"))
check("fields_only: every state's VTU", len(glob.glob("fields_only/solution-*.vtu")) == 11)
s = steps("stalled")
check("stalled: steps.csv has steps 0 to 5", s == list(range(6)), s)
check("stalled: its last converged state's VTU, alone, in solution.pvd",
      listed("stalled/solution.pvd") == ["solution-0005.vtu"], listed("stalled/solution.pvd"))
check("stalled: no other VTU", sorted(os.path.basename(f) for f in glob.glob("stalled/*.vtu")) ==
      ["rod-0005.vtu", "solution-0005.vtu"], glob.glob("stalled/*.vtu"))
check("events: the event's state and mode", os.path.exists("events/event-01.vtu") and
      os.path.exists("events/event-01-mode.vtu"), glob.glob("events/*.vtu"))
check("events: no converged state's VTU (the run stopped at the event)",
      not glob.glob("events/section-*.vtu") + glob.glob("events/strip-*.vtu"), glob.glob("events/*.vtu"))
check("no_events: no event file without 'fields'", not glob.glob("no_events/*.vtu"), glob.glob("no_events/*"))
check("auto_stop: the event's state and mode", os.path.exists("auto_stop/event-01.vtu") and
      os.path.exists("auto_stop/event-01-mode.vtu"), glob.glob("auto_stop/*.vtu"))
check("auto_stop: no converged state's VTU on the way to the event",
      not glob.glob("auto_stop/section-*.vtu") + glob.glob("auto_stop/strip-*.vtu"), glob.glob("auto_stop/*.vtu"))
n = len(steps("auto_path"))
m = len(glob.glob("auto_path/strip-*.vtu"))
check("auto_path: past the event, every converged state's VTU (%d states)" % n, n > 2 and m == n, (n, m))
sys.exit(0 if ok else 1)
PY
exit $fail

#!/usr/bin/env bash
# plate_rod on a mesh distributed over the MPI ranks ('Mesh / Distributed',
# doc/parallel-runs.md): each rank assembles its own cells, MUMPS factorizes
# with distributed input, the drivers' vectors are whole on every rank. The
# ranks' partial sums are added in another order than one process's, so the
# runs agree to round-off, not bitwise. Checked against one process on a
# serial mesh:
#  - the dome (sector pi/2) past its first branch point onto the bifurcated
#    branch, at np = 1 and np = 2 on the distributed mesh: the same events
#    with the same inertia counts (INFOG(12), exact in parallel: a wrong
#    count moves or loses an event), the located loads equal to their
#    resolution (summary.json location.resolution, the round-off bound of
#    the test function, 6.6e-9 here; measured 3e-10 and 5e-10), the same
#    branches and stability counts at every step and the dome height on
#    the bifurcated branch to 1e-6 of its largest value (the states agree
#    to Newton's stopping test, amplified just past the bifurcation; the
#    same bound as the one-path test);
#  - the lobes on the full disc (a double eigenvalue, n = 2): the critical
#    point located in the fixed-point space of the reflection y -> -y, which
#    the distributed mesh gathers from the ranks; without it the run finds
#    the other of the discretization-split pair, 2.2e-8 away against a
#    resolution of 5.4e-11;
#  - the output: each plate-K.pvtu lists one piece per rank, all present;
#    VTK reads the record with as many cells as the serial VTU and the same
#    largest |displacement| (Float32: to 1e-6 of it);
#  - interrupted (SIGTERM to both ranks after a checkpoint) and resumed on
#    2 ranks: the uninterrupted run's event, to its resolution; resuming on
#    1 rank is refused (exit 1) naming 'Distributed' and the ranks to use,
#    since the DoF numbering depends on the ranks' parts;
#  - SIGTERM to one rank only: all stop together (not the timeout: no rank
#    left in a collective call) and go on from the checkpoint to the event.
# usage: mpi_distributed_mesh.sh <plate_rod> <scratch dir>
set -uo pipefail
plate=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }

# name, source file, extra lines
make_prm() {
  sed -e "s|^\( *set Output directory *=\).*|\1 $1|" "$here/../parameter_files/plate_rod/$2.prm" > $1.prm
  printf "$3" >> $1.prm
}
distributed='subsection Mesh\n  set Distributed = true\nend\n'
dome_range='subsection Arclength continuation\n  set Parameter range = 0, 0.16\n  set Maximum number of branches = 2\nend\n'
full_disc='subsection Mesh\n  set Domain = full disc\nend\nsubsection Growth path\n  set Stop at first event = true\nend\n'
make_prm dome_serial dome "$dome_range"
make_prm dome_np1 dome "$dome_range$distributed"
make_prm dome_np2 dome "$dome_range$distributed"
make_prm lobes_serial lobes "$full_disc"
make_prm lobes_np2 lobes "$full_disc$distributed"
make_prm stopped dome "$dome_range$distributed"
make_prm one_rank dome "$dome_range$distributed"

run() { # name, ranks (0: one process, no mpirun)
  if [ $2 -eq 0 ]; then timeout 300 "$plate" --quiet $1.prm > $1.txt 2>&1
  else timeout 300 mpirun -np $2 "$plate" --quiet $1.prm > $1.txt 2>&1; fi || { bad "$1 failed"; tail -n 5 $1.txt; }
}
run dome_serial 0; run dome_np1 1; run dome_np2 2; run lobes_serial 0; run lobes_np2 2

# Stopped after its first checkpoint (the ranks stopped, sent SIGTERM, continued: each takes
# it whenever it is, and they stop together), then resumed.
timeout -k 10 300 mpirun -np 2 "$plate" --quiet stopped.prm > stopped-0.txt 2>&1 & pid=$!
for _ in $(seq 1 30000); do [ -f stopped/checkpoint.cosmo ] && break; sleep 0.01; done
launcher=$(pgrep -f "^mpirun -np 2 $plate --quiet stopped.prm" | head -1)
pkill -STOP -P "$launcher"; pkill -TERM -P "$launcher"; pkill -CONT -P "$launcher"
wait $pid; s1=$?
[ -f stopped/checkpoint.cosmo ] && ok "stopped on 2 ranks (exit $s1): a checkpoint" || bad "stopped on 2 ranks (exit $s1): no checkpoint"
timeout 120 "$plate" --resume stopped > resume-1.txt 2>&1; s=$?
if [ $s -eq 1 ] && grep -q "Distributed" resume-1.txt && grep -q "mpirun -np 2" resume-1.txt && [ -f stopped/checkpoint.cosmo ]; then
  ok "resumed on 1 rank: refused (exit 1), the checkpoint kept: $(grep -o 'the checkpoint was written.*' resume-1.txt | head -1)"
else bad "resumed on 1 rank: exit $s"; tail -n 5 resume-1.txt; fi
timeout 300 mpirun -np 2 "$plate" --resume stopped > resume-2.txt 2>&1; s2=$?
[ $s2 -eq 0 ] && grep -q "going on after step" stopped/log.txt && [ ! -f stopped/checkpoint.cosmo ] &&
  ok "resumed on 2 ranks: exit 0, went on from the checkpoint" || { bad "resumed on 2 ranks: exit $s2"; tail -n 5 resume-2.txt; }

# SIGTERM to one rank only, as it is (a signal that reaches the ranks at
# different moments), in the middle of a Newton solve: the first step on
# the bifurcated branch has just converged (6 rows in steps.csv) and the
# next takes 5 iterations. Every rank stops after the same step, well within
# the timeout (before the signal was decided together, the signalled rank
# left its solve alone and the other waited in the residual's sum for ever:
# 3 of 3 runs hung), with a checkpoint from which 2 ranks go on to the
# uninterrupted run's event.
timeout -k 10 60 mpirun -np 2 "$plate" --quiet one_rank.prm > one_rank-0.txt 2>&1 & pid=$!
for _ in $(seq 1 30000); do
  [ -f one_rank/steps.csv ] && [ "$(wc -l < one_rank/steps.csv)" -ge 7 ] && break
  kill -0 $pid 2>/dev/null || break; sleep 0.002
done
launcher=$(pgrep -f "^mpirun -np 2 $plate --quiet one_rank.prm" | head -1)
pkill -TERM -n -P "$launcher"
wait $pid; s1=$?
if [ $s1 -eq 0 ]; then
  echo "  skip  SIGTERM to one rank: the run ended before the signal (a machine faster than the last 3 steps' 0.8 s here)"
elif [ $s1 -ne 124 ] && [ -f one_rank/checkpoint.cosmo ]; then
  ok "SIGTERM to one rank: every rank stopped (exit $s1, not the timeout), a checkpoint"
else bad "SIGTERM to one rank: exit $s1 (124: a rank waited for ever), checkpoint $( [ -f one_rank/checkpoint.cosmo ] && echo present || echo missing)"; tail -n 5 one_rank-0.txt; fi
if [ $s1 -ne 0 ] && [ -f one_rank/checkpoint.cosmo ]; then
  timeout 300 mpirun -np 2 "$plate" --resume one_rank > one_rank-1.txt 2>&1 ||
    { bad "resumed after SIGTERM to one rank: exit $?"; tail -n 5 one_rank-1.txt; }
fi

/usr/bin/python3 - "$here" <<'PY' || fail=1
import csv, os, re, sys
sys.path.insert(0, sys.argv[1])
from mpi_checks import check, load, same_events, pieces_present, same_as_serial_vtu
import mpi_checks
serial = load("dome_serial")
for run, ranks in (("dome_np1", 1), ("dome_np2", 2)):
    s = load(run)
    check(s.get("distributed_mesh_ranks") == ranks and s["dofs"] == serial["dofs"] and s["cells"] == serial["cells"],
          f"{run}: the mesh over {s.get('distributed_mesh_ranks')} rank(s), {s['dofs']} DoFs and {s['cells']} cells as one process's")
    same_events(run, serial, s)
    s1, s2 = (list(csv.DictReader(open(f"{d}/steps.csv"))) for d in ("dome_serial", run))
    check(len(s1) == len(s2) and all(a["n_negative_eigenvalues"] == b["n_negative_eigenvalues"] and a["branch"] == b["branch"] for a, b in zip(s1, s2)),
          f"{run}: {len(s1)} and {len(s2)} steps, the same branches and stability counts")
    scale = max(abs(float(a["dome_height"])) for a in s1)
    d = max(abs(float(a["dome_height"]) - float(b["dome_height"])) for a, b in zip(s1, s2)) / scale
    check(scale > 1e-3 and d <= 1e-6, f"{run}: dome height (largest {scale:.3g}, on the bifurcated branch) the same to {d:.1e} <= 1e-6")
same_events("lobes on the full disc, 2 ranks", load("lobes_serial"), load("lobes_np2"))
check(all(e.get("mode_number") == 2 for e in load("lobes_np2")["events"]), "lobes on the full disc, 2 ranks: mode n = 2")
same_events("stopped and resumed on 2 ranks", load("dome_np2"), load("stopped"))
same_events("SIGTERM to one rank, resumed on 2 ranks", load("dome_np2"), load("one_rank"))

# The .pvtu records and their pieces.
records = sorted(f[:-5] for f in os.listdir("dome_np2") if re.fullmatch(r"plate-\d{4}\.pvtu", f))
check(len(records) == len(list(csv.DictReader(open("dome_np2/steps.csv")))) and
      all(pieces_present("dome_np2", r, 2) for r in records),
      f"{len(records)} plate-K.pvtu records, one per step, each with its 2 pieces present")
pvd = open("dome_np2/plate.pvd").read()
check(all(r + ".pvtu" in pvd for r in records), "plate.pvd names the .pvtu records")
same_as_serial_vtu("dome_serial", "dome_np2", records[-1], "displacement")
sys.exit(mpi_checks.failures > 0)
PY
exit $fail

#!/usr/bin/env bash
# The SLURM job scripts of doc/ (doc/parallel-runs.md) under a stand-in
# `srun` (mpirun -np 2 here): doc/slurm-table.sh runs a small strip table
# on 2 ranks; doc/slurm-path.sh runs the dome to its first event with the
# factorization on both ranks, is stopped (SIGSTOP, then SIGTERM, as SLURM
# does at the time limit) and, submitted again, goes on from its checkpoint
# to the end: exit 0, the resume in the log, no checkpoint left, and the
# event of an uninterrupted run to its resolution.
# usage: slurm_scripts.sh <build dir> <scratch dir>
set -uo pipefail
build=$(realpath "$1") dir=$2
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir/bin" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export COSMO_BUILD=$build SLURM_CPUS_PER_TASK=1 COSMO_PARALLEL_FACTORIZATION_MIN=0
printf '#!/bin/sh\nexec mpirun -np 2 "$@"\n' > bin/srun && chmod +x bin/srun
export PATH=$dir/bin:$PATH
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }

sed -e "s|^\( *set Output directory *=\).*|\1 table|" -e "s|^\( *set First range *=\).*|\1 0, 1, 5|" \
    -e "s|^\( *set Second range *=\).*|\1 0, 0.2, 3|" -e "s|^\( *set Number of cells *=\).*|\1 20|" \
    "$here/../parameter_files/strip/ribbon_comparison.prm" > table.prm
timeout 300 bash "$here/../doc/slurm-table.sh" table.prm strip > table.txt 2>&1; s=$?
if [ $s -eq 0 ] && [ -f table/table.csv ] && grep -q "on 2 MPI ranks" table/log.txt; then
  ok "slurm-table.sh: the table on 2 ranks"
else bad "slurm-table.sh: exit $s"; tail -n 5 table.txt; fi

# (the path followed to the event, 'First event by estimate = false': what
# is stopped and resumed is a path's checkpoint)
for run in whole path; do
  sed -e "s|^\( *set Output directory *=\).*|\1 $run|" \
      -e "s|^\( *set Event tolerance *=.*\)|\1\n  set Stop at first event = true\n  set First event by estimate = false|" \
      "$here/../parameter_files/plate_rod/dome.prm" > $run.prm
done
timeout 300 bash "$here/../doc/slurm-path.sh" whole.prm > whole.txt 2>&1 || { bad "slurm-path.sh, uninterrupted"; tail -n 5 whole.txt; }
bash "$here/../doc/slurm-path.sh" path.prm > path-0.txt 2>&1 & pid=$!
for _ in $(seq 1 30000); do [ -f path/checkpoint.cosmo ] && break; sleep 0.01; done
# As SLURM at the time limit: SIGTERM to every task (the ranks). They are
# stopped first and take it when continued, whatever the machine's speed.
launcher=$(pgrep -f "^mpirun -np 2 $build/plate_rod path.prm" | head -1)
pkill -STOP -P "$launcher"; pkill -TERM -P "$launcher"; pkill -CONT -P "$launcher"
wait $pid; s1=$?
timeout 300 bash "$here/../doc/slurm-path.sh" path.prm > path-1.txt 2>&1; s2=$?
if [ $s1 -ne 0 ] && [ $s2 -eq 0 ] && grep -q "resumed from the checkpoint" path/log.txt && [ ! -f path/checkpoint.cosmo ] &&
   /usr/bin/python3 - <<'PY'
import json, sys
a, b = (json.load(open(f"{d}/summary.json")) for d in ("whole", "path"))
ea, eb = a["events"][0], b["events"][0]
res = max(ea["location"]["resolution"], eb["location"]["resolution"])
print(f"  event t = {ea['t']:.12g} and {eb['t']:.12g}: |difference| {abs(ea['t'] - eb['t']):.1e}, resolution {res:.1e}")
sys.exit(not (abs(ea["t"] - eb["t"]) <= res and b.get("mumps_phases_on_all_ranks", 0) > 0))
PY
then
  ok "slurm-path.sh stopped (exit $s1) and submitted again: resumed from its checkpoint to the uninterrupted event"
else bad "slurm-path.sh stop and resume: exits $s1 $s2"; tail -n 5 path-0.txt path-1.txt; fi

# doc/slurm-mesh.sh: the dome on a mesh distributed over the 2 ranks, to its first event.
sed -e "s|^\( *set Output directory *=\).*|\1 mesh|" -e "s|^\( *set Global refinements *=.*\)|\1\n  set Distributed = true|" \
    -e "s|^\( *set Event tolerance *=.*\)|\1\n  set Stop at first event = true|" \
    "$here/../parameter_files/plate_rod/dome.prm" > mesh.prm
timeout 300 bash "$here/../doc/slurm-mesh.sh" mesh.prm > mesh.txt 2>&1; s=$?
timeout 60 bash "$here/../doc/slurm-mesh.sh" whole.prm > refused.txt 2>&1; r=$?
if [ $s -eq 0 ] && [ $r -eq 1 ] && grep -q "Distributed = true" refused.txt && /usr/bin/python3 - <<'PY'
import json, sys
a, b = (json.load(open(f"{d}/summary.json")) for d in ("whole", "mesh"))
ea, eb = a["events"][0], b["events"][0]
res = max(ea["location"]["resolution"], eb["location"]["resolution"])
print(f"  event t = {ea['t']:.12g} (one path) and {eb['t']:.12g} (distributed mesh): |difference| {abs(ea['t'] - eb['t']):.1e}, resolution {res:.1e}")
sys.exit(not (abs(ea["t"] - eb["t"]) <= res and b.get("distributed_mesh_ranks") == 2))
PY
then
  ok "slurm-mesh.sh: the dome on a mesh distributed over 2 ranks, the event of one path; a file without 'Distributed = true' refused"
else bad "slurm-mesh.sh: exits $s (run) and $r (refused)"; tail -n 5 mesh.txt refused.txt; fi
exit $fail

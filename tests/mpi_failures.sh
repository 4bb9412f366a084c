#!/usr/bin/env bash
# Failures of a run on a distributed mesh end as on one process (issue 37,
# item 5). A failure that is neither bad input nor a driver's (here made on
# demand with COSMO_FAULT, io/fault_injection.h, after the second step):
#  - on one process: summary.json "failed" with the message, exit 2;
#  - raised on every rank (the ranks in lockstep meet it at the same point):
#    the same summary.json and exit 2 -- the ranks agree that all failed and
#    finish as one process does (before: MPI_Abort, exit 1, no summary);
#  - raised on rank 1 alone: rank 1 writes summary.json "failed" with the
#    message, naming the rank, and ends every rank (exit 2), instead of
#    leaving rank 0 waiting in a collective call (a hang).
# And a .geo section on a distributed mesh is meshed by rank 0 alone and sent
# to the others (gmsh run once, logged once per run).
# usage: mpi_failures.sh <plate_rod> <rod_cross_section> <scratch dir>
set -uo pipefail
plate=$(realpath "$1") section=$(realpath "$2") dir=$3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export COSMO_FAILURE_AGREEMENT_SECONDS=10
fail=0
ok() { echo "  ok    $1"; }
bad() { echo "  FAIL  $1"; fail=1; }

make_prm() { # name, extra lines
  sed -e "s|^\( *set Output directory *=\).*|\1 $1|" "$here/../parameter_files/plate_rod/dome.prm" > $1.prm
  printf 'subsection Mesh\n  set Global refinements = 1\n%s\nend\n' "$2" >> $1.prm
}
make_prm serial ""
make_prm all_ranks "  set Distributed = true"
make_prm one_rank "  set Distributed = true"

summary_says() { # dir, status, message pattern
  python3 - "$@" <<'PY'
import json, re, sys
d, status, pattern = sys.argv[1:4]
j = json.load(open(f"{d}/summary.json"))
sys.exit(0 if j["status"] == status and re.search(pattern, j["message"]) else 1)
PY
}
check() { # name, dir, exit status, expected status, message pattern, seconds
  if [ "$3" -eq "$4" ] && summary_says "$2" failed "$5"; then
    ok "$1: exit $3, summary.json \"failed\" naming the fault (${6}s)"
  else
    bad "$1: exit $3 (expected $4)"; tail -5 "$2.txt"; cat "$2/summary.json" 2>/dev/null | head -8
  fi
}
s0=$SECONDS; COSMO_FAULT="step 2" timeout 300 "$plate" --quiet serial.prm > serial.txt 2>&1; st=$?
check "one process" serial $st 2 "injected fault at step 2" $((SECONDS - s0))
s0=$SECONDS; COSMO_FAULT="step 2" timeout 300 mpirun -np 2 "$plate" --quiet all_ranks.prm > all_ranks.txt 2>&1; st=$?
check "every rank (2 ranks)" all_ranks $st 2 "injected fault at step 2" $((SECONDS - s0))
s0=$SECONDS; COSMO_FAULT="step 2@1" timeout 300 mpirun -np 2 "$plate" --quiet one_rank.prm > one_rank.txt 2>&1; st=$?
check "rank 1 alone (2 ranks)" one_rank $st 2 "injected fault at step 2 .*on MPI rank 1 alone" $((SECONDS - s0))
# The same steps before the fault as on one process.
python3 - <<'PY' || fail=1
import csv
a = list(csv.DictReader(open("serial/steps.csv")))
b = list(csv.DictReader(open("all_ranks/steps.csv")))
ok = len(a) == len(b) >= 2 and all(abs(float(x["t"]) - float(y["t"])) <= 1e-12 for x, y in zip(a, b))
print(f"  {'ok  ' if ok else 'FAIL'}  the steps before the fault: {len(a)} on one process, {len(b)} on 2 ranks, same loads")
raise SystemExit(0 if ok else 1)
PY

# A .geo section on a distributed mesh: gmsh runs on rank 0 alone. A stand-in
# 'gmsh' that counts its calls and runs the real one.
mkdir -p bin && cat > bin/gmsh <<SH
#!/bin/sh
echo called >> "$PWD/gmsh_calls"
exec $(command -v gmsh) "\$@"
SH
chmod +x bin/gmsh
cat > channel.prm <<PRM
subsection Cross-section
  set Shape = gmsh
  set Mesh file = $here/../parameter_files/rod_cross_section/geometry/channel.geo
  set Gmsh program = $PWD/bin/gmsh
  set Global refinements = 0
end
subsection Finite element
  set Distributed = true
end
subsection Output
  set Output directory = channel
end
subsection Postprocess
  set List of postprocessors = steps table
end
PRM
sed -e 's/set Distributed = true/set Distributed = false/' -e 's/= channel$/= channel_serial/' channel.prm > channel_serial.prm
rm -f gmsh_calls
timeout 300 "$section" --quiet channel_serial.prm > channel_serial.txt 2>&1
serial_calls=$(cat gmsh_calls 2>/dev/null | wc -l)
rm -f gmsh_calls
# (Debian's gmsh 4.8.4 crashes in Mesh.Algorithm 8 and is run again with 6:
# one process may run it twice; 2 ranks must not run it more often.)
if timeout 300 mpirun -np 2 "$section" --quiet channel.prm > channel.txt 2>&1 &&
   [ "$serial_calls" -ge 1 ] && [ "$(cat gmsh_calls | wc -l)" -eq "$serial_calls" ]; then
  ok "a .geo on a distributed mesh: gmsh ran $serial_calls time(s) for 2 ranks, as for one process; the run converged"
else
  bad "a .geo on a distributed mesh: gmsh ran $(cat gmsh_calls 2>/dev/null | wc -l) times on 2 ranks, $serial_calls on one process"; tail -5 channel.txt
fi
exit $fail

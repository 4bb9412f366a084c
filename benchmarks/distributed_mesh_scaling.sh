#!/usr/bin/env bash
# Strong scaling of the plate on a distributed mesh ('Mesh / Distributed',
# doc/parallel-runs.md "Distributed meshes"), beside the single-process path
# and the one-path mode (rank 0 assembles, the ranks share its large
# factorizations), run side by side on this machine: the dome of
# parameter_files/plate_rod/dome.prm (the quarter disc) to its first event
# ('Stop at first event') at REF global refinements (5: 74 886 DoFs).
# Per configuration: whole-process wall seconds (median of REPEATS paired
# runs), the phases of summary.json (factorizations with their calls,
# solves, assembly), the largest peak resident memory of a rank
# (/usr/bin/time %M: of the largest process of the tree) and MUMPS's memory
# of the largest factorization (INFOG(21), INFOG(22): the rank that used
# most, all ranks).
#
# usage: benchmarks/distributed_mesh_scaling.sh [build dir = build] [REF = 5] [repeats = 3]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") REF=${2:-5} R=${3:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
base() {
  sed -e "s|^\( *set Global refinements *=\).*|\1 $REF\n  set Distributed = $2|" \
      -e "s|^\( *set Event tolerance *=.*\)|\1\n  set Stop at first event = true|" \
      -e "s|^\( *set Output directory *=\).*|\1 $dir/$1|" "$REPO/parameter_files/plate_rod/dome.prm" > "$dir/$1.prm"
}
# name: ranks, distributed
configs="serial:1:false shared-factorization:2:false distributed-1:1:true distributed-2:2:true"
for c in $configs; do IFS=: read -r name ranks dist <<< "$c"; base "$name" "$dist"; done
for k in $(seq 1 "$R"); do
  for c in $configs; do
    IFS=: read -r name ranks dist <<< "$c"
    launch=(); [ "$ranks" -gt 1 ] && launch=(mpirun -np "$ranks")
    t0=$(date +%s.%N)
    /usr/bin/time -f "%M" -o "$dir/$name.mem" "${launch[@]}" "$build/plate_rod" --quiet "$dir/$name.prm" > "$dir/$name.txt" 2>&1 ||
      { cat "$dir/$name.txt"; exit 1; }
    t1=$(date +%s.%N)
    /usr/bin/python3 - "$dir/$name/summary.json" "$name" "$ranks" "$(echo "$t1 - $t0" | bc -l)" "$(tail -1 "$dir/$name.mem")" <<'PY' >> "$dir/rows.txt"
import json, sys
j = json.load(open(sys.argv[1])); t = j["timings"]
def ph(k):
    return t[k]["seconds"] if k in t else 0.0
f = j.get("factorization_memory", {})
print(sys.argv[2], sys.argv[3], sys.argv[4], ph("factorization"), t.get("factorization", {}).get("calls", 0),
      ph("solve") + ph("stability (smallest eigenvalue)"), ph("assembly (Jacobian)") + ph("assembly (residual)"),
      j["dofs"], int(sys.argv[5]) / 1024, f.get("mb_per_rank", 0), f.get("mb_all_ranks", 0), repr(j["events"][0]["t"]))
PY
  done
done
/usr/bin/python3 - "$dir/rows.txt" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print("| configuration | ranks | DoFs | whole process [s] | factorizations [s] (calls) | solves [s] | assembly [s] | peak memory of a rank [MB] | factorization MB: a rank / all | event t |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
med = {}
for name in dict.fromkeys(r[0] for r in rows):
    sel = [r for r in rows if r[0] == name]
    m = lambda i: statistics.median(float(r[i]) for r in sel)
    med[name] = m(2)
    print(f"| {name} | {sel[0][1]} | {sel[0][7]} | {m(2):.2f} | {m(3):.2f} ({sel[0][4]}) | {m(5):.2f} | {m(6):.2f} | {m(8):.0f} | {m(9):.0f} / {m(10):.0f} | {sel[0][11]} |")
s = med["serial"]
print("whole process against one process on a serial mesh: " +
      ", ".join(f"{n} {s / v:.2f}x" for n, v in med.items() if n != "serial"))
PY

#!/usr/bin/env bash
# Strong scaling on a distributed mesh ('Distributed = true',
# doc/parallel-runs.md "Distributed meshes"), beside the single-process path
# and the one-path mode (rank 0 assembles, the ranks share its large
# factorizations), run side by side on this machine:
#  - plate: the dome of parameter_files/plate_rod/dome.prm (the quarter
#    disc) to its first event ('Stop at first event') at REF global
#    refinements (5: 74 886 DoFs);
#  - section: the natural shape of benchmarks/growing_disc.prm at REF_DISC
#    refinements (6: 246 531 field DoFs), all without the coarse-mesh start
#    (which a distributed mesh does not have), plus one process with it
#    (the default).
# Per configuration: whole-process wall seconds (median of REPEATS paired
# runs), the phases of summary.json (factorizations with their calls,
# solves, assembly), the largest peak resident memory of a rank
# (/usr/bin/time %M: of the largest process of the tree) and MUMPS's memory
# of the largest factorization (INFOG(21), INFOG(22): the rank that used
# most, all ranks).
#
# usage: benchmarks/distributed_mesh_scaling.sh [build dir = build] [REF = 5] [repeats = 3] [REF_DISC = 0: no section]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") REF=${2:-5} R=${3:-3} RD=${4:-0}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
base() {
  sed -e "s|^\( *set Global refinements *=\).*|\1 $REF\n  set Distributed = $2|" \
      -e "s|^\( *set Event tolerance *=.*\)|\1\n  set Stop at first event = true|" \
      -e "s|^\( *set Output directory *=\).*|\1 $dir/$1|" "$REPO/parameter_files/plate_rod/dome.prm" > "$dir/$1.prm"
}
section() { # name, distributed, coarse-mesh start
  sed -e "s|^\( *set Global refinements *=\).*|\1 $RD|" -e "s|^\( *set Output directory *=\).*|\1 $dir/$1|" \
      "$REPO/benchmarks/growing_disc.prm" > "$dir/$1.prm"
  printf 'subsection Finite element\n  set Distributed = %s\nend\nsubsection Nonlinear solver\n  set Coarse-mesh start = %s\nend\n' "$2" "$3" >> "$dir/$1.prm"
}
# name: application, ranks, distributed
configs="serial:plate_rod:1:false shared-factorization:plate_rod:2:false distributed-1:plate_rod:1:true distributed-2:plate_rod:2:true"
for c in $configs; do IFS=: read -r name app ranks dist <<< "$c"; base "$name" "$dist"; done
if [ "$RD" -gt 0 ]; then
  configs="$configs section-serial-coarse-start:rod_cross_section:1:false section-serial:rod_cross_section:1:false"
  configs="$configs section-shared-factorization:rod_cross_section:2:false section-distributed-1:rod_cross_section:1:true"
  configs="$configs section-distributed-2:rod_cross_section:2:true"
  section section-serial-coarse-start false 2
  for c in section-serial:false section-shared-factorization:false section-distributed-1:true section-distributed-2:true; do
    section "${c%:*}" "${c#*:}" 0
  done
fi
for k in $(seq 1 "$R"); do
  for c in $configs; do
    IFS=: read -r name app ranks dist <<< "$c"
    launch=(); [ "$ranks" -gt 1 ] && launch=(mpirun -np "$ranks")
    t0=$(date +%s.%N)
    /usr/bin/time -f "%M" -o "$dir/$name.mem" "${launch[@]}" "$build/$app" --quiet "$dir/$name.prm" > "$dir/$name.txt" 2>&1 ||
      { cat "$dir/$name.txt"; exit 1; }
    t1=$(date +%s.%N)
    /usr/bin/python3 - "$dir/$name/summary.json" "$name" "$ranks" "$(echo "$t1 - $t0" | bc -l)" "$(tail -1 "$dir/$name.mem")" <<'PY' >> "$dir/rows.txt"
import json, sys
j = json.load(open(sys.argv[1])); t = j["timings"]
def ph(k):
    return t[k]["seconds"] if k in t else 0.0
f = j.get("factorization_memory", {})
dofs = j.get("dofs") or j["mesh"]["field_dofs"]
result = repr(j["events"][0]["t"]) if j.get("events") else "kappa2=" + repr(j["strains"]["kappa2"])
print(sys.argv[2], sys.argv[3], sys.argv[4], ph("factorization"), t.get("factorization", {}).get("calls", 0),
      ph("solve") + ph("stability (smallest eigenvalue)"), ph("assembly (Jacobian)") + ph("assembly (residual)"),
      dofs, int(sys.argv[5]) / 1024, f.get("mb_per_rank", 0), f.get("mb_all_ranks", 0), result)
PY
  done
done
/usr/bin/python3 - "$dir/rows.txt" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print("| configuration | ranks | DoFs | whole process [s] | factorizations [s] (calls) | solves [s] | assembly [s] | peak memory of a rank [MB] | factorization MB: a rank / all | event t or kappa2 |")
print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---|")
med = {}
for name in dict.fromkeys(r[0] for r in rows):
    sel = [r for r in rows if r[0] == name]
    m = lambda i: statistics.median(float(r[i]) for r in sel)
    med[name] = m(2)
    print(f"| {name} | {sel[0][1]} | {sel[0][7]} | {m(2):.2f} | {m(3):.2f} ({sel[0][4]}) | {m(5):.2f} | {m(6):.2f} | {m(8):.0f} | {m(9):.0f} / {m(10):.0f} | {sel[0][11]} |")
for prefix in ("", "section-"):
    if prefix + "serial" not in med:
        continue
    s = med[prefix + "serial"]
    print(f"{prefix or 'plate-'}whole process against one process on a serial mesh: " +
          ", ".join(f"{n} {s / v:.2f}x" for n, v in med.items() if n != prefix + "serial" and n.startswith(prefix) and (prefix or not n.startswith("section-"))))
PY

#!/usr/bin/env bash
# One path on one process against the same path under `mpirun -np 2`, where
# rank 1 takes part in rank 0's MUMPS factorizations and solves
# (solvers::factorization_ranks, doc/parallel-runs.md "One path on several
# ranks"): whole-process wall seconds (median of REPEATS, paired runs) and
# the phases of summary.json.
#
#  - plate: parameter_files/plate_rod/dome.prm to its first event ('Stop at
#    first event'), the quarter disc at REF_PLATE global refinements
#    (5: 74 886 DoFs);
#  - disc: the natural shape of benchmarks/growing_disc.prm at
#    REF_DISC refinements (6: 246 543 DoFs).
#
# usage: benchmarks/one_path_ranks.sh [build dir = build] [REF_PLATE = 5] [REF_DISC = 6] [repeats = 3]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") RP=${2:-5} RD=${3:-6} R=${4:-3}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
sed -e "s|^\( *set Global refinements *=\).*|\1 $RP|" \
    -e "s|^\( *set Event tolerance *=.*\)|\1\n  set Stop at first event = true|" \
    -e "s|^\( *set Output directory *=\).*|\1 OUT|" "$REPO/parameter_files/plate_rod/dome.prm" > "$dir/plate.prm"
sed -e "s|^\( *set Global refinements *=\).*|\1 $RD|" -e "s|^\( *set Output directory *=\).*|\1 OUT|" \
    "$REPO/benchmarks/growing_disc.prm" > "$dir/disc.prm"
for case in plate:plate_rod disc:rod_cross_section; do
  name=${case%:*} exe=$build/${case#*:}
  for ranks in 1 2; do sed "s|OUT|$dir/$name-$ranks|" "$dir/$name.prm" > "$dir/$name-$ranks.prm"; done
  for k in $(seq 1 "$R"); do
    for ranks in 1 2; do
      launch=(); [ "$ranks" -gt 1 ] && launch=(mpirun -np "$ranks")
      t0=$(date +%s.%N)
      "${launch[@]}" "$exe" --quiet "$dir/$name-$ranks.prm" > "$dir/$name-$ranks.txt" 2>&1 ||
        { cat "$dir/$name-$ranks.txt"; exit 1; }
      t1=$(date +%s.%N)
      /usr/bin/python3 - "$dir/$name-$ranks/summary.json" "$name" "$ranks" "$(echo "$t1 - $t0" | bc -l)" <<'PY' >> "$dir/rows.txt"
import json, sys
j = json.load(open(sys.argv[1])); t = j["timings"]
def ph(k):
    return t[k]["seconds"] if k in t else 0.0
dofs = j.get("dofs") or j.get("mesh", {}).get("field_dofs", "")
print(sys.argv[2], sys.argv[3], sys.argv[4], ph("factorization"), t.get("factorization", {}).get("calls", 0),
      ph("solve") + ph("stability (smallest eigenvalue)"), ph("assembly (Jacobian)") + ph("assembly (residual)"),
      j.get("mumps_phases_on_all_ranks", 0), dofs)
PY
    done
  done
done
/usr/bin/python3 - "$dir/rows.txt" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1])]
print("| run | ranks | DoFs | whole process [s] | factorizations [s] (calls) | solves [s] | assembly [s] | MUMPS phases on both ranks |")
print("|---|---:|---:|---:|---:|---:|---:|---:|")
med = {}
for name in dict.fromkeys(r[0] for r in rows):
    for ranks in ("1", "2"):
        sel = [r for r in rows if r[0] == name and r[1] == ranks]
        m = lambda i: statistics.median(float(r[i]) for r in sel)
        med[name, ranks] = (m(2), m(3))
        print(f"| {name} | {ranks} | {sel[0][8]} | {m(2):.2f} | {m(3):.2f} ({sel[0][4]}) | {m(5):.2f} | {m(6):.2f} | {sel[0][7]} |")
    w1, f1 = med[name, "1"]; w2, f2 = med[name, "2"]
    print(f"| {name}: 2 ranks against 1 | | | {w1 / w2:.2f}x | {f1 / f2:.2f}x | | | |")
PY

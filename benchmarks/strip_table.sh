#!/usr/bin/env bash
# Part 2's target of the performance issue, side by side in one run: the
# 40 x 40 constitutive table of (kappa1, kappa3) over [0, 2] x [0, 0.8] at
# zero axial force (nu3 free), strip w = 1, h = 0.02, 20 graded cells, Q2
# (205 field DoFs), 1600 points, on one process with all cores:
#   - as the issue was filed: nested AD of the energy in all 16 local
#     variables, Newton's first Jacobian refactorized, KINSOL's J p by a
#     difference quotient (COSMO_NESTED_AD=1 COSMO_NO_REUSE=1 COSMO_DQ_JP=1);
#   - with the factorization reused (COSMO_NESTED_AD=1 COSMO_DQ_JP=1);
#   - now: the energy's Hessian by the chain rule through the plate measures,
#     and J p from the solve (no residual for it).
# Prints, per variant, the whole-process wall seconds (median of REPEATS),
# the phases of summary.json (median run) and the ratio against the first;
# and the largest difference of the tables, per column, in units of the
# column's scale (round-off: each variant solves the same Newton problems).
#
# usage: benchmarks/strip_table.sh [build dir = build] [repeats = 3] [scratch]
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(realpath "${1:-$REPO/build}") R=${2:-3}
dir=$(realpath -m "${3:-/tmp/cosmo_strip_table}")
rm -rf "$dir" && mkdir -p "$dir"
prm() { # output directory
  cat <<EOF
subsection Strip
  set Width           = 1
  set Thickness       = 0.02
  set Number of cells = 20
end
subsection Rod strains
  set Mode         = prescribed strains
  set Free strains = nu3
end
subsection Constitutive table
  set Enabled       = true
  set First strain  = kappa1
  set First range   = 0, 2, 40
  set Second strain = kappa3
  set Second range  = 0, 0.8, 40
end
subsection Output
  set Output directory = $1
end
EOF
}
echo "40 x 40 strip table, 205 field DoFs, $(nproc) cores, $R runs each (median)"
for variant in filed reuse now; do
  case $variant in
    filed) env="COSMO_NESTED_AD=1 COSMO_NO_REUSE=1 COSMO_DQ_JP=1" ;;
    reuse) env="COSMO_NESTED_AD=1 COSMO_DQ_JP=1" ;;
    now)   env="" ;;
  esac
  prm "$dir/$variant" > "$dir/$variant.prm"
  for r in $(seq 1 "$R"); do
    rm -rf "$dir/$variant"
    t0=$(date +%s.%N)
    env $env "$build/strip" --quiet "$dir/$variant.prm" > "$dir/$variant.txt" 2>&1 ||
      { echo "failed: $variant" >&2; cat "$dir/$variant.txt" >&2; exit 1; }
    t=$(python3 -c "import time; print(time.time() - $t0)")
    cp "$dir/$variant/summary.json" "$dir/$variant-$r.json"
    echo "$t $r"
  done | sort -g > "$dir/$variant.times"
  median=$(awk -v n="$R" 'NR == int((n + 1) / 2) {print $2}' "$dir/$variant.times")
  cp "$dir/$variant-$median.json" "$dir/$variant.json"
done
/usr/bin/python3 - "$dir" <<'EOF'
import json, sys
import numpy as np
d = sys.argv[1]
labels = {'filed': 'as filed (nested AD, no reuse)', 'reuse': 'nested AD, factorization reused',
          'now': 'chain rule, reused, J p from the solve'}
walls = {v: sorted(float(l.split()[0]) for l in open(f'{d}/{v}.times')) for v in labels}
wall = {v: w[(len(w) - 1) // 2] for v, w in walls.items()}
print('| variant | wall [s] | Jacobian assembly [s] (calls) | residual assembly [s] (calls) | factorization [s] (calls) | against as filed |')
print('|---|---:|---:|---:|---:|---:|')
for v, label in labels.items():
    t = json.load(open(f'{d}/{v}.json'))['timings']
    cell = lambda k: '%.2f (%d)' % (t[k]['seconds'], t[k]['calls'])
    print(f"| {label} | {wall[v]:.2f} | {cell('assembly (Jacobian)')} | {cell('assembly (residual)')} | "
          f"{cell('factorization')} | {wall['filed'] / wall[v]:.2f}x |")
a = np.genfromtxt(f'{d}/filed/table.csv', delimiter=',', names=True)
b = np.genfromtxt(f'{d}/now/table.csv', delimiter=',', names=True)
# Scales as in tests/compare_tables.py: the energy's largest value, the
# stiffness' largest diagonal entry, the resultants sqrt(2 max K max Psi).
K = max(abs(a[n]).max() for n in a.dtype.names if n.startswith('K_'))
P = abs(a['energy']).max()
scale = {n: (P if n == 'energy' else K if n.startswith('K_') else np.sqrt(2 * K * P)) for n in a.dtype.names}
worst = max((abs(a[n] - b[n]).max() / scale[n], n) for n in a.dtype.names[3:])
print(f"largest difference of the tables (now against as filed): {worst[0]:.1e} of the scale ({worst[1]})")
EOF

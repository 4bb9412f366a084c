#!/usr/bin/env bash
# Part 1 side by side: the natural shape of the growing unit disc (neo-Hookean,
# axial growth 1 + 0.3 X1, all six strains free, kappa2 = -0.3 exactly) by
# rod_cross_section (Q2, MUMPS LDL^T of the bordered system) and by a legacy
# DOLFIN script a user would write instead (benchmarks/natural_shape_dolfin.py:
# P2, UFL's exact tangent, MUMPS). Whole processes, wall time, the median of
# RUNS paired runs after one warm-up of each (DOLFIN's JIT cache); prints the
# ratio and cosmo's split per phase (summary.json).
#   bash benchmarks/natural_shape_vs_dolfin.sh [build dir] [refinements] [dolfin rings] [runs] [growth] [coarse levels] [peer]
# Defaults: build, 5 (61 839 DoFs), 40 (about 61 600 DoFs), 3, "1 + 0.3*x", 2, shape.
# peer: "shape", the natural shape alone (the script as the issue filed it),
# or "stiffness", the natural shape and the 6x6 stiffness there, which cosmo
# reports too (one more assembly and factorization in both); then the two
# stiffnesses are compared.
# growth: the axial growth factor in x, y (muparser; given to DOLFIN with x, y
# -> X[0], X[1] and ^ -> **, letter by letter: no function names such as exp
# that contain an x or a y). The default's natural state, u = 0, lies in both
# FE spaces, so cosmo's coarse-mesh start (Nonlinear solver / Coarse-mesh
# start, 0 to switch it off) leaves nothing to do on the full mesh; with
# "1 + 0.3*x + 0.3*y^2" the full mesh needs two Newton iterations.
# Installs python3-dolfin if missing (as scripts/setup.sh installs packages).
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(realpath "${1:-$REPO/build}")" REF="${2:-5}" RINGS="${3:-40}" RUNS="${4:-3}"
GROWTH="${5:-1 + 0.3*x}" LEVELS="${6:-2}" PEER="${7:-shape}"
PYGROWTH="$(echo "$GROWTH" | sed -e 's/x/X[0]/g' -e 's/y/X[1]/g' -e 's/\^/**/g')"
source "$REPO/benchmarks/dolfin_peer.sh" && ensure_dolfin
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
sed -e "s|^\( *set Global refinements *=\).*|\1 $REF|" -e "s|^\( *set Output directory *=\).*|\1 $work/cosmo|" \
    -e "s|^\( *set Growth factor *=\).*|\1 $GROWTH|" \
    "$REPO/benchmarks/growing_disc.prm" > "$work/disc.prm"
printf 'subsection Nonlinear solver\n  set Coarse-mesh start = %s\nend\n' "$LEVELS" >> "$work/disc.prm"
now() { date +%s.%N; }
cosmo_times=() dolfin_times=()
"$BUILD/rod_cross_section" --quiet "$work/disc.prm"
(cd "$work" && /usr/bin/python3 "$REPO/benchmarks/natural_shape_dolfin.py" "$RINGS" "$PYGROWTH" "$PEER" >/dev/null 2>&1)
for ((k = 0; k < RUNS; ++k)); do
  a=$(now); "$BUILD/rod_cross_section" --quiet "$work/disc.prm"; b=$(now)
  cosmo_times+=("$(echo "$b - $a" | bc -l)")
  a=$(now); (cd "$work" && /usr/bin/python3 "$REPO/benchmarks/natural_shape_dolfin.py" "$RINGS" "$PYGROWTH" "$PEER" > "$work/dolfin.txt" 2>/dev/null); b=$(now)
  dolfin_times+=("$(echo "$b - $a" | bc -l)")
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
mc=$(median "${cosmo_times[@]}") md=$(median "${dolfin_times[@]}")
/usr/bin/python3 - "$work/cosmo/summary.json" "$mc" "$md" "$work/dolfin.txt" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
t = s["timings"]
mc, md = float(sys.argv[2]), float(sys.argv[3])
dolfin = open(sys.argv[4]).read().strip().splitlines()
print(dolfin[0])
for line in dolfin[1:]:
    if line.startswith("dolfin stiffness"):
        Kd = [float(v) for v in line.split(":")[1].split()]
        Kc = [v for row in s["stiffness"] for v in row]
        scale = max(abs(v) for v in Kc)
        print("  6x6 stiffness, cosmo (Q2) against dolfin (P2): max difference %.2e of the largest entry %.4g"
              % (max(abs(a - b) for a, b in zip(Kc, Kd)) / scale, scale))
print("cosmo:  %d DoFs (with 12 global), Newton %s, kappa2 %.12g (error against -0.3 %.2e)" %
      (s["mesh"]["field_dofs"] + 12, s.get("newton_iterations"), s["strains"]["kappa2"],
       abs(s["strains"]["kappa2"] + 0.3)))
if "coarse-mesh start" in t:
    print("  %-22s %.2f s (Newton on the coarser meshes, whole)" % ("coarse-mesh start", t["coarse-mesh start"]["seconds"]))
for phase in ("assembly (residual)", "assembly (Jacobian)", "factorization", "solve"):
    if phase in t:
        c = t[phase]
        print("  %-22s %3d x %.3f s = %.2f s" % (phase, c["calls"], c["seconds"] / c["calls"], c["seconds"]))
jac, fac = t["assembly (Jacobian)"], t["factorization"]
jf = jac["seconds"] / jac["calls"] + fac["seconds"] / fac["calls"]
print("  one Jacobian + factorization: %.3f s" % jf)
# A Newton iteration on the full mesh: its Jacobian and factorization, and
# every residual and solve of the process (the stiffness's Jacobian and
# factorization at the natural state, the last call of each, are not one).
it = s.get("newton_iterations") or 0
if it > 0:
    rest = sum(t[p]["seconds"] for p in ("assembly (residual)", "solve") if p in t)
    per = jf + rest / it
    print("  per factorized Newton iteration on the full mesh (%d; the chord steps' residuals and"
          " solves in it): %.3f s = %.2fx (Jacobian + factorization)" % (it, per, per / jf))
print("  the rest of the process (start-up, mesh, section properties, output): %.2f s"
      % (mc - sum(t[p]["seconds"] for p in ("assembly (residual)", "assembly (Jacobian)", "factorization", "solve",
                                              "coarse-mesh start") if p in t)))
print("whole process, median of paired runs: cosmo %.2f s, dolfin %.2f s: cosmo %.2fx faster" % (mc, md, md / mc))
PY

#!/usr/bin/env bash
# Part 3 side by side: the critical growth of the dome (h/R = 0.01, E = 1,
# Poisson 0.3, isotropic plate growth 0.1 % at t = 1; the rim a rod of
# circular section a = 0.02 R of the plate's material, not growing, welded
# to the edge) on the quarter disc with mirror edges, by plate_rod
# (Kirchhoff model, Q2, arclength continuation with the Hessian's inertia,
# 'Stop at first event', the threshold located by Newton on the augmented
# system) and by a legacy-DOLFIN linear buckling analysis a user would write
# instead (benchmarks/plate_buckling_dolfin.py: plane-stress prestress with
# the rim's hoop stiffness, Kirchhoff plate in P3 with C0 interior penalty
# plus the rim's bending and torsion, SLEPc with MUMPS).
#
# For each code and each resolution of its ladder: the DoFs, the whole-process
# wall time (median of RUNS paired runs, Python start-up included, after one
# untimed run of each: file cache, DOLFIN's JIT cache), the computing time
# beyond start-up (cosmo: wall minus the median wall time of 'plate_rod
# --version', which loads the same libraries and initializes MPI; DOLFIN:
# the script's own clock after its imports) and the critical t, with its
# error against the code's own converged value. cosmo: the Richardson
# extrapolation of its two finest runs with order 4 (Q2 eigenvalues converge
# like h^4; the observed ratios are printed). The peer: the continuum limit
# of its linear problem is the Kirchhoff closed form of sections 1-2 of
# doc/theory-plate-rod.md (uniform Lame prestress, axisymmetric mode, rim
# rolling against EI1), which cosmo prints: its error is measured against
# that, and its own Richardson extrapolation is printed beside it (P3 C0-IP
# also converges like h^4; from N ~ 16 on its round-off, ~N^4, reaches
# 1e-7, printed per run as the Rayleigh quotient's departure from t_cr).
# Then, for the tolerances 1e-3 ... 1e-7, the cheapest run of each code
# within it and the ratio of the times. The two converged values differ by
# the linearization (cosmo's threshold is that of the finite-strain model,
# the peer's the small-strain initial-stress one, section 4 of
# doc/theory-plate-rod.md): printed.
#
#   bash benchmarks/plate_buckling_vs_dolfin.sh [build dir] [cosmo refinements] [dolfin N] [runs] [degree] [cosmo reference]
# Defaults: build, "1 2 3 4 5" (366 ... 74 886 DoFs), "2 3 4 6 8 12 16"
# (6 N^2 triangles per quarter), 3, 2 (cosmo's 'Polynomial degree'), and
# cosmo's reference from its own two finest runs. With degree 3 or 4 the
# finest runs are at their round-off resolution (~1e-7) before the
# extrapolation means anything: give the reference then, e.g. the degree-2
# ladder's 0.5534116363 (every degree converges to the same threshold).
# Installs python3-dolfin if missing (as scripts/setup.sh installs packages).
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(realpath "${1:-$REPO/build}")" LEVELS="${2:-1 2 3 4 5}" RINGS="${3:-2 3 4 6 8 12 16}" RUNS="${4:-3}"
DEGREE="${5:-2}" CREF="${6:-}"
source "$REPO/benchmarks/dolfin_peer.sh" && ensure_dolfin
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# the rim: GA = (6/7) G pi a^2 (the circle's shear coefficient,
# doc/theory-rod-cross-section.md 6.1; the Kirchhoff model multiplies it by
# its penalty), EA = E pi a^2, EI1 = EI2 = E pi a^4/4, GJ = G pi a^4/2,
# G = E/(2 (1 + v)), a = 0.02
cat > "$work/dome.prm" <<'EOF'
subsection Plate
  set Radius    = 1
  set Thickness = 0.01
end
subsection Plate material
  set Young's modulus = 1
  set Poisson's ratio = 0.3
end
subsection Plate growth
  set Kind                 = isotropic
  set Radial growth factor = 1.001
end
subsection Rim rod
  # GA1, GA2, EA, EI1, EI2, GJ
  set Stiffnesses   = 4.1427595431953315e-4, 4.1427595431953315e-4, 1.2566370614359175e-3, 1.2566370614359172e-7, 1.2566370614359172e-7, 9.66643893412244e-8
  set Growth factor = 1
end
subsection Model
  set Model = kirchhoff
end
subsection Mesh
  set Domain             = sector
  set Sector angle       = 90
  set Global refinements = 3
end
subsection Growth path
  set Stop at first event = true
end
subsection Arclength continuation
  set Initial step    = 0.02
  set Maximum step    = 0.1
  set Parameter range = 0, 1
  set Event tolerance = 1e-7
end
subsection Output
  set Output directory = out
end
EOF
for r in $LEVELS; do
  sed -e "s|^\( *set Global refinements *=\).*|\1 $r\n  set Polynomial degree = $DEGREE|" -e "s|^\( *set Output directory *=\).*|\1 $work/cosmo-$r|" \
      "$work/dome.prm" > "$work/cosmo-$r.prm"
done
now() { date +%s.%N; }
elapsed() { echo "$2 - $1" | bc -l; }
peer() { (cd "$work" && /usr/bin/python3 "$REPO/benchmarks/plate_buckling_dolfin.py" "$1" 2>/dev/null | grep "^dolfin result:"); }
uptime | sed 's/^/load before: /'
# untimed: file cache, DOLFIN's JIT cache
"$BUILD/plate_rod" --version >/dev/null
"$BUILD/plate_rod" --quiet "$work/cosmo-${LEVELS%% *}.prm"
for n in $RINGS; do peer "$n" >/dev/null; done
: > "$work/times.txt"
for ((k = 0; k < RUNS; ++k)); do
  a=$(now); "$BUILD/plate_rod" --version >/dev/null; b=$(now)
  echo "startup cosmo $(elapsed "$a" "$b")" >> "$work/times.txt"
  set -- $RINGS
  for r in $LEVELS; do
    a=$(now); "$BUILD/plate_rod" --quiet "$work/cosmo-$r.prm"; b=$(now)
    echo "cosmo $r $(elapsed "$a" "$b")" >> "$work/times.txt"
    if [[ $# -gt 0 ]]; then  # pair the runs: one of each code in turn
      a=$(now); line=$(peer "$1"); b=$(now)
      echo "dolfin $1 $(elapsed "$a" "$b") $line" >> "$work/times.txt"
      shift
    fi
  done
  for n in "$@"; do
    a=$(now); line=$(peer "$n"); b=$(now)
    echo "dolfin $n $(elapsed "$a" "$b") $line" >> "$work/times.txt"
  done
done
uptime | sed 's/^/load after:  /'
/usr/bin/python3 - "$work" "$LEVELS" "$RINGS" "$CREF" <<'PY'
import json, statistics, sys
from math import inf
work, levels, rings = sys.argv[1], sys.argv[2].split(), sys.argv[3].split()
lines = [l.split() for l in open(work + "/times.txt")]
startup = statistics.median(float(l[2]) for l in lines if l[0] == "startup")
runs = {"cosmo": {}, "dolfin": {}}
for l in lines:
    if l[0] == "cosmo":
        s = json.load(open("%s/cosmo-%s/summary.json" % (work, l[1])))
        e = s["events"][0]
        r = runs["cosmo"].setdefault(l[1], {"wall": [], "compute": [], "dofs": str(s["dofs"]), "t": e["t"],
                                            "mode": "n = %d %s" % (e["mode_number"], e["mode_type"]),
                                            "resolution": e["location"]["resolution"]})
        r["wall"].append(float(l[2]))
        r["compute"].append(float(l[2]) - startup)
        closed = s["closed_form"]["axisymmetric"]["t"]
    elif l[0] == "dolfin":
        v = l[5:]  # dolfin result: P2 DoFs, P3 DoFs, t_cr, mode n, computing seconds, round-off
        r = runs["dolfin"].setdefault(l[1], {"wall": [], "compute": [], "dofs": "%s + %s" % (v[0], v[1]),
                                             "t": float(v[2]), "mode": "n = %s, round-off %s" % (v[3], v[5])})
        r["wall"].append(float(l[2]))
        r["compute"].append(float(v[4]))
ref, rich = {}, {}
for code, ladder, ratio in (("cosmo", levels, lambda a, b: 2.0 ** (int(b) - int(a))),
                            ("dolfin", rings, lambda a, b: int(b) / int(a))):
    (c, f), q = ladder[-2:], ratio(*ladder[-2:])
    tc, tf = runs[code][c]["t"], runs[code][f]["t"]
    rich[code] = tf + (tf - tc) / (q ** 4 - 1)
    print("%s: Richardson (order 4, from %s and %s) t = %.10f" % (code, c, f, rich[code]))
    d = [runs[code][ladder[i]]["t"] - runs[code][ladder[i + 1]]["t"] for i in range(len(ladder) - 1)]
    print("  successive differences: " + " ".join("%.2e" % x for x in d))
    print("  their ratios: " + " ".join("%.1f" % (d[i] / d[i + 1]) if d[i + 1] else "-" for i in range(len(d) - 1)))
ref["cosmo"], ref["dolfin"] = rich["cosmo"], closed
if sys.argv[4]:
    ref["cosmo"] = float(sys.argv[4])
    print("cosmo's reference given: t = %.10f" % ref["cosmo"])
print("Kirchhoff closed form (small strain, sections 1-2): t = %.10f (dolfin's Richardson - 1 = %.1e)"
      % (closed, rich["dolfin"] / closed - 1))
print("converged values: cosmo %.10f (Richardson), dolfin %.10f (closed form): cosmo / dolfin - 1 = %.3e"
      % (ref["cosmo"], ref["dolfin"], ref["cosmo"] / ref["dolfin"] - 1))
print()
print("%-7s %-6s %-15s %-10s %-10s %-16s %-10s %s" % ("code", "level", "DoFs", "wall [s]", "compute", "t_cr",
                                                    "error", "mode"))
table = {}
for code, ladder in (("cosmo", levels), ("dolfin", rings)):
    for lv in ladder:
        r = runs[code][lv]
        wall, comp = statistics.median(r["wall"]), statistics.median(r["compute"])
        err = abs(r["t"] / ref[code] - 1)
        table.setdefault(code, []).append((wall, comp, err, lv, r["dofs"]))
        print("%-7s %-6s %-15s %-10.2f %-10.2f %-16.12f %-10.1e %s" % (code, lv, r["dofs"], wall, comp, r["t"], err,
                                                                     r["mode"]))
print("(cosmo: level = global refinements; dolfin: N, 6 N^2 triangles; wall: whole process, median of %d; "
      "compute: beyond start-up, cosmo's start-up %.2f s; error against the code's own converged value;\n"
      " dolfin's round-off: |Rayleigh quotient of the mode / t_cr - 1|)"
      % (len(runs["cosmo"][levels[0]]["wall"]), startup))
print()
print("%-9s %-28s %-28s %s" % ("tolerance", "cosmo: level, wall (compute)", "dolfin: level, wall (compute)",
                               "time ratio cosmo/dolfin: wall (compute)"))
for tol in (1e-3, 1e-4, 1e-5, 1e-6, 1e-7):
    best = {}
    for code in table:
        ok = [x for x in table[code] if x[2] <= tol]
        best[code] = min(ok) if ok else None
    cells = []
    for code in ("cosmo", "dolfin"):
        b = best[code]
        cells.append("%s, %.2f s (%.2f s)" % (b[3], b[0], b[1]) if b else "not reached")
    ratio = ("%.2f (%.2f)" % (best["cosmo"][0] / best["dolfin"][0], best["cosmo"][1] / best["dolfin"][1])
             if best["cosmo"] and best["dolfin"] else "-")
    print("%-9.0e %-28s %-28s %s" % (tol, cells[0], cells[1], ratio))
print("(cosmo's error at its finest two runs is that of its Richardson extrapolation itself: a tolerance only "
      "they reach\n is not resolved by the ladder)")
PY

#!/usr/bin/env bash
# Part 2 side by side: the width-wise twist-buckling threshold of a strip
# (w = 1, h/w = 0.01 by default, E = 1, Poisson 0.3, nu3 free: zero axial
# force; doc/theory-strip.md 7) by `strip` (P2 on the graded width mesh,
# arclength continuation in the twist with the Hessian's inertia, 'Stop at
# first event', Newton on the augmented system) and by a legacy-DOLFIN script
# a user would write instead (benchmarks/strip_buckling_dolfin.py: the same
# model and discretization, Newton on the flat branch at twists 0.05 apart,
# SLEPc shift-and-invert for the constrained Hessian's lowest eigenvalue,
# Brent on it).
#
# Both codes discretize alike (P2 on the same vertices, the same quadrature),
# so at each number of cells they locate the same threshold, to round-off;
# the script prints their difference. The error of a run is against the
# Richardson limit (order 4) of the two finest runs of cosmo's ladder.
# Whole-process wall time: the median of RUNS paired runs (one of each code
# in turn) after one untimed run of each (file cache, DOLFIN's JIT cache);
# beyond start-up: cosmo's wall minus the median of 'strip --version',
# DOLFIN's own clock after its imports. Then, for the tolerances 1e-3 ...
# 1e-7, the cheapest run of each code within it and the ratio of the times.
#
#   bash benchmarks/strip_buckling_vs_dolfin.sh [build dir] [cells ladder] [runs] [thickness]
# Defaults: build, "10 20 30 45 60 90 135", 3, 0.01.
# Installs python3-dolfin if missing (as scripts/setup.sh installs packages).
set -euo pipefail
REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(realpath "${1:-$REPO/build}")" LADDER="${2:-10 20 30 45 60 90 135}" RUNS="${3:-3}" H="${4:-0.01}"
source "$REPO/benchmarks/dolfin_peer.sh" && ensure_dolfin
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for n in $LADDER; do
  cat > "$work/cosmo-$n.prm" <<EOF
subsection Strip
  set Width           = 1
  set Thickness       = $H
  set Number of cells = $n
end
subsection Rod strains
  set Mode         = prescribed strains
  set Strains      = 0, 0, 1, 0, 0, 1
  set Free strains = nu3
end
subsection Nonlinear solver
  set Relative tolerance = 1e-12
end
subsection Path following
  set Method = arclength
end
subsection Arclength continuation
  set Parameter range     = 0, 2
  set Initial step        = 0.02
  set Maximum step        = 0.1
  set Stop at first event = true
end
subsection Output
  set Output directory = $work/cosmo-$n
end
EOF
done
now() { date +%s.%N; }
elapsed() { echo "$2 - $1" | bc -l; }
peer() { (cd "$work" && /usr/bin/python3 "$REPO/benchmarks/strip_buckling_dolfin.py" "$1" "$H" 2>/dev/null | grep "^dolfin result:"); }
uptime | sed 's/^/load before: /'
"$BUILD/strip" --version >/dev/null
for n in $LADDER; do "$BUILD/strip" --quiet "$work/cosmo-$n.prm"; peer "$n" >/dev/null; done
: > "$work/times.txt"
for ((k = 0; k < RUNS; ++k)); do
  a=$(now); "$BUILD/strip" --version >/dev/null; b=$(now)
  echo "startup cosmo $(elapsed "$a" "$b")" >> "$work/times.txt"
  for n in $LADDER; do
    a=$(now); "$BUILD/strip" --quiet "$work/cosmo-$n.prm"; b=$(now)
    echo "cosmo $n $(elapsed "$a" "$b")" >> "$work/times.txt"
    a=$(now); line=$(peer "$n"); b=$(now)
    echo "dolfin $n $(elapsed "$a" "$b") $line" >> "$work/times.txt"
  done
done
uptime | sed 's/^/load after:  /'
/usr/bin/python3 - "$work" "$LADDER" <<'PY'
import json, statistics, sys
work, ladder = sys.argv[1], sys.argv[2].split()
lines = [l.split() for l in open(work + "/times.txt")]
startup = statistics.median(float(l[2]) for l in lines if l[0] == "startup")
runs = {"cosmo": {}, "dolfin": {}}
for l in lines:
    if l[0] == "cosmo":
        s = json.load(open("%s/cosmo-%s/summary.json" % (work, l[1])))
        r = runs["cosmo"].setdefault(l[1], {"wall": [], "compute": [], "t": s["events"][0]["t"],
                                            "dofs": str(s["field_dofs"])})
        r["wall"].append(float(l[2]))
        r["compute"].append(float(l[2]) - startup)
    elif l[0] == "dolfin":
        v = l[5:]  # dolfin result: cells, DoFs (the field's and 7 Reals), tau_c, computing seconds
        r = runs["dolfin"].setdefault(l[1], {"wall": [], "compute": [], "t": float(v[2]), "dofs": str(int(v[1]) - 7)})
        r["wall"].append(float(l[2]))
        r["compute"].append(float(v[3]))
c, f = ladder[-2:]
tc, tf = runs["cosmo"][c]["t"], runs["cosmo"][f]["t"]
ref = tf + (tf - tc) / ((int(f) / int(c)) ** 4 - 1)
print("reference: Richardson (order 4) of cosmo's %s and %s cells: tau_c = %.12f" % (c, f, ref))
print("largest |cosmo - dolfin| over the ladder: %.1e" % max(abs(runs["cosmo"][n]["t"] - runs["dolfin"][n]["t"])
                                                           for n in ladder))
print()
print("%-7s %-6s %-6s %-10s %-10s %-16s %s" % ("code", "cells", "field DoFs", "wall [s]", "compute", "tau_c", "error"))
table = {}
for code in ("cosmo", "dolfin"):
    for n in ladder:
        r = runs[code][n]
        wall, comp = statistics.median(r["wall"]), statistics.median(r["compute"])
        err = abs(r["t"] / ref - 1)
        table.setdefault(code, []).append((wall, comp, err, n))
        print("%-7s %-6s %-6s %-10.2f %-10.2f %-16.12f %.1e" % (code, n, r["dofs"], wall, comp, r["t"], err))
print("(wall: whole process, median of %d paired runs; compute: beyond start-up, cosmo's start-up %.2f s)"
      % (len(runs["cosmo"][ladder[0]]["wall"]), startup))
print()
print("%-9s %-24s %-24s %s" % ("tolerance", "cosmo: cells, wall (compute)", "dolfin: cells, wall (compute)",
                               "time ratio dolfin/cosmo: wall (compute)"))
for tol in (1e-3, 1e-4, 1e-5, 1e-6, 1e-7):
    best = {code: min([x for x in table[code] if x[2] <= tol], default=None) for code in table}
    cells = ["%s, %.2f s (%.2f s)" % (b[3], b[0], b[1]) if b else "not reached" for b in (best["cosmo"], best["dolfin"])]
    ratio = ("%.2f (%.2f)" % (best["dolfin"][0] / best["cosmo"][0], best["dolfin"][1] / best["cosmo"][1])
             if best["cosmo"] and best["dolfin"] else "-")
    print("%-9.0e %-24s %-24s %s" % (tol, cells[0], cells[1], ratio))
PY

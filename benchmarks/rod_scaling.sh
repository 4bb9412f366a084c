#!/bin/bash
# The rod (part 4) at 10^3, 10^4 and 10^5 elements: a clamped-clamped rod
# shortened to its first Euler threshold (arclength continuation with the
# inertia at every step, the branch point located by Newton on the
# minimally augmented system, 'Stop at first event', no VTU but the last
# state's), whole process, and the cost per Newton step (one Jacobian
# assembly and one factorization) from summary.json's timings; the exponent
# of a least-squares fit of log time against log elements. Then a path of
# 100 steps at 10^4 elements to its located threshold.
#
#   bash benchmarks/rod_scaling.sh [build = build] [repeats = 3]
#
# Prints one line per size (the median of the repeats) and the fitted
# exponents; benchmarks/README.md keeps the measured table.
set -euo pipefail
REPO=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "${1:-$REPO/build}" && pwd)
REPEATS=${2:-3}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

prm() { # prm <elements> <initial and largest step> <range end> <directory>
  cat <<PRM
subsection Rod
  set Length = 1
  set Number of elements = $1
  subsection Material
    set Law = quadratic
    set Stiffnesses = 500, 500, 1000, 2, 1, 0.8
  end
end
subsection End A
  set Support = clamped
end
subsection End B
  set Support = clamped
  set Displacement = 0; 0; -t
end
subsection Path following
  set Method = arclength
end
subsection Arclength continuation
  set Parameter range         = 0, $3
  set Initial step            = $2
  set Maximum step            = $2
  set Maximum number of steps = 400
  set Stop at first event     = true
end
subsection Postprocess
  subsection fields
    set Steps between outputs = 0
  end
end
subsection Output
  set Output directory = $4
end
PRM
}

measure() { # measure <elements> <step> <range end> -> "wall states factorizations J_per_call F_per_call t_event"
  local n=$1 dir="$WORK/run-$1-$2"
  prm "$n" "$2" "$3" "$dir" > "$WORK/run.prm"
  local start=$EPOCHREALTIME
  "$BUILD/rod" --quiet "$WORK/run.prm" > /dev/null
  local wall; wall=$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }')
  /usr/bin/python3 - "$dir/summary.json" "$wall" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); t = s["timings"]
J, F = t["assembly (Jacobian)"], t["factorization"]
steps = s["last_state"]["step"] + 1
print(sys.argv[2], steps, F["calls"], "%.5f" % (J["seconds"] / J["calls"]), "%.5f" % (F["seconds"] / F["calls"]),
      "%.12f" % s["events"][0]["t"])
PY
}

median_line() { # the line of median wall time among the repeats
  sort -n | awk '{ a[NR] = $0 } END { print a[int((NR + 1) / 2)] }'
}

echo "elements unknowns wall_s states factorizations jacobian_s_per_call factorization_s_per_call t_event"
declare -a sizes=(1000 10000 100000) walls=() steps=()
for n in "${sizes[@]}"; do
  line=$(for r in $(seq "$REPEATS"); do measure "$n" 0.01 0.08; done | median_line)
  echo "$n $((7 * (n + 1))) $line"
  walls+=("$(echo "$line" | cut -d' ' -f1)")
  steps+=("$(echo "$line" | cut -d' ' -f4) $(echo "$line" | cut -d' ' -f5)")
done
/usr/bin/python3 - "${sizes[*]}" "${walls[*]}" "${steps[*]}" <<'PY'
import math, sys
n = [float(x) for x in sys.argv[1].split()]
w = [float(x) for x in sys.argv[2].split()]
js = [float(x) for x in sys.argv[3].split()]
step = [js[2 * i] + js[2 * i + 1] for i in range(len(n))]
def slope(x, y):
    lx, ly = [math.log(a) for a in x], [math.log(b) for b in y]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)
print("fitted exponent, Newton step (one Jacobian + one factorization): %.3f" % slope(n, step))
print("fitted exponent, whole process to the located threshold:        %.3f" % slope(n, w))
PY
echo "a path of ~100 steps at 10^4 elements to its located threshold:"
line=$(for r in $(seq "$REPEATS"); do measure 10000 0.0004 0.05; done | median_line)
echo "10000 70007 $line"

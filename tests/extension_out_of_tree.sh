#!/usr/bin/env bash
# Extension without forking (doc/cookbook.md): the suite installed with
# cmake --install, then the two projects of examples/ built out of tree
# against it with find_package(cosmo), and run:
# 1. examples/section_stiffness, an application of one's own: the linear
#    stiffnesses of a circle against their closed forms (EA = E pi r^2,
#    EI = E pi r^4/4, GJ = G pi r^4/2), at two refinements, with the error
#    falling at least 8x per refinement (the Q2 mapping's boundary error is
#    O(h^4): 16x; 8x leaves room for the pre-asymptotic mesh);
# 2. examples/plugin, a plugin library loaded at run time through
#    'Additional shared libraries' by the installed applications: its growth
#    law 'volumetric' is a value of 'Growth kind' with the library and not
#    without, and the cookbook's example run with it reproduces its closed
#    form and reference key numbers (the same as the law compiled in,
#    doc.cookbook_growth_law); its postprocessor 'quantity history' is called
#    at every converged state and located event of a strip run (its rows are
#    steps.csv's, its event rows summary.json's events), with the library's
#    own 'unknowns' beside it; in a study each point's postprocessors are its
#    own (a point's unknowns.csv has its own states only);
# 3. bad input: a library that cannot be loaded, or that registers a name
#    already registered, is exit status 1 naming the entry.
# usage: extension_out_of_tree.sh <build dir> <source dir> <scratch dir>
set -euo pipefail
build=$(realpath "$1") src=$(realpath "$2") dir=$(realpath -m "$3")
rm -rf "$dir" && mkdir -p "$dir"
prefix=$dir/prefix
cmake --install "$build" --prefix "$prefix" > "$dir/install.log"
for f in lib/libcosmo.so lib/cmake/cosmo/cosmoConfig.cmake include/cosmo/config.h \
         include/cosmo/io/postprocessors.h bin/strip bin/rod_cross_section bin/plate_rod; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
echo "installed into the prefix"

launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
for project in section_stiffness plugin; do
  cmake -S "$src/examples/$project" -B "$dir/build-$project" -DCMAKE_BUILD_TYPE=Release \
        -Dcosmo_DIR="$prefix/lib/cmake/cosmo" "${launcher[@]}" > "$dir/$project-configure.log"
  cmake --build "$dir/build-$project" -j2 > "$dir/$project-build.log" ||
    { tail -30 "$dir/$project-build.log"; exit 1; }
done
echo "examples/section_stiffness and examples/plugin built against the installed suite"

# 1. The application of one's own.
app=$dir/build-section_stiffness/section_stiffness
for r in 2 3; do
  sed -e "s|^\( *set Output directory *=\).*|\1 $dir/circle-$r|" \
      -e "s|^\( *set Global refinements *=\).*|\1 $r|" "$src/examples/section_stiffness/circle.prm" > "$dir/circle-$r.prm"
  "$app" --quiet "$dir/circle-$r.prm"
done
python3 - "$dir/circle-2/summary.json" "$dir/circle-3/summary.json" <<'PY'
import json, math, sys
E, nu, r = 2.0, 0.25, 0.5
G = E / (2 * (1 + nu))
exact = {"EA": E * math.pi * r**2, "EI11": E * math.pi * r**4 / 4,
         "EI22": E * math.pi * r**4 / 4, "GJ": G * math.pi * r**4 / 2}
errors = []
for path in sys.argv[1:]:
    s = json.load(open(path))["section"]
    errors.append({k: abs(s[k] - v) / v for k, v in exact.items()})
for k in exact:
    e2, e3 = errors[0][k], errors[1][k]
    print(f"{k}: relative error {e2:.2e} (2 refinements), {e3:.2e} (3), ratio {e2 / max(e3, 1e-300):.1f}")
    # 3 refinements: the discretization error, measured 3.1e-6 (EA) to 6.2e-6 (EI, GJ), the
    # same on any CPU (round-off here is ~1e-15); 1e-5 is above it.
    assert e3 < 1e-5, (k, e3)
    assert e2 > 8 * e3 or e2 < 1e-12, (k, e2, e3)
print("section_stiffness: the circle's stiffnesses converge to their closed forms")
PY

# 2. The plugin library, loaded at run time by the installed applications.
plugin=$dir/build-plugin/libcosmo_example_plugin.so
[ -f "$plugin" ] || { echo "no $plugin"; exit 1; }
with_plugin() { { echo "set Additional shared libraries = $plugin"; cat "$1"; } > "$2"; }
with_plugin "$src/tests/cookbook/volumetric_growth.prm" "$dir/volumetric.prm"
lists_volumetric() {
  "$prefix/bin/rod_cross_section" --print-parameters json "$@" | python3 -c '
import json, sys
def walk(d):
    for k, v in d.items():
        if isinstance(v, dict):
            if k == "Growth kind" and "volumetric" in v.get("pattern_description", ""):
                return True
            if walk(v):
                return True
    return False
sys.exit(0 if walk(json.load(sys.stdin)) else 1)'
}
lists_volumetric "$dir/volumetric.prm" || { echo "'volumetric' is not a value of 'Growth kind' with the plugin"; exit 1; }
if lists_volumetric; then echo "'volumetric' is a value of 'Growth kind' without the plugin"; exit 1; fi
echo "'volumetric' is a value of 'Growth kind' with the plugin library only"
"$src/tests/run_example.sh" "$prefix/bin/rod_cross_section" "$dir/volumetric.prm" \
  "$src/tests/cookbook/volumetric_growth.output" "$dir/volumetric"

cat > "$dir/postprocess.txt" <<EOP
subsection Postprocess
  set List of postprocessors = steps table, fields, quantity history, unknowns
  subsection quantity history
    set Quantities = energy, m3, kappa3, n_negative_eigenvalues
  end
end
EOP
for example in twisting twist_buckling; do
  with_plugin "$src/parameter_files/strip/$example.prm" "$dir/$example.prm"
  cat "$dir/postprocess.txt" >> "$dir/$example.prm"
  sed -i -e "s|^\( *set Output directory *=\).*|\1 $dir/$example|" "$dir/$example.prm"
  (cd "$src" && "$prefix/bin/strip" --quiet "$dir/$example.prm")
  python3 - "$dir/$example" <<'PY'
import csv, json, math, sys
d = sys.argv[1]
def rows(path):
    with open(path) as f:
        r = list(csv.reader(f))
    return [h.split(" [")[0] for h in r[0]], [[float(x) for x in row] for row in r[1:]]
sh, steps = rows(d + "/steps.csv")
qh, hist = rows(d + "/quantity_history.csv")
uh, unknowns = rows(d + "/unknowns.csv")
states = [r for r in hist if r[0] == 0]
events = [r for r in hist if r[0] == 1]
assert len(states) == len(steps), (len(states), len(steps))
for row, step in zip(states, steps):
    for name in ["t", "energy", "m3", "kappa3", "n_negative_eigenvalues"]:
        a, b = row[qh.index(name)], step[sh.index(name)]
        # both files print numbers that read back to the same double
        assert a == b, (name, a, b)
summary = json.load(open(d + "/summary.json"))
n_events = len(summary.get("events", []))
assert len(events) == n_events, (len(events), n_events)
assert len(unknowns) == len(hist), (len(unknowns), len(hist))
assert [r[uh.index("t")] for r in unknowns] == [r[qh.index("t")] for r in hist]
assert all(r[uh.index("l2_norm")] >= r[uh.index("max_norm")] > 0 or r[uh.index("t")] == 0 for r in unknowns)
q = json.load(open(d + "/quantity_history.json"))
assert q["states"] == len(hist)
largest = max(abs(s[sh.index("energy")]) for s in steps)
assert abs(q["largest |energy|"] - largest) <= 1e-9 * largest
print(f"{d.rsplit('/', 1)[1]}: the postprocessors saw {len(states)} states (steps.csv's) and {len(events)} events (summary.json's)")
PY
done

# In a study each point's run has postprocessors of its own: its unknowns.csv
# holds its own states, as many as its steps.csv (not the points' before it).
cat "$src/parameter_files/rod_cross_section/studies/curvature_vs_differential_growth.prm" \
  - > "$dir/study.prm" <<'EOP'
subsection Postprocess
  set List of postprocessors = steps table, unknowns
end
EOP
sed -i -e "s|^\( *set Output directory *=\).*|\1 $dir/study|" "$dir/study.prm"
(cd "$src" && "$prefix/bin/rod_cross_section" --quiet "$dir/study.prm")
python3 - "$dir/study" <<'PY'
import glob, sys
points = sorted(glob.glob(sys.argv[1] + "/point-*"))
assert len(points) > 1, points
for d in points:
    steps = sum(1 for _ in open(d + "/steps.csv")) - 1
    own = sum(1 for _ in open(d + "/unknowns.csv")) - 1
    assert own == steps > 0, (d, own, steps)
print(f"study: each of the {len(points)} points' unknowns.csv has its own states only")
PY

# 3. Bad input.
expect_error() {
  local prm=$1 text=$2 status=0
  (cd "$dir" && "$prefix/bin/strip" --quiet "$prm") > "$dir/err.out" 2>&1 || status=$?
  [ "$status" = 1 ] || { echo "exit $status, not 1:"; cat "$dir/err.out"; exit 1; }
  grep -q "Additional shared libraries" "$dir/err.out" && grep -q -- "$text" "$dir/err.out" ||
    { echo "the error does not name the entry and '$text':"; cat "$dir/err.out"; exit 1; }
}
sed -e "s|$plugin|$dir/no-such-library.so|" "$dir/twisting.prm" > "$dir/missing.prm"
expect_error "$dir/missing.prm" "could not be loaded"
cp "$plugin" "$dir/second_copy.so"
sed -e "s|$plugin|$plugin, $dir/second_copy.so|" "$dir/twisting.prm" > "$dir/twice.prm"
expect_error "$dir/twice.prm" "registered twice"
echo "a library that cannot be loaded, or registers a name twice, is bad input"

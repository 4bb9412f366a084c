#!/usr/bin/env bash
# Regenerate the figures of the user guide, doc/figures/*.png, from the
# example output under output/. Run `bash scripts/run_examples.sh` first (it
# runs the examples and studies and writes their steps.png and sweep.png);
# this script only copies and plots, it neither builds nor runs anything.
#   doc/figures/sweep_<study>.png   output/studies/<study>/sweep.png
#   doc/figures/steps_<name>.png    output/<name>/steps.png (surface_growth,
#                                   differential_axial_growth)
#   doc/figures/section_embedded_filaments.png
#                                   deformed section of embedded_filaments
#                                   coloured by von_Mises_stress
#                                   (scripts/plot_section.py)
#   doc/figures/strip_shearing_branches.png
#                                   output/strip_shearing/branches.png
#   doc/figures/strip_torque_buckling_branches.png
#                                   output/strip_torque_buckling/branches.png
#   doc/figures/strip_seed_pod_branches.png
#                                   output/strip_seed_pod/branches.png
#   doc/figures/strip_ribbons.png   output/strip_ribbon_comparison/ribbons.png
#   doc/figures/plate_rod_{dome,lobes,heated_lenticular_disc}_bifurcation.png
#                                   output/plate_rod/{dome,lobes,heated_lenticular_disc}/bifurcation.png
#   doc/figures/plate_rod_critical_growth_vs_rim_stiffness.png
#                                   the three models' study (plot_plate_rod_study.py)
#   doc/figures/plate_rod_critical_growth_vs_thickness.png
#                                   Cosserat and Kirchhoff against h/R
#   doc/figures/plate_rod_critical_curve_vs_rim_stiffness.png
#                                   the critical curve against the independent study
#   doc/figures/rod_euler_clamped_bifurcation.png
#                                   output/rod/euler_clamped/bifurcation.png
#   doc/figures/rod_{helix,rollup,euler_clamped,tendril,ribbon_rollup,michell_figure_eight,tendril_perversion,plectoneme}.png
#                                   output/rod/<example>: its last state (the
#                                   buckled branch's for euler_clamped) drawn
#                                   by ParaView (scripts/render_paraview.py on
#                                   an Xvfb display)
# It then records what made each figure (the example's parameter file, the
# regression key numbers of that example, the plotting script) in
# doc/figures/provenance.json; the test doc.figures_current fails when any of
# these changed after the figure was made.
# Exit status 1 if an expected input is missing (run run_examples.sh).
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$REPO"
log() { echo "[cosmo] $*"; }

STUDIES=(curvature_vs_differential_growth stretch_vs_surface_growth
         twist_vs_activation twist_vs_fibre_angle)
STEPS=(surface_growth differential_axial_growth)
SECTION=embedded_filaments

missing=0
for s in "${STUDIES[@]}"; do
  [[ -f "output/studies/$s/sweep.png" ]] || { log "missing output/studies/$s/sweep.png" >&2; missing=1; }
done
for n in "${STEPS[@]}"; do
  [[ -f "output/$n/steps.png" ]] || { log "missing output/$n/steps.png" >&2; missing=1; }
done
[[ -f "output/$SECTION/solution.pvd" ]] || { log "missing output/$SECTION/solution.pvd" >&2; missing=1; }
for f in output/strip_shearing/branches.png output/strip_torque_buckling/branches.png \
         output/strip_seed_pod/branches.png \
         output/strip_ribbon_comparison/ribbons.png \
         output/plate_rod/dome/bifurcation.png output/plate_rod/lobes/bifurcation.png \
         output/plate_rod/heated_lenticular_disc/bifurcation.png \
         output/plate_rod/studies/critical_growth_vs_rim_stiffness.png \
         output/plate_rod/studies/critical_growth_vs_thickness.png \
         output/rod/helix/summary.json output/rod/rollup/summary.json \
         output/rod/euler_clamped/summary.json output/rod/euler_clamped/bifurcation.png \
         output/rod/tendril/summary.json output/rod/ribbon_rollup/summary.json \
         output/rod/michell_figure_eight/summary.json output/rod/tendril_perversion/summary.json \
         output/rod/seed_pod/summary.json output/rod/tendril_overwinding/summary.json \
         output/rod/plectoneme/summary.json; do
  [[ -f "$f" ]] || { log "missing $f" >&2; missing=1; }
done
if ((missing)); then
  log "run 'bash scripts/run_examples.sh' first" >&2
  exit 1
fi

mkdir -p doc/figures
for s in "${STUDIES[@]}"; do
  cp "output/studies/$s/sweep.png" "doc/figures/sweep_$s.png"
done
for n in "${STEPS[@]}"; do
  cp "output/$n/steps.png" "doc/figures/steps_$n.png"
done
cp output/strip_shearing/branches.png doc/figures/strip_shearing_branches.png
cp output/strip_torque_buckling/branches.png doc/figures/strip_torque_buckling_branches.png
cp output/strip_seed_pod/branches.png doc/figures/strip_seed_pod_branches.png
cp output/strip_ribbon_comparison/ribbons.png doc/figures/strip_ribbons.png
for n in dome lobes heated_lenticular_disc; do
  cp "output/plate_rod/$n/bifurcation.png" "doc/figures/plate_rod_${n}_bifurcation.png"
done
for s in rim_stiffness thickness; do
  cp "output/plate_rod/studies/critical_growth_vs_$s.png" "doc/figures/plate_rod_critical_growth_vs_$s.png"
done
cp output/rod/euler_clamped/bifurcation.png doc/figures/rod_euler_clamped_bifurcation.png
# The rod's shapes, rendered by ParaView on a display of their own.
display=$((90 + RANDOM % 100))
Xvfb ":$display" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 & xvfb=$!
sleep 2
for n in helix rollup euler_clamped tendril ribbon_rollup michell_figure_eight tendril_perversion seed_pod plectoneme; do
  DISPLAY=":$display" pvbatch scripts/render_paraview.py "output/rod/$n" "doc/figures/rod_$n.png" >/dev/null 2>&1 \
    || { kill $xvfb; log "rendering output/rod/$n FAILED" >&2; exit 1; }
done
kill $xvfb
# The overwinding tendril: its helices against the closed form (theory-rod.md
# 7.9), C/B2 of the section's law (0.178) and of its stiffened first stage.
python3 scripts/plot_overwinding.py output/rod/tendril_overwinding doc/figures/rod_tendril_overwinding.png \
  --kappa0 20 --c 0.747,0.178 >/dev/null
curve=output/plate_rod/studies/critical_curve_vs_rim_stiffness_cosserat/critical_curve.png
if [[ -f "$curve" ]]; then
  cp "$curve" doc/figures/plate_rod_critical_curve_vs_rim_stiffness.png
else
  log "missing $curve (run run_examples.sh)" >&2
  missing=1
fi
python3 scripts/plot_section.py "output/$SECTION" "doc/figures/section_$SECTION.png" von_Mises_stress >/dev/null
python3 scripts/figure_provenance.py --write
for f in doc/figures/*.png; do
  printf '[cosmo] %-55s %6s bytes\n' "$f" "$(wc -c <"$f")"
done

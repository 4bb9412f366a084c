#!/usr/bin/env bash
# Build, then run every default rod_cross_section example and every study
# (parameter sweep, parameter_files/rod_cross_section/studies/) from the
# repository root (the .prm files set output directories relative to it, under
# output/ and output/studies/). Each run's console output goes to
# output/logs/<name>.log. Then plot: output/<example>/steps.png and
# output/studies/<study>/sweep.png; the strip's and the plate_rod's
# bifurcation diagrams and the plate_rod critical-growth study figure.
set -euo pipefail

REPO="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${COSMO_BUILD_DIR:-build}"
[[ "$BUILD" = /* ]] || BUILD="$REPO/$BUILD"
EXE="$BUILD/rod_cross_section"

log() { echo "[cosmo] $*"; }

bash "$REPO/scripts/setup.sh"
[[ -x "$EXE" ]] || { log "executable not found: $EXE" >&2; exit 1; }

cd "$REPO"
shopt -s nullglob
prms=(parameter_files/rod_cross_section/*.prm)
((${#prms[@]})) || { log "no parameter files in parameter_files/rod_cross_section/" >&2; exit 1; }
studies=(parameter_files/rod_cross_section/studies/*.prm)

mkdir -p output/logs
failed=0
strips=(parameter_files/strip/*.prm parameter_files/strip/studies/*.prm)
plates=(parameter_files/plate_rod/*.prm parameter_files/plate_rod/studies/*.prm)
rods=(parameter_files/rod/*.prm parameter_files/rod/studies/*.prm)
for prm in "${prms[@]}" "${studies[@]}" "${strips[@]}" "${plates[@]}" "${rods[@]}"; do
  name="$(basename "$prm" .prm)"
  exe="$EXE"
  case "$prm" in
    parameter_files/strip/*) name="strip_$name"; exe="$BUILD/strip" ;;
    parameter_files/plate_rod/*) name="plate_rod_$name"; exe="$BUILD/plate_rod" ;;
    parameter_files/rod/*) name="rod_$name"; exe="$BUILD/rod" ;;
  esac
  logfile="output/logs/$name.log"
  start=$EPOCHREALTIME
  if "$exe" "$prm" >"$logfile" 2>&1; then result=OK; else result=FAILED; failed=1; fi
  secs=$(awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }')
  printf '[cosmo] %-40s %-6s %8ss\n' "$name" "$result" "$secs"
  # Show the end of the log right away so failures are diagnosable in CI.
  [[ "$result" == OK ]] || tail -n 20 "$logfile" | sed 's/^/    /'
done

if [[ -f scripts/plot_steps.py ]]; then
  log "plotting"
  python3 scripts/plot_steps.py output || { log "plotting FAILED" >&2; failed=1; }
fi
if ((${#studies[@]})) && [[ -f scripts/plot_sweep.py ]]; then
  log "plotting sweeps"
  python3 scripts/plot_sweep.py output/studies || { log "plotting sweeps FAILED" >&2; failed=1; }
fi
if ((${#strips[@]})); then
  log "plotting strips (bifurcation diagrams, ribbon models)"
  for d in output/strip_*/; do
    if [[ -f "$d/steps.csv" ]] && head -1 "$d/steps.csv" | grep -q branch; then
      python3 scripts/plot_branches.py "$d" || { log "plotting $d FAILED" >&2; failed=1; }
    fi
  done
  if [[ -d output/strip_studies ]]; then
    python3 scripts/plot_sweep.py output/strip_studies || { log "plotting strip studies FAILED" >&2; failed=1; }
  fi
  if [[ -f output/strip_ribbon_comparison/table.csv ]]; then
    # numpy and matplotlib: Debian's interpreter
    py=python3; [[ -x /usr/bin/python3 ]] && py=/usr/bin/python3
    "$py" scripts/ribbon_models.py --plot output/strip_ribbon_comparison/table.csv \
      --out output/strip_ribbon_comparison/ribbons.png --h 0.01 \
      || { log "plotting ribbons FAILED" >&2; failed=1; }
  fi
fi

if ((${#rods[@]})); then
  log "plotting rods (bifurcation diagrams)"
  for d in output/rod/*/; do
    if [[ -f "$d/steps.csv" ]] && head -1 "$d/steps.csv" | grep -q branch; then
      python3 scripts/plot_rod.py "$d" || { log "plotting $d FAILED" >&2; failed=1; }
    fi
  done
fi

if ((${#plates[@]})); then
  log "plotting plate_rod (bifurcation diagrams, critical growth study)"
  for d in output/plate_rod/*/; do
    [[ -f "$d/steps.csv" ]] || continue
    python3 scripts/plot_plate_rod.py "$d" || { log "plotting $d FAILED" >&2; failed=1; }
  done
  for s in rim_stiffness thickness; do
    studies_pr=(output/plate_rod/studies/critical_growth_vs_${s}_*/)
    [[ -d "${studies_pr[0]}" ]] || continue
    python3 scripts/plot_plate_rod_study.py "output/plate_rod/studies/critical_growth_vs_$s.png" \
      "${studies_pr[@]}" || { log "plotting the plate_rod study vs $s FAILED" >&2; failed=1; }
  done
  curve=output/plate_rod/studies/critical_curve_vs_rim_stiffness_cosserat
  if [[ -f "$curve/critical_curve.csv" ]]; then
    python3 scripts/plot_plate_rod_study.py "$curve/critical_curve.png" "$curve" \
      output/plate_rod/studies/critical_growth_vs_rim_stiffness_cosserat ||
      { log "plotting the critical curve FAILED" >&2; failed=1; }
  fi
fi

log "output is in $REPO/output/ (logs in output/logs/)"
exit "$failed"

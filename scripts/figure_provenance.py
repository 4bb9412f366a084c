#!/usr/bin/env python3
"""What each figure of doc/figures is made from, and whether it still is.

Every PNG in doc/figures is made by scripts/make_figures.sh from the output of
an example (or study) run by scripts/run_examples.sh. A figure is current when
none of what made it has changed since: the example's parameter file(s), the
key numbers the regression suite guards for that example
(tests/reference/<name>.output: a change in the computed results changes
these, since the regression test fails until they are renewed), and the
plotting script(s).

  figure_provenance.py --write   record the SHA-256 of each figure's inputs in
                                 doc/figures/provenance.json (make_figures.sh
                                 calls it after making the figures)
  figure_provenance.py --check   exit 1, naming the figure and the input, if
                                 a figure is stale, missing, unlisted here or
                                 referenced from doc/ or the README but absent

The map below is the one place that says which inputs make which figure.
"""
import glob
import hashlib
import json
import os
import re
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROVENANCE = "doc/figures/provenance.json"

RCS = "parameter_files/rod_cross_section"
PR = "parameter_files/plate_rod"
REF = "tests/reference"
STEPS_PLOT = ["scripts/plot_steps.py"]
SWEEP_PLOT = ["scripts/plot_sweep.py", "scripts/plot_steps.py"]
PLATE_PLOT = ["scripts/plot_plate_rod.py"]
PLATE_STUDY_PLOT = ["scripts/plot_plate_rod_study.py", "scripts/plot_steps.py"]


def _figures():
    f = {}
    for s in ["curvature_vs_differential_growth", "stretch_vs_surface_growth",
              "twist_vs_activation", "twist_vs_fibre_angle"]:
        f[f"sweep_{s}.png"] = [f"{RCS}/studies/{s}.prm", f"{REF}/{s}.output"] + SWEEP_PLOT
    for n in ["surface_growth", "differential_axial_growth"]:
        f[f"steps_{n}.png"] = [f"{RCS}/{n}.prm", f"{REF}/{n}.output"] + STEPS_PLOT
    f["section_embedded_filaments.png"] = [f"{RCS}/embedded_filaments.prm",
                                           f"{REF}/embedded_filaments.output",
                                           "scripts/plot_section.py"]
    f["strip_shearing_branches.png"] = ["parameter_files/strip/shearing.prm",
                                        f"{REF}/strip_shearing.output",
                                        "scripts/plot_branches.py"]
    f["strip_torque_buckling_branches.png"] = ["parameter_files/strip/torque_buckling.prm",
                                               f"{REF}/strip_torque_buckling.output",
                                               "scripts/plot_branches.py"]
    f["strip_seed_pod_branches.png"] = ["parameter_files/strip/seed_pod.prm",
                                        f"{REF}/strip_seed_pod.output",
                                        "scripts/plot_branches.py"]
    f["strip_ribbons.png"] = ["parameter_files/strip/ribbon_comparison.prm",
                              f"{REF}/strip_ribbon_comparison.output",
                              "scripts/ribbon_models.py"]
    for n in ["dome", "lobes", "heated_lenticular_disc"]:
        f[f"plate_rod_{n}_bifurcation.png"] = [f"{PR}/{n}.prm", f"{REF}/plate_rod_{n}.output"] + PLATE_PLOT
    for s, models in [("rim_stiffness", ["cosserat", "kirchhoff", "von_karman"]),
                      ("thickness", ["cosserat", "kirchhoff"])]:
        inputs = []
        for m in models:
            inputs += [f"{PR}/studies/critical_growth_vs_{s}_{m}.prm",
                       f"{REF}/plate_rod_critical_growth_vs_{s}_{m}.output"]
        f[f"plate_rod_critical_growth_vs_{s}.png"] = inputs + PLATE_STUDY_PLOT
    f["plate_rod_critical_curve_vs_rim_stiffness.png"] = [
        f"{PR}/studies/critical_curve_vs_rim_stiffness_cosserat.prm",
        f"{REF}/plate_rod_critical_curve_vs_rim_stiffness_cosserat.output",
        f"{PR}/studies/critical_growth_vs_rim_stiffness_cosserat.prm",
        f"{REF}/plate_rod_critical_growth_vs_rim_stiffness_cosserat.output"] + PLATE_STUDY_PLOT
    f["rod_euler_clamped_bifurcation.png"] = ["parameter_files/rod/euler_clamped.prm",
                                              f"{REF}/rod_euler_clamped.output", "scripts/plot_rod.py",
                                              "scripts/plot_plate_rod.py", "scripts/plot_steps.py"]
    for n in ["helix", "rollup", "euler_clamped", "tendril", "ribbon_rollup", "michell_figure_eight", "tendril_perversion",
              "seed_pod", "plectoneme"]:
        f[f"rod_{n}.png"] = [f"parameter_files/rod/{n}.prm", f"{REF}/rod_{n}.output",
                             "scripts/render_paraview.py"]
    f["rod_tendril.png"].append("parameter_files/rod/sections/tendril_bilayer.prm")
    f["rod_ribbon_rollup.png"].append("parameter_files/rod/sections/ribbon_table.prm")
    f["rod_tendril_perversion.png"].append("parameter_files/rod/sections/tendril_disc.prm")
    f["rod_seed_pod.png"].append("parameter_files/rod/sections/seed_pod_strip.prm")
    f["rod_tendril_overwinding.png"] = ["parameter_files/rod/tendril_overwinding.prm",
                                        f"{REF}/rod_tendril_overwinding.output",
                                        "parameter_files/rod/sections/tendril_cross.prm",
                                        f"{RCS}/geometry/cross.geo",
                                        "scripts/plot_overwinding.py", "scripts/rod_vtu.py", "scripts/plot_steps.py"]
    return f


FIGURES = _figures()


def digest(path):
    with open(os.path.join(REPO, path), "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def write():
    record = {"how": "bash scripts/run_examples.sh && bash scripts/make_figures.sh",
              "figures": {}}
    for fig, inputs in sorted(FIGURES.items()):
        if not os.path.isfile(os.path.join(REPO, "doc/figures", fig)):
            sys.exit(f"figure_provenance: doc/figures/{fig} was not made")
        record["figures"][fig] = {p: digest(p) for p in inputs}
    with open(os.path.join(REPO, PROVENANCE), "w") as fh:
        json.dump(record, fh, indent=1, sort_keys=True)
        fh.write("\n")
    print(f"figure_provenance: {len(FIGURES)} figures recorded in {PROVENANCE}")


def check():
    problems = []
    try:
        with open(os.path.join(REPO, PROVENANCE)) as fh:
            recorded = json.load(fh)["figures"]
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"figure_provenance: cannot read {PROVENANCE}: {e}")
    present = {os.path.basename(p) for p in glob.glob(os.path.join(REPO, "doc/figures/*.png"))}
    for fig in sorted(present - set(FIGURES)):
        problems.append(f"doc/figures/{fig} is not in the map of scripts/figure_provenance.py")
    for fig, inputs in sorted(FIGURES.items()):
        if fig not in present:
            problems.append(f"doc/figures/{fig} is missing")
            continue
        if fig not in recorded:
            problems.append(f"doc/figures/{fig} has no provenance record")
            continue
        for p in inputs:
            if not os.path.isfile(os.path.join(REPO, p)):
                problems.append(f"{fig}: its input {p} does not exist")
            elif recorded[fig].get(p) != digest(p):
                problems.append(f"{fig} is stale: {p} changed since the figure was made")
    # every figure the documentation shows exists
    docs = glob.glob(os.path.join(REPO, "doc/**/*.md"), recursive=True) + [os.path.join(REPO, "README.md")]
    for d in docs:
        with open(d) as fh:
            for fig in re.findall(r"figures/([A-Za-z0-9_.-]+\.png)", fh.read()):
                if fig not in present:
                    problems.append(f"{os.path.relpath(d, REPO)} shows figures/{fig}, which does not exist")
    print(f"figure_provenance: {len(FIGURES)} figures, {len(problems)} problem(s)")
    for p in problems:
        print("  " + p)
    if problems:
        print("  refresh with: bash scripts/run_examples.sh && bash scripts/make_figures.sh")
        return 1
    return 0


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        write()
    elif sys.argv[1:] == ["--check"]:
        sys.exit(check())
    else:
        sys.exit(__doc__)

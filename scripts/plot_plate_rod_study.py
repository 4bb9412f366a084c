#!/usr/bin/env python3
"""Critical growth against a swept parameter for several plate_rod studies.

Usage: python3 scripts/plot_plate_rod_study.py OUT.png DIR [DIR ...]

Each DIR is the output directory of a plate_rod study (sweep.csv and
parameters.prm). Draws, in one figure, the critical mismatch (first change
of stability on the flat branch) of every study against the swept value
(log axis when the values span more than a decade), the Kirchhoff closed
form as a line, and in a second panel each study's relative difference to
the closed form. The legend names each study by its model. Exit status 0,
1 bad usage, 2 no matplotlib.
"""

import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_steps  # noqa: E402


def read_study(d):
    with open(os.path.join(d, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    col = {}
    for r in rows:
        for k, v in r.items():
            col.setdefault(k.split(" [")[0], []).append(plot_steps.to_float(v))
    model = "?"
    text = ""
    try:
        text = open(os.path.join(d, "parameters.prm")).read()
        m = re.search(r"^\s*set Model\s*=\s*([^#\n]+)", text, re.M)
        if m:
            model = m.group(1).strip()
        if re.search(r"^\s*set Critical curve\s*=\s*true", text, re.M):
            model += " (critical curve)"
    except OSError:
        pass
    axis = next((k for k in rows[0] if k.startswith("value")), "value") if rows else "value"
    rho_scale = rim_bending_scale(text)
    return col, model, axis, rho_scale, thickness_scale(text)


def thickness_scale(text):
    """R when the study sweeps 'Plate / Thickness' (the axis is then h/R); None otherwise."""
    m = re.search(r"^\s*set Entry\s*=\s*([^#\n]+)", text, re.M)
    if not m or m.group(1).strip() != "Plate/Thickness":
        return None
    m = re.search(r"^\s*set Radius\s*=\s*([^#\n]+)", text, re.M)
    try:
        return float(m.group(1)) if m else 1.0
    except ValueError:
        return None


def rim_bending_scale(text):
    """R D when the study sweeps the rim's EI1 (the 4th of 'Rim rod / Stiffnesses'),
    so that the axis can be rho = EI1/(R D); None otherwise."""
    def entry(name, default):
        m = re.search(r"^\s*set %s\s*=\s*([^#\n]+)" % re.escape(name), text, re.M)
        return m.group(1).strip() if m else default
    if entry("Entry", "") != "Rim rod/Stiffnesses":
        return None
    template = [t.strip() for t in entry("Template", "").split(",")]
    if len(template) != 6 or template[3] != "{}":
        return None
    try:
        R, h = float(entry("Radius", "1")), float(entry("Thickness", "0.01"))
        E, v = float(entry("Young's modulus", "1")), float(entry("Poisson's ratio", "0.3"))
    except ValueError:
        return None
    return R * E * h ** 3 / (12 * (1 - v * v))


def main(argv):
    if len(argv) < 3 or any(a.startswith("-") for a in argv[1:]):
        sys.stderr.write(__doc__)
        return 1
    plt = plot_steps.import_pyplot()
    if plt is None:
        plot_steps.reexec_with_system_python()
        sys.stderr.write("plot_plate_rod_study.py: matplotlib cannot be imported\n")
        return 2
    out, dirs = argv[1], argv[2:]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    axis_label = "value"
    closed_done = False
    markers = ["o", "s", "^", "v", "D"]
    rho_axis = h_axis = False
    for k, d in enumerate(dirs):
        col, model, axis_label, rho_scale, radius = read_study(d)
        x, y, c = col["value"], col["mismatch_critical"], col["closed_form_mismatch"]
        if rho_scale:
            # The dimensionless rim bending stiffness rho = EI1/(R D) (simply supported at 0,
            # clamped as rho -> infinity).
            x = [v / rho_scale for v in x]
            rho_axis = True
        elif radius:
            x = [v / radius for v in x]
            h_axis = True
        if not closed_done and any(math.isfinite(v) for v in c):
            axes[0].plot(x, c, "k-", lw=1, label="closed form (Kirchhoff)")
            closed_done = True
        axes[0].plot(x, y, markers[k % len(markers)], ms=6, mfc="none", label=model)
        axes[1].plot(x, [a / b - 1 if b else math.nan for a, b in zip(y, c)],
                     markers[k % len(markers)] + "-", ms=5, mfc="none", label=model)
    for ax in axes:
        values = [v for v in read_study(dirs[0])[0]["value"] if v > 0]
        if values and max(values) / min(values) > 10:
            ax.set_xscale("log")
        if rho_axis:
            ax.set_xlabel(r"rim bending stiffness $\rho = EI_1/(R D)$")
        elif h_axis:
            ax.set_xlabel(r"plate thickness $h/R$")
        else:
            inside = axis_label.split(" [", 1)[1].rstrip("]") if " [" in axis_label else axis_label
            import plot_sweep
            ax.set_xlabel(plot_sweep.value_label("swept value {} in: " + inside.replace(";", ",")))
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=9)
    # Thresholds over decades (they grow as (h/R)^2 against the thickness): log scale.
    ys = [v for line in axes[0].get_lines() for v in line.get_ydata() if math.isfinite(v)]
    if ys and min(ys) > 0 and max(ys) / min(ys) > 100:
        axes[0].set_yscale("log")
    axes[0].set_ylabel(r"critical mismatch $\Delta = g_{plate}/g_{rim} - 1$")
    axes[1].set_ylabel(r"$\Delta_{cr}$ / closed form $- 1$")
    fig.suptitle("critical growth of the flat state", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print("wrote %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

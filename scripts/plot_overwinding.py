#!/usr/bin/env python3
"""Overwinding diagram of a tendril run of the rod application.

Usage: python3 scripts/plot_overwinding.py DIR OUT.png --kappa0 K --c C1[,C2...]

DIR is the output of a rod run of a perverted tendril (clamped ends on the
e3 axis, e.g. parameter_files/rod/tendril_overwinding.prm). For every state
the helix in the middle of the first half (s/L in [0.15, 0.35]) is read
from rod-NNNN.vtu: its turn density rho = |kappa| and x = kappa3/rho, the
axis' share of its tangent. Left: rho/kappa0 against the end distance D/L,
coloured by the load parameter t (the path's order). Right: rho/kappa0
against x with the closed form of a helix pulled with no moment about its
axis, rho/kappa0 = sqrt(1 - x^2)/(1 - (1 - c) x^2), for each torsion ratio
c = C/B given (doc/theory-rod.md 7.9): it overwinds (rho rises with x)
while 1 - x^2 > c/(1 - c), so only if c < 1/2.
Exit status 0, 1 bad usage, 2 no matplotlib or numpy.
"""
import argparse
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_steps  # noqa: E402  (matplotlib set-up)


def helices(run_dir):
    """(t, D/L, rho, x) of the first half's middle at every state but the straight start."""
    import numpy as np
    from rod_vtu import element_strains, vtu_arrays
    text = open(os.path.join(run_dir, "parameters.prm")).read()
    length = float(re.search(r"^\s*set Length\s*=\s*([^\s#]+)", text, re.M).group(1))
    out = []
    for r in csv.DictReader(open(os.path.join(run_dir, "steps.csv"))):
        kappa = element_strains(vtu_arrays(os.path.join(run_dir, "rod-%04d.vtu" % int(r["step"]))))
        s = (np.arange(len(kappa)) + 0.5) / len(kappa)
        k = kappa[(s > 0.15) & (s < 0.35)]
        rho = np.linalg.norm(k, axis=1)
        if rho.mean() > 0:
            out.append((float(r["t"]), float(r["end_z"]) / length, rho.mean(), np.mean(np.abs(k[:, 2]) / rho)))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run")
    parser.add_argument("png")
    parser.add_argument("--kappa0", type=float, required=True, help="the natural curvature")
    parser.add_argument("--c", required=True, help="torsion ratios C/B of the closed forms, comma-separated")
    a = parser.parse_args()
    plt = plot_steps.import_pyplot()
    if plt is None:
        plot_steps.reexec_with_system_python()
        print("plot_overwinding: matplotlib is needed", file=sys.stderr)
        return 2
    import numpy as np
    states = np.array(helices(a.run))
    t, D, rho, x = states.T
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    points = left.scatter(D, rho / a.kappa0, c=t, s=9, cmap="viridis")
    fig.colorbar(points, ax=left, label="load parameter t")
    left.set_xlabel("end distance D/L")
    left.set_ylabel("turn density of each helix  |kappa| / kappa0")
    left.set_title("the path, in the order of t")
    right.scatter(x, rho / a.kappa0, c=t, s=9, cmap="viridis")
    xs = np.linspace(0, 0.995, 400)
    for i, c in enumerate(float(v) for v in a.c.split(",")):
        right.plot(xs, np.sqrt(1 - xs**2) / (1 - (1 - c) * xs**2), "--", color="C%d" % (i + 1),
                   label="closed form, C/B = %.3g" % c)
    right.set_xlabel("x = kappa3/|kappa| (the axis' share of the tangent)")
    right.set_ylabel("|kappa| / kappa0")
    right.set_ylim(0, 1.05 * max(rho / a.kappa0))
    right.legend(loc="lower left")
    right.set_title("against a helix with no moment about its axis")
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    print("plot_overwinding: wrote", a.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())

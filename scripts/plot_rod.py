#!/usr/bin/env python3
"""Bifurcation diagram of a rod run.

Usage: python3 scripts/plot_rod.py DIR [DIR ...]

DIR is the output directory of a `rod` run (steps.csv with a `branch`
column, summary.json with `events`). Writes DIR/bifurcation.png with two
panels against the load parameter t: the axial force the support at end B
applies (force_B_z; the ring's writhe for a ring) and the energy. One colour
per branch, solid where the state is stable (no negative eigenvalue), dashed
where it is not or where the count was not computed; located events as
dotted lines labelled BP (branch point) or F (fold) with their branch.
Exit status 0, 1 bad usage, 2 no matplotlib.
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_steps  # noqa: E402  (CSV reading, matplotlib set-up)
from plot_plate_rod import segments  # noqa: E402  (runs of equal stability)


def plot_run(plt, run_dir):
    columns, _ = plot_steps.read_steps(os.path.join(run_dir, "steps.csv"))
    if "branch" not in columns or not columns.get("t"):
        return None
    summary = plot_steps.read_summary(os.path.join(run_dir, "summary.json")) or {}
    ring = "writhe" in columns
    quantities = [("writhe", "writhe (turns)") if ring else ("force_B_z", "axial force at B"),
                  ("energy", "energy")]
    n_rows = len(columns["t"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for (name, label), ax in zip(quantities, axes):
        for b in sorted(set(int(x) for x in columns["branch"])):
            rows = [i for i in range(n_rows) if int(columns["branch"][i]) == b]
            stable = [columns["n_negative_eigenvalues"][i] == 0 for i in rows]
            colour = "C%d" % (b % 10)
            for run, is_stable in segments(rows, stable):
                ax.plot([columns["t"][i] for i in run], [columns[name][i] for i in run], color=colour,
                        ls="-" if is_stable else "--", lw=1.6,
                        label=("branch %d" % b) if run[0] == rows[0] else None)
        for e in summary.get("events", []):
            ax.axvline(e.get("t", math.nan), color="gray", lw=0.6, ls=":")
            ax.annotate("%s b%d" % ("BP" if e.get("kind") == "branch point" else "F", e.get("branch", 0)),
                        (e.get("t", math.nan), 1.0), xycoords=("data", "axes fraction"), fontsize=7,
                        rotation=90, va="top", ha="right", color="gray")
        ax.set_xlabel("load parameter t")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("%s: solid stable, dashed unstable" % os.path.basename(os.path.normpath(run_dir)))
    fig.tight_layout()
    out = os.path.join(run_dir, "bifurcation.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def main(argv):
    return plot_steps.plot_each_directory(argv, __doc__, plot_run, "steps.csv with branches")


if __name__ == "__main__":
    sys.exit(main(sys.argv))

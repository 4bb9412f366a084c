#!/usr/bin/env python3
"""Bifurcation diagrams of strip runs with arclength continuation.

Usage: python3 scripts/plot_branches.py DIR [DIR ...]

DIR is the output directory of a `strip` run (steps.csv with a `branch`
column, summary.json with `events`). Writes DIR/branches.png: the load
parameter t against the resultant that the path drives (the one of the
largest prescribed strain change: m3 for twisting, n1 for shearing, m1 for
bending; the same panel shows the energy), one line per branch, solid where
the state is stable (no negative eigenvalue) and dashed where it is not; the
located events are marked. Under resultant control (a resultant of the
driven strain held at t times a target, `Rod strains / Resultants`) the left
panel is that strain against its resultant instead (e.g. twist against
torque: the fold of a snap shows as a turning point), events as dots. At
a natural shape (`Mode = natural shape`: every strain free, a natural
curvature drives the path) the left panel is that strain against t.
Exit status 0, 1 bad usage, 2 no matplotlib.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_steps  # noqa: E402  (CSV reading, matplotlib set-up)

STRAINS = plot_steps.STRAINS
RESULTANTS = plot_steps.RESULTANTS


def plot_run(plt, run_dir):
    columns, units = plot_steps.read_steps(os.path.join(run_dir, "steps.csv"))

    def label(name):  # symbol with its unit, e.g. "$m_3$ [E w h L]"
        return plot_steps.symbol(name) + (" [%s]" % units[name] if units.get(name) else "")
    if "branch" not in columns or not columns.get("t"):
        return None
    try:
        summary = json.load(open(os.path.join(run_dir, "summary.json")))
    except (OSError, ValueError):
        summary = {}
    # The driven strain: the one that changes most along the first branch;
    # the order parameter: the strain that differs most between branches
    # (e.g. the twist a sheared strip buckles into), else the energy.
    first = [i for i, b in enumerate(columns["branch"]) if int(b) == 0]
    change = {s: max(columns[s][i] for i in first) - min(columns[s][i] for i in first)
              for s in STRAINS if s in columns}
    driven = max(change, key=change.get)
    resultant = RESULTANTS[STRAINS.index(driven)]
    others = [i for i, b in enumerate(columns["branch"]) if int(b) != 0]
    spread = {s: max((abs(columns[s][i] - columns[s][first[0]]) for i in others), default=0)
              for s in STRAINS if s in columns and s != driven}
    order = max(spread, key=spread.get) if spread and max(spread.values()) > 1e-8 else "energy"
    # A natural shape (all strains free, no resultant: a natural curvature
    # drives it): the left panel is the driven strain itself against t.
    natural = False
    try:
        with open(os.path.join(run_dir, "parameters.prm")) as f:
            # the value, not the '# default: ...' comment after it
            natural = any(l.split("=")[0].split() == ["set", "Mode"] and
                          l.split("=", 1)[1].split("#")[0].strip() == "natural shape" for l in f)
    except OSError:
        pass
    if natural:
        resultant = driven
    # resultant control: the driven strain is free, its resultant held at t x target
    target = None
    if resultant in summary.get("held_resultants", {}):
        ratios = [columns[resultant][i] / columns["t"][i] for i in range(len(columns["t"]))
                  if abs(columns["t"][i]) > 1e-12]
        target = ratios[-1] if ratios and abs(ratios[-1]) > 0 else None
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    branches = sorted(set(int(b) for b in columns["branch"]))
    for b in branches:
        rows = [i for i, x in enumerate(columns["branch"]) if int(x) == b]
        for k, (ax, name) in enumerate(zip(axes, (resultant, order))):
            xname = driven if (k == 0 and target is not None) else "t"
            # Split into runs of equal stability so that stable is solid.
            start = 0
            while start < len(rows):
                stable = columns["n_negative_eigenvalues"][rows[start]] == 0
                end = start
                while end + 1 < len(rows) and \
                        (columns["n_negative_eigenvalues"][rows[end + 1]] == 0) == stable:
                    end += 1
                seg = rows[start:end + 2] if end + 1 < len(rows) else rows[start:end + 1]
                ax.plot([columns[xname][i] for i in seg], [columns[name][i] for i in seg],
                        "-" if stable else "--", color="C%d" % b,
                        label=("branch %d" % b) if start == 0 else None)
                start = end + 1
    for e in summary.get("events", []):
        for k, ax in enumerate(axes):
            if k == 0 and target is not None:
                ax.plot([e.get("strains", {}).get(driven, math.nan)], [e.get("t", math.nan) * target],
                        "o", color="k", ms=4)
            else:
                ax.axvline(e.get("t", math.nan), color="gray", lw=0.6, ls=":")
    for k, (ax, name) in enumerate(zip(axes, (resultant, order))):
        if natural:
            ax.set_xlabel("load parameter t (natural shape: every strain free)")
        elif target is None:
            ax.set_xlabel("load parameter t (%s prescribed)" % plot_steps.symbol(driven))
        elif k == 0:
            ax.set_xlabel("%s (free; %s held; dots: events)" % (label(driven), plot_steps.symbol(resultant)))
        else:
            ax.set_xlabel("load parameter t (%s held at t x %.4g)" % (plot_steps.symbol(resultant), target))
        ax.set_ylabel(label(name))
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=9)
    n_events = len(summary.get("events", []))
    fig.suptitle("%s: %d branch(es), %d event(s); solid stable, dashed unstable"
                 % (os.path.basename(os.path.normpath(run_dir)), len(branches), n_events),
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    out = os.path.join(run_dir, "branches.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def main(argv):
    return plot_steps.plot_each_directory(argv, __doc__, plot_run, "branch data")


if __name__ == "__main__":
    sys.exit(main(sys.argv))

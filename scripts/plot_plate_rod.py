#!/usr/bin/env python3
"""Bifurcation diagram of a plate_rod run.

Usage: python3 scripts/plot_plate_rod.py DIR [DIR ...]

DIR is the output directory of a `plate_rod` run (steps.csv with a
`branch` column, summary.json with `events` and `closed_form`). Writes
DIR/bifurcation.png with three panels against the load parameter t:
the out-of-plane amplitude (the dome height w(0) - mean rim w when the
shape is a dome, else half the range of w, signed by the rim's leading
out-of-plane lobe), the rim's lobe amplitudes (Fourier amplitudes of w and
of the radial displacement, for the mode numbers the domain admits) on the
bifurcated branches, and the
energy relative to the flat branch. One colour per branch, solid where the
state is stable (no negative eigenvalue), dashed where it is not; located
events are marked with dotted lines labelled with their kind (BP branch
point, F fold), mode number and branch, the closed-form threshold with a
grey band. Exit status 0, 1 bad usage, 2 no matplotlib.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_steps  # noqa: E402  (CSV reading, matplotlib set-up)


def segments(rows, stable):
    """Split the row indices of a branch into runs of equal stability."""
    out, start = [], 0
    for k in range(1, len(rows) + 1):
        if k == len(rows) or stable[k] != stable[start]:
            end = min(k, len(rows) - 1)
            out.append((rows[start:end + 1], stable[start]))
            start = k
    return out


def plot_run(plt, run_dir):
    columns, _ = plot_steps.read_steps(os.path.join(run_dir, "steps.csv"))
    if "branch" not in columns or not columns.get("t"):
        return None
    summary = plot_steps.read_summary(os.path.join(run_dir, "summary.json")) or {}
    n_rows = len(columns["t"])
    branches = sorted(set(int(b) for b in columns["branch"]))
    flat_energy = {}
    for i in range(n_rows):
        if int(columns["branch"][i]) == 0:
            flat_energy[columns["t"][i]] = columns["energy"][i]
    flat_t = sorted(flat_energy)

    def flat_at(t):
        if not flat_t:
            return 0.0
        if t <= flat_t[0]:
            return flat_energy[flat_t[0]]
        for a, b in zip(flat_t, flat_t[1:]):
            if a <= t <= b:
                f = (t - a) / (b - a) if b > a else 0
                return (1 - f) * flat_energy[a] + f * flat_energy[b]
        return flat_energy[flat_t[-1]]

    # The rim's mode numbers in the table (0, n, 2n, ... on a sector pi/n).
    numbers = sorted(int(k[len("rim_w_"):]) for k in columns if k.startswith("rim_w_"))
    numbers = [n for n in numbers if n > 0]

    def amplitude(i):
        dome = columns["dome_height"][i]
        lobes = [columns["rim_w_%d" % n][i] for n in numbers]
        if abs(dome) >= max(lobes + [0]):
            return dome
        return 0.5 * columns["w_range"][i]

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    for b in branches:
        rows = [i for i in range(n_rows) if int(columns["branch"][i]) == b]
        stable = [columns["n_negative_eigenvalues"][i] == 0 for i in rows]
        for seg, st in segments(rows, stable):
            t = [columns["t"][i] for i in seg]
            style = "-" if st else "--"
            axes[0].plot(t, [amplitude(i) for i in seg], style, color="C%d" % b,
                         label=("branch %d" % b) if seg[0] == rows[0] else None)
            axes[2].plot(t, [columns["energy"][i] - flat_at(columns["t"][i]) for i in seg],
                         style, color="C%d" % b)
        if b == 0:
            continue
        drawn = False
        for n in numbers:
            for name, marker in (("rim_w_%d" % n, "o"), ("rim_ur_%d" % n, "s")):
                values = [columns.get(name, [0] * n_rows)[i] for i in rows]
                if max(values + [0]) > 1e-3 * max(abs(amplitude(i)) for i in rows):
                    axes[1].plot([columns["t"][i] for i in rows], values, marker=marker, ms=3,
                                 lw=0.8, label="branch %d: %s" % (b, name))
                    drawn = True
        if not drawn and "rim_radial_strain" in columns:
            # An axisymmetric branch: no lobes; the rim's radial strain instead.
            axes[1].plot([columns["t"][i] for i in rows],
                         [columns["rim_radial_strain"][i] for i in rows], "-", color="C%d" % b,
                         label="branch %d: rim radial strain (no lobes)" % b)
    for k, e in enumerate(summary.get("events", [])):
        for ax in axes:
            ax.axvline(e.get("t", math.nan), color="gray", lw=0.6, ls=":")
        # Label: kind (BP branch point, F fold), mode number and type, branch.
        label = "%s%s b%d" % ("F" if e.get("kind") == "fold" else "BP",
                              (" n=%d%s" % (e["mode_number"],
                                            "" if e.get("mode_type_out_of_plane", 1) else " planar"))
                              if "mode_number" in e else "", e.get("branch", 0))
        axes[0].annotate(label, xy=(e.get("t", math.nan), 1 - 0.06 * (k % 8)),
                         xycoords=("data", "axes fraction"), fontsize=6, rotation=90,
                         ha="right", va="top", color="dimgray")
    first = summary.get("closed_form", {}).get("first", {}).get("t")
    if first is not None and math.isfinite(first):
        for ax in axes:
            ax.axvline(first, color="k", lw=4, alpha=0.12)
    axes[0].set_ylabel("out-of-plane amplitude (dome height or half the w range)")
    axes[1].set_ylabel("rim lobe amplitudes |w_n| (o), |u_r,n| (s); or rim radial strain")
    axes[2].set_ylabel("energy - flat branch")
    for ax in axes:
        ax.set_xlabel("growth parameter t")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    if any(not l.get_label().startswith("_") for l in axes[1].lines):
        axes[1].legend(fontsize=6, ncol=2)
    fig.suptitle("%s (%s, %s): %d branch(es), %d event(s); solid stable, dashed unstable; "
                 "grey band: closed-form threshold"
                 % (os.path.basename(os.path.normpath(run_dir)), summary.get("model", "?"),
                    summary.get("domain", "?"), len(branches), len(summary.get("events", []))),
                 fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.94))
    out = os.path.join(run_dir, "bifurcation.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return out


def main(argv):
    return plot_steps.plot_each_directory(argv, __doc__, plot_run, "steps.csv with branches")


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Plot parameter sweeps (sweep.csv) of rod_cross_section studies.

Usage: python3 scripts/plot_sweep.py DIR [DIR ...]

Each DIR is a sweep's output directory (it holds sweep.csv) or a directory
searched recursively for them. For every sweep.csv, <dir>/sweep.png is
written: two panels against the swept value (its entry is the unit of the
'value' column),
  (a) the final strains that vary over the sweep (natural strains for a
      natural-shape study),
  (b) the diagonal stiffnesses at the final states (log scale when all
      positive).
Points that did not converge (converged = 0) are left out and counted in
the title. One line is printed per PNG written.

Exit status: 0, 1 bad usage, 2 matplotlib cannot be imported.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_steps  # noqa: E402  (shared CSV reading and panels)

USAGE = "usage: python3 scripts/plot_sweep.py DIR [DIR ...]\n"


def find_sweeps(arg):
    found = []
    for root, dirs, files in os.walk(arg):
        dirs.sort()
        if "sweep.csv" in files:
            found.append(root)
    return found


def plot_critical_points(plt, sweep_dir, x, keep, units, failed):
    """A study of critical points: (a) the critical load, (b) the strains there."""
    strains = [s + "_critical" for s in plot_steps.STRAINS]
    varying = [s for s in strains
               if s in keep and keep[s] and max(keep[s]) - min(keep[s]) > 1e-12]
    fig, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    plot_steps.plot_panel(axes[0], x, keep, units, ["t_critical"], "(a) critical load t")
    plot_steps.plot_panel(axes[1], x, keep, units, varying or strains,
                          "(b) strains at the critical point")
    suffix = " (critical curve)" if os.path.exists(os.path.join(sweep_dir, "critical_curve.csv")) else ""
    return save(plt, fig, axes, units, sweep_dir, suffix, failed)


def value_label(text):
    """The x label from the value column's unit text, e.g. 'swept value {} in:
    Rim rod/Stiffnesses = 0.1, 0.1, 0.1, {}, 1e-6, 1e-6' -> 'Rim rod / Stiffnesses,
    item 4 of 6 (EI1 of GA1, GA2, EA, EI1, EI2, GJ)' where the entry lists
    several values; the entry path alone otherwise."""
    if " in: " not in text:
        return text or "swept value"
    entry, _, template = text.split(" in: ", 1)[1].partition(" = ")
    entry = " / ".join(p.strip() for p in entry.split("/"))
    items = [i.strip() for i in template.split(",")]
    if len(items) > 1:
        k = next((i for i, item in enumerate(items) if "{}" in item), None)
        if k is not None:
            return "%s, item %d of %d" % (entry, k + 1, len(items))
    if template.strip() not in ("{}", ""):
        return "%s = %s" % (entry, template.strip())
    return entry


def stability_of(keep):
    negative = [v for v in keep.get("n_negative_eigenvalues", []) if v == v]
    if negative and max(negative) > 0:
        return "solid: stable; dashed: unstable (up to %d negative eigenvalues)" % max(negative)
    return ""


def save(plt, fig, axes, units, sweep_dir, suffix, failed, stability_note=""):
    """Label, title (the directory, suffix, failed points) and write sweep.png."""
    axes[1].set_xlabel(value_label(units.get("value", "")))
    title = os.path.basename(os.path.normpath(os.path.abspath(sweep_dir))) + suffix
    if stability_note:
        title += "\n" + stability_note
    if failed:
        title += "  (%d point(s) did not converge)" % failed
    fig.suptitle(title, fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    out = os.path.join(sweep_dir, "sweep.png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out, []


def plot_sweep(plt, sweep_dir):
    columns, units = plot_steps.read_steps(os.path.join(sweep_dir, "sweep.csv"))
    if not columns.get("value"):
        return None, ["note: %s/sweep.csv has no data rows; skipped" % sweep_dir]
    ok = [c == 1 for c in columns.get("converged", [])]
    keep = {n: [v for v, good in zip(vals, ok) if good] for n, vals in columns.items()}
    x = keep["value"]
    if "t_critical" in keep:
        return plot_critical_points(plt, sweep_dir, x, keep, units, len(ok) - sum(ok))
    # Only the strains that change: a natural-shape study of bending has
    # five flat lines that would hide the one that matters.
    varying = [s for s in plot_steps.STRAINS
               if s in keep and keep[s] and max(keep[s]) - min(keep[s]) > 1e-12]
    fig, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    plot_steps.plot_panel(axes[0], x, keep, units, varying or plot_steps.STRAINS,
                          "(a) strains at the final state")
    plot_steps.plot_panel(axes[1], x, keep, units, plot_steps.STIFFNESS,
                          "(b) diagonal stiffness", log_if_positive=True)
    return save(plt, fig, axes, units, sweep_dir, "", len(ok) - sum(ok), stability_of(keep))


def main(argv):
    args = argv[1:]
    if any(a in ("-h", "--help") for a in args):
        sys.stdout.write(USAGE)
        return 0
    if not args or any(a.startswith("-") for a in args):
        sys.stderr.write(USAGE)
        return 1
    plt = plot_steps.import_pyplot()
    if plt is None:
        plot_steps.reexec_with_system_python()
        sys.stderr.write("plot_sweep.py: matplotlib cannot be imported by %s "
                         "(Debian: apt-get install python3-matplotlib)\n" % sys.executable)
        return 2
    for arg in args:
        for d in find_sweeps(arg):
            out, notes = plot_sweep(plt, d)
            for n in notes:
                print(n)
            if out:
                print("wrote %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

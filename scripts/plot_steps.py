#!/usr/bin/env python3
"""Plot the continuation history (steps.csv) of rod_cross_section runs.

Usage: python3 scripts/plot_steps.py DIR [DIR ...]

Each DIR is either the output directory of one run (it holds steps.csv and
summary.json) or a parent directory whose immediate subdirectories are such
run directories. For every run directory found, <run>/steps.png is written:
three panels against the load parameter t (solid where the state is
stable, dashed where the Hessian has negative eigenvalues; each branch
drawn apart; quantities at round-off named in the legend, not drawn),
  (a) the strains nu1, nu2, nu3, kappa1, kappa2, kappa3,
  (b) the resultants n1, n2, n3, m1, m2, m3,
  (c) the diagonal stiffnesses K_nu1_nu1 ... K_kappa3_kappa3 (log scale when
      all of their values are positive),
titled with the run directory's name and summary["helix"]["description"].
One line is printed per PNG written.

Exit status: 0 (also when a directory holds no steps.csv: a note is
printed), 1 bad usage, 2 matplotlib cannot be imported.

Needs matplotlib only (Agg backend); the CSV is read with the csv module.
If the interpreter running this script has no matplotlib but the system
interpreter /usr/bin/python3 has it (Debian's python3-matplotlib), the
script re-runs itself with that interpreter.
"""

import csv
import json
import math
import os
import subprocess
import sys

STRAINS = ["nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"]
RESULTANTS = ["n1", "n2", "n3", "m1", "m2", "m3"]
STIFFNESS = ["K_%s_%s" % (s, s) for s in STRAINS]
SYSTEM_PYTHON = "/usr/bin/python3"
ticker = None  # the module matplotlib.ticker, set by import_pyplot()
USAGE = "usage: python3 scripts/plot_steps.py DIR [DIR ...]\n" \
        "  DIR: a run's output directory (steps.csv, summary.json) or a\n" \
        "       directory whose subdirectories are run directories\n"


def import_pyplot():
    """Return matplotlib.pyplot with the Agg backend, or None."""
    try:
        import matplotlib
    except ImportError:
        return None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    global ticker
    import matplotlib.ticker as ticker_module
    ticker = ticker_module
    return plt


def reexec_with_system_python():
    """Re-run this script with the system interpreter if it has matplotlib."""
    if os.environ.get("PLOT_STEPS_REEXEC"):
        return
    if not os.access(SYSTEM_PYTHON, os.X_OK):
        return
    if os.path.realpath(SYSTEM_PYTHON) == os.path.realpath(sys.executable):
        return
    probe = subprocess.call([SYSTEM_PYTHON, "-c", "import matplotlib"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if probe != 0:
        return
    env = dict(os.environ, PLOT_STEPS_REEXEC="1")
    sys.stdout.flush()
    os.execve(SYSTEM_PYTHON,
              [SYSTEM_PYTHON, os.path.abspath(sys.argv[0])] + sys.argv[1:], env)


def plot_each_directory(argv, doc, plot_run, what):
    """The main() of a plotting script that draws one figure per run directory:
    usage check, matplotlib (or the system interpreter that has it), then
    plot_run(plt, DIR) for every DIR; `what` names what a skipped one lacks."""
    args = argv[1:]
    if not args or any(a.startswith("-") for a in args):
        sys.stderr.write(doc)
        return 1
    plt = import_pyplot()
    if plt is None:
        reexec_with_system_python()
        sys.stderr.write("%s: matplotlib cannot be imported\n" % os.path.basename(argv[0]))
        return 2
    for d in args:
        out = plot_run(plt, d)
        print("wrote %s" % out if out else "note: %s has no %s; skipped" % (d, what))
    return 0


def column_name(header):
    """'kappa1 [1/L]' -> 'kappa1'."""
    return header.split(" [", 1)[0].strip()


def column_unit(header):
    """'kappa1 [1/L]' -> '1/L', 'K_nu1_nu1' -> ''."""
    if " [" in header and header.rstrip().endswith("]"):
        return header.split(" [", 1)[1].rstrip()[:-1]
    return ""


def to_float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def read_steps(path):
    """Return ({name: [floats]}, {name: unit}) of steps.csv."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        try:
            header = next(reader)
        except StopIteration:
            return {}, {}
        names = [column_name(h) for h in header]
        units = {column_name(h): column_unit(h) for h in header}
        columns = {n: [] for n in names}
        for row in reader:
            if not row:
                continue
            for i, n in enumerate(names):
                columns[n].append(to_float(row[i]) if i < len(row) else math.nan)
    return columns, units


def read_summary(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def is_run_dir(d):
    return (os.path.isfile(os.path.join(d, "steps.csv"))
            or os.path.isfile(os.path.join(d, "summary.json")))


def find_run_dirs(arg):
    """Run directories for one argument, and notes about what was skipped."""
    if not os.path.isdir(arg):
        return [], ["note: %s is not a directory; skipped" % arg]
    if is_run_dir(arg):
        return [arg], []
    runs = []
    for entry in sorted(os.listdir(arg)):
        sub = os.path.join(arg, entry)
        if os.path.isdir(sub) and is_run_dir(sub):
            runs.append(sub)
    if not runs:
        return [], ["note: no steps.csv in %s nor in its subdirectories; skipped"
                    % arg]
    return runs, []


def finite(values):
    return [v for v in values if not math.isnan(v)]


SYMBOLS = {"nu1": r"$\nu_1$", "nu2": r"$\nu_2$", "nu3": r"$\nu_3$",
           "kappa1": r"$\kappa_1$", "kappa2": r"$\kappa_2$", "kappa3": r"$\kappa_3$",
           "n1": r"$n_1$", "n2": r"$n_2$", "n3": r"$n_3$", "m1": r"$m_1$", "m2": r"$m_2$", "m3": r"$m_3$"}
for _s in STRAINS:
    SYMBOLS["K_%s_%s" % (_s, _s)] = r"$K_{%s%s}$" % ((SYMBOLS[_s][1:-1],) * 2)


def symbol(name):
    return SYMBOLS.get(name, name)


def segments(columns, n):
    """Runs of consecutive rows on one branch with one stability: (rows, stable).
    Each run shares its first row with the previous run of its branch, so a
    branch is drawn without gaps; different branches are never joined."""
    branch = columns.get("branch", [0] * n)
    negative = columns.get("n_negative_eigenvalues", [0] * n)
    out, start = [], 0
    for i in range(1, n + 1):
        if i == n or branch[i] != branch[start] or \
                ((negative[i] == 0) != (negative[start] == 0)):
            rows = list(range(start, i))
            if i < n and branch[i] == branch[start]:
                rows.append(i)  # join to the next run of the same branch
            out.append((rows, negative[start] == 0 or math.isnan(negative[start])))
            start = i
    return out


def plot_panel(ax, t, columns, units, names, ylabel, log_if_positive=False, scale=0.0):
    """Plot the given columns against t, solid where the state is stable and
    dashed where it is not, each branch apart; a quantity that stays at
    round-off (below 1e-9 of the panel's largest or of `scale`, or 1e-13) is
    named in the legend instead of drawn. Return the names that were missing."""
    missing = []
    plotted = []
    present = [name for name in names if name in columns]
    missing = [name for name in names if name not in columns]
    largest = max([abs(v) for name in present for v in finite(columns[name])] + [scale])
    zero = []
    for name in present:
        values = finite(columns[name])
        if values and max(abs(v) for v in values) < max(1e-9 * largest, 1e-13):
            zero.append(name)
            continue
        label = symbol(name)
        if units.get(name):
            label += " [%s]" % units[name]
        color = None
        for rows, stable in segments(columns, len(t)):
            line, = ax.plot([t[i] for i in rows], [columns[name][i] for i in rows],
                            linestyle="-" if stable else "--", marker="o", markersize=2.5,
                            linewidth=1.3, color=color, label=label if color is None else None)
            color = line.get_color()
        plotted.extend(values)
    if log_if_positive and plotted and all(v > 0 for v in plotted):
        ax.set_yscale("log")
        ratio = max(plotted) / min(plotted)
        if ratio < 1e3:
            # At most a few decades: plain-number labels at 1..9 (within a
            # decade) or 1, 2, 5 (more) times powers of ten.
            subs = tuple(range(1, 10)) if ratio < 10 else (1, 2, 5)
            ax.yaxis.set_major_locator(ticker.LogLocator(base=10, subs=subs))
            ax.yaxis.set_major_formatter(ticker.FuncFormatter(lambda v, _: "%g" % v))
            ax.yaxis.set_minor_formatter(ticker.NullFormatter())
        ylabel += " (log scale)"
    if zero:
        # Invisible handle: the legend names them.
        ax.plot([], [], " ", label="%s: 0 (round-off)" % ", ".join(symbol(z) for z in zero))
    if not plotted:
        ax.text(0.5, 0.5, "no data" if not zero else "all at round-off",
                transform=ax.transAxes, ha="center", va="center", color="gray")
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", alpha=0.3)
    if present:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=9,
                  frameon=False)
    return missing


def plot_run(plt, run_dir):
    """Write run_dir/steps.png; return (path or None, notes)."""
    steps = os.path.join(run_dir, "steps.csv")
    if not os.path.isfile(steps):
        return None, ["note: no steps.csv in %s; skipped" % run_dir]
    try:
        columns, units = read_steps(steps)
    except OSError as e:
        return None, ["note: cannot read %s (%s); skipped" % (steps, e)]
    if "t" not in columns:
        return None, ["note: %s has no column 't'; skipped" % steps]
    t = columns["t"]
    if not t:
        return None, ["note: %s has no data rows; skipped" % steps]

    run_name = os.path.basename(os.path.normpath(os.path.abspath(run_dir)))
    summary = read_summary(os.path.join(run_dir, "summary.json"))
    notes = []
    title = run_name
    if summary is None:
        notes.append("note: no readable summary.json in %s" % run_dir)
    else:
        helix = summary.get("helix") or {}
        if helix.get("description"):
            title += ": " + str(helix["description"])
        status = summary.get("status")
        if status and status != "converged":
            title += "  [status: %s]" % status

    fig, axes = plt.subplots(3, 1, figsize=(9, 10), sharex=True)
    missing = []
    missing += plot_panel(axes[0], t, columns, units, STRAINS, "(a) strains")
    # Resultants are round-off against the stiffness times a unit strain.
    stiffness_scale = max([abs(v) for name in STIFFNESS if name in columns
                           for v in finite(columns[name])] + [0.0])
    missing += plot_panel(axes[1], t, columns, units, RESULTANTS,
                          "(b) resultants", scale=stiffness_scale)
    missing += plot_panel(axes[2], t, columns, units, STIFFNESS,
                          "(c) diagonal stiffness", log_if_positive=True)
    axes[2].set_xlabel("load parameter t")
    negative = [v for v in columns.get("n_negative_eigenvalues", []) if not math.isnan(v)]
    if negative and max(negative) > 0:
        title += "\nsolid: stable; dashed: unstable (up to %d negative eigenvalues)" % max(negative)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    out = os.path.join(run_dir, "steps.png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    if missing:
        notes.append("note: %s lacks column(s) %s" % (steps, ", ".join(missing)))
    return out, notes


def main(argv):
    args = argv[1:]
    if any(a in ("-h", "--help") for a in args):
        sys.stdout.write(USAGE)
        return 0
    if not args or any(a.startswith("-") and a != "-" for a in args):
        sys.stderr.write(USAGE)
        return 1

    plt = import_pyplot()
    if plt is None:
        reexec_with_system_python()
        sys.stderr.write("plot_steps.py: matplotlib cannot be imported by %s "
                         "(Debian: apt-get install python3-matplotlib)\n"
                         % sys.executable)
        return 2

    for arg in args:
        runs, notes = find_run_dirs(arg)
        for n in notes:
            print(n)
        for run in runs:
            out, notes = plot_run(plt, run)
            for n in notes:
                print(n)
            if out:
                print("wrote %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Generate the markdown parameter reference of rod_cross_section.

The reference is made from the program itself: `--print-parameters json`
gives every entry's default, pattern and documentation, `--print-parameters
prm` gives the declaration order (the JSON output is sorted by name).
Sections that differ only in a trailing number and declare the same entries
(Material 1 ... Material 4) are merged into one table whose Default column
lists the defaults that differ.

Usage:
  python3 scripts/make_parameter_reference.py [--exe PATH]
        print the markdown to standard output
  python3 scripts/make_parameter_reference.py [--exe PATH] --update FILE
        replace the generated block of FILE (between the BEGIN/END markers)
  python3 scripts/make_parameter_reference.py [--exe PATH] --check FILE
        exit 1 if the generated block of FILE is out of date

PATH defaults to $COSMO_BUILD_DIR/rod_cross_section, else
<repository>/build/rod_cross_section. Needs only the standard library.
Exit status: 0 success, 1 out of date (--check) or bad usage, 2 the program
could not be run or its output not understood.
"""

import json
import os
import re
import subprocess
import sys

BEGIN = "<!-- BEGIN GENERATED PARAMETER REFERENCE (scripts/make_parameter_reference.py) -->"
END = "<!-- END GENERATED PARAMETER REFERENCE -->"
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def default_exe():
    build = os.environ.get("COSMO_BUILD_DIR", "build")
    if not os.path.isabs(build):
        build = os.path.join(REPO, build)
    return os.path.join(build, "rod_cross_section")


def run(exe, fmt):
    out = subprocess.run([exe, "--print-parameters", fmt], check=True,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         universal_newlines=True)
    return out.stdout


def declaration_order(prm_text):
    """[(section path tuple, [entry names in order])] from the prm listing."""
    order, index = [], {}
    path = []
    for line in prm_text.splitlines():
        s = line.strip()
        if s.startswith("#") or not s:
            continue
        if s.startswith("subsection "):
            path.append(s[len("subsection "):].strip())
        elif s == "end":
            path.pop()
        elif s.startswith("set "):
            name = s[len("set "):].split("=", 1)[0].strip()
            key = tuple(path)
            if key not in index:
                index[key] = len(order)
                order.append((key, []))
            order[index[key]][1].append(name)
    return order


def lookup(tree, path):
    for p in path:
        tree = tree[p]
    return tree


UNBOUNDED = {"MAX_DOUBLE": None, "-MAX_DOUBLE": None, "2147483647": None,
       "4294967295": None}


def describe_range(kind, lo, hi):
    """'Double', '0', 'MAX_DOUBLE' -> 'real >= 0' and so on."""
    word = "real" if kind == "Double" else "integer"
    lo_v = None if lo in UNBOUNDED else lo
    hi_v = None if hi in UNBOUNDED else hi
    if lo_v is None and hi_v is None:
        return "any " + word
    if hi_v is None:
        return "%s ≥ %s" % (word, lo_v)
    if lo_v is None:
        return "%s ≤ %s" % (word, hi_v)
    return "%s from %s to %s" % (word, lo_v, hi_v)


def describe_pattern(p):
    """Turn a deal.II pattern description into readable text."""
    p = p.strip()
    m = re.fullmatch(r"\[Selection (.*?) ?\]", p)
    if m:
        return "one of " + ", ".join("`%s`" % o for o in m.group(1).split("|"))
    m = re.fullmatch(r"\[MultipleSelection (.*?) ?\]", p)
    if m:
        return ("comma-separated subset (possibly empty) of "
                + ", ".join("`%s`" % o for o in m.group(1).split("|")))
    m = re.fullmatch(r"\[(Double|Integer range) (-?[\w.+-]+?)\.\.\.(-?[\w.+-]+) \(inclusive\)\]", p)
    if m:
        return describe_range("Double" if m.group(1) == "Double" else "Integer",
                              m.group(2), m.group(3))
    m = re.fullmatch(r"\[List of <(.*)> of length (\d+)\.\.\.(\d+) \(inclusive\)\]", p)
    if m:
        inner = describe_pattern(m.group(1))
        lo, hi = m.group(2), m.group(3)
        if lo == hi:
            count = "%s comma-separated values" % lo
        elif lo == "0" and hi in UNBOUNDED:
            count = "comma-separated list (possibly empty)"
        else:
            count = "comma-separated list of %s to %s values" % (lo, hi)
        return "%s, each %s" % (count, inner)
    if p == "[Bool]":
        return "`true` or `false`"
    if p == "[Anything]":
        return "any text"
    return "`%s`" % p


def cell(text):
    """Escape text for a markdown table cell."""
    text = " ".join(str(text).split())
    return text.replace("|", "\\|").replace("*", "\\*")


def code(value):
    return "(empty)" if value == "" else "`%s`" % value.replace("|", "\\|")


def sections(tree, order):
    """[[section paths]] in declaration order; consecutive sections named
    'PREFIX N' with the same entries, documentation and patterns share one
    group."""
    groups, last_key = [], None
    for path, names in order:
        sig = [(n, lookup(tree, path + (n,))["documentation"],
                lookup(tree, path + (n,))["pattern_description"]) for n in names]
        m = re.fullmatch(r"(.*) (\d+)", path[-1]) if path else None
        key = (path[:-1], m.group(1), repr(sig)) if m else None
        if key is not None and key == last_key:
            groups[-1].append(path)
        else:
            groups.append([path])
        last_key = key
    return groups


def default_cell(tree, paths, name):
    values = [lookup(tree, p + (name,))["default_value"] for p in paths]
    if len(set(values)) == 1:
        return code(values[0])
    groups = []
    for p, v in zip(paths, values):
        label = p[-1].rsplit(" ", 1)[-1] if len(paths) > 1 else p[-1]
        if groups and groups[-1][0] == v:
            groups[-1][1].append(label)
        else:
            groups.append((v, [label]))
    prefix = paths[0][-1].rsplit(" ", 1)[0]
    return "; ".join("%s %s: %s" % (prefix, ", ".join(ls), code(v))
                     for v, ls in groups)


def generate(exe):
    tree = json.loads(run(exe, "json"))
    order = declaration_order(run(exe, "prm"))
    lines = []
    for paths in sections(tree, order):
        first, last = " / ".join(paths[0]), " / ".join(paths[-1])
        if not first:
            lines.append("### Top level (every application)")
        else:
            lines.append("### `%s`" % first if len(paths) == 1 else
                         "### `%s` … `%s`" % (first, last))
        lines.append("")
        if len(paths) > 1:
            lines.append("These %d sections declare the same entries; only some "
                         "defaults differ." % len(paths))
            lines.append("")
        lines.append("| Parameter | Default | Allowed values | Meaning |")
        lines.append("| --- | --- | --- | --- |")
        for name in dict(order)[paths[0]]:
            e = lookup(tree, paths[0] + (name,))
            lines.append("| `%s` | %s | %s | %s |" % (
                name, default_cell(tree, paths, name),
                cell(describe_pattern(e["pattern_description"])),
                cell(e["documentation"])))
        lines.append("")
    return "\n".join(lines).rstrip("\n") + "\n"


def splice(text, block):
    i, j = text.find(BEGIN), text.find(END)
    if i < 0 or j < i:
        raise ValueError("markers not found")
    return text[:i + len(BEGIN)] + "\n\n" + block + "\n" + text[j:]


def main(argv):
    args = argv[1:]
    exe, mode, target = default_exe(), None, None
    try:
        while args:
            a = args.pop(0)
            if a in ("-h", "--help"):
                sys.stdout.write(__doc__)
                return 0
            elif a == "--exe":
                exe = args.pop(0)
            elif a in ("--update", "--check"):
                mode, target = a, args.pop(0)
            else:
                raise IndexError
    except IndexError:
        sys.stderr.write(__doc__)
        return 1
    try:
        block = generate(exe)
    except (OSError, subprocess.CalledProcessError, ValueError, KeyError) as e:
        sys.stderr.write("make_parameter_reference.py: cannot get the parameters "
                         "from %s: %s\n" % (exe, e))
        return 2
    if mode is None:
        sys.stdout.write(block)
        return 0
    with open(target) as f:
        text = f.read()
    try:
        new = splice(text, block)
    except ValueError:
        sys.stderr.write("make_parameter_reference.py: %s lacks the lines\n  %s\n  %s\n"
                         % (target, BEGIN, END))
        return 1
    if mode == "--check":
        if new != text:
            print("%s: the parameter reference is out of date; run "
                  "python3 scripts/make_parameter_reference.py --update %s"
                  % (target, target))
            return 1
        print("%s: the parameter reference is up to date" % target)
        return 0
    if new != text:
        with open(target, "w") as f:
            f.write(new)
        print("updated %s" % target)
    else:
        print("%s already up to date" % target)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

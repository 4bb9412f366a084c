#!/usr/bin/env python3
"""Check doc/code-map.md against the code: every file it names exists, the
first function of each row (its primary implementation) is found in the
row's files, and every other `Name::name` it mentions exists somewhere in
the code. Fails (exit 1) listing the stale rows.

usage: check_code_map.py [repository root]
"""
import glob, os, re, sys

root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
code_dirs = ["include", "source", "applications", "tests", "scripts", "parameter_files", "benchmarks"]


def expand(path):
    """Paths of one file cell entry: {a,b} alternatives and globs."""
    m = re.search(r"\{([^}]*)\}", path)
    if m:
        out = []
        for alt in m.group(1).split(","):
            out += expand(path[: m.start()] + alt.strip() + path[m.end():])
        return out
    return sorted(glob.glob(os.path.join(root, path))) or [os.path.join(root, path)]


texts = {}


def text(path):
    if path not in texts:
        try:
            texts[path] = open(path, errors="replace").read()
        except OSError:
            texts[path] = None
    return texts[path]


everything = None


def all_code():
    global everything
    if everything is None:
        parts = []
        for d in code_dirs:
            for dirpath, _, files in os.walk(os.path.join(root, d)):
                for f in files:
                    if f.endswith((".h", ".cc", ".py", ".sh", ".prm", ".txt")):
                        parts.append(text(os.path.join(dirpath, f)) or "")
        everything = "\n".join(parts)
    return everything


def found(name, content):
    return content is not None and re.search(r"(?<![\w])" + re.escape(name) + r"(?![\w])", content)


problems, rows = [], 0
for number, line in enumerate(open(os.path.join(root, "doc", "code-map.md")), 1):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if not line.startswith("|") or len(cells) != 4 or cells[0] in ("manual section", "---") or set(cells[0]) <= {"-"}:
        continue
    rows += 1
    files_cell, functions_cell = cells[2], cells[3]
    files = []
    for entry in files_cell.split(";"):
        entry = entry.strip()
        if not entry or entry in ("—", "-"):
            continue
        for p in expand(entry):
            if not os.path.exists(p):
                problems.append("line %d: no file %s" % (number, os.path.relpath(p, root)))
            files.append(p)
    names = re.findall(r"`([A-Za-z_~][\w:~<>]*)(?:\(\))?`", functions_cell)
    names = [n for n in names if "::" in n or re.match(r"^[a-z_]\w*$", n)]
    for k, n in enumerate(names):
        last = re.sub(r"<.*>", "", n).split("::")[-1]
        if k == 0 and files:
            parts = re.sub(r"<.*>", "", n).split("::")
            # A member defined in a .cc is defined as Class::name( there.
            def defines(p):
                t = text(p)
                if len(parts) >= 2 and parts[-2][:1].isupper() and p.endswith(".cc"):
                    return t is not None and ((parts[-2] + "::" + last) in t or (
                        re.search(r"\b(class|struct) " + parts[-2] + r"\b", t) and found(last, t)))
                return found(last, t)
            if not any(defines(p) for p in files):
                problems.append("line %d: `%s` not in %s" % (number, n, files_cell))
        elif not found(last, all_code()):
            problems.append("line %d: `%s` not found in the code" % (number, n))

for p in problems:
    print(p)
print("%d rows of doc/code-map.md checked, %d problems" % (rows, len(problems)))
sys.exit(1 if problems else 0)

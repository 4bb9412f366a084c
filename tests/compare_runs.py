#!/usr/bin/env python3
"""Do two runs have the same result? usage: compare_runs.py A B [table.csv ...]

Every number of the named tables and of summary.json (events, states,
stiffness, ...) must agree to 1e-12 relative (of the larger, or for a
table column of the largest finite value of its quantity: the columns of
one unit, e.g. the strains' [1] and [1/L], or of one name before its first
'_'; a stiffness entry K_a_b of sqrt(max |K_a_a| max |K_b_b|), the bound
its matrix puts on it: an entry that is zero by symmetry carries the
round-off of its matrix, not of itself, and the OpenBLAS threads of one
process and of a rank change it); wall times, file names, messages, the
rod law's description (it names the file it read and whether the run
computed or reused it) and
mpi_ranks, mumps_phases_on_all_ranks and factorization_memory (MPI ranks, the MUMPS phases
they shared, the memory MUMPS used) are not results. A resumed run goes on
from bitwise the state it saved,
so it reaches the uninterrupted numbers to round-off or better. Prints
what differs and exits 1 if anything does.
"""
import csv
import json
import math
import sys

SKIP = {"timings", "work_per_state", "seconds", "parameter_file", "message", "pid", "mpi_ranks", "mumps_phases_on_all_ranks", "factorization_memory", "law"}


def close(x, y, scale):
    if x == y or (math.isnan(x) and math.isnan(y)):
        return True
    return abs(x - y) <= 1e-12 * max(scale, abs(x), abs(y), 1e-300)


def walk(a, b, path, bad):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k in SKIP:
                continue
            if k not in a or k not in b:
                bad.append("%s/%s only in one run" % (path, k))
            else:
                walk(a[k], b[k], path + "/" + k, bad)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            bad.append("%s: %d against %d items" % (path, len(a), len(b)))
        for k, (x, y) in enumerate(zip(a, b)):
            walk(x, y, "%s[%d]" % (path, k), bad)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if not close(float(a), float(b), 0):
            bad.append("%s: %r against %r" % (path, a, b))
    elif a is None and b is None:
        pass
    elif a != b and not (isinstance(a, str) and a.endswith((".vtu", ".pvd", "/"))):
        bad.append("%s: %r against %r" % (path, a, b))


def main():
    a, b, tables = sys.argv[1], sys.argv[2], sys.argv[3:]
    bad = []
    for table in tables:
        ra = list(csv.reader(open(a + "/" + table)))
        rb = list(csv.reader(open(b + "/" + table)))
        if ra[0] != rb[0] or len(ra) != len(rb):
            bad.append("%s: %d against %d rows" % (table, len(ra), len(rb)))
            continue
        def quantity(name):
            return name[name.index("["):] if "[" in name else name.split(" ")[0].split("_")[0]

        scales, column_max = {}, {}
        for c, name in enumerate(ra[0]):
            for x in ra[1:]:
                try:
                    v = abs(float(x[c]))
                except ValueError:
                    continue
                if math.isfinite(v):
                    scales[quantity(name)] = max(scales.get(quantity(name), 0), v)
                    column_max[name.split(" ")[0]] = max(column_max.get(name.split(" ")[0], 0), v)

        def scale_of(name):
            key = name.split(" ")[0]
            parts = key.split("_")
            if len(parts) == 3 and parts[0] == "K":
                diagonal = ["K_%s_%s" % (p, p) for p in parts[1:]]
                if all(d in column_max for d in diagonal):
                    return math.sqrt(column_max[diagonal[0]] * column_max[diagonal[1]])
                return column_max.get(key, 0)
            return scales.get(quantity(name), 0)

        for c, name in enumerate(ra[0]):
            if name.split(" ")[0] in SKIP:
                continue
            col = [(float(x[c]), float(y[c])) for x, y in zip(ra[1:], rb[1:])]
            scale = scale_of(name)
            bad += ["%s column %s row %d: %r against %r" % (table, name, k + 1, x, y)
                    for k, (x, y) in enumerate(col) if not close(x, y, scale)][:2]
    try:
        sa, sb = json.load(open(a + "/summary.json")), json.load(open(b + "/summary.json"))
        walk(sa, sb, "summary.json", bad)
    except FileNotFoundError:
        pass  # a study: its table is its result
    for line in bad[:20]:
        print(line)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()

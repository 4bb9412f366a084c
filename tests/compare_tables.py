#!/usr/bin/env python3
"""A constitutive table of several MPI ranks against one process's.

usage: compare_tables.py ONE_THREAD TWO_THREADS RANKS [--resumed] [NEWTON]
       (run directories; NEWTON: the runs' Newton relative tolerance,
       default 1e-10; --resumed: RANKS was resumed on another number of
       ranks, so its rank 0 block is not one thread's run alone)

ONE_THREAD and TWO_THREADS are one process on one and two threads: their
largest difference is the round-off resolution R of the table (threaded
sums and BLAS kernels in another order), per quantity as a fraction of its
scale. RANKS (mpirun) must then
 - hold rank 0's block (the serpentine's first ceil(N/ranks) rows)
   bitwise as ONE_THREAD does: each rank runs on one thread;
 - agree with ONE_THREAD everywhere to 10 max(R, newton): a later rank
   reaches its first point by another path, so its states are the same
   only to Newton's stopping test, a scaled residual below `newton` (the
   'Relative tolerance' of 'Newton', 1e-10 by default; measured 1.9e-10 of
   m3's scale, 10x for the conditioning of the condensed resultants);
 - have a table.h5 with the values of its table.csv, and the attributes
   and dimension scales of ONE_THREAD's.
The scale of a quantity: K_ab is measured against sqrt(max K_aa max K_bb),
a resultant n_a or m_a against sqrt(2 max K_aa max Psi) (Psi ~ K e^2 / 2,
so K e ~ sqrt(2 K Psi)): the free strains' resultants are held at 0 and are
round-off themselves, not a scale.
"""
import csv
import math
import sys

import h5py
import numpy as np


def table(d):
    rows = list(csv.reader(open(d + "/table.csv")))
    return rows[0], np.array([[float(x) for x in r] for r in rows[1:]]), rows[1:]


def scaled_difference(header, a, b):
    """Largest |a - b| / scale over the columns, and the column where it is."""
    name = [h.split(" ")[0] for h in header]
    col = {n: k for k, n in enumerate(name)}
    scale = {}
    diag = {}
    for n in name:
        if n.startswith("K_"):
            _, x, y = n.split("_")
            if x == y:
                diag[x] = np.nanmax(np.abs(a[:, col[n]]))
    energy = np.nanmax(np.abs(a[:, col["energy"]]))
    strains = ["nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"]
    for k, n in enumerate(["n1", "n2", "n3", "m1", "m2", "m3"]):
        # Psi ~ K e^2 / 2, so a resultant K e ~ sqrt(2 K Psi).
        scale[n] = math.sqrt(2 * diag[strains[k]] * energy)
    for n in name:
        if n.startswith("K_"):
            _, x, y = n.split("_")
            scale[n] = math.sqrt(diag[x] * diag[y])
        elif n not in scale:
            scale[n] = np.nanmax(np.abs(a[:, col[n]]))
    worst, where = 0.0, ""
    for n in name:
        d = np.abs(a[:, col[n]] - b[:, col[n]])
        d = d[~np.isnan(d)]
        if d.size and scale[n] > 0:
            e = d.max() / scale[n]
            if e > worst:
                worst, where = e, n
    return worst, where


def main():
    one, two, ranks = sys.argv[1:4]
    rest = sys.argv[4:]
    resumed = "--resumed" in rest
    rest = [x for x in rest if x != "--resumed"]
    newton = float(rest[0]) if rest else 1e-10
    fail = False

    def check(ok, what):
        nonlocal fail
        print("  %s  %s%s" % ("ok  " if ok else "FAIL", ranks + ": " if resumed else "", what))
        fail |= not ok

    h1, a1, raw1 = table(one)
    h2, a2, _ = table(two)
    hr, ar, rawr = table(ranks)
    check(h1 == hr and a1.shape == ar.shape, "the same columns and %d rows" % len(a1))
    if fail:
        return 1
    check(np.array_equal(a1[:, :3], ar[:, :3]), "the same grid points (bitwise) and converged flags")
    n_ranks = 2
    block0 = (len(a1) + n_ranks - 1) // n_ranks
    if not resumed:
        check(raw1[:block0] == rawr[:block0],
              "rank 0's %d rows bitwise those of one process on one thread" % block0)
    R, where_R = scaled_difference(h1, a1, a2)
    tol = 10 * max(R, newton)
    e, where = scaled_difference(h1, a1, ar)
    against = "the uninterrupted run" if resumed else "one process"
    check(e <= tol, "every number against %s: %.2g (%s), tolerance %.2g = "
          "10 max(R, Newton's %.0e), R = %.2g (%s one thread against two)"
          % (against, e, where, tol, newton, R, where_R + "," if where_R else "not measured here:"))

    # table.h5: written collectively; its values are the CSV's.
    f, g = h5py.File(one + "/table.h5", "r"), h5py.File(ranks + "/table.h5", "r")
    check(sorted(f.keys()) == sorted(g.keys()), "table.h5: the same datasets")
    col = {h.split(" ")[0]: k for k, h in enumerate(hr)}
    n1, n2 = g["energy"].shape
    s1, s2 = g["strain_1"][()], g["strain_2"][()]
    same = True
    for r in ar:
        i = int(np.argmin(np.abs(s1 - r[0])))
        j = int(np.argmin(np.abs(s2 - r[1])))
        same &= s1[i] == r[0] and s2[j] == r[1]
        same &= bool(g["converged"][i, j]) == bool(r[2])
        same &= g["energy"][i, j] == r[col["energy"]] or (math.isnan(r[col["energy"]]) and math.isnan(g["energy"][i, j]))
        for k, n in enumerate(["n1", "n2", "n3", "m1", "m2", "m3"]):
            same &= g["resultants"][i, j, k] == r[col[n]] or math.isnan(r[col[n]])
    check(same and n1 * n2 == len(ar), "table.h5 holds table.csv's %d points, bitwise" % len(ar))
    attrs = lambda h: {k: (v.decode() if isinstance(v, bytes) else str(v)) for k, v in h.attrs.items()}
    check(attrs(f) == attrs(g), "table.h5: the file attributes of one process's")
    check([d.label for d in g["stiffness"].dims] == [d.label for d in f["stiffness"].dims]
          and len(g["energy"].dims[0]) == 1, "table.h5: the dimension scales of one process's")
    return 1 if fail else 0


if __name__ == "__main__":
    sys.exit(main())

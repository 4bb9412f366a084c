#!/usr/bin/env python3
"""Read a cosmo constitutive table (table.h5 of strip or rod_cross_section)
and interpolate it, as a rod simulator would.

The file describes itself (doc/user-guide-strip.md, "Constitutive tables"):
datasets strain_1, strain_2 (the grid axes, HDF5 dimension scales),
energy [n1, n2], resultants [n1, n2, 6], stiffness [n1, n2, 6, 6] and
converged [n1, n2] (1/0), each with 'units' and 'description'; the file's
attributes name the application, version, axis strains, free strains, held
resultants and every parameter of the run.

As a module:
    from read_table import read_table, interpolate
    t = read_table("table.h5")
    e, n, K = interpolate(t, 0.05, 0.1)   # energy, resultants, stiffness

From the command line:
    python3 scripts/read_table.py table.h5            # describe the table
    python3 scripts/read_table.py table.h5 E1 E2      # and interpolate at (E1, E2)

Interpolation is bicubic (scipy's RegularGridInterpolator, 'cubic', needs
>= 4 points per axis; linear otherwise) on each component; a point outside
the grid, or in a cell with a point that did not converge, is an error.
Requires h5py, numpy and scipy (Debian: python3-h5py python3-numpy
python3-scipy; scripts/setup.sh installs them).
"""
import sys

import h5py
import numpy as np


def read_table(path):
    """The table as a dict: axes, names, units, arrays and attributes."""
    with h5py.File(path, "r") as f:
        t = {name: f[name][()] for name in ("strain_1", "strain_2", "energy", "resultants",
                                             "stiffness", "converged")}
        t["units"] = {name: f[name].attrs["units"] for name in f}
        t["attributes"] = {k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()}
        # The axes are the dimension scales of the data (h5py: dims).
        assert f["energy"].dims[0][0].name == "/strain_1" and f["energy"].dims[1][0].name == "/strain_2"
    t["converged"] = t["converged"].astype(bool)
    t["names"] = (t["attributes"]["strain_1_name"], t["attributes"]["strain_2_name"])
    t["resultant_order"] = [s.strip() for s in t["attributes"]["resultant_order"].split(",")]
    t["strain_order"] = [s.strip() for s in t["attributes"]["strain_order"].split(",")]
    return t


def interpolate(t, e1, e2):
    """Energy, resultants (6) and stiffness (6x6) at the strains (e1, e2)."""
    from scipy.interpolate import RegularGridInterpolator
    x, y = t["strain_1"], t["strain_2"]
    if not (x[0] <= e1 <= x[-1] and y[0] <= e2 <= y[-1]):
        raise ValueError("(%g, %g) is outside the table [%g, %g] x [%g, %g]" % (e1, e2, x[0], x[-1], y[0], y[-1]))
    i = min(np.searchsorted(x, e1, side="right") - 1, len(x) - 2) if len(x) > 1 else 0
    j = min(np.searchsorted(y, e2, side="right") - 1, len(y) - 2) if len(y) > 1 else 0
    if not t["converged"][i:i + 2, j:j + 2].all():
        raise ValueError("(%g, %g) lies in a cell with a point that did not converge" % (e1, e2))
    method = "cubic" if min(len(x), len(y)) >= 4 else "linear"

    def at(data):
        flat = data.reshape(len(x), len(y), -1)
        return np.array([RegularGridInterpolator((x, y), flat[:, :, c], method=method)((e1, e2))
                         for c in range(flat.shape[2])]).reshape(data.shape[2:])

    return float(at(t["energy"][:, :, None])), at(t["resultants"]), at(t["stiffness"])


def main(argv):
    if len(argv) not in (2, 4):
        print(__doc__)
        return 1
    t = read_table(argv[1])
    a = t["attributes"]
    print("%s %s table of (%s, %s): %d x %d points, %d converged" % (
        a["application"], a["version"], t["names"][0], t["names"][1], len(t["strain_1"]),
        len(t["strain_2"]), t["converged"].sum()))
    print("  free strains: %s; held resultants: %s" % (a["free_strains"], a["held_resultants"]))
    print("  units: energy %s; resultants %s" % (t["units"]["energy"], t["units"]["resultants"]))
    if len(argv) == 4:
        e1, e2 = float(argv[2]), float(argv[3])
        energy, n, K = interpolate(t, e1, e2)
        print("at %s = %g, %s = %g:" % (t["names"][0], e1, t["names"][1], e2))
        print("  energy %.10g" % energy)
        print("  " + "  ".join("%s %.6g" % (name, v) for name, v in zip(t["resultant_order"], n)))
        print("  stiffness (rows %s; columns %s):" % (", ".join(t["resultant_order"]), ", ".join(t["strain_order"])))
        for row in K:
            print("   " + " ".join("%12.6g" % v for v in row))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

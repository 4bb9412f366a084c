#!/usr/bin/env python3
"""Cosserat against Kirchhoff over a critical-growth study (part 3).

usage: model_comparison.py COSSERAT_DIR KIRCHHOFF_DIR

Both directories are the outputs of a pair of studies that differ only in the
model, e.g. parameter_files/plate_rod/studies/
critical_growth_vs_{rim_stiffness,thickness}_{cosserat,kirchhoff}.prm
(sweep.csv, parameters.prm). At every swept value the Cosserat threshold
must lie below the Kirchhoff one by Mindlin's shift: with the Kirchhoff
penalty p, Delta_C/Delta_K - 1 = -(1 - 1/p) r/(1 + r), r = P/(ks G h), P the
critical hoop compression of the plate (section 1-2 of
doc/theory-plate-rod.md: P = Delta k EA/(R (EA + k)), k = R E h/(1 - v)).
Tolerance: 2 % + 2r of the shift (the relation is the first order in r: the
next term, of relative size O(r) with a coefficient of order one (taken <= 2), is not
zero for an elastically restrained edge; r <= 5e-4 over the rim-stiffness
study, up to 0.04 at h/R = 0.1; the finite-strain offset acts on both
models alike) plus the two thresholds' round-off resolutions relative to t,
where those are below half the shift;
where not, only the order (Cosserat below) is checked. Exit 1 on failure.
"""
import csv
import re
import sys


def read(d):
    rows = list(csv.DictReader(open(d + "/sweep.csv")))
    text = open(d + "/parameters.prm").read()

    def entry(name, default):
        m = re.search(r"^\s*set %s\s*=\s*([^#\n]+)" % re.escape(name), text, re.M)
        return m.group(1).strip() if m else default

    col = lambda name: [float(r[next(k for k in r if k.split(" [")[0] == name)]) for r in rows]
    return {"value": col("value"), "t": col("t_critical"), "res": col("t_resolution"),
            "D": col("mismatch_critical"), "entry": entry}


cos, kir = read(sys.argv[1]), read(sys.argv[2])
e = kir["entry"]
R = float(e("Radius", "1"))
E, v = float(e("Young's modulus", "1")), float(e("Poisson's ratio", "0.3"))
p = float(e("Shear penalty factor", "100"))
# The swept entry: the rim's stiffnesses (through a template) or the thickness.
swept = e("Entry", "")
rim = e("Template", "") if swept == "Rim rod/Stiffnesses" else e("Stiffnesses", "")
EA = float(rim.split(",")[2])
failed = 0
for i, value in enumerate(kir["value"]):
    assert cos["value"][i] == value, "the studies sweep different values"
    h = value if swept == "Plate/Thickness" else float(e("Thickness", "0.01"))
    k = R * E * h / (1 - v)
    ksGh = 5.0 / 6 * E / (2 * (1 + v)) * h
    P = kir["D"][i] * k * EA / (R * (EA + k))
    r = P / ksGh
    mindlin = -(1 - 1 / p) * r / (1 + r)
    diff = cos["D"][i] / kir["D"][i] - 1
    res = cos["res"][i] / cos["t"][i] + kir["res"][i] / kir["t"][i]
    ok = diff < 0
    if res < 0.5 * abs(mindlin):
        ok = ok and abs(diff - mindlin) <= (0.02 + 2 * r) * abs(mindlin) + res
        how = "within 2 %% + 2r = %.2g %% + resolution %.2g" % (100 * (0.02 + 2 * r), res)
    else:
        how = "order only (resolution %.2g above half the shift)" % res
    print("%s  %s = %g: Cosserat/Kirchhoff - 1 = %.4e, Mindlin %.4e (%.2f %%), %s"
          % ("ok  " if ok else "FAIL", swept, value, diff, mindlin, 100 * abs(diff / mindlin - 1), how))
    failed += not ok
sys.exit(1 if failed else 0)

#!/usr/bin/python3
"""The strip's constitutive table against Audoly & Neukirch's ribbon energy
(JMPS 2021) off the axes as well as on them.

Runs parameter_files/strip/ribbon_comparison.prm on a coarser grid of
(kappa1, kappa3) (6 x 6 points: Searle parameters up to 100, twists
tau w^2/h up to 20, most of them combined bending and twist) and requires at
every point with W > 0

    |W_strip / W_AN - 1| <= 1.25 eps,   eps = h / (w sqrt(3 ks)).

Why eps: the strip is a Cosserat (Naghdi) plate, AN's ribbon is a Kirchhoff
one; their difference at small strain is the torsion boundary layer of width
h/sqrt(12 ks) at the free edges, which lowers the twisting stiffness by
GJ/GJ0 - 1 = -(2 ell/w) tanh(w/(2 ell)) = -eps (doc/theory-strip.md 2.4;
0.0063 here) and leaves bending alone (measured on the bending axis: 0.012
eps); a combined state lies between. The factor 1.25 covers the finite-strain
and discretization terms beyond it (measured: 0.96 eps at pure twist, the
worst point). Were a strain that the ribbon model leaves free held at zero
(the example's former 'Free strains = nu3'), the off-axis energies would be
up to 83 % (130 eps) too high.

usage: ribbon_comparison.py <strip> <ribbon_comparison.prm> <scratch dir>
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "scripts"))
import ribbon_models as rm  # noqa: E402

exe, prm, scratch = sys.argv[1:4]
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
text = open(prm).read()
text = re.sub(r"(?m)^(\s*set Output directory\s*=).*$", r"\1 " + scratch + "/out", text)
text = re.sub(r"(?m)^(\s*set First range\s*=).*$", r"\1 0, 1, 6", text)
text = re.sub(r"(?m)^(\s*set Second range\s*=).*$", r"\1 0, 0.2, 6", text)
open(os.path.join(scratch, "run.prm"), "w").write(text)
subprocess.run([exe, "--quiet", os.path.join(scratch, "run.prm")], check=True)

w, h, E, v = 1.0, 0.01, 1.0, 0.3
assert re.search(r"(?m)^\s*set Width\s*=\s*1\s*$", text) and re.search(r"(?m)^\s*set Thickness\s*=\s*0.01\s*$", text)
eps = h / (w * math.sqrt(3.0 * rm.KS))
tol = 1.25 * eps
worst, n, n_off = (0.0, None), 0, 0
for r in csv.DictReader(open(os.path.join(scratch, "out", "table.csv"))):
    k, t, W = float(r["kappa1"]), float(r["kappa3"]), float(r["energy"])
    assert float(r["converged"]) == 1, "point (%g, %g) did not converge" % (k, t)
    if k == 0 and t == 0:
        continue
    d = W / rm.W_audoly_neukirch(k, t, w, h, E, v) - 1
    n += 1
    n_off += k != 0 and t != 0
    if abs(d) > abs(worst[0]):
        worst = (d, (k, t))
print("%d points (%d with bending and twist): largest |W/W_AN - 1| = %.3g at (kappa1, kappa3) = %s; "
      "tolerance 1.25 eps = %.3g" % (n, n_off, abs(worst[0]), worst[1], tol))
if abs(worst[0]) > tol:
    sys.exit("FAIL: the table departs from Audoly-Neukirch by more than the boundary-layer bound")

#!/usr/bin/env python3
"""The constitutive table of rod_cross_section as a rod simulator reads it
(scripts/read_table.py): run parameter_files/rod_cross_section/
table_bending_twist.prm (a circle, kappa1 x kappa3 in [-0.2, 0.2]^2, nu3
free) and check

- the file describes itself: units and descriptions on every dataset,
  component names, the strain axes attached as dimension scales, converged
  an integer mask, the application, version, free strains, held resultants
  and the run's parameters as attributes;
- what the physics fixes: odd symmetry m1(-k1, k3) = -m1(k1, k3) and
  m3(k1, -k3) = -m3(k1, k3), the energy even in both (the circle and its
  mesh are symmetric; each point is its own Newton solve, converged to
  the default relative tolerance 1e-10: asserted to 1e-8 of the scale,
  measured 1.4e-10); the stiffness symmetric (1e-10); the held axial
  force n3 = 0 (1e-8 EI, measured 1.6e-10);
- small strain: m1 = EI k1, m3 = GJ k3 with EI = pi/4 and GJ = pi/(4 (1 +
  nu)) (the R = 1 disc at 2 refinements: mapping error 3e-5), up to the
  finite-strain terms O(k^2 R^2) = 1e-2 at k = 0.1: asserted there to
  2 %;
- interpolation: exact at the grid points (1e-12), and between them the
  resultants within the cubic interpolant's error of the energy's
  derivative (central difference of the interpolated energy; the cubic
  spline error O(h^4) at h = 0.1: measured 7e-4 of the scale, asserted 3e-3).

usage: table_h5.py <rod_cross_section executable> <repository root> <scratch dir>
"""
import math, os, re, shutil, subprocess, sys

import numpy as np

exe, root, scratch = (os.path.abspath(a) for a in sys.argv[1:4])
sys.path.insert(0, os.path.join(root, "scripts"))
from read_table import read_table, interpolate  # noqa: E402

shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(scratch)
prm = open(os.path.join(root, "parameter_files/rod_cross_section/table_bending_twist.prm")).read()
prm = re.sub(r"set Output directory *=.*", "set Output directory = " + os.path.join(scratch, "out"), prm)
open(os.path.join(scratch, "run.prm"), "w").write(prm)
subprocess.run([exe, "--quiet", os.path.join(scratch, "run.prm")], check=True, cwd=root)
path = os.path.join(scratch, "out", "table.h5")

failures = 0


def check(what, ok, detail=""):
    global failures
    print(("  ok    " if ok else "  FAIL  ") + what + ("  (" + detail + ")" if detail else ""))
    failures += 0 if ok else 1


t = read_table(path)
a = t["attributes"]
check("application and version recorded", a["application"] == "rod_cross_section" and a["version"] != "")
check("axes named kappa1, kappa3", t["names"] == ("kappa1", "kappa3"))
check("free strains recorded", a["free_strains"] == "nu3", a["free_strains"])
check("held resultants recorded", a["held_resultants"] == "n3 = 0", a["held_resultants"])
check("the run's parameters recorded", "Constitutive table/First strain = kappa1" in a["parameters"])
check("every dataset has units", all(t["units"][k] for k in ("strain_1", "strain_2", "energy", "resultants",
                                                              "stiffness", "converged")))
check("curvature axes in 1/L", t["units"]["strain_1"] == "1/L" and t["units"]["strain_2"] == "1/L")
check("all 25 points converged", t["converged"].all() and t["converged"].size == 25)

E, nu, R = 1.0, 0.3, 1.0
EI, GJ = math.pi / 4 * E * R**4, math.pi / 2 * E / (2 * (1 + nu)) * R**4
k1, k3 = t["strain_1"], t["strain_2"]
n = t["resultants"]
scale = EI * 0.2
check("m1 odd in kappa1", np.abs(n[:, :, 3] + n[::-1, :, 3]).max() < 1e-8 * scale)
check("m3 odd in kappa3", np.abs(n[:, :, 5] + n[:, ::-1, 5]).max() < 1e-8 * scale)
check("energy even in both", np.abs(t["energy"] - t["energy"][::-1, ::-1]).max() < 1e-8 * scale * 0.2)
K = t["stiffness"]
check("stiffness symmetric", np.abs(K - np.swapaxes(K, 2, 3)).max() < 1e-10 * EI)
check("held axial force n3 = 0", np.abs(n[:, :, 2]).max() < 1e-8 * EI)
index = lambda axis, v: int(np.argmin(np.abs(axis - v)))
m1 = n[index(k1, 0.1), index(k3, 0), 3]
m3 = n[index(k1, 0), index(k3, 0.1), 5]
check("m1 = EI kappa1 at kappa1 = 0.1 (2 %)", abs(m1 - EI * 0.1) < 0.02 * EI * 0.1, "%.6g vs %.6g" % (m1, EI * 0.1))
check("m3 = GJ kappa3 at kappa3 = 0.1 (2 %)", abs(m3 - GJ * 0.1) < 0.02 * GJ * 0.1, "%.6g vs %.6g" % (m3, GJ * 0.1))

worst = 0
for i in range(len(k1)):
    for j in range(len(k3)):
        e, r, S = interpolate(t, k1[i], k3[j])
        worst = max(worst, abs(e - t["energy"][i, j]), np.abs(r - n[i, j]).max(), np.abs(S - K[i, j]).max())
check("interpolation exact at the grid points", worst < 1e-12, "%.2g" % worst)
h = 1e-4
for (x, y) in [(0.05, 0.1), (-0.13, 0.07)]:
    _, r, _ = interpolate(t, x, y)
    d1 = (interpolate(t, x + h, y)[0] - interpolate(t, x - h, y)[0]) / (2 * h)
    d3 = (interpolate(t, x, y + h)[0] - interpolate(t, x, y - h)[0]) / (2 * h)
    check("between points: m1 = dPsi/dkappa1 of the interpolants at (%g, %g)" % (x, y),
          abs(d1 - r[3]) < 3e-3 * EI * 0.2, "%.6g vs %.6g" % (d1, r[3]))
    check("between points: m3 = dPsi/dkappa3 of the interpolants at (%g, %g)" % (x, y),
          abs(d3 - r[5]) < 3e-3 * GJ * 0.2, "%.6g vs %.6g" % (d3, r[5]))
try:
    interpolate(t, 0.3, 0)
    check("a point outside the grid is an error", False)
except ValueError as e:
    check("a point outside the grid is an error", "outside the table" in str(e))
print("%d check(s) FAILED" % failures if failures else "all checks passed")
sys.exit(1 if failures else 0)

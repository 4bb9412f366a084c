#!/usr/bin/env python3
"""validation.strip_seed_pod: a strip whose stress-free plate is a saddle,
principal curvatures +-kappa0 at +-45 degrees (natural curvature k12 =
kappa0), against doc/theory-strip.md 8:

1. the helicoid (narrow strips): the twist tau = -kappa3 solves
   x + (1 + nu) wt^4 x^3 / 60 = 1, x = tau/kappa0, wt = w sqrt(kappa0/h),
   at wt = 0.5, 1 and 2; kappa1 = 0 (the saddle does not bend it);
2. the pitchfork where the helicoid gives way to the helix: its critical
   width wt_c = w sqrt(kappa0 t_c/h) is one number for every w and h, up to
   the plate's O(h/w) (three strips, h/w halved twice: the differences fall
   at first order and all three agree to 0.2 %);
3. the helix (wide strips): kappa1 and kappa3 tend to -(1 - nu) kappa0/2, the
   cylinder along the saddle's positive principal direction, at first order
   in 1/wt (the free edges' boundary layers).

usage: seed_pod.py <strip executable> <scratch directory>
"""
import json
import math
import os
import subprocess
import sys

NU = 0.3


def run(exe, directory, name, width, thickness, curvature, path):
    """One strip run at its natural shape; returns summary.json."""
    out = os.path.join(directory, name)
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write(f"""subsection Strip
  set Width = {width!r}
  set Thickness = {thickness!r}
  set Number of cells = {80 if path == 'wide' else 40}
  set Natural curvature = {curvature}
end
subsection Plate material
  set Young's modulus = 1
  set Poisson's ratio = {NU}
end
subsection Rod strains
  set Mode = natural shape
end
""")
        if path == "critical":
            f.write("""subsection Path following
  set Method = arclength
end
subsection Arclength continuation
  set Parameter range = 0, 1
  set Maximum step = 0.05
  set Stop at first event = true
end
""")
        elif path == "wide":
            # Small steps, so that the path stays on the stable branch the
            # imperfection selects.
            f.write("""subsection Continuation
  set Initial step = 0.01
  set Maximum step = 0.02
end
""")
        f.write(f"subsection Output\n  set Output directory = {out}\nend\n")
    subprocess.run([exe, "--quiet", prm], check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def helicoid_twist(wt):
    """x of x + (1 + nu) wt^4 x^3 / 60 = 1 by Newton."""
    a, x = (1 + NU) * wt**4 / 60, 1.0
    for _ in range(50):
        x -= (x + a * x**3 - 1) / (1 + 3 * a * x**2)
    return x


def main():
    exe, directory = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    os.makedirs(directory, exist_ok=True)
    failures = []

    def check(ok, text):
        print(("ok   " if ok else "FAIL ") + text)
        if not ok:
            failures.append(text)

    # 1. The helicoid: w = 1, h = 0.01 (h/w = 0.01), kappa0 = wt^2 h/w^2.
    # Resolution: the closed form neglects the free edges' O(h/w) share of
    # the torsional stiffness (doc/theory-strip.md 2.4) and the plate's
    # shear; measured agreement 0.2 % at wt = 0.5 (of a 0.14 % effect: the
    # bound is on delta = 1 - x, 3 % of it) and better than 0.5 % of x.
    for wt in (0.5, 1.0, 2.0):
        kappa0 = wt**2 * 0.01
        s = run(exe, directory, "helicoid-%g" % wt, 1.0, 0.01, "0; 0; %r*t" % kappa0, "natural")
        x, e = helicoid_twist(wt), s["strains"]
        measured = -e["kappa3"] / kappa0
        check(s["status"] == "converged", "helicoid wt = %g: converged" % wt)
        check(abs(measured - x) <= 0.03 * (1 - x) + 1e-4,
              "helicoid wt = %g: tau/kappa0 = %.6f, closed form %.6f (1 - x = %.5f)" % (wt, measured, x, 1 - x))
        check(abs(e["kappa1"]) <= 1e-9 * kappa0 and abs(e["kappa2"]) <= 1e-9 * kappa0,
              "helicoid wt = %g: kappa1 = %g, kappa2 = %g (no bending)" % (wt, e["kappa1"], e["kappa2"]))

    # 2. The pitchfork, at one wt_c for every (w, h): kappa0 = 1.
    wtc = []
    for w, h in ((1.0, 0.01), (0.5, 0.0025), (0.25, 0.000625)):
        s = run(exe, directory, "critical-%g" % w, w, h, "0; 0; t", "critical")
        events = [e for e in s["events"] if e["kind"] == "branch point"]
        check(len(events) == 1, "critical w = %g, h = %g: one branch point located" % (w, h))
        if events:
            wtc.append(w * math.sqrt(events[0]["t"] / h))
            print("     wt_c = %.6f (h/w = %g)" % (wtc[-1], h / w))
    if len(wtc) == 3:
        d1, d2 = wtc[0] - wtc[1], wtc[1] - wtc[2]
        check(1.4 <= d1 / d2 <= 2.8, "wt_c converges at first order in h/w: differences %.2e, %.2e (ratio %.2f)"
              % (d1, d2, d1 / d2))
        check((max(wtc) - min(wtc)) / min(wtc) < 2e-3, "wt_c the same to 0.2 %%: %s" % wtc)
        print("     extrapolated to h/w -> 0: wt_c = %.4f" % (wtc[2] - d2 * d2 / (d1 - d2)))

    # 3. The helix: kappa0 t^2 (the branch point early on the path, at t =
    # wt_c/wt), an imperfection k22 = -0.02 t (1 - t) that picks kappa1 < 0
    # and is gone at t = 1; h = 0.01, wt = 10 and 20.
    limit = (1 - NU) / 2
    deviation = []
    for w in (1.0, 2.0):
        s = run(exe, directory, "helix-%g" % w, w, 0.01, "0; -0.02*t*(1-t); t^2", "wide")
        e = s["strains"]
        check(s["status"] == "converged" and s["stability"]["n_negative_eigenvalues"] == 0,
              "helix wt = %g: converged and stable" % (10 * w))
        mean = -(e["kappa1"] + e["kappa3"]) / 2
        deviation.append(mean - limit)
        print("     wt = %g: kappa1 = %.5f, kappa3 = %.5f, their mean %.5f against %.5f"
              % (10 * w, e["kappa1"], e["kappa3"], mean, limit))
        last = (e["kappa1"], e["kappa3"])
    check(1.4 <= deviation[0] / deviation[1] <= 2.8,
          "helix: the mean's distance to (1 - nu)/2 falls at first order in 1/wt: %.4f, %.4f"
          % tuple(deviation))
    # Resolution at wt = 20: the O(1/wt) distance, 1.7 % for the mean and
    # 2.8 % for kappa3 measured: 4 % bounds both curvatures.
    check(all(abs(-k - limit) <= 0.04 * limit for k in last),
          "helix wt = 20: kappa1, kappa3 within 4 %% of -(1 - nu)/2: %.5f, %.5f" % last)

    if failures:
        print("%d check(s) failed" % len(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()

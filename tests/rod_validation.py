#!/usr/bin/env python3
"""Validation of the rod application against closed forms (doc/theory-rod.md 7).

usage: rod_validation.py <rod executable> <case> <scratch directory>

Cases:
  helix   a rod clamped at one end, its natural strains (with shear, stretch
          and a coupled 6x6 law) ramped from straight: at t = 1 the free end
          is where the exact constant-strain curve H(s) = exp(s xi) puts it,
          on every mesh (3, 8 and 40 elements), the energy zero.
  rollup  a cantilever whose end is turned by 2 pi t about e2, its position
          free: at t = 1 an exact circle on every mesh (4, 7 and 30
          elements): the end back at the clamp, the end moment 2 pi B2 / L,
          no end force.
  euler   clamped-clamped, the end pushed by t L: the first branch point at
          the exact threshold of the discrete rod, P_h [lambda (1 + T^2/3)
          + P_h / GA] = 4 B T^2 / h^2 with T = tan(pi h / L) and lambda =
          1 - P_h / EA (theory-rod.md 7.3), on 8, 20 and 40 elements; the
          threshold converging to the continuum's P [lambda + P / GA] =
          4 pi^2 B / L^2 at second order in h.
  section a rod on the law of part-1 sections computed by the run itself (a
          rod_cross_section sweep of a disc with growth 1 + p X1, whose
          natural curvature is kappa2 = -p exactly): the family interpolated
          in p = 0.25 t s along a cantilever of length 2; at t = 1 the
          clothoid theta(s) = -s^2/8, whose end (Fresnel integrals) the
          meshes of 10, 20 and 40 elements approach at second order; the
          sections reused by a second run; a p past the family stops the
          path (exit 2, the range named); one section (p = 0.3) closes a
          cantilever of length 2 pi / 0.3 into a circle.
  table   a ribbon on the strip's nonlinear law (a strip table.h5 of (kappa1,
          kappa3), w/h = 20, the rest free): bent and twisted uniformly by
          its end's rotation, its end moment against the strip computed
          directly there, within the cubic Hermite bound on tables of 11
          and 21 points in kappa1; bent past the grid, the path stops with
          the strain and the range named (exit 2).
  elastica the pinned-pinned rod pushed past its Euler threshold and
          followed on its buckled branch (arclength, branch switching) to
          35 % end shortening: the end load against Euler's elastica,
          P = 4 K(k)^2 B/L^2 at D/L = 2 E(k)/K(k) - 1 (complete elliptic
          integrals), converging at second order on 20, 40, 80 elements.
  clamped_link a rod clamped at both ends, bowed, twisted by 3 t turns and
          shortened: Tw + Wr of the rod closed far out along its clamps'
          line equals the clamps' 3 t turns at every state.
  perversion a tendril on a part-1 grown disc (natural curvature 20/L), clamped, held straight under
          tension and its ends brought together without turning them: a
          stable path to two helices of opposite handedness (the torsion's
          halves), Tw + Wr = 0 throughout, the turns touching (self-contact)
          where without contact they overlap.
  section_stress the body coloured by the section's stress at the rod's own
          strains (theory-rod.md 10): the tendril's disc (stress-free at its
          natural kappa2 = -20) bent uniformly by an end rotation; the
          stress the body carries, part 1's linearized about the natural
          state, against part 1 run directly at the element's strains:
          their difference is the linearization's O(|e|^2), halving the
          rotation quarters it.
  twisted_threshold a straight isotropic rod clamped at both ends, pulled
          (T = 400 B/L^2), twisted by 7 turns and shortened until it buckles:
          the double branch point (0 -> 2) at the tension of the clamped
          twisted rod's determinant (theory-rod.md 9.3), approached at second
          order on 100 and 200 elements.
  overwinding a perverted tendril pulled (quadratic law, B = 1, kappa0 = 20/L,
          L = 3): formed at C = B/1.3, its torsion then softened to C = B/4
          at fixed D ('Stiffness factors'), then pulled to D = 0.96 L. In the
          middle of each half the helix obeys the closed form of a helix
          under pure tension with no axial moment (theory-rod.md 7.8),
          rho = B kappa0 sqrt(1 - x^2) / (B (1 - x^2) + C x^2) (+ the natural
          twist's share), to the window's own non-uniformity; pulled it
          overwinds to the closed form's largest turn density
          kappa0 / (2 sqrt(c (1 - c))), c = C/B < 1/2, then unwinds; at
          C = B/1.3 > B/2 it unwinds at once.
  figure_eight Michell's ring with self-contact: without it the subcritical
          branch passes through itself (Tw + Wr - Lk jumps by 2); with it
          the link is conserved, the branch turns back at a fold into the
          figure eight pressed at its crossing, and that fold tends, as the
          radius a -> 0 (0.1, 0.05), to the zero-thickness figure eight's
          Lk = 1.
"""
import csv, json, math, os, subprocess, sys

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from rod_vtu import element_strains, rod_nodes, vtu_arrays  # noqa: E402

exe, case, scratch = sys.argv[1], sys.argv[2], sys.argv[3]
# (the strip beside the rod: the table case computes its law)
strip = os.path.join(os.path.dirname(os.path.abspath(exe)), "strip")
os.makedirs(scratch, exist_ok=True)
failures = 0


def check(what, value, reference, tol):
    global failures
    ok = abs(value - reference) <= tol
    print("  %s  %-52s value %.15g  reference %.15g  tol %.3g" %
          ("ok  " if ok else "FAIL", what, value, reference, tol))
    failures += not ok


def prm_text(entries):
    """Nested dict -> a ParameterHandler file."""
    out = []
    def walk(d, indent):
        for k, v in d.items():
            if isinstance(v, dict):
                out.append(" " * indent + "subsection " + k)
                walk(v, indent + 2)
                out.append(" " * indent + "end")
            else:
                out.append(" " * indent + "set %s = %s" % (k, v))
    walk(entries, 0)
    return "\n".join(out) + "\n"


def run(name, entries, status=0):
    """Run the rod on `entries` into scratch/name; its summary.json. Fails
    the case unless the exit status is `status` (2: a path that stops)."""
    directory = os.path.join(scratch, name)
    entries = dict(entries)
    entries["Output"] = dict(entries.get("Output", {}), **{"Output directory": directory})
    prm = os.path.join(scratch, name + ".prm")
    open(prm, "w").write(prm_text(entries))
    r = subprocess.run([exe, "--quiet", prm], capture_output=True, text=True)
    if r.returncode != status:
        print(r.stdout, r.stderr)
        raise SystemExit("%s: exit status %d, expected %d" % (name, r.returncode, status))
    return json.load(open(os.path.join(directory, "summary.json")))


# Newton stops where the weighted residual is below its tolerance, the nodal
# forces against F = sqrt(EA B)/L and the moments against F L
# (RodProblem::residual_weights). The cases that compare a converged state
# with an exact one run at 1e-12 (the round-off floor of these meshes is
# ~1e-14) and bound their tolerances by it: a support's load balances the
# others' to N 1e-12 F, and a stress-free end sits within L N 1e-12 F L / B.
NEWTON = {"Nonlinear solver": {"Relative tolerance": 1e-12}}


def statics_bound(n, force_stiffness, moment_stiffness, L):
    return n * 1e-12 * math.sqrt(force_stiffness * moment_stiffness) / L


def twist_exponential(nu, kappa, s):
    """exp of the 4x4 twist [[s [kappa]x, s nu], [0, 0]] (scaling and squaring)."""
    A = np.zeros((4, 4))
    k = np.asarray(kappa, float)
    A[:3, :3] = s * np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    A[:3, 3] = s * np.asarray(nu, float)
    A /= 2.0 ** 10
    E, term = np.eye(4), np.eye(4)
    for n in range(1, 25):
        term = term @ A / n
        E = E + term
    for _ in range(10):
        E = E @ E
    return E


def write_stiffness(K):
    path = os.path.join(scratch, "stiffness.json")
    json.dump({"stiffness": [list(map(float, row)) for row in K]}, open(path, "w"))
    return path


def helix():
    # A coupled, symmetric positive definite 6x6 (extension-twist and
    # bending-bending couplings, as a chiral or unsymmetric section has).
    K = np.diag([40., 50., 100., 1.2, 0.8, 0.6])
    K[2, 5] = K[5, 2] = 2.5
    K[3, 4] = K[4, 3] = 0.3
    K[0, 4] = K[4, 0] = 1.0
    assert np.all(np.linalg.eigvalsh(K) > 0)
    xi = [0.05, -0.03, 1.1, 0.9, -0.4, 1.3]
    strains = "; ".join("%r*t" % x if i != 2 else "1 + %r*t" % (x - 1) for i, x in enumerate(xi))
    E = twist_exponential(xi[:3], xi[3:], 1.0)
    for n in (3, 8, 40):
        s = run("helix-%d" % n, {**NEWTON,
            "Rod": {"Length": 1, "Number of elements": n, "Natural strains": strains,
                    "Material": {"Law": "quadratic", "Stiffness file": write_stiffness(K)}},
            "End A": {"Support": "clamped"}, "End B": {"Support": "free"},
            "Continuation": {"Initial step": 0.25, "Maximum step": 0.25}})
        last = s["last_state"]
        check("%d elements: t at the end" % n, last["t"], 1.0, 0)
        # The exact end: measured 3e-14; bounded by Newton's tolerance.
        err = np.linalg.norm(np.array(last["end_position"]) - E[:3, 3])
        check("%d elements: end on the exact helix" % n, err, 0, statics_bound(n, 100, 1.2, 1) / 0.6)
        check("%d elements: stress-free (energy / K_max)" % n, last["energy"] / 100, 0, 1e-20)


def rollup():
    B2 = 0.8
    for n in (4, 7, 30):
        s = run("rollup-%d" % n, {**NEWTON,
            "Rod": {"Length": 2, "Number of elements": n,
                    "Material": {"Law": "quadratic", "Stiffnesses": "40, 50, 100, 1.2, %r, 0.6" % B2}},
            "End A": {"Support": "clamped"},
            "End B": {"Support": "rotation only", "Rotation": "0; 2*pi*t; 0"},
            "Continuation": {"Initial step": 0.125, "Maximum step": 0.125}})
        last = s["last_state"]
        L = 2.0
        check("%d elements: t at the end" % n, last["t"], 1.0, 0)
        # Round-off: the strains' and the end position's ~1e-15 L.
        # Bounded by Newton's tolerance (measured: 2e-15 to 2e-12).
        F = statics_bound(n, 100, 1.2, L)
        check("%d elements: the circle closes (|end|)" % n, np.linalg.norm(last["end_position"]), 0, F * L * L / B2)
        check("%d elements: end moment 2 pi B2 / L" % n, last["loads_B"][4], 2 * math.pi * B2 / L, F * L)
        check("%d elements: clamp moment -2 pi B2 / L" % n, last["loads_A"][4], -2 * math.pi * B2 / L, F * L)
        check("%d elements: no end force" % n, max(abs(x) for x in last["loads_B"][:3]), 0, F)


def discrete_euler(n, L, B, EA, GA, k):
    h = L / n
    T = math.tan(k * h / 2)
    f = lambda P: P * ((1 - P / EA) * (1 + T * T / 3) + P / GA) - 4 * B * T * T / h ** 2
    return brentq(f, 1e-9 * B / L ** 2, 10 * B * k * k)


def euler(pinned=False):
    L, GA, EA, B1, B2 = 1.0, 500.0, 1000.0, 2.0, 1.0
    k = (1 if pinned else 2) * math.pi / L
    support = "pinned" if pinned else "clamped"
    continuum = brentq(lambda P: P * ((1 - P / EA) + P / GA) - B2 * k * k, 1e-9, 10 * B2 * k * k)
    errors = []
    for n in (8, 20, 40):
        s = run("euler-%s-%d" % (support, n), {
            "Rod": {"Length": L, "Number of elements": n,
                    "Material": {"Law": "quadratic", "Stiffnesses": "%r, %r, %r, %r, %r, 0.8" % (GA, GA, EA, B1, B2)}},
            "End A": {"Support": support},
            "End B": {"Support": support, "Displacement": "0; 0; -%r*t" % L},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Initial step": 0.01 if not pinned else 0.003,
                                       "Maximum step": 0.01 if not pinned else 0.003,
                                       "Parameter range": "0, 0.08", "Stop at first event": "true"}})
        assert s["events"], "no event located"
        e = s["events"][0]
        P = EA * e["t"]
        P_h = discrete_euler(n, L, B2, EA, GA, k)
        check("%d elements: event is a branch point" % n, e["kind"] == "branch point", True, 0)
        check("%d elements: count 0 -> 1" % n, e["n_negative_before"] * 10 + e["n_negative_after"], 1, 0)
        # Located by Newton to ~1e-12 of t; the tolerance is 100x that.
        check("%d elements: P at the discrete closed form (relative)" % n, P / P_h - 1, 0, 1e-9)
        errors.append(abs(P / continuum - 1))
    rate = math.log(errors[1] / errors[2]) / math.log(2)
    check("convergence order to the continuum (20 -> 40 elements)", rate, 2.0, 0.05)


def growth():
    # The law (4.1) with natural stretch g is a rod of stiffnesses K/g whose
    # natural extension is g; held at its length (stretch 1) it carries P =
    # EA (g - 1)/g, and (7.2) with lambda = 1, GA/g and B/g gives g_c.
    L, GA, EA, B1, B2 = 1.0, 500.0, 1000.0, 2.0, 1.0
    k = 2 * math.pi / L
    for n in (8, 40):
        h = L / n
        T = math.tan(k * h / 2)
        def f(t):
            g = 1 + t
            P = EA * (g - 1) / g
            return P * ((1 + T * T / 3) + P * g / GA) - 4 * (B2 / g) * T * T / h ** 2
        t_h = brentq(f, 1e-9, 0.5)
        s = run("growth-%d" % n, {
            "Rod": {"Length": L, "Number of elements": n, "Growth": "1 + t",
                    "Material": {"Law": "quadratic", "Stiffnesses": "%r, %r, %r, %r, %r, 0.8" % (GA, GA, EA, B1, B2)}},
            "End A": {"Support": "clamped"}, "End B": {"Support": "clamped"},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Initial step": 0.01, "Maximum step": 0.01,
                                       "Parameter range": "0, 0.1", "Stop at first event": "true"}})
        assert s["events"], "no event located"
        e = s["events"][0]
        check("%d elements: growth at the first branch point (relative)" % n, e["t"] / t_h - 1, 0, 1e-9)


def michell():
    # An isotropic ring (B1 = B2 = B, C = B/1.3), nearly inextensible and
    # unshearable, twisted at its seam by 3 t turns: the planar ring loses
    # stability at Tw = sqrt(3) B/C turns (Michell 1889; Goriely, J Elast 84
    # (2006) 281). On 48 and 96 elements the thresholds converge at second
    # order; their Richardson limit is within the extension and shear
    # corrections, O(B/(EA R^2)) = 1e-4, of Michell's value.
    B, C, EA = 1.0, 1.0 / 1.3, 1e4
    michell_turns = math.sqrt(3) * B / C
    found = []
    for n in (48, 96):
        s = run("michell-%d" % n, {
            "Rod": {"Length": 2 * math.pi, "Number of elements": n, "Shape": "ring", "Ring twist": "3*t",
                    "Material": {"Law": "quadratic", "Stiffnesses": "%r, %r, %r, %r, %r, %r" % (EA, EA, EA, B, B, C)}},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Initial step": 0.02, "Maximum step": 0.05,
                                       "Parameter range": "0, 1", "Stop at first event": "true"}})
        assert s["events"], "no event located"
        found.append(3 * s["events"][0]["t"])
        print("  %d elements: Tw at the first event %.9f (Michell %.9f)" % (n, found[-1], michell_turns))
    limit = found[1] + (found[1] - found[0]) / 3
    check("Richardson limit of the threshold / Michell's", limit / michell_turns - 1, 0, 1e-3)
    check("96 elements within 1% of Michell's", found[1] / michell_turns - 1, 0, 1e-2)


def link():
    # A ring whose natural curvature out of its plane and natural twist grow
    # (kappa1 = 1.5 t sin 2s, kappa3 = 0.75 t) leaves its plane without a
    # bifurcation and writhes; its frame is continuous (no seam twist), so
    # its link stays 0: twist and writhe, measured independently on the
    # polygon, must add up to it at every state (to round-off: the discrete
    # Calugareanu-White identity, theory-rod.md 8).
    s = run("link", {
        "Rod": {"Length": 2 * math.pi, "Number of elements": 48, "Shape": "ring",
                "Natural strains": "0; 0; 1; 1.5*t*sin(2*s); 0; 0.75*t",
                "Material": {"Law": "quadratic", "Stiffnesses": "1e4, 1e4, 1e4, 1, 1, 0.769"}},
        "Continuation": {"Initial step": 0.1, "Maximum step": 0.1}})
    rows = list(csv.DictReader(open(os.path.join(scratch, "link", "steps.csv"))))
    gap = max(abs(float(r["link [turns]"]) - float(r["twist [turns]"]) - float(r["writhe [turns]"])) for r in rows)
    check("t reaches 1", float(rows[-1]["t"]), 1, 0)
    check("Tw + Wr = Lk = 0 at all %d states (max gap)" % len(rows), gap, 0, 1e-9)
    check("the ring writhes (|Wr| at t = 1 > 0.05)", abs(float(rows[-1]["writhe [turns]"])) > 0.05, True, 0)


def study():
    # The critical curve of parameter_files/rod/studies/euler_vs_length.prm
    # (the clamped rod's threshold against its length, each point continued
    # from the previous ones): every point at the discrete closed form, the
    # supports' axial force there -P_h, the mode in the (e1, e3) plane.
    prm = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_files", "rod", "studies",
                       "euler_vs_length.prm")
    out = os.path.join(scratch, "study")
    text = open(prm).read().replace("output/rod/studies/euler_vs_length", out)
    open(os.path.join(scratch, "study.prm"), "w").write(text)
    r = subprocess.run([exe, "--quiet", os.path.join(scratch, "study.prm")], capture_output=True, text=True)
    if r.returncode != 0:
        print(r.stdout, r.stderr)
        raise SystemExit("study: exit status %d" % r.returncode)
    rows = list(csv.DictReader(open(os.path.join(out, "sweep.csv"))))
    col = lambda r, name: float(next(v for k, v in r.items() if k.split(" [")[0] == name))
    check("six points", len(rows), 6, 0)
    for r in rows:
        L = col(r, "value")
        P = discrete_euler(40, L, 1.0, 1000.0, 500.0, 2 * math.pi / L)
        check("L = %g: t_critical = L P_h / EA (relative)" % L, col(r, "t_critical") / (L * P / 1000.0) - 1, 0, 1e-9)
        check("L = %g: force at B = -P_h (relative)" % L, col(r, "force_B_z") / -P - 1, 0, 1e-8)
        check("L = %g: mode along e1" % L, col(r, "mode_direction"), 1, 0)


def loads():
    # Dead loads on a cantilever (clamped at A, free at B). Statics, exact
    # for any deformation: the clamp's force balances the loads, its moment
    # the end force's about A. A small end force along e1 deflects the end
    # by Timoshenko's F L^3/(3 B2) + F L/GA1 (the helicoidal element is exact
    # for it only as h -> 0, at O(h^2): 40 elements, measured 1.6e-4, within
    # 1e-3; the nonlinear terms
    # are (F L^2/B)^2 ~ 1e-8).
    law = {"Law": "quadratic", "Stiffnesses": "400, 500, 1000, 2, 1.5, 0.8"}
    base = {"End A": {"Support": "clamped"}, "Continuation": {"Initial step": 0.2, "Maximum step": 0.2}, **NEWTON}
    bound = statics_bound(30, 1000, 2, 2)  # the clamp's loads balance the rest to this
    F = np.array([0.9, -0.4, -0.6])
    s = run("end-force", dict(base, **{"Rod": {"Length": 2, "Number of elements": 30, "Material": law},
                                        "End B": {"Support": "free", "Force": "%r*t; %r*t; %r*t" % tuple(F)}}))
    last = s["last_state"]
    rB = np.array(last["end_position"])
    check("end force: the clamp's force is -F", np.linalg.norm(np.array(last["loads_A"][:3]) + F), 0, bound)
    check("end force: the clamp's moment is -r_B x F", np.linalg.norm(np.array(last["loads_A"][3:]) + np.cross(rB, F)), 0,
          bound * 2)
    check("end force: the end moves (a nonlinear state, |u_B| > 0.3)", bool(np.linalg.norm(rB - [0, 0, 2]) > 0.3), True, 0)
    f = np.array([0.2, 0.3, -0.5])
    s = run("weight", dict(base, **{"Rod": {"Length": 2, "Number of elements": 30, "Material": law,
                                             "Distributed force": "%r*t; %r*t; %r*t" % tuple(f)}}))
    check("weight: the clamp's force is -f L", np.linalg.norm(np.array(s["last_state"]["loads_A"][:3]) + 2 * f), 0, bound)
    P, L, B2, GA1 = 1e-5, 2.0, 1.5, 400.0
    s = run("small-force", dict(base, **{"Rod": {"Length": L, "Number of elements": 40, "Material": law},
                                          "End B": {"Support": "free", "Force": "%r*t; 0; 0" % P}}))
    w = s["last_state"]["end_position"][0]
    timoshenko = P * L ** 3 / (3 * B2) + P * L / GA1
    check("small end force: Timoshenko's deflection (relative)", w / timoshenko - 1, 0, 1e-3)


SECTION_SWEEP = """# A disc growing axially by 1 + p X1 (doc/theory-rod-cross-section.md 6.2:
# kappa2 = -p exactly, on any mesh), swept over p.
subsection Cross-section
  set Shape              = circle
  set Radius             = 1
  set Global refinements = 1
end
subsection Material 1
  set Young's modulus = 1
  set Poisson's ratio = 0.3
  set Growth kind     = axial
  set Growth factor   = 1 + 0.3*x
end
subsection Rod strains
  set Mode = natural shape
end
subsection Parameter sweep
  set Entry    = Material 1/Growth factor
  set Template = 1 + {}*x
  set Range    = 0, 0.5, 6
end
"""


def section():
    from scipy.integrate import quad
    sweep = os.path.join(scratch, "disc-sweep.prm")
    open(sweep, "w").write(SECTION_SWEEP)
    law = {"Law": "section", "Section file": sweep, "Section parameter": "0.25*t*s"}
    base = {"End A": {"Support": "clamped"}, "End B": {"Support": "free"},
            "Continuation": {"Initial step": 0.25, "Maximum step": 0.25}, **NEWTON}
    # theta(s) = int_0^s kappa2 = -s^2/8; the tangent e3 turned about e2 by theta.
    exact = np.array([quad(lambda s: math.sin(-s * s / 8), 0, 2, epsabs=1e-14)[0], 0,
                      quad(lambda s: math.cos(-s * s / 8), 0, 2, epsabs=1e-14)[0]])
    errors = []
    for n in (10, 20, 40):
        s = run("family-%d" % n, dict(base, Rod={"Length": 2, "Number of elements": n, "Material": law}))
        errors.append(np.linalg.norm(np.array(s["last_state"]["end_position"]) - exact))
        print("  %d elements: end error %.3e" % (n, errors[-1]))
    # Second order: each element's natural curvature is the midpoint's.
    for k in (1, 2):
        check("order of the end's error, %d -> %d elements" % (10 * 2 ** (k - 1), 10 * 2 ** k),
              math.log2(errors[k - 1] / errors[k]), 2, 0.1)
    # The same parameters again: the sections are reused, not computed.
    run("family-10", dict(base, Rod={"Length": 2, "Number of elements": 10, "Material": law}))
    log = open(os.path.join(scratch, "family-10", "log.txt")).read()
    check("a second run reuses the sections", "reused from an earlier run" in log, True, 0)
    # A file the section's parameters name (its gmsh .geo) is part of the
    # key: edited, the section is computed again, not taken from the cache.
    geo = os.path.join(scratch, "square.geo")
    square = os.path.join(scratch, "square-section.prm")
    open(square, "w").write(prm_text({
        "Cross-section": {"Shape": "gmsh", "Mesh file": geo, "Global refinements": 0},
        "Material 1": {"Young's modulus": 1, "Poisson's ratio": 0.3},
        "Rod strains": {"Mode": "natural shape"}}))
    def square_run(side):
        open(geo, "w").write("a = %g;\nPoint(1) = {-a/2, -a/2, 0, a/4}; Point(2) = {a/2, -a/2, 0, a/4};\n"
                             "Point(3) = {a/2, a/2, 0, a/4}; Point(4) = {-a/2, a/2, 0, a/4};\n"
                             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                             "Curve Loop(1) = {1:4}; Plane Surface(1) = {1};\n"
                             "Physical Surface(\"section\", 1) = {1}; Physical Curve(\"outer\", 1) = {1:4};\n" % side)
        run("square", dict(base, Rod={"Length": 1, "Number of elements": 4,
                                      "Material": {"Law": "section", "Section file": square}}))
        log = open(os.path.join(scratch, "square", "log.txt")).read()
        K = json.load(open(os.path.join(scratch, "square", "section", "summary.json")))["stiffness"]
        return "reused from an earlier run" in log, K[3][3]
    first, again, edited = square_run(0.1), square_run(0.1), square_run(0.2)
    check("a section's unchanged .geo: computed, then reused", not first[0] and again[0], True, 0)
    check("its .geo edited (side doubled): computed again, B x 16 (exact for a square)", edited[0] is False and
          abs(edited[1] / first[1] / 16 - 1) < 1e-6, True, 0)
    # p past the family's range [0, 0.5] at t = 0.64: the path stops there.
    over = dict(law, **{"Section parameter": "0.4*t*s"})
    summary = run("family-over", dict(base, Rod={"Length": 2, "Number of elements": 10, "Material": over}), status=2)
    check("p past the family: status failed, the range named",
          summary["status"] == "failed" and "outside the family's range [0, 0.5]" in summary["message"], True, 0)
    # The last state is inside: p = 0.4 t s at the last element's midpoint s = 1.9 is at most 0.5.
    check("p past the family: the path ends inside the range", 0.4 * summary["last_state"]["t"] * 1.9 <= 0.5, True, 0)
    # One section: p = 0.3, kappa2 = -0.3; a cantilever of length 2 pi / 0.3 is a closed circle.
    one = os.path.join(scratch, "family-10", "section", "point-03", "summary.json")
    L = 2 * math.pi / 0.3
    # (Shape natural: the section's natural curvature is not a function of t to ramp.)
    s = run("one-section", dict(base, Rod={"Length": L, "Number of elements": 16, "Shape": "natural",
                                           "Material": {"Law": "section", "Section file": one}}))
    K = json.load(open(one))["stiffness"]
    check("one section: the cantilever closes into a circle (|r_B|)", np.linalg.norm(s["last_state"]["end_position"]), 0,
          statics_bound(16, K[2][2], K[4][4], L) * L / K[4][4])


def strip_table(name, kappa1_points):
    """A strip's constitutive table of (kappa1, kappa3), w/h = 20, the rest free."""
    directory = os.path.join(scratch, name)
    prm = os.path.join(scratch, name + ".prm")
    open(prm, "w").write(prm_text({
        "Strip": {"Width": 1, "Thickness": 0.05, "Number of cells": 20},
        "Rod strains": {"Mode": "prescribed strains", "Free strains": "nu1, nu2, nu3, kappa2"},
        "Constitutive table": {"Enabled": "true", "First strain": "kappa1",
                               "First range": "-1, 1, %d" % kappa1_points, "Second strain": "kappa3",
                               "Second range": "-0.4, 0.4, 21"},
        "Output": {"Output directory": directory}}))
    subprocess.run([strip, "--quiet", prm], check=True, capture_output=True)
    return os.path.join(directory, "table.h5")


def strip_direct(name, strains):
    """The strip's resultants at prescribed (kappa1, kappa3), the rest free."""
    directory = os.path.join(scratch, name)
    prm = os.path.join(scratch, name + ".prm")
    open(prm, "w").write(prm_text({
        "Strip": {"Width": 1, "Thickness": 0.05, "Number of cells": 20},
        "Rod strains": {"Mode": "prescribed strains", "Strains": "0, 0, 1, %r, 0, %r" % strains,
                        "Free strains": "nu1, nu2, nu3, kappa2"},
        "Output": {"Output directory": directory}}))
    subprocess.run([strip, "--quiet", prm], check=True, capture_output=True)
    return json.load(open(os.path.join(directory, "summary.json")))["resultants"]


def hermite_bound(table, axis, at):
    """|f' - p'| <= h^3 max|f''''| / (72 sqrt 3) for the cubic Hermite p of f
    (the derivative of f''''/24 (x - x0)^2 (x - x1)^2 peaks at h^3 / (3 sqrt 3));
    f'''' = K'' estimated by second differences of the tabulated stiffness
    over the cell and its neighbours."""
    import h5py
    with h5py.File(table, "r") as f:
        x = f["strain_1"][()] if axis == 0 else f["strain_2"][()]
        K = f["stiffness"][()]
        k = K[:, 10, 3, 3] if axis == 0 else K[5, :, 5, 5]  # along kappa1 at kappa3 = 0, or kappa3 at kappa1 = 0
    h = x[1] - x[0]
    i = int((at - x[0]) // h)
    second = [abs(k[j - 1] - 2 * k[j] + k[j + 1]) / h ** 2 for j in range(max(i - 1, 1), min(i + 3, len(x) - 1))]
    return h ** 3 * max(second) / (72 * math.sqrt(3))


def table():
    # The rod on the strip's nonlinear law (doc/theory-rod.md 4.2): a ribbon
    # bent, then twisted, uniformly by its end's rotation; its end moment
    # against the strip computed directly at that curvature, within the
    # interpolation bound, on two tables.
    base = {"End A": {"Support": "clamped"},
            "Continuation": {"Initial step": 0.25, "Maximum step": 0.25}, **NEWTON}
    for points in (11, 21):
        h5 = strip_table("table-%d" % points, points)
        law = {"Law": "table", "Table file": h5}
        # Bent about d1 to kappa1 = 0.43 (the end turned by kappa1 L about e1 = d1).
        s = run("bend-%d" % points, dict(base, Rod={"Length": 2, "Number of elements": 10, "Material": law},
                                         **{"End B": {"Support": "rotation only", "Rotation": "%r*t; 0; 0" % 0.86}}))
        m = s["last_state"]["loads_B"][3]
        direct = strip_direct("bend-direct", (0.43, 0.0))["m1"]
        bound = hermite_bound(h5, 0, 0.43)
        print("  %d points in kappa1: m1 %.10e, strip %.10e, bound %.2e" % (points, m, direct, bound))
        check("%d points: bent, m1 against the strip's (Hermite bound)" % points, m, direct, 2 * bound + 1e-9 * abs(direct))
    # Twisted about d3 to kappa3 = 0.23: the torque of the relaxed strip (its
    # nu3 shortens; the table's energy is that of the relaxed strip).
    s = run("twist", dict(base, Rod={"Length": 2, "Number of elements": 10, "Material": law},
                          **{"End B": {"Support": "rotation only", "Rotation": "0; 0; %r*t" % 0.46}}))
    direct = strip_direct("twist-direct", (0.0, 0.23))["m3"]
    check("twisted, m3 against the strip's (Hermite bound)", s["last_state"]["loads_B"][5], direct,
          2 * hermite_bound(h5, 1, 0.23) + 1e-9 * abs(direct))
    # Bent past the grid (kappa1 = 1.2 > 1): the path stops there, the strain and range named.
    summary = run("past", dict(base, Rod={"Length": 2, "Number of elements": 10, "Material": law},
                               **{"End B": {"Support": "rotation only", "Rotation": "2.4*t; 0; 0"}}), status=2)
    check("past the grid: status failed, kappa1 and [-1, 1] named", summary["status"] == "failed" and
          "kappa1" in summary["message"] and "outside the table's range [-1, 1]" in summary["message"], True, 0)
    check("past the grid: the last state inside (kappa1 = 1.2 t <= 1)", 1.2 * summary["last_state"]["t"] <= 1 + 1e-12,
          True, 0)


def elastica():
    # Euler's elastica (pinned-pinned, inextensible and unshearable): at the
    # end-to-end distance D = L (2 E(k)/K(k) - 1), the load P = 4 K(k)^2 B/L^2
    # (k = sin(alpha/2), alpha the end slope). EA = GA = 1e8 B/L^2 leave a
    # relative correction ~P/EA < 4e-7, far below the discretization's error
    # (O(h^2), ~1e-3 on 20 elements) at the meshes compared.
    from scipy.special import ellipk, ellipe
    L, B = 1.0, 1.0
    def exact(D):
        k2 = brentq(lambda m: 2 * ellipe(m) / ellipk(m) - 1 - D / L, 1e-14, 1 - 1e-12)
        return 4 * ellipk(k2) ** 2 * B / L ** 2
    errors = []
    for n in (20, 40, 80):
        directory = os.path.join(scratch, "elastica-%d" % n)
        run("elastica-%d" % n, {
            "Rod": {"Length": L, "Number of elements": n,
                    "Material": {"Law": "quadratic", "Stiffnesses": "1e8, 1e8, 1e8, 2, %r, 1" % B}},
            "End A": {"Support": "pinned"},
            "End B": {"Support": "pinned", "Displacement": "0; 0; -%r*t" % L},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Initial step": 0.002, "Maximum step": 0.04, "Maximum number of steps": 400,
                                       "Parameter range": "0, 0.36", "Both directions": "false"}})
        rows = [r for r in csv.DictReader(open(os.path.join(directory, "steps.csv")))
                if r["branch"] == "1" and 0.05 <= float(r["t"]) <= 0.35]
        check("%d elements: the buckled branch reaches t = 0.35 (states on it)" % n, len(rows) > 10, True, 0)
        err = max(abs(abs(float(r["force_B_z"])) / exact(L * (1 - float(r["t"]))) - 1) for r in rows)
        print("  %d elements: %d states on the buckled branch, largest relative error of P %.3e" % (n, len(rows), err))
        errors.append(err)
    for k in (1, 2):
        check("order of P's error, %d -> %d elements" % (10 * 2 ** k, 20 * 2 ** k),
              math.log2(errors[k - 1] / errors[k]), 2, 0.1)


def figure_eight():
    # Michell's ring (isotropic, B = 1, C = 1/1.3, nearly inextensible) with
    # a small dead load 1e-3 e3 sin 2s as the imperfection, twisted at its
    # seam by 3 t turns: past the imperfect fold near Michell's sqrt(3) B/C
    # turns its subcritical branch writhes while the link falls. A ring
    # without thickness passes through itself there: its writhe jumps by
    # -2 and Tw + Wr no longer equals the link its seam fixes. With
    # self-contact of radius a the strands touch first, and the branch
    # turns back at a fold into the figure eight pressed at its crossing,
    # the link conserved. As a -> 0 that fold tends to the zero-thickness
    # figure eight, the elastica whose crossing closes at Tw = 0, Wr = Lk =
    # 1 (theory-rod.md 9.2): linear in a, the extrapolation from a = 0.1
    # and 0.05 is within its a^2 term of 1 (measured with a = 0.025 on 512
    # elements: the three folds at Lk = 1.2279, 1.1149, 1.0576 extrapolate
    # to 1.0019 and 1.0002).
    B, C, EA = 1.0, 1.0 / 1.3, 1e4
    def ring(name, radius, status=0):
        entries = {
            "Rod": {"Length": 2 * math.pi, "Number of elements": 256, "Shape": "ring", "Ring twist": "3*t",
                    "Distributed force": "0; 0; 1e-3*sin(2*s)",
                    "Material": {"Law": "quadratic", "Stiffnesses": "%r, %r, %r, %r, %r, %r" % (EA, EA, EA, B, B, C)},
                    "Contact": {"Radius": radius}},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Initial step": 0.02, "Maximum step": 0.05, "Parameter range": "0, 1",
                                       "Maximum number of steps": 160, "Switch branches": "false"},
            "Output": {"Tube radius": 0}}
        s = run(name, entries, status)
        rows = list(csv.DictReader(open(os.path.join(scratch, name, "steps.csv"))))
        gap = [abs(float(r["link [turns]"]) - float(r["twist [turns]"]) - float(r["writhe [turns]"])) for r in rows]
        return s, rows, gap
    # Without contact: the ring passes through itself.
    s, rows, gap = ring("passes", 0)
    check("Michell's imperfect fold within 0.5 % below sqrt(3) B/C turns",
          3 * s["events"][0]["t"] / (math.sqrt(3) * B / C) - 1, -0.0025, 0.0025)
    k = next(i for i, g in enumerate(gap) if g > 1)
    check("without contact, |Tw + Wr - Lk| jumps to 2 (passage)", gap[k], 2, 1e-9)
    check("  and is 0 up to the passage", max(gap[:k]), 0, 1e-9)
    passage = [float(rows[i]["link [turns]"]) for i in (k, k - 1)]
    print("  passage between Lk = %.4f and %.4f" % tuple(passage))
    folds = []
    for radius in (0.1, 0.05):
        s, rows, gap = ring("contact-%g" % radius, radius)
        check("a = %g: Tw + Wr = Lk at all %d states" % (radius, len(rows)), max(gap), 0, 1e-9)
        fold = [e for e in s["events"] if e["kind"] == "fold" and e.get("contact_pairs", 0) > 0]
        check("a = %g: a fold with the strands in contact" % radius, len(fold) >= 1, True, 0)
        if not fold:
            return
        e = fold[0]
        print("  a = %g: contact fold at Lk = %.6f (Tw %.4f, Wr %.4f), %d pairs, force %.3g" %
              (radius, e["link"], e["twist"], e["writhe"], e["contact_pairs"], e["contact_force"]))
        check("a = %g: contact restabilizes (negative eigenvalues 1 -> 0)" % radius,
              e["n_negative_before"] - e["n_negative_after"], 1, 0)
        check("a = %g: the fold before the zero-thickness passage" % radius, e["link"] > passage[1], True, 0)
        folds.append(e["link"])
    check("a -> 0: the contact fold extrapolates to Lk = 1", 2 * folds[1] - folds[0], 1, 0.01)


def clamped_link():
    # A rod clamped at both ends on the e3 axis, its end B turned by 3 t
    # turns about that axis and pushed towards A by t/2; a natural curvature
    # kappa1 = 1 bows it, so that it writhes while it twists. The clamps'
    # frames continue the rod along the axis and a planar rectangle far out
    # closes it (theory-rod.md 8.1): Tw + Wr is the turns the clamps impose,
    # 3 t, at every state, Tw and Wr measured independently (to round-off:
    # the discrete Calugareanu identity, as for the ring).
    s = run("clamped_link", {
        "Rod": {"Length": 1, "Number of elements": 80, "Natural strains": "0; 0; 1; 1; 0; 0",
                "Material": {"Law": "quadratic", "Stiffnesses": "1e4, 1e4, 1e4, 1, 1, 0.769230769230769"}},
        "End A": {"Support": "clamped"},
        "End B": {"Support": "clamped", "Displacement": "0; 0; -0.5*t", "Rotation": "0; 0; 2*pi*3*t"},
        "Path following": {"Method": "arclength"},
        "Arclength continuation": {"Initial step": 0.005, "Maximum step": 0.02, "Parameter range": "0, 1",
                                   "Switch branches": "false", "Maximum number of steps": 500}})
    rows = list(csv.DictReader(open(os.path.join(scratch, "clamped_link", "steps.csv"))))
    gap = max(abs(float(r["link [turns]"]) - 3 * float(r["t"])) for r in rows)
    check("Tw + Wr = 3 t, the clamps' turns, at all %d states (max gap)" % len(rows), gap, 0, 1e-9)
    check("t reaches 1", float(rows[-1]["t"]) >= 1, True, 0)
    check("the rod writhes (Wr at t = 1 > 0.5)", float(rows[-1]["writhe [turns]"]) > 0.5, True, 0)
    check("summary.json's last state: its link the clamps' turns", s["last_state"]["link"] - 3 * s["last_state"]["t"],
          0, 1e-9)


def chain_rule():
    # The element's derivatives by the chain rule through (theta, u) against
    # nested AD of its whole energy (COSMO_NESTED_AD): a twisted ring (its
    # seam) to Michell's threshold and a pinned-pinned rod (the spin gauge)
    # to Euler's. The two Hessians differ by round-off (1e-13 of their
    # entries, measured on the examples), so the located loads agree within
    # the location's round-off resolution.
    cases = {
        "ring": {"Rod": {"Length": 1, "Number of elements": 40, "Shape": "ring", "Ring twist": "3*t",
                         "Material": {"Law": "quadratic", "Stiffnesses": "1e4, 1e4, 1e4, 1, 1, %r" % (1 / 1.3)}},
                 "Path following": {"Method": "arclength"},
                 "Arclength continuation": {"Parameter range": "0, 1", "Maximum step": 0.05,
                                            "Stop at first event": "true", "Event tolerance": 1e-10}},
        "pinned": {"Rod": {"Length": 1, "Number of elements": 40,
                           "Material": {"Law": "quadratic", "Stiffnesses": "500, 500, 1000, 2, 1, 0.8"}},
                   "End A": {"Support": "pinned"},
                   "End B": {"Support": "pinned", "Displacement": "0; 0; -t"},
                   "Path following": {"Method": "arclength"},
                   "Arclength continuation": {"Parameter range": "0, 0.05", "Maximum step": 0.002,
                                              "Initial step": 0.002,
                                              "Stop at first event": "true", "Event tolerance": 1e-10}}}
    for name, entries in cases.items():
        located, resolution = [], 0
        for nested in (False, True):
            env = dict(os.environ)
            env.pop("COSMO_NESTED_AD", None)
            if nested:
                env["COSMO_NESTED_AD"] = "1"
            directory = os.path.join(scratch, "%s-%s" % (name, "nested" if nested else "chain"))
            prm = directory + ".prm"
            open(prm, "w").write(prm_text(dict(entries, Output={"Output directory": directory})))
            subprocess.run([exe, "--quiet", prm], check=True, env=env)
            s = json.load(open(os.path.join(directory, "summary.json")))
            located.append(s["events"][0]["t"] if s["events"] else math.nan)
            resolution = max(resolution, s["events"][0]["location"]["resolution"] if s["events"] else 0)
        print("  %s: first event at t = %.12f (chain rule), %.12f (nested AD), resolution %.2e"
              % (name, located[0], located[1], resolution))
        # Two locations of one point agree within their round-off resolution
        # (each event's own, summary.json); 10 times it bounds the difference.
        check("%s: the chain rule's event against nested AD's" % name, located[0], located[1],
              10 * max(resolution, 1e-12))


def body():
    # The rod drawn as its part-1 section (Output / Body = section): the
    # tendril's disc (radius 0.02, stress-free at its natural shape) swept
    # along a clamped rod (L = 0.2, 8 elements, less than a turn of its
    # natural curvature 20) bent by its natural curvature. Every
    # body point lies at |w| = 0.02 from its node (w in the (d1, d2) plane),
    # so at that distance from the nearest centreline node (the next is
    # farther: h = 0.025); at the clamp (frame the fixed axes) the points are
    # the outline's (w1, w2, w3) themselves. Resolution: the VTU's single
    # precision and the spread of the outline's radii (7e-10, its mapping).
    disc = os.path.join(scratch, "disc.prm")
    text = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_files", "rod",
                             "sections", "tendril_disc.prm")).read()
    open(disc, "w").write(text)
    s = run("body", {"Rod": {"Length": 0.2, "Number of elements": 8, "Shape": "natural",
                             "Material": {"Law": "section", "Section file": disc}},
                     "End A": {"Support": "clamped"}, "End B": {"Support": "free", "Force": "0; 0; 1e-6*t"},
                     "Continuation": {"Initial step": 0.5, "Maximum step": 0.5},
                     "Output": {"Body": "section"}})
    directory = os.path.join(scratch, "body")
    outline = np.loadtxt(os.path.join(directory, "section", "outline.csv"), delimiter=",", skiprows=1)
    last = sorted(f for f in os.listdir(directory) if f.startswith("body-") and f.endswith(".vtu"))[-1]
    points = vtu_points(os.path.join(directory, last))
    # rod-NNNN.vtu: per element node a, its midpoint, node b
    centreline = vtu_points(os.path.join(directory, last.replace("body-", "rod-")))
    nodes = np.vstack([centreline[0::3], centreline[-1:]])
    check("body: points = 4 per outline segment per element", len(points), 4 * len(outline) * 8, 0)
    radius = np.linalg.norm(outline[:, 3:6], axis=1)
    distance = np.min(np.linalg.norm(points[:, None, :] - nodes[None, :, :], axis=2), axis=1)
    # (the VTU's points are single precision: 6e-8 of the coordinates each)
    float32 = 4 * 6e-8 * np.max(np.abs(points))
    check("body: every point at |w| from the centreline (max error)", np.max(np.abs(distance - radius.mean())), 0,
          float32 + np.ptp(radius))
    at_clamp = points[np.linalg.norm(points - nodes[0], axis=1) < 0.021]
    worst = max(np.min(np.linalg.norm(outline[:, 3:6] - p, axis=1)) for p in at_clamp - nodes[0])
    check("body: at the clamp the points are the outline's w", worst, 0, float32)
    # A strip's section (part 2; the seed pod's valve, w = 1, h = 0.01, at
    # its natural curvature): its outline is the width line thickened by h,
    # one closed loop, X2 = -h/2 along the width and +h/2 back; swept, the
    # ribbon's points at the clamp are the outline's w.
    strip_prm = os.path.join(scratch, "valve.prm")
    open(strip_prm, "w").write(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                                 "parameter_files", "rod", "sections", "seed_pod_strip.prm")).read())
    run("ribbon", {"Rod": {"Length": 2, "Number of elements": 8, "Shape": "natural",
                           "Material": {"Law": "section", "Section file": strip_prm}},
                   "End A": {"Support": "clamped"}, "End B": {"Support": "free", "Force": "0; 0; 1e-9*t"},
                   "Continuation": {"Initial step": 0.5, "Maximum step": 0.5},
                   "Output": {"Body": "section"}})
    directory = os.path.join(scratch, "ribbon")
    outline = np.loadtxt(os.path.join(directory, "section", "outline.csv"), delimiter=",", skiprows=1)
    half = len(outline) // 2
    check("ribbon: one loop of 2 (40 cells x degree + 1) points", len(outline) % 2 == 0 and
          set(outline[:, 0]) == {0} and half % 40 == 1, True, 0)
    check("ribbon: X2 = -h/2 along the width, +h/2 back",
          np.max(np.abs(outline[:half, 2] + 0.005)) + np.max(np.abs(outline[half:, 2] - 0.005)), 0, 1e-15)
    check("ribbon: X1 from -w/2 to w/2 and back", np.max(np.abs([outline[0, 1] + 0.5, outline[half - 1, 1] - 0.5,
                                                                  outline[half, 1] - 0.5, outline[-1, 1] + 0.5])),
          0, 1e-15)
    check("ribbon: the two faces h apart (|w(+h/2) - w(-h/2)| at each eta)",
          np.max(np.abs(np.linalg.norm(outline[:half, 3:6] - outline[half:, 3:6][::-1], axis=1) - 0.01)), 0, 1e-12)
    last = sorted(f for f in os.listdir(directory) if f.startswith("body-") and f.endswith(".vtu"))[-1]
    points = vtu_points(os.path.join(directory, last))
    node0 = vtu_points(os.path.join(directory, last.replace("body-", "rod-")))[0]
    float32 = 4 * 6e-8 * np.max(np.abs(points))
    worst = max(np.min(np.linalg.norm(points - (node0 + w), axis=1)) for w in outline[:, 3:6])
    check("ribbon: at the clamp the points are the outline's w", worst, 0, float32)


def vtu_points(path):
    """All points of a VTU written by the suite."""
    return vtu_arrays(path)["points"]


def vtu_nodes(path):
    """The nodes of a rod-NNNN.vtu."""
    return rod_nodes(vtu_arrays(path))


def perversion():
    # Tendril perversion (McMillen & Goriely 2002; Gerbode et al. 2012) on
    # the law of a part-1 section the run computes: a disc of radius 0.02
    # growing by 1 + 20 X1 (parameter_files/rod/sections/tendril_disc.prm),
    # whose natural curvature is kappa0 = 20/L exactly. The rod, clamped at
    # both ends, is held straight and pulled (D = 1.06 L, tension 1.5 B
    # kappa0^2, stable), its ends then brought together to D = 0.3 L without
    # turning them. An antisymmetric natural twist of 1 % of kappa0 (0.2 t
    # cos(pi s/L), 'Natural strain imperfection') is the imperfection that
    # picks one of the straight rod's modes. With self-contact of the
    # section's radius (a = 0.02 L, h = a/4):
    # - every state on the path stable, no event: the tendril coils smoothly;
    # - Tw + Wr = 0 at every state: the clamps are not turned, so the link
    #   is conserved;
    # - at the end two helices of opposite handedness: the centreline's
    #   torsion sums to opposite values on the two halves, antisymmetric to
    #   the discretization's O(h^2) (measured on the same rod with a
    #   quadratic law: 1.1 % on 100 elements, 0.28 % on 200; here 0.27 %:
    #   the bound 1 %);
    # - the turns press on each other without passing: the closest points
    #   apart more than pi a along the rod stay within 5 % of 2a (measured
    #   1.5 %), where the same path without contact overlaps the body by
    #   more than half its diameter (closest 0.41 (2a)).
    a = 0.02
    disc = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_files", "rod", "sections",
                        "tendril_disc.prm")
    def tendril(name, radius):
        s = run(name, {
            "Rod": {"Length": 1, "Number of elements": 200,
                    "Natural strain imperfection": "0; 0; 0; 0; 0; 0.2*t*cos(pi*s)",
                    "Material": {"Law": "section", "Section file": disc},
                    "Contact": {"Radius": radius}},
            "End A": {"Support": "clamped"},
            "End B": {"Support": "clamped", "Displacement": "0; 0; 0.06 - 0.76*t"},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Initial step": 0.005, "Maximum step": 0.05, "Parameter range": "0, 1",
                                       "Switch branches": "false"}})
        rows = list(csv.DictReader(open(os.path.join(scratch, name, "steps.csv"))))
        last = sorted(f for f in os.listdir(os.path.join(scratch, name)) if f.startswith("rod-") and f.endswith(".vtu"))[-1]
        x = vtu_nodes(os.path.join(scratch, name, last))
        n = len(x)
        distance = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2)
        i, j = np.triu_indices(n, 1)
        apart = (j - i) / (n - 1) > math.pi * a
        return s, rows, x, distance[i[apart], j[apart]].min() / (2 * a)
    s, rows, x, closest = tendril("perversion", a)
    check("every state stable (largest negative-eigenvalue count)",
          max(int(r["n_negative_eigenvalues"]) for r in rows), 0, 0)
    check("no event on the path", len(s["events"]), 0, 0)
    check("the ends brought to D = 0.3 L (t reaches 1)", float(rows[-1]["t"]) >= 1, True, 0)
    check("Tw + Wr = 0 at all %d states (link conserved)" % len(rows),
          max(abs(float(r["link [turns]"])) for r in rows), 0, 1e-9)
    segment = x[1:] - x[:-1]
    torsion = np.einsum("ij,ij->i", np.cross(segment[:-2], segment[1:-1]), segment[2:])
    half = len(torsion) // 2
    first, second = torsion[:half].sum(), torsion[-half:].sum()
    print("  torsion sums of the halves %.4e, %.4e; closest non-neighbours %.4f (2a)" % (first, second, closest))
    check("two helices of opposite handedness", bool(first * second < 0), True, 0)
    check("  antisymmetric: (first + second)/first", (first + second) / first, 0, 0.01)
    check("the turns touch without passing (closest / 2a)", closest, 1, 0.05)
    check("  pairs in contact at the end", s["last_state"]["contact_pairs"] > 0, True, 0)
    s, rows, x, closest = tendril("perversion-no-contact", 0)
    print("  without contact: closest non-neighbours %.4f (2a)" % closest)
    check("without contact the body overlaps itself (closest / 2a < 0.8)", bool(closest < 0.8), True, 0)


def overwinding():
    # Gerbode et al. (2012): a perverted tendril, pulled, first adds turns.
    # Each half's middle is a helix of uniform strains under the clamps'
    # tension alone; the perversion's mirror symmetry leaves no moment about
    # the axis there, so none anywhere (theory-rod.md 7.8):
    #   B (kappa_perp - kappa0) kappa_perp + C (kappa3 - tau0) kappa3 = 0,
    # with rho = |kappa| and x = kappa3/rho (the axis' share of the
    # tangent): rho(x) in closed form, largest at an interior x iff C < B/2.
    # The path: formed at C = B/1.3 (t in [0, 1], the perversion path of
    # the disc), the torsion softened to C = B/4 at D = 0.4 L (t in [1, 2]),
    # pulled to D = 0.96 L (t in [2, 3]).
    L, k0, n = 3.0, 20.0, 400
    C0 = 1 / 1.3
    def C(t):
        return C0 * (1 if t < 1 else (1 - 0.675 * (t - 1) if t < 2 else 0.325))
    run("overwinding", {
        "Rod": {"Length": L, "Number of elements": n, "Natural strains": "0; 0; 1; 0; -%g; 0" % k0,
                "Natural strain imperfection": "0; 0; 0; 0; 0; 0.2*min(t,1)*cos(pi*s/%g)" % L,
                "Stiffness factors": "1; 1; 1; 1; 1; t < 1 ? 1 : (t < 2 ? 1 - 0.675*(t-1) : 0.325)",
                "Material": {"Law": "quadratic", "Stiffnesses": "1e4, 1e4, 1e4, 1, 1, %.17g" % C0}},
        "End A": {"Support": "clamped"},
        "End B": {"Support": "clamped",
                  "Displacement": "0; 0; %g*(0.06 - 0.66*min(t,1) + 0.55*max(t-2,0))" % L},
        "Path following": {"Method": "arclength"},
        "Arclength continuation": {"Initial step": 0.005, "Maximum step": 0.1, "Parameter range": "0, 3",
                                   "Switch branches": "false"}})
    d = os.path.join(scratch, "overwinding")
    rows = list(csv.DictReader(open(os.path.join(d, "steps.csv"))))
    check("every state stable", max(int(r["n_negative_eigenvalues"]) for r in rows), 0, 0)
    check("Tw + Wr = 0 at all %d states (link conserved)" % len(rows),
          max(abs(float(r["link [turns]"])) for r in rows), 0, 1e-9)
    check("pulled to D = 0.96 L (t reaches 3)", float(rows[-1]["t"]) >= 3, True, 0)
    halves = ([], [])  # per state: t, D/L, mean rho, ptp(rho)/rho, mean x, worst |rho/exact - 1|, mean tau0
    for r in rows[1:]:  # (the straight start has no helix)
        t = float(r["t"])
        kappa = element_strains(vtu_arrays(os.path.join(d, "rod-%04d.vtu" % int(r["step"]))))
        s = (np.arange(len(kappa)) + 0.5) / len(kappa)
        for half, (lo, hi) in zip(halves, ((0.15, 0.35), (0.65, 0.85))):
            window = (s > lo) & (s < hi)
            k, tau0 = kappa[window], np.abs(0.2 * min(t, 1) * np.cos(np.pi * s[window]))
            rho = np.linalg.norm(k, axis=1)
            x = np.abs(k[:, 2]) / rho
            perp = np.sqrt(1 - x**2)
            exact = (k0 * perp + C(t) * tau0 * x) / (perp**2 + C(t) * x**2)
            half.append((t, float(r["end_z"]) / L, rho.mean(), np.ptp(rho) / rho.mean(), x.mean(),
                         np.abs(rho / exact - 1).max(), tau0.mean()))
    # The closed form where the halves' middles are helices (x >= 0.45 once
    # pulled; tighter coils are shorter than their boundary layers): within
    # the window's own non-uniformity ptp(rho)/rho, the resolution of
    # 'uniform' (the element reproduces a uniform helix exactly).
    pulled = [q for half in halves for q in half if q[0] >= 2 and q[4] >= 0.45]
    worst = max(pulled, key=lambda q: q[5] / q[3])
    print("  %d half-states pulled at C = B/4; worst |rho/rho_exact - 1| = %.2e where ptp(rho)/rho = %.2e (x = %.3f)"
          % (len(pulled), worst[5], worst[3], worst[4]))
    check("the helix's rho(x) against the closed form, / ptp(rho)/rho", worst[5] / worst[3], 0, 1)
    check("the halves mirror each other (max |rho_1/rho_2 - 1|)",
          max(abs(p[2] / q[2] - 1) for p, q in zip(*halves)), 0, 1e-6)
    # Overwinding: the turn density rises to an interior maximum, the closed
    # form's kappa0 / (2 sqrt(c (1 - c))) (+ the natural twist's share, at
    # the window's mean tau0), then falls.
    pull = [q for q in halves[0] if q[0] >= 2]
    top = max(range(len(pull)), key=lambda i: pull[i][2])
    c, xs = 0.25, np.linspace(0.5, 0.95, 4501)
    peak = max((k0 * np.sqrt(1 - xs**2) + c * pull[top][6] * xs) / (1 - xs**2 + c * xs**2))
    print("  pulled from D = %.3f L: rho %.4f -> %.4f at D = %.3f L (x = %.3f) -> %.4f at D = %.3f L; "
          "closed-form peak %.4f" % (pull[0][1], pull[0][2], pull[top][2], pull[top][1], pull[top][4],
                                      pull[-1][2], pull[-1][1], peak))
    check("overwinds: the largest turn density inside the pull", 0 < top < len(pull) - 1, True, 0)
    check("  rising by more than 5 %", bool(pull[top][2] / pull[0][2] - 1 > 0.05), True, 0)
    check("  its largest rho against kappa0 / (2 sqrt(c (1 - c)))", pull[top][2] / peak - 1, 0,
          pull[top][3] + 2e-3)
    # On the disc's torsion (C = B/1.3 > B/2) the same tendril unwinds at
    # once: rho falls monotonically as D grows (t falling in [0.15, 1]).
    formed = [q[2] for q in halves[0] if 0.15 <= q[0] <= 1]
    check("at C = B/1.3 it unwinds at once (rho monotone in D)",
          all(b >= a for a, b in zip(formed, formed[1:])), True, 0)


def section_stress():
    # The body's colour at the rod's strains (theory-rod.md 10). A cantilever
    # of the tendril's disc (radius R = 0.02, growth 1 + 20 X1, stress-free at
    # its natural kappa2 = -20), L = 0.1 on 4 elements in its natural shape,
    # its free end turned about e2 (the bending axis) by -alpha t, its
    # position free: a pure moment, every element at kappa2 = -20 - alpha t/L.
    # The stress the body draws, sigma0 + dsigma/de e (part 1's Cauchy stress
    # at the natural state and its derivatives in the strains, outline.csv),
    # against part 1 run directly at the element's six strains (prescribed).
    # Their difference is the linearization's remainder O(|e|^2): at
    # alpha/L = 1 and 2 (5 and 10 % of kappa0) the ratio of the two
    # differences is 4 to the next order, O(|e|) relative: the bound 4 +- 1.
    # The stress itself is first order in e: doubled with alpha to O(|e|)
    # (the bound 10 %), and the drawn one within 10 % of it (its elastic
    # strain is ~|e| X1/g <= 0.07: the remainder a few % of sigma).
    # Resolution: part 1's central differences (1e-10 of sigma), the VTU's
    # single precision (6e-8 of it).
    disc = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "parameter_files", "rod", "sections",
                        "tendril_disc.prm")
    part1 = os.path.join(os.path.dirname(os.path.abspath(exe)), "rod_cross_section")
    errors, scales = [], []
    for alpha in (0.1, 0.2):
        name = "stress-%g" % alpha
        run(name, {"Rod": {"Length": 0.1, "Number of elements": 4, "Shape": "natural",
                           "Material": {"Law": "section", "Section file": disc}},
                   "End A": {"Support": "clamped"},
                   "End B": {"Support": "rotation only", "Rotation": "0; %r*t; 0" % -alpha},
                   "Continuation": {"Initial step": 1, "Maximum step": 1},
                   "Output": {"Body": "section"}})
        directory = os.path.join(scratch, name)
        header = open(os.path.join(directory, "section", "outline.csv")).readline().strip().split(",")
        check("outline.csv: the stress and its 36 derivatives beside the 7 columns", len(header), 49, 0)
        last = sorted(f for f in os.listdir(directory) if f.startswith("rod-") and f.endswith(".vtu"))[-1]
        rod = vtu_arrays(os.path.join(directory, last))
        strains = element_strains(rod, ("nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"))
        check("alpha %g: every element at kappa2 = -20 - alpha/L" % alpha,
              np.max(np.abs(strains[:, 4] + 20 + alpha / 0.1)), 0, 1e-5)
        drawn = vtu_arrays(os.path.join(directory, last.replace("rod-", "body-")))["section_stress"]
        # Part 1 at the first element's strains (all six prescribed).
        direct_prm = os.path.join(scratch, name + "-direct.prm")
        text = open(disc).read().replace("set Mode = natural shape", "set Mode = prescribed strains\n  set Strains = " +
                                         ", ".join(repr(float(x)) for x in strains[0]))
        text = text.replace("output/rod/sections/tendril_disc", os.path.join(directory, "direct"))
        open(direct_prm, "w").write(text)
        subprocess.run([part1, "--quiet", direct_prm], check=True, capture_output=True)
        direct = np.loadtxt(os.path.join(directory, "direct", "outline.csv"), delimiter=",", skiprows=1)
        n = len(direct)
        # body-NNNN.vtu: per element, per outline segment j, 4 points, the first
        # at node a the outline's point j.
        at_node_a = drawn[0:4 * n:4]
        scale = np.max(direct[:, 6])
        scales.append(scale)
        errors.append(np.max(np.abs(at_node_a - direct[:, 6])))
        check("alpha %g: the drawn stress against part 1's, relative" % alpha, errors[-1] / scale, 0, 0.1)
    check("the stress itself first order in e: its ratio at 2 alpha and alpha", scales[1] / scales[0], 2, 0.2)
    check("the difference is the linearization's O(|e|^2): ratio at 2 alpha and alpha", errors[1] / errors[0], 4, 1)


def twisted_clamped_threshold(M, B, L):
    # The tension T below which a straight rod clamped at both ends, twisted
    # by the moment M, buckles (theory-rod.md 9.3): the first root, coming
    # down from above M^2/4B, of the clamped determinant of
    # B u'''' - i M u''' - T u'' = 0 (u = x + i y the lateral displacement).
    a = M / (2 * B)

    def det(T):
        b = np.sqrt(complex(4 * B * T - M * M)) / (2 * B)
        E = np.exp(1j * a * L)
        ch = np.cosh(b * L)
        sh = np.sinh(b * L) / b if b != 0 else L  # sinh(b s)/b: real-analytic in b^2
        d = ((-1 - 1j * a * L + E * ch) * (-1 + E * (ch + 1j * a * sh)) -
             (-L + E * sh) * (-1j * a + E * (1j * a * ch + b * b * sh)))
        return (d / E).real  # (d/E is real: its imaginary part is round-off)

    T = np.linspace(2 * M * M / (4 * B), 0, 4001)
    values = [det(x) for x in T]
    k = next(i for i in range(len(T) - 1) if values[i] * values[i + 1] < 0)
    return brentq(det, T[k + 1], T[k], xtol=1e-12)


def twisted_threshold():
    # A straight isotropic rod (B = 1, C = 0.77, GA = EA = 1e6, L = 1)
    # clamped at both ends: pulled to T = 400 (t < 0.1), its end B turned by
    # 7 turns (t < 0.3, M = 14 pi C = 33.87, below Greenhill's 2 sqrt(B T)
    # at that tension), then shortened, T falling. The straight branch loses
    # stability at a double branch point (the isotropic rod's two lateral
    # directions, count 0 -> 2) at the tension of the clamped twisted rod's
    # determinant, 276.768 (Greenhill's infinite rod: M^2/4B = 286.7). The
    # discrete threshold approaches it at the element's second order: the
    # errors at 100 and 200 elements in the ratio 4 +- 1, and the
    # Richardson extrapolation within the extensible rod's O(T/EA + T/GA)
    # = 5.5e-4 relative of the inextensible closed form. Resolution: the
    # bisection's bracket, 1e-8 in t (1e-5 in T).
    M, B = 0.77 * 2 * math.pi * 7, 1.0
    exact = twisted_clamped_threshold(M, B, 1.0)
    check("the closed form's threshold below Greenhill's M^2/4B", exact < M * M / (4 * B), True, 0)
    errors = []
    for n in (100, 200):
        s = run("twisted-%d" % n, {
            "Rod": {"Length": 1, "Number of elements": n,
                    "Material": {"Law": "quadratic", "Stiffnesses": "1e6, 1e6, 1e6, 1, 1, 0.77"}},
            "End A": {"Support": "clamped"},
            "End B": {"Support": "clamped",
                      "Displacement": "0; 0; 0.0004*min(t/0.1, 1) - 0.0006*max(0, (t-0.3)/0.7)",
                      "Rotation": "0; 0; 2*pi*7*min(1, t/0.3)"},
            "Path following": {"Method": "arclength"},
            "Arclength continuation": {"Parameter range": "0, 1", "Initial step": 0.005, "Maximum step": 0.01,
                                       "Field weight": 1e-5, "Maximum number of steps": 600,
                                       "Switch branches": "false", "Stop at first event": "true"},
            "Output": {"Tube radius": 0}, **NEWTON})
        e = s["events"][0]
        check("%d elements: a double branch point (0 -> 2)" % n,
              (e["kind"], e["n_negative_before"], e["n_negative_after"]) == ("branch point", 0, 2), True, 0)
        check("%d elements: the end moment 14 pi C" % n, e["loads_B"][5], M, 1e-9 * M)
        errors.append(e["loads_B"][2] - exact)
        print("  %d elements: T = %.9g, closed form %.9g" % (n, e["loads_B"][2], exact))
    check("second order: the errors' ratio", errors[0] / errors[1], 4, 1)
    richardson = exact + (4 * errors[1] - errors[0]) / 3
    check("Richardson's T against the closed form", richardson, exact, 5.5e-4 * exact)


{"helix": helix, "section": section, "table": table, "elastica": elastica, "rollup": rollup, "euler": euler, "euler_pinned": lambda: euler(True),
 "growth": growth, "michell": michell, "figure_eight": figure_eight, "clamped_link": clamped_link, "perversion": perversion, "link": link, "study": study, "loads": loads,
 "chain_rule": chain_rule, "body": body, "overwinding": overwinding,
 "section_stress": section_stress, "twisted_threshold": twisted_threshold}[case]()
print("%d check(s) failed" % failures if failures else "all checks passed")
sys.exit(1 if failures else 0)

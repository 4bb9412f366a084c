"""The strip's width-wise twist-buckling threshold in legacy DOLFIN: the peer of
benchmarks/strip_buckling_vs_dolfin.sh (part 2, doc/theory-strip.md 1 and 7).

The same model as `strip`: a Naghdi plate on the width eta in [-w/2, w/2]
under the helical Cauchy-Born ansatz, the section curve y(eta) and the
director q = exp([theta]x) E2 (theta = (theta1, 0, theta3)) as P2 fields on
the graded mesh eta = (w/2) sin(pi xi / 2), the six gauge constraints with
"Real" multipliers, nu3 free as a "Real" unknown (zero axial force) and the
twist kappa3 = tau prescribed; membrane and bending with 3 Gauss points a
cell, the transverse shear with 2 (reduced), as strip does by default.

What a user of DOLFIN would write: Newton on the flat branch (UFL's exact
tangent, MUMPS) at twists 0.05 apart until the lowest eigenvalue of the
constrained Hessian, by SLEPc shift-and-invert at 0 (the multipliers and nu3
massless, so their rows condense), changes sign; then Brent on it.

usage: python3 strip_buckling_dolfin.py <cells> [thickness = 0.01]
Prints "dolfin result: <cells> <DoFs> <tau_c> <seconds after imports>".
"""
import sys
import time

from dolfin import (Constant, FiniteElement, Function, FunctionSpace, IntervalMesh, MixedElement,
                    PETScMatrix, SLEPcEigenSolver, SpatialCoordinate, TestFunction, TrialFunction,
                    VectorElement, as_matrix, as_vector, assemble, cross, derivative, dx, inner,
                    interval, parameters, solve, split, tr, Identity, set_log_level, LogLevel)
import numpy as np
from scipy.optimize import brentq

cells = int(sys.argv[1])
h = float(sys.argv[2]) if len(sys.argv) > 2 else 0.01
started = time.perf_counter()
set_log_level(LogLevel.ERROR)
parameters["form_compiler"]["optimize"] = True
w, E, nu = 1.0, 1.0, 0.3
C = E * h / (1 - nu**2)
D = E * h**3 / (12 * (1 - nu**2))
S = 5.0 / 6.0 * E / (2 * (1 + nu)) * h

mesh = IntervalMesh(cells, -1.0, 1.0)
x = mesh.coordinates()
x[:, 0] = 0.5 * w * np.sin(np.pi * x[:, 0] / 2)  # strip's 'Mesh = graded'
P2v = VectorElement("CG", interval, 2, dim=3)
P2 = FiniteElement("CG", interval, 2)
R = FiniteElement("Real", interval, 0)
W = FunctionSpace(mesh, MixedElement([P2v, P2, P2] + [R] * 7))
U = Function(W)
u, th1, th3, l0, l1, l2, l3, l4, l5, nu3 = split(U)  # field, 6 multipliers, nu3
eta = SpatialCoordinate(mesh)[0]
tau = Constant(0.0)

# The director: cos|theta| E2 + sin|theta|/|theta| (theta x E2), by their
# series in r2 = |theta|^2 (UFL's derivatives of sqrt fail at theta = 0);
# to round-off for |theta| < 0.6 (the flat helicoid's director turns by
# atan(tau w / 2), 0.21 at the threshold of h/w = 0.01).
r2 = th1**2 + th3**2
cos_r = 1 - r2 / 2 + r2**2 / 24 - r2**3 / 720 + r2**4 / 40320 - r2**5 / 3628800 + r2**6 / 479001600
sinc_r = 1 - r2 / 6 + r2**2 / 120 - r2**3 / 5040 + r2**4 / 362880 - r2**5 / 39916800 + r2**6 / 6227020800
q = as_vector([-sinc_r * th3, cos_r, sinc_r * th1])

y = as_vector([eta + u[0], u[1], u[2]])
kappa = as_vector([0, 0, tau])
a2 = as_vector([0, 0, nu3]) + cross(kappa, y)
d2 = cross(kappa, q)
yp, qp = y.dx(0), q.dx(0)
Fp = as_matrix([[yp[i], a2[i]] for i in range(3)])
Gd = as_matrix([[qp[i], d2[i]] for i in range(3)])
eps = 0.5 * (Fp.T * Fp - Identity(2))
kb = 0.5 * (Fp.T * Gd + Gd.T * Fp)
gam = Fp.T * q
membrane_bending = (C / 2 * (nu * tr(eps)**2 + (1 - nu) * inner(eps, eps)) +
                    D / 2 * (nu * tr(kb)**2 + (1 - nu) * inner(kb, kb)))
shear = S / 2 * inner(gam, gam)
gauge = l0 * u[0] + l1 * u[1] + l2 * u[2] + l3 * eta * u[2] + l4 * eta * u[1] + l5 * th1
energy = (membrane_bending * dx(metadata={"quadrature_degree": 5}) +
          shear * dx(metadata={"quadrature_degree": 3}) +
          gauge * dx(metadata={"quadrature_degree": 4}))
residual = derivative(energy, U, TestFunction(W))
tangent = derivative(residual, U, TrialFunction(W))
du, dt1, dt3 = split(TrialFunction(W))[:3]
vu, vt1, vt3 = split(TestFunction(W))[:3]
mass = (inner(du, vu) + dt1 * vt1 + dt3 * vt3) * dx(metadata={"quadrature_degree": 4})

# the reference state: u = 0, theta = 0, nu3 = 1
U.vector()[W.sub(9).dofmap().dofs()] = 1.0
newton = {"newton_solver": {"linear_solver": "mumps", "relative_tolerance": 1e-13,
                            "absolute_tolerance": 1e-15, "maximum_iterations": 20}}
states = {}


def lowest_eigenvalue(t):
    """Newton on the flat branch at tau = t (from the nearest state solved),
    then the constrained Hessian's eigenvalue nearest zero."""
    if states:
        U.vector()[:] = states[min(states, key=lambda s: abs(s - t))]
    tau.assign(t)
    solve(residual == 0, U, J=tangent, solver_parameters=newton)
    states[t] = U.vector().get_local().copy()
    A, M = PETScMatrix(), PETScMatrix()
    assemble(tangent, tensor=A)
    assemble(mass, tensor=M)
    eig = SLEPcEigenSolver(A, M)
    eig.parameters["problem_type"] = "gen_non_hermitian"
    eig.parameters["spectral_transform"] = "shift-and-invert"
    # the shift just below zero: (A - s M) stays regular where the lowest
    # eigenvalue crosses zero, which Brent's iterates approach
    eig.parameters["spectral_shift"] = -shift
    eig.parameters["spectrum"] = "target magnitude"
    eig.parameters["tolerance"] = 1e-14
    eig.solve(3)
    values = [eig.get_eigenvalue(i)[0] for i in range(eig.get_number_converged())]
    if not values:
        sys.exit("SLEPc converged no eigenvalue at tau = %.15g" % t)
    return min(values, key=lambda m: abs(m + shift))


shift = 0.0
lo, mu_lo = 0.05, lowest_eigenvalue(0.05)
shift = 1e-3 * abs(mu_lo)  # (the eigenvalues' scale: that of the start)
hi = lo
while True:
    hi = lo + 0.05
    mu_hi = lowest_eigenvalue(hi)
    if mu_hi < 0 < mu_lo:
        break
    lo, mu_lo = hi, mu_hi
    if hi > 2:
        sys.exit("no sign change of the lowest eigenvalue up to tau = 2")
tau_c = brentq(lowest_eigenvalue, lo, hi, xtol=1e-13, rtol=1e-15)
print("dolfin result: %d %d %.12f %.3f" % (cells, W.dim(), tau_c, time.perf_counter() - started))

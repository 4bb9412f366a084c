#!/usr/bin/env python3
"""The part-1 natural shape of a growing disc as a user would write it in
legacy DOLFIN (Debian's python3-dolfin): the peer of rod_cross_section in
benchmarks/natural_shape_vs_dolfin.sh.

Unit disc, compressible neo-Hookean (E = 1, Poisson 0.3), axial growth
g = 1 + 0.3 X1, P2 displacement (3 components on the section) and the six
rod strains and six gauge multipliers as global ("Real") unknowns; the
energy int Jg W(Fbar Fg^-1) with Fbar = [dw/dX1 | dw/dX2 | nu + kappa x w],
w = X + u (doc/theory-rod-cross-section.md 1-3), the gauge int u = 0,
int (X1 u2 - X2 u1) = 0, int X1 u3 = int X2 u3 = 0 by multipliers, all six
strains free (natural shape). Newton from the reference state with the
exact tangent (UFL), MUMPS. Exact answer: kappa2 = -0.3.

usage: natural_shape_dolfin.py N [g] [stiffness]
  N: rings of dolfin's UnitDiscMesh; g: the growth factor as a Python
  expression in X[0], X[1] (default "1 + 0.3*X[0]", whose natural state
  u = 0 lies in every FE space; "1 + 0.3*X[0] + 0.3*X[1]**2" does not).
  stiffness: also the 6x6 stiffness at the natural state, as cosmo reports
  it (d resultants / d strains, the field and multipliers relaxed): the
  Jacobian assembled and factorized there, six solves for the unit strain
  loads, whose strain parts are the columns of K^-1.
prints the DoFs, Newton iterations, kappa2 (and its error against -0.3 for
the default growth), the time per phase and, with 'stiffness', K.
"""
import sys
import time

t_start = time.time()
import dolfin as df  # noqa: E402

df.parameters["form_compiler"]["representation"] = "uflacs"
df.parameters["form_compiler"]["cpp_optimize"] = True
df.set_log_level(df.LogLevel.WARNING)

n = int(sys.argv[1]) if len(sys.argv) > 1 else 40
growth = sys.argv[2] if len(sys.argv) > 2 else "1 + 0.3*X[0]"
with_stiffness = len(sys.argv) > 3 and sys.argv[3] == "stiffness"
t0 = time.time()
mesh = df.UnitDiscMesh.create(df.MPI.comm_world, n, 2, 2)  # quadratic (curved) cells
V = df.VectorElement("CG", mesh.ufl_cell(), 2, dim=3)
R = df.VectorElement("R", mesh.ufl_cell(), 0, dim=6)
W = df.FunctionSpace(mesh, df.MixedElement([V, R, R]))
w = df.Function(W)
u, e, lam = df.split(w)
X = df.SpatialCoordinate(mesh)
E, poisson = 1.0, 0.3
mu, lmbda = E / (2 * (1 + poisson)), E * poisson / ((1 + poisson) * (1 - 2 * poisson))
wpos = df.as_vector([X[0] + u[0], X[1] + u[1], u[2]])
nu = df.as_vector([e[0], e[1], e[2]])
kappa = df.as_vector([e[3], e[4], e[5]])
third = nu + df.cross(kappa, wpos)
Fbar = df.as_matrix([[1 + u[0].dx(0), u[0].dx(1), third[0]],
                     [u[1].dx(0), 1 + u[1].dx(1), third[1]],
                     [u[2].dx(0), u[2].dx(1), third[2]]])
g = eval(growth, {"X": X})
Fe = Fbar * df.as_matrix([[1, 0, 0], [0, 1, 0], [0, 0, 1 / g]])
J = df.det(Fe)
Wden = mu / 2 * (df.tr(Fe.T * Fe) - 3 - 2 * df.ln(J)) + lmbda / 2 * df.ln(J) ** 2
gauge = df.as_vector([u[0], u[1], u[2], X[0] * u[1] - X[1] * u[0], X[0] * u[2], X[1] * u[2]])
# Degree-4 quadrature (6 points per triangle): UFL's estimate for ln J and
# 1/g would be 2401 points per cell; cosmo's Q2 uses 3x3 Gauss points.
dx = df.dx(metadata={"quadrature_degree": 4})
Psi = g * Wden * dx + df.dot(lam, gauge) * dx
residual = df.derivative(Psi, w)
jacobian = df.derivative(residual, w)
# reference state: nu3 = 1
df.assign(w.sub(1), df.interpolate(df.Constant((0, 0, 1, 0, 0, 0)), W.sub(1).collapse()))
t_setup = time.time() - t0

problem = df.NonlinearVariationalProblem(residual, w, J=jacobian)
solver = df.NonlinearVariationalSolver(problem)
prm = solver.parameters["newton_solver"]
prm["linear_solver"] = "mumps"
prm["relative_tolerance"] = 1e-12
prm["absolute_tolerance"] = 1e-12
prm["maximum_iterations"] = 20
t1 = time.time()
iterations, converged = solver.solve()
t_solve = time.time() - t1
strains = w.sub(1, deepcopy=True).vector().get_local()
t_stiffness = 0
if with_stiffness:
    import numpy as np
    t2 = time.time()
    A = df.assemble(jacobian)
    lu = df.LUSolver(A, "mumps")
    strain_dofs = W.sub(1).dofmap().dofs()
    Kinv = np.zeros((6, 6))
    for k in range(6):
        b, x = df.Function(W).vector(), df.Function(W).vector()
        values = np.zeros(b.local_size())
        values[strain_dofs[k]] = 1.0
        b.set_local(values)
        b.apply("insert")
        lu.solve(x, b)
        Kinv[:, k] = x.get_local()[strain_dofs]
    K = np.linalg.inv(Kinv)
    t_stiffness = time.time() - t2
print("dolfin: %d DoFs, Newton %d iterations (converged %s), kappa2 %.12g (error against -0.3 "
      "%.2e), setup %.2f s, solve %.2f s, stiffness %.2f s, whole process %.2f s"
      % (W.dim(), iterations, converged, strains[4], abs(strains[4] + 0.3), t_setup, t_solve,
         t_stiffness, time.time() - t_start))
if with_stiffness:
    print("dolfin stiffness (nu1, nu2, nu3, kappa1, kappa2, kappa3): "
          + " ".join("%.10g" % K[i, j] for i in range(6) for j in range(6)))

#!/usr/bin/env python3
"""The part-3 dome as a user would write it in legacy DOLFIN (Debian's
python3-dolfin): a linear buckling analysis, the peer of plate_rod in
benchmarks/plate_buckling_vs_dolfin.sh.

Setting (parameter_files/plate_rod/dome.prm with a rim of circular section):
plate R = 1, h = 0.01, E = 1, Poisson 0.3, isotropic in-plane growth
g(t) = 1 + t (GROWTH - 1); the rim a rod of circular section of radius
a = 0.02 of the plate's material (EA = E pi a^2, EI1 = EI2 = E pi a^4/4,
GJ = G pi a^4/2), not growing, its axis on the plate's edge, welded.
Quarter disc with mirror edges; the mode sought is mirror-symmetric about
both edges (the modes cos(2 k theta), as cosmo's sector pi/2).

1. Prestress: plane stress of the flat quarter disc (P2 displacement) with
   the growth strain (GROWTH - 1) I as an eigenstrain, welded to the rim's
   hoop stiffness EA/2 int (t . grad u t)^2 ds on the arc (the linearized
   stretch of the curve), u . m = 0 on the mirrors. Membrane force N0 and
   rim force T0 at t = 1; both are linear in t.
2. Buckling: Kirchhoff plate, w in P3 with the C0 interior penalty method
   (the DOLFIN biharmonic demo, here with the full isotropic moment
   M = D ((1 - v) H + v tr H I), H = grad grad w): broken bending energy,
   consistency terms -{M_nn}[dw/dn] on interior edges, penalty
   ALPHA D/h [dw/dn]^2; on the mirrors dw/dn = 0 by Nitsche's method. The
   rim follows the plate's edge: with t, n the edge's tangent and outward
   normal its out-of-plane curvature is t.H t (= w_ss + w_n/R) and its twist
   -n.H t (= -(w_n)_s + w_s/R), energy 1/2 int (EI1 (t.H t)^2 +
   GJ (n.H t)^2) ds (doc/theory-plate-rod.md section 3 writes them in
   polar form); its prestress T0 (tension) adds T0/2 int w_s^2 ds.
   w = 0 at the apex removes the vertical translation. The pencil
   K_b w = t K_s w, K_s = -(int N0 grad w . grad v + int T0 w_s v_s) (not
   definite: the rim is in tension): SLEPc Krylov-Schur on the symmetric-
   definite K_s w = (1/t) K_b w, K_b^-1 applied by one MUMPS factorization,
   i.e. shift-and-invert of the buckling pencil at zero shift; the largest
   1/t gives the lowest positive critical t. The critical growth strain is
   t_cr (GROWTH - 1). Round-off: the Rayleigh quotient of the computed
   mode against t_cr (equal in exact arithmetic) is printed; it grows like
   the condition number of K_b (~N^4), 1e-8 relative at N = 12 to 16,
   6e-8 at N = 24.

The rim's terms are integrated facet by facet; P3 is only C0, so w_s and
w_n jump at the rim's vertices, and the rim gets C0 interior-penalty terms
of its own there (rim_vertex_terms: the beam's consistency and penalty
terms). Without them the rim's stiffness leaks through kinks at its
vertices and the threshold drifts towards the simply supported one as the
mesh is refined (0.467, 0.439, 0.407, 0.381 at N = 1, 2, 4, 8 instead of
0.5537).

Mesh: three Coons patches (a kite at the centre, two curved quadrilaterals
to the arc), each N x N quadrilaterals split into two triangles, quadratic
(isoparametric) geometry: the arc's edges are quadratic arcs through points
of the circle; read through an XDMF file (Triangle_6).

usage: plate_buckling_dolfin.py N [GROWTH] [ALPHA]
  N: quadrilaterals along each patch edge (6 N^2 triangles); GROWTH: the
  plate's growth factor at t = 1 (default 1.001); ALPHA: the interior
  penalty (default 20).
prints the DoFs (prestress, buckling), the critical t and growth, the
round-off indicator, the mode's rim Fourier content (cos(k theta), k = 0,
2, ..., 8; the first mode is axisymmetric, k = 0, as cosmo's), the rim's
mean N_rr against the Lame closed form (section 1), the time per phase,
and one line 'dolfin result:' for the side-by-side script.
"""
import os
import sys
import tempfile
import time

t_start = time.time()
import numpy as np  # noqa: E402
import dolfin as df  # noqa: E402
import ufl  # noqa: E402
from petsc4py import PETSc  # noqa: E402
from slepc4py import SLEPc  # noqa: E402

df.parameters["form_compiler"]["representation"] = "uflacs"
df.parameters["form_compiler"]["cpp_optimize"] = True
df.set_log_level(df.LogLevel.WARNING)
t_import = time.time() - t_start  # interpreter start-up not included

N = int(sys.argv[1]) if len(sys.argv) > 1 else 8
GROWTH = float(sys.argv[2]) if len(sys.argv) > 2 else 1.001
ALPHA = float(sys.argv[3]) if len(sys.argv) > 3 else 20.0
alpha = df.Constant(ALPHA)  # as a Constant: another value needs no new JIT

R, h, E, nu = 1.0, 0.01, 1.0, 0.3
G = E / (2 * (1 + nu))
a = 0.02
EA, EI1, GJ = E * np.pi * a**2, E * np.pi * a**4 / 4, G * np.pi * a**4 / 2
C = E * h / (1 - nu**2)
D = E * h**3 / (12 * (1 - nu**2))
ep, er = GROWTH - 1.0, 0.0  # growth strains of plate and rim at t = 1
growth_strain = df.Constant(ep)


def quarter_disc(n):
    """Points and Triangle_6 cells of the quarter disc, three Coons patches."""
    s, c = 0.5, 0.4
    e = np.array([np.sqrt(0.5), np.sqrt(0.5)])

    def line(p, q):
        p, q = np.asarray(p, float), np.asarray(q, float)
        return lambda x: (1 - x) * p + x * q

    def arc(th0, th1):
        return lambda x: R * np.array([np.cos(th0 + x * (th1 - th0)), np.sin(th0 + x * (th1 - th0))])

    def coons(bottom, top, left, right):
        p00, p10, p01, p11 = bottom(0), bottom(1), top(0), top(1)
        return lambda x, y: ((1 - y) * bottom(x) + y * top(x) + (1 - x) * left(y) + x * right(y)
                             - ((1 - x) * (1 - y) * p00 + x * (1 - y) * p10 + (1 - x) * y * p01 + x * y * p11))

    P, Q, Cc = (s, 0.0), (0.0, s), (c, c)
    patches = [
        coons(line((0, 0), P), line(Q, Cc), line((0, 0), Q), line(P, Cc)),
        coons(line(P, (R, 0)), line(Cc, e), line(P, Cc), arc(0, np.pi / 4)),
        coons(line(Q, (0, R)), line(Cc, e), line(Q, Cc), arc(np.pi / 2, np.pi / 4)),
    ]
    index, points = {}, []

    def node(x):
        key = (round(x[0] * 1e9), round(x[1] * 1e9))
        if key not in index:
            index[key] = len(points)
            points.append(x)
        return index[key]

    cells = []
    for f in patches:
        m = 2 * n
        grid = [[node(f(i / m, j / m)) for j in range(m + 1)] for i in range(m + 1)]
        for i in range(0, m, 2):
            for j in range(0, m, 2):
                v00, v20, v02, v22 = grid[i][j], grid[i + 2][j], grid[i][j + 2], grid[i + 2][j + 2]
                # two triangles split along the (i, j) - (i+2, j+2) diagonal;
                # Triangle_6 order: v0 v1 v2, mid(v0 v1), mid(v1 v2), mid(v2 v0)
                cells.append([v00, v20, v22, grid[i + 1][j], grid[i + 2][j + 1], grid[i + 1][j + 1]])
                cells.append([v00, v22, v02, grid[i + 1][j + 1], grid[i + 1][j + 2], grid[i][j + 1]])
    # DOLFIN's reader takes the vertices to be the first points: renumber
    # them first, and sort each cell's vertices (with its edge points)
    cells = np.array(cells)
    vertices = np.unique(cells[:, :3])
    others = np.setdiff1d(np.arange(len(points)), vertices)
    order = np.concatenate([vertices, others])
    new = np.empty(len(points), dtype=int)
    new[order] = np.arange(len(points))
    cells = new[cells]
    for k, cell in enumerate(cells):
        mid = {frozenset((cell[0], cell[1])): cell[3], frozenset((cell[1], cell[2])): cell[4],
               frozenset((cell[2], cell[0])): cell[5]}
        v = sorted(cell[:3])
        cells[k] = v + [mid[frozenset((v[0], v[1]))], mid[frozenset((v[1], v[2]))], mid[frozenset((v[2], v[0]))]]
    return np.array(points)[order], cells


def read_mesh(points, cells):
    tmp = tempfile.mkdtemp()
    path = os.path.join(tmp, "quarter.xdmf")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<Xdmf Version="3.0">\n<Domain>\n<Grid Name="mesh" GridType="Uniform">\n')
        f.write('<Topology NumberOfElements="%d" TopologyType="Triangle_6" NodesPerElement="6">\n' % len(cells))
        f.write('<DataItem Dimensions="%d 6" NumberType="UInt" Format="XML">\n' % len(cells))
        f.write("\n".join(" ".join(str(v) for v in c) for c in cells))
        f.write('\n</DataItem>\n</Topology>\n<Geometry GeometryType="XY">\n')
        f.write('<DataItem Dimensions="%d 2" Format="XML">\n' % len(points))
        f.write("\n".join("%.17g %.17g" % tuple(p) for p in points))
        f.write("\n</DataItem>\n</Geometry>\n</Grid>\n</Domain>\n</Xdmf>\n")
    mesh = df.Mesh()
    with df.XDMFFile(df.MPI.comm_self, path) as f:
        f.read(mesh)
    os.remove(path)
    os.rmdir(tmp)
    return mesh


t0 = time.time()
mesh = read_mesh(*quarter_disc(N))
# facets: 1 the arc (rim), 2 the mirror y = 0, 3 the mirror x = 0
marks = df.MeshFunction("size_t", mesh, 1, 0)
df.CompiledSubDomain("on_boundary && x[0]*x[0] + x[1]*x[1] > 0.25").mark(marks, 1)
df.CompiledSubDomain("on_boundary && near(x[1], 0.0)").mark(marks, 2)
df.CompiledSubDomain("on_boundary && near(x[0], 0.0)").mark(marks, 3)
ds = df.Measure("ds", domain=mesh, subdomain_data=marks)
n = df.FacetNormal(mesh)
tau = df.as_vector([-n[1], n[0]])
hK = df.Function(df.FunctionSpace(mesh, "DG", 0))
hK.vector()[:] = np.array([c.h() for c in df.cells(mesh)])
t_mesh = time.time() - t0

# 1. prestress at t = 1
t0 = time.time()
V2 = df.VectorFunctionSpace(mesh, "CG", 2)
u, v = df.TrialFunction(V2), df.TestFunction(V2)
I2 = df.Identity(2)


def membrane(strain):
    return C * ((1 - nu) * strain + nu * df.tr(strain) * I2)


def hoop(x):
    return df.dot(tau, df.grad(x) * tau)


a_m = df.inner(membrane(df.sym(df.grad(u))), df.sym(df.grad(v))) * df.dx + EA * hoop(u) * hoop(v) * ds(1)
L_m = df.inner(membrane(growth_strain * I2), df.sym(df.grad(v))) * df.dx + EA * er * hoop(v) * ds(1)
bcs_m = [df.DirichletBC(V2.sub(1), 0.0, marks, 2), df.DirichletBC(V2.sub(0), 0.0, marks, 3)]
u0 = df.Function(V2)
df.solve(a_m == L_m, u0, bcs_m, solver_parameters={"linear_solver": "mumps"})
N0 = membrane(df.sym(df.grad(u0)) - growth_strain * I2)
T0 = EA * (hoop(u0) - er)
t_prestress = time.time() - t0

# 2. buckling
t0 = time.time()
V3 = df.FunctionSpace(mesh, "CG", 3)
w, z = df.TrialFunction(V3), df.TestFunction(V3)


def hess(x):
    return df.grad(df.grad(x))


def moment(x):
    H = hess(x)
    return D * ((1 - nu) * H + nu * df.tr(H) * I2)


def mnn(x, nn):
    return df.dot(nn, moment(x) * nn)


h_avg = (hK("+") + hK("-")) / 2
jump_n = lambda x: df.jump(df.grad(x), n)  # noqa: E731
mirrors = ds(2) + ds(3)
k_b = (df.inner(moment(w), hess(z)) * df.dx
       - (df.avg(mnn(w, n)) * jump_n(z) + df.avg(mnn(z, n)) * jump_n(w)) * df.dS
       + alpha * D / h_avg * jump_n(w) * jump_n(z) * df.dS
       - (mnn(w, n) * df.dot(df.grad(z), n) + mnn(z, n) * df.dot(df.grad(w), n)) * mirrors
       + alpha * D / hK * df.dot(df.grad(w), n) * df.dot(df.grad(z), n) * mirrors
       + (EI1 * df.dot(tau, hess(w) * tau) * df.dot(tau, hess(z) * tau)
          + GJ * df.dot(n, hess(w) * tau) * df.dot(n, hess(z) * tau)) * ds(1))
k_s = -(df.inner(N0 * df.grad(w), df.grad(z)) * df.dx
        + T0 * df.dot(df.grad(w), tau) * df.dot(df.grad(z), tau) * ds(1))


def rim_vertex_terms():
    """The rim's interior-penalty terms at its vertices, as (dofs, 2D array)
    blocks: P3 is only C0, so w_s and w_n jump where two rim facets meet;
    the curvature w_ss + w_n/R and the twist -(w_n)_s + w_s/R carry the
    deltas [w_s] and -[w_n] there ([.] = after - before along the arc). The
    symmetric C0 interior penalty of a beam: {M1}[v_s] + {M1(v)}[w_s]
    - {M3}[v_n] - {M3(v)}[w_n] + ALPHA/h (EI1 [w_s][v_s] + GJ [w_n][v_n]),
    M1 = EI1 t.H t, M3 = -GJ n.H t, with the circle's exact t and n at the
    vertex. At a mirror the symmetric image has w_s -> -w_s, n.H t -> -n.H t:
    half of the term with [w_s] = +-2 w_s, {M3} = [w_n] = 0 (the other half
    belongs to the image sector). Gradients and Hessians of the P3 basis at
    the vertex from the reference Lagrange bases (in DOLFIN's order) and the
    cell's quadratic geometry."""
    def lagrange(nodes, degree):
        """derivatives (orders <= 2) of the reference Lagrange basis at the
        three corners: {(dx, dy): array (corner, basis function)}"""
        powers = [(i, k - i) for k in range(degree + 1) for i in range(k, -1, -1)]

        def monomials(x, y, dx, dy):
            return np.array([0.0 if i < dx or j < dy else
                             np.prod(range(i - dx + 1, i + 1)) * np.prod(range(j - dy + 1, j + 1))
                             * x ** (i - dx) * y ** (j - dy) for i, j in powers])
        coef = np.linalg.inv(np.array([monomials(x, y, 0, 0) for x, y in nodes]))
        return {d: np.array([monomials(x, y, *d) @ coef for x, y in corners])
                for d in ((1, 0), (0, 1), (2, 0), (1, 1), (0, 2))}

    # the nodes in FIAT's (FFC's, DOLFIN's) order: vertices, then edge k
    # opposite vertex k from its lower to its higher vertex, then the interior
    corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)]
    third = 1.0 / 3.0
    p3 = lagrange(corners + [(2 * third, third), (third, 2 * third), (0, third), (0, 2 * third),
                             (third, 0), (2 * third, 0), (third, third)], 3)
    p2 = lagrange(corners + [(0.5, 0.5), (0, 0.5), (0.5, 0)], 2)
    dofmap = V3.dofmap()

    def at_vertex(cell, vertex):
        """dofs, gradients (10 x 2) and Hessians (10 x 2 x 2) at a vertex"""
        i = list(cell.entities(0)).index(vertex)
        X = np.array(cell.get_coordinate_dofs()).reshape(6, 2)
        J = np.column_stack([X.T @ p2[(1, 0)][i], X.T @ p2[(0, 1)][i]])  # dx/dxi
        Jinv = np.linalg.inv(J)
        grad = np.column_stack([p3[(1, 0)][i], p3[(0, 1)][i]]) @ Jinv
        x2 = {(0, 0): X.T @ p2[(2, 0)][i], (0, 1): X.T @ p2[(1, 1)][i], (1, 1): X.T @ p2[(0, 2)][i]}
        href = {(0, 0): p3[(2, 0)][i], (0, 1): p3[(1, 1)][i], (1, 1): p3[(0, 2)][i]}
        hess = np.empty((10, 2, 2))
        for a in range(10):
            Hxi = np.empty((2, 2))
            for (k, m), d2 in href.items():
                Hxi[k, m] = Hxi[m, k] = d2[a] - grad[a] @ x2[(k, m)]
            hess[a] = Jinv.T @ Hxi @ Jinv
        return dofmap.cell_dofs(cell.index()), grad, hess

    arc = {}  # rim vertex -> [(polar angle of the facet's midpoint, cell, facet length)]
    for f in df.facets(mesh):
        if marks[f] != 1:
            continue
        cell = df.Cell(mesh, f.entities(2)[0])
        mid = f.midpoint()
        length = np.linalg.norm(mesh.coordinates()[f.entities(0)[0]] - mesh.coordinates()[f.entities(0)[1]])
        for v in f.entities(0):
            arc.setdefault(v, []).append((np.arctan2(mid.y(), mid.x()), cell, length))
    blocks = []
    for v, sides in arc.items():
        x = mesh.coordinates()[v]
        th = np.arctan2(x[1], x[0])
        t, nn = np.array([-np.sin(th), np.cos(th)]), np.array([np.cos(th), np.sin(th)])
        data = []
        for _, cell, _ in sorted(sides, key=lambda s: s[0]):
            dofs, grad, hess = at_vertex(cell, v)
            data.append((dofs, grad @ t, grad @ nn, EI1 * np.einsum("i,aij,j->a", t, hess, t),
                         -GJ * np.einsum("i,aij,j->a", nn, hess, t)))
        hv = np.mean([s[2] for s in sides])
        if len(data) == 2:
            (d0, s0, n0, m10, m30), (d1, s1, n1, m11, m31) = data
            dofs = np.concatenate([d0, d1])
            js, jn = np.concatenate([-s0, s1]), np.concatenate([-n0, n1])
            m1, m3 = np.concatenate([m10, m11]) / 2, np.concatenate([m30, m31]) / 2
            K = (np.outer(m1, js) + np.outer(js, m1) - np.outer(m3, jn) - np.outer(jn, m3)
                 + ALPHA / hv * (EI1 * np.outer(js, js) + GJ * np.outer(jn, jn)))
        else:  # a mirror: theta = 0 (the facet after it) or pi/2 (before it)
            dofs, s0, _, m10, _ = data[0]
            sign = 1.0 if th < np.pi / 4 else -1.0
            K = sign * (np.outer(m10, s0) + np.outer(s0, m10)) + 2 * ALPHA * EI1 / hv * np.outer(s0, s0)
        blocks.append((np.asarray(dofs, dtype=np.int32), K))
    return blocks


apex = df.DirichletBC(V3, 0.0, "near(x[0], 0.0) && near(x[1], 0.0)", method="pointwise")
A, B = df.PETScMatrix(), df.PETScMatrix()
dummy = df.Constant(0.0) * z * df.dx
df.assemble_system(k_b, dummy, apex, A_tensor=A)
Am = A.mat()
Am.setOption(PETSc.Mat.Option.NEW_NONZERO_ALLOCATION_ERR, False)  # vertex terms couple cells
for dofs, K in rim_vertex_terms():
    Am.setValues(dofs, dofs, K, addv=PETSc.InsertMode.ADD_VALUES)
Am.assemble()
df.assemble_system(k_s, dummy, apex, A_tensor=B)  # the apex's row and column zero,
for dof in apex.get_boundary_values():  # and its diagonal too
    B.mat().setValue(dof, dof, 0.0)
B.mat().assemble()
t_assembly = time.time() - t0

t0 = time.time()
eps = SLEPc.EPS().create()
eps.setOperators(B.mat(), A.mat())  # K_s w = mu K_b w, mu = 1/t
eps.setProblemType(SLEPc.EPS.ProblemType.GHEP)
eps.setType(SLEPc.EPS.Type.KRYLOVSCHUR)
eps.setWhichEigenpairs(SLEPc.EPS.Which.LARGEST_REAL)
eps.setDimensions(1, 20)
eps.setTolerances(1e-12, 200)
st = eps.getST()
st.setType(SLEPc.ST.Type.SHIFT)  # applies K_b^-1 K_s: K_b^-1 by one LU
st.setShift(0.0)
ksp = st.getKSP()
ksp.setType(PETSc.KSP.Type.PREONLY)
ksp.getPC().setType(PETSc.PC.Type.LU)
ksp.getPC().setFactorSolverType("mumps")
eps.solve()
assert eps.getConverged() >= 1, "SLEPc: no eigenpair converged"
mode = df.Function(V3)
mu = eps.getEigenpair(0, df.as_backend_type(mode.vector()).vec()).real
t_cr = 1.0 / mu
# round-off indicator: the Rayleigh quotient of the computed mode against
# t_cr (equal in exact arithmetic); it grows like the condition number of
# K_b, ~N^4 (measured: 1.2e-8 relative at N = 12, 7e-9 at 16, 6e-8 at 24)
x = df.as_backend_type(mode.vector()).vec()
Ax, Bx = x.duplicate(), x.duplicate()
A.mat().mult(x, Ax)
B.mat().mult(x, Bx)
roundoff = abs(x.dot(Ax) / x.dot(Bx) / t_cr - 1)
t_eigen = time.time() - t0

# the mode's rim content (cos(k theta), k even on the quarter disc)
xs = df.SpatialCoordinate(mesh)
polar = ufl.atan_2(xs[1], xs[0])
amps = [abs(df.assemble(mode * df.cos(k * polar) * ds(1))) * (2 if k else 1) / (np.pi / 2) for k in range(0, 9, 2)]
kmax = 2 * int(np.argmax(amps))
rim_n = df.assemble(df.dot(N0 * n, n) * ds(1)) / (np.pi / 2)
kk = R * E * h / (1 - nu)
lame = -(kk * EA / (R * (EA + kk))) * ep
print("dolfin: %d + %d DoFs (prestress P2, buckling P3), N = %d, %d triangles, penalty %g: t_cr %.12g, "
      "critical growth strain %.10g (Rayleigh quotient of the mode: %.1e relative); mode: rim w ~ cos(%d theta) (amplitudes k = 0, 2, 4, 6, 8: %s); "
      "prestress N_rr at the rim %.8g (Lame %.8g, %.1e)"
      % (V2.dim(), V3.dim(), N, mesh.num_cells(), ALPHA, t_cr, t_cr * ep, roundoff, kmax,
         " ".join("%.2g" % (x / max(amps)) for x in amps), rim_n, lame, rim_n / lame - 1))
t_total = time.time() - t_start
print("dolfin times: import %.2f s, mesh %.2f s, prestress %.2f s, assembly %.2f s, eigen %.2f s, "
      "after the imports %.2f s, since the script's first line %.2f s"
      % (t_import, t_mesh, t_prestress, t_assembly, t_eigen, t_total - t_import, t_total))
# one line for benchmarks/plate_buckling_vs_dolfin.sh: DoFs (prestress,
# buckling), t_cr, the mode's number, seconds of computing after the imports,
# the round-off indicator
print("dolfin result: %d %d %.15g %d %.4f %.2e" % (V2.dim(), V3.dim(), t_cr, kmax, t_total - t_import, roundoff))
sys.stdout.flush()

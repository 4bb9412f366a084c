#!/usr/bin/python3
"""Independent check of the lobed thresholds of part 3 (doc/theory-plate-rod.md,
sections 3 and 4; C++: analysis/plate_rod_thresholds.h).

1. Ring kinematics: the second variation of the exact rod energy of the rim
   (strains nu = Lambda^T r', [kappa]x = Lambda^T Lambda', Kirchhoff frame
   d3 = r'/|r'|, d2 = plate normal) is expanded with sympy for lobed
   perturbations and compared with the quadratic forms used in the closed
   forms.
2. Planar lobes: Ritz with piecewise-linear finite elements in r for the
   disc's in-plane mode (u_r, u_theta) = (U(r) cos n th, V(r) sin n th), the
   ring energy added at r = R; linear eigenproblem (K0 + T K1) v = 0 solved
   with scipy, Richardson-extrapolated, compared with the closed-form root.
3. Out-of-plane lobes: Ritz with C1 cubic Hermite elements in r for
   w = f(r) cos n th under the tension N = -T/R, ring added at r = R; same
   comparison with the Bessel determinant.

Run: /usr/bin/python3 scripts/check_lobed_thresholds.py
"""
import numpy as np
import scipy.linalg as sla
import scipy.special as sp_
import scipy.optimize as so


# --------------------------------------------------------------------------
# closed forms (python transcription of the C++ implementation)
# --------------------------------------------------------------------------
def plate_moduli(h, E, v):
    Eh = E * h
    lam = Eh * v / (1 - v * v)
    mu = Eh / (2 * (1 + v))
    D = E * h**3 / (12 * (1 - v * v))
    return lam, mu, D


def planar_matrix(T, n, R, lam, mu, EA, EI2):
    """Q = pi [a P^2 + 2 b P M + c M^2], P = (A + B)/2, M = (A - B)/2."""
    N = -T / R
    s = EI2 * n * n / R**2 + T
    FP = 2 * (mu + N) * (lam + mu) / (lam + 3 * mu + 2 * N) + N
    FM = N + 2 * mu
    a = (n + 1)**2 * (EA + s) / (2 * R) + (n + 1) * FP
    c = (n - 1)**2 * (EA + s) / (2 * R) + (n - 1) * FM
    b = (n * n - 1) * (s - EA) / (2 * R)
    return a, b, c


def planar_T(n, R, h, E, v, EA, EI2):
    lam, mu, D = plate_moduli(h, E, v)
    det = lambda T: (lambda a, b, c: a * c - b * b)(*planar_matrix(T, n, R, lam, mu, EA, EI2))
    scale = EA + E * h * R + EI2 / R**2
    T0 = -1e-14 * scale
    while det(T0 * 1.05) > 0:
        T0 *= 1.05
        if -T0 > 1e14 * scale:
            raise RuntimeError('no planar root')
    return so.brentq(det, T0 * 1.05, T0, xtol=1e-300, rtol=1e-15)


def chi(n, x):
    """x I_n(x) / I_{n+1}(x) with exponentially scaled Bessel functions."""
    return x * sp_.ive(n, x) / sp_.ive(n + 1, x)


def oop_det(x, n, v, e1, g):
    c = chi(n, x)
    return (c * (n * (n - 1) * (e1 + g) + 2 * n * (1 - v))
            + n * (n + 1) * (e1 * g * (n * n - 1) + (1 - v) * (e1 + g) - (1 - v)**2)
            - x * x * (c - (1 - v) + e1 + g * n * n))


def oop_T(n, R, h, E, v, EI1, GJ):
    lam, mu, D = plate_moduli(h, E, v)
    e1, g = EI1 / (R * D), GJ / (R * D)
    x = 1e-6
    while oop_det(x * 1.02, n, v, e1, g) > 0:
        x *= 1.02
        if x > 1e9:
            raise RuntimeError('no out-of-plane root')
    x = so.brentq(oop_det, x, x * 1.02, args=(n, v, e1, g), xtol=1e-300, rtol=1e-15)
    return -D * x * x / R, x


# --------------------------------------------------------------------------
# 1. ring kinematics from the exact rod strains
# --------------------------------------------------------------------------
def check_ring_kinematics(n=3, R=1.3, A=0.7, B=-0.4, W=0.5, Bt=0.3, M=256, h=1e-4):
    """Exact rod strains of the rim for the perturbation of amplitude h
    u_r = A cos, u_t = B sin, w = W cos, beta = Bt cos (rotation about e_theta),
    evaluated on a periodic grid with spectral theta-derivatives; the first-
    order curvature changes (central difference in h) and the second-order
    stretch are compared pointwise with the closed-form expressions."""
    th = 2 * np.pi * np.arange(M) / M
    k = np.fft.fftfreq(M, 1.0 / M)
    dth = lambda f: np.real(np.fft.ifft(1j * k * np.fft.fft(f, axis=-1), axis=-1))
    c, s = np.cos(n * th), np.sin(n * th)
    er = np.array([np.cos(th), np.sin(th), 0 * th])
    et = np.array([-np.sin(th), np.cos(th), 0 * th])
    E3 = np.array([0 * th, 0 * th, 1 + 0 * th])

    def strains(e):
        ur, ut, w, beta = e * A * c, e * B * s, e * W * c, e * Bt * c
        r = (R + ur) * er + ut * et + w * E3
        rp = dth(r) / R                       # per reference arc length
        st = np.linalg.norm(rp, axis=0)
        d3 = rp / st
        # the plate normal at the rim: -grad w with dw/dr = -beta and the
        # slope along the rim; made exactly orthogonal to d3 and unit
        nrm = E3 + beta * er - dth(w) / R * et
        nrm = nrm - np.sum(nrm * d3, axis=0) * d3
        d2 = nrm / np.linalg.norm(nrm, axis=0)
        d1 = np.cross(d3, d2, axis=0)         # = e_r in the reference
        dp = [dth(d) / R for d in (d1, d2, d3)]
        k1 = np.sum(dp[1] * d3, axis=0)       # rotation rate about d1
        k2 = np.sum(dp[2] * d1, axis=0)       # about d2
        k3 = np.sum(dp[0] * d2, axis=0)       # about d3
        return st, np.array([k1, k2, k3])

    s0, k0 = strains(0.0)
    sp, kp = strains(h)
    sm, km = strains(-h)
    dk = (kp - km) / (2 * h)
    st2 = (sp + sm - 2 * s0) / (2 * h * h)
    # closed forms (' = d/dtheta), amplitudes 1
    phi = (-n * A - B) * s / R                           # (u_r' - u_t)/R
    kap_ip = -n * (n * A + B) * c / R**2                 # phi'/R
    kap1 = (-n * n * W - R * Bt) * c / R**2              # (w'' - R beta)/R^2
    kap3 = (-n * R * Bt - n * W) * s / R**2              # (R beta' + w')/R^2
    wp = -n * W * s / R                                   # w'/R
    ok = True
    for got, want, name in ((dk[0], kap1, 'kappa_1 about d1 = e_r'),
                            (dk[1], kap_ip, 'kappa_2 about d2 = E3'),
                            (dk[2], kap3, 'kappa_3 (twist)')):
        err = min(np.abs(got - want).max(), np.abs(got + want).max())  # sign = convention
        print('  ring kinematics %-24s  max |change - closed form| = %.1e (amplitude %.1e)'
              % (name, err, np.abs(want).max()))
        ok = ok and err < 1e-6 * np.abs(want).max()
    # second-order part of the stretch, averaged (its first-order part e
    # squared belongs to EA; the e*phi-type products are third order)
    e1 = (A + n * B) * c / R
    lin = (sp - sm) / (2 * h)
    err_lin = np.abs(lin - e1).max()
    # second-order: (phi^2 + w'^2)/2 + (second-order part of sqrt((1+e)^2 + ...)) = (phi^2+wp^2)/2
    want2 = (phi**2 + wp**2) / 2
    err2 = np.abs(st2 - want2).max()
    print('  ring stretch: first order e = (u_r + u_t\')/R           max err %.1e' % err_lin)
    print('  ring stretch: second order (phi^2 + (w\'/R)^2)/2        max err %.1e' % err2)
    ok = ok and err_lin < 1e-8 and err2 < 1e-5
    return ok


# --------------------------------------------------------------------------
# 2. planar Ritz (P1 in r)
# --------------------------------------------------------------------------
gx, gw = np.polynomial.legendre.leggauss(4)


def planar_ritz(n, R, h, E, v, EA, EI2, m):
    lam, mu, D = plate_moduli(h, E, v)
    nodes = R * (np.arange(m + 1) / m)
    ndof = 2 * (m + 1)
    K0 = np.zeros((ndof, ndof))
    K1 = np.zeros((ndof, ndof))
    for e in range(m):
        r0, r1 = nodes[e], nodes[e + 1]
        L = r1 - r0
        idx = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]  # U0 V0 U1 V1
        for xi, wq in zip(gx, gw):
            r = r0 + (xi + 1) / 2 * L
            N0, N1 = (1 - (xi + 1) / 2), (xi + 1) / 2
            dN0, dN1 = -1 / L, 1 / L
            # rows: U, U', V, V' as linear functionals of the element dofs
            U = np.array([N0, 0, N1, 0]); Up = np.array([dN0, 0, dN1, 0])
            V = np.array([0, N0, 0, N1]); Vp = np.array([0, dN0, 0, dN1])
            err = Up
            ett = (U + n * V) / r
            grt = (V_p := Vp) - (n * U + V) / r     # 2 eps_rt / sin
            q_el = (lam * np.outer(err + ett, err + ett)
                    + 2 * mu * (np.outer(err, err) + np.outer(ett, ett) + 0.5 * np.outer(grt, grt)))
            g1, g2 = (n * U + V) / r, (U + n * V) / r
            q_geo = np.outer(Up, Up) + np.outer(V_p, V_p) + np.outer(g1, g1) + np.outer(g2, g2)
            wgt = np.pi / 2 * r * wq * L / 2 * 2   # pi/2 * int (.) r dr ; factor 2: Q = 1/2 v K v
            K0[np.ix_(idx, idx)] += wgt * q_el
            K1[np.ix_(idx, idx)] += wgt * q_geo * (-1 / R)   # N = -T/R
    # ring at r = R: Q = pi/(2R) [EA (A + n B)^2 + (EI2 n^2/R^2 + T)(n A + B)^2]
    iA, iB = 2 * m, 2 * m + 1
    a1 = np.zeros(ndof); a1[iA], a1[iB] = 1, n
    a2 = np.zeros(ndof); a2[iA], a2[iB] = n, 1
    K0 += np.pi / R * (EA * np.outer(a1, a1) + EI2 * n * n / R**2 * np.outer(a2, a2))
    K1 += np.pi / R * np.outer(a2, a2)
    keep = np.arange(2, ndof)   # U(0) = V(0) = 0 for n >= 2
    K0, K1 = K0[np.ix_(keep, keep)], K1[np.ix_(keep, keep)]
    mu_ = sla.eigh(K1, K0, eigvals_only=True)
    return -1 / mu_.max()


# --------------------------------------------------------------------------
# 3. out-of-plane Ritz (cubic Hermite in r)
# --------------------------------------------------------------------------
def hermite(xi, L):
    t = (xi + 1) / 2
    H = np.array([1 - 3 * t**2 + 2 * t**3, L * (t - 2 * t**2 + t**3), 3 * t**2 - 2 * t**3, L * (-t**2 + t**3)])
    dH = np.array([-6 * t + 6 * t**2, L * (1 - 4 * t + 3 * t**2), 6 * t - 6 * t**2, L * (-2 * t + 3 * t**2)]) / L
    d2H = np.array([-6 + 12 * t, L * (-4 + 6 * t), 6 - 12 * t, L * (-2 + 6 * t)]) / L**2
    return H, dH, d2H


def oop_ritz(n, R, h, E, v, EI1, GJ, m):
    lam, mu, D = plate_moduli(h, E, v)
    nodes = R * (np.arange(m + 1) / m)
    ndof = 2 * (m + 1)
    K0 = np.zeros((ndof, ndof))
    K1 = np.zeros((ndof, ndof))
    for e in range(m):
        r0, r1 = nodes[e], nodes[e + 1]
        L = r1 - r0
        idx = [2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3]
        for xi, wq in zip(gx, gw):
            r = r0 + (xi + 1) / 2 * L
            f, fp, fpp = hermite(xi, L)
            lap = fpp + fp / r - n * n * f / r**2
            t1 = fp / r - n * n * f / r**2
            t2 = fp / r - f / r**2
            # D/2 [(lap w)^2 - 2(1-v)(w_rr (w_r/r + w_thth/r^2) - (d_r(w_th/r))^2)]
            q_b = D * (np.outer(lap, lap) - (1 - v) * (np.outer(fpp, t1) + np.outer(t1, fpp))
                       + 2 * (1 - v) * n * n * np.outer(t2, t2))
            q_g = np.outer(fp, fp) + n * n * np.outer(f / r, f / r)
            wgt = np.pi * r * wq * L / 2   # theta average pi, Q = 1/2 v K v
            K0[np.ix_(idx, idx)] += wgt * q_b
            K1[np.ix_(idx, idx)] += wgt * q_g * (-1 / R)
    iW, iF = 2 * m, 2 * m + 1     # f(R), f'(R); Theta = R f'(R)
    cW = np.zeros(ndof); cW[iW] = 1
    cT = np.zeros(ndof); cT[iF] = R
    # ring: Q = pi/(2R^3) [EI1 (Th - n^2 W)^2 + GJ n^2 (Th - W)^2 + T R^2 n^2 W^2]
    b1 = cT - n * n * cW
    b3 = cT - cW
    K0 += np.pi / R**3 * (EI1 * np.outer(b1, b1) + GJ * n * n * np.outer(b3, b3))
    K1 += np.pi / R * n * n * np.outer(cW, cW)
    keep = np.arange(2, ndof)   # f(0) = f'(0) = 0 for n >= 2
    K0, K1 = K0[np.ix_(keep, keep)], K1[np.ix_(keep, keep)]
    mu_ = sla.eigh(K1, K0, eigvals_only=True)
    return -1 / mu_.max()


def richardson(fun, m, p):
    a, b = fun(m), fun(2 * m)
    return b + (b - a) / (2**p - 1), abs(b - a)


def main():
    print('1. ring kinematics from the exact rod strains (n = 3, spectral in theta)')
    ok = check_ring_kinematics()

    print('\n2. planar lobes: closed-form root vs P1 Ritz in r (Richardson 400/800 elements)')
    cases = [dict(R=1, h=0.01, E=1, v=0.3, EA=1e-3, EI2=1e-8),
             dict(R=1, h=0.01, E=1, v=0.3, EA=1e-1, EI2=1e-6),
             dict(R=2, h=0.02, E=3, v=0.25, EA=10, EI2=1e-3),
             dict(R=1, h=1e-3, E=1e-3, v=0.3, EA=1, EI2=1e-3)]   # soft plate
    worst = 0
    for cs in cases:
        for n in (2, 3, 5):
            Tc = planar_T(n, cs['R'], cs['h'], cs['E'], cs['v'], cs['EA'], cs['EI2'])
            Tr, _ = richardson(lambda m: planar_ritz(n, cs['R'], cs['h'], cs['E'], cs['v'], cs['EA'], cs['EI2'], m), 400, 2)
            rel = abs(Tr / Tc - 1)
            worst = max(worst, rel)
            print('  %-58s n=%d  T_closed % .10e  T_ritz % .10e  rel %.1e' % (cs, n, Tc, Tr, rel))
    print('  worst planar rel. difference %.1e' % worst)
    ok = ok and worst < 1e-5

    print('\n3. out-of-plane lobes: Bessel determinant vs Hermite Ritz in r (Richardson 200/400 elements)')
    cases = [dict(R=1, h=0.01, E=1, v=0.3, EI1=1e-8, GJ=1e-8),
             dict(R=1, h=0.01, E=1, v=0.3, EI1=1e-6, GJ=1e-6),
             dict(R=1, h=0.05, E=1, v=0.3, EI1=1e-5, GJ=3e-5),
             dict(R=2, h=0.02, E=3, v=0.25, EI1=1e-2, GJ=1e-3),
             dict(R=1, h=0.01, E=1, v=0.3, EI1=0, GJ=0)]
    worst = 0
    for cs in cases:
        for n in (2, 3, 5):
            Tc, x = oop_T(n, cs['R'], cs['h'], cs['E'], cs['v'], cs['EI1'], cs['GJ'])
            Tr, _ = richardson(lambda m: oop_ritz(n, cs['R'], cs['h'], cs['E'], cs['v'], cs['EI1'], cs['GJ'], m), 200, 4)
            rel = abs(Tr / Tc - 1)
            worst = max(worst, rel)
            print('  %-58s n=%d  x=%8.4f  T_closed % .10e  T_ritz % .10e  rel %.1e' % (cs, n, x, Tc, Tr, rel))
    print('  worst out-of-plane rel. difference %.1e' % worst)
    ok = ok and worst < 1e-5

    print('\n4. limits of the closed forms')
    # planar, soft plate (E h -> 0 at fixed T), inextensible rim: n^2 (n^2-1)/(n^2-n-1) EI2/R^2
    for n in (2, 3, 4):
        T = planar_T(n, 1.0, 1e-3, 1e-12, 0.3, 1e8, 1.0)
        ref = -n * n * (n * n - 1) / (n * n - n - 1)
        print('  planar soft plate   n=%d  T R^2/EI2 = %.10f  formula -n^2(n^2-1)/(n^2-n-1) = %.10f  rel %.1e'
              % (n, T, ref, abs(T / ref - 1)))
        ok = ok and abs(T / ref - 1) < 1e-6
    # planar rigid plate: T_cr/(E h R) tends to a constant (no lobing within small strain)
    for E in (1e2, 1e4, 1e6):
        print('  planar stiff plate  E h R = %.0e: T_cr/(E h R) = %.6f (n = 2, EA = 1, EI2 = 1e-3)'
              % (E * 1e-2, planar_T(2, 1.0, 1e-2, E, 0.3, 1.0, 1e-3) / (E * 1e-2)))
    # out of plane, vanishing plate bending (D -> 0 at fixed T): membrane + ring
    for n in (2, 3):
        T, x = oop_T(n, 1.0, 1e-4, 1.0, 0.3, 1.0, 0.5)
        ref = -n * (n + 1) * (n * n - 1) * 1.0 * 0.5 / (1.0 + n * n * 0.5)
        print('  out-of-plane membrane limit n=%d  T = %.10f  -n(n+1)(n^2-1) EI1 GJ/(R^2(EI1 + n^2 GJ)) = %.10f  rel %.1e'
              % (n, T, ref, abs(T / ref - 1)))
        ok = ok and abs(T / ref - 1) < 1e-4

    print('\n5. reference numbers for tests/plate_rod_thresholds.cc (R = 1, h = 0.01, E = 1, v = 0.3)')
    k = lambda R, h, E, v: R * E * h / (1 - v)
    for EA, EI, GJ in ((1e-3, 1e-8, 1e-8), (1e-1, 1e-6, 1e-6)):
        R, h, E, v = 1, 0.01, 1, 0.3
        kk = k(R, h, E, v)
        to_delta = lambda T: T * (EA + kk) / (EA * kk)
        pl = [(n, to_delta(planar_T(n, R, h, E, v, EA, EI))) for n in range(2, 201)]
        oo = [(n, to_delta(oop_T(n, R, h, E, v, EI, GJ)[0])) for n in range(2, 13)]
        fp = max(pl, key=lambda t: t[1])
        fp12 = max(pl[:11], key=lambda t: t[1])
        fo = max(oo, key=lambda t: t[1])
        print('  EA=%g EI1=EI2=%g GJ=%g' % (EA, EI, GJ))
        print('    planar: first over n<=12: n=%d Delta=%.12e; over n<=200: n=%d Delta=%.12e'
              % (fp12[0], fp12[1], fp[0], fp[1]))
        print('    out-of-plane: first n=%d Delta=%.12e (x = %.12f)' % (fo[0], fo[1], oop_T(fo[0], R, h, E, v, EI, GJ)[1]))
        print('    planar     Delta(n=2,3,5): ' + ' '.join('%.12e' % d for m, d in pl if m in (2, 3, 5)))
        print('    out-of-pl. Delta(n=2,3,5): ' + ' '.join('%.12e' % d for m, d in oo if m in (2, 3, 5)))
    print('\nall agree' if ok else '\nDISAGREEMENT')
    return 0 if ok else 1


if __name__ == '__main__':
    raise SystemExit(main())

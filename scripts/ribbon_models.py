#!/usr/bin/python3
"""Closed forms for part 2 (the strip as a special Cosserat rod) and the
one-dimensional ribbon energies of the literature.

Everything here is documented and derived in doc/theory-strip.md; the section
numbers below refer to that file.  Standard library + numpy (+ matplotlib for
`plot`).  Units: any consistent set; energies are per unit length of the strip.

Strains (director frame): kappa1 easy (out-of-plane) bending, kappa3 = tau twist.
Strip: width w (E1), thickness h (E2), Young's modulus E, Poisson ratio v,
shear correction ks (5/6).

    /usr/bin/python3 scripts/ribbon_models.py --table          # energies on a grid
    /usr/bin/python3 scripts/ribbon_models.py --references     # test reference numbers
    /usr/bin/python3 scripts/ribbon_models.py --plot [models.csv] [--out ribbons.png]
"""
import argparse
import csv
import math
import sys

import numpy as np

KS = 5.0 / 6.0


# ---------------------------------------------------------------------------
# elastic constants
def shear_modulus(E, v):
    return E / (2.0 * (1.0 + v))


def plate_D(E, v, h):
    """Plate bending stiffness D = E h^3 / (12 (1 - v^2))."""
    return E * h**3 / (12.0 * (1.0 - v**2))


# ---------------------------------------------------------------------------
# section 2: small-strain stiffness of the Naghdi strip at the reference
def torsion_boundary_layer(h, ks=KS):
    """ell = sqrt(A/S) = h / sqrt(12 ks), A = G h^3/12, S = ks G h."""
    return h / math.sqrt(12.0 * ks)


def GJ_naghdi(w, h, E, v, ks=KS):
    """Exact torsional stiffness of the linearized strip model (section 2.4):
    GJ = G w h^3/3 [1 - (2 ell/w) tanh(w/(2 ell))],  ell = h/sqrt(12 ks)."""
    G = shear_modulus(E, v)
    ell = torsion_boundary_layer(h, ks)
    return G * w * h**3 / 3.0 * (1.0 - 2.0 * ell / w * math.tanh(w / (2.0 * ell)))


def GJ_naghdi_expansion(w, h, E, v, ks=KS):
    """G w h^3/3 (1 - h/(w sqrt(3 ks))): exact up to exponentially small terms."""
    G = shear_modulus(E, v)
    return G * w * h**3 / 3.0 * (1.0 - h / (w * math.sqrt(3.0 * ks)))


def GJ_saint_venant_rectangle(w, h, E, v, nterms=50):
    """3D Saint-Venant torsion of a w x h rectangle (w >= h), for comparison."""
    G = shear_modulus(E, v)
    a, b = max(w, h), min(w, h)
    s = sum(math.tanh(n * math.pi * a / (2 * b)) / n**5 for n in range(1, 2 * nterms, 2))
    return G * a * b**3 * (1.0 / 3.0 - 64.0 / math.pi**5 * (b / a) * s)


def small_strain_stiffness(w, h, E, v, ks=KS):
    """Diagonal 6x6 stiffness at the reference, order (nu1, nu2, nu3, k1, k2, k3).
    All off-diagonal entries vanish (symmetry).  Section 2."""
    G = shear_modulus(E, v)
    return np.diag([
        5.0 / 6.0 * G * w * h,          # nu1: in-plane shear, 5/6 from int eta y.E3 = 0 (not ks)
        ks * G * w * h,                 # nu2: transverse shear
        E * w * h,                      # nu3: EA (free edges, N11 = 0)
        E * w * h**3 / 12.0,            # k1: tangent at the reference = narrow limit
        E * h * w**3 / 12.0,            # k2: in-plane bending
        GJ_naghdi(w, h, E, v, ks),      # k3: torsion with the free-edge boundary layer
    ])


# ---------------------------------------------------------------------------
# section 3: anticlastic bending (Fung-Wittrick / Ashwell, first-order theory)
_PSI_SERIES = [1 / 2, -1 / 360, 1 / 45360, -2879 / 16345929600, 3911 / 2778808032000,
               -74070881 / 6585941764321920000, 226894807 / 2524611009656736000000]


def searle_q(beta, v):
    """q = m w = (3(1-v^2))^(1/4) sqrt(|beta|),  beta = w^2 kappa1 / h.
    Equals sqrt(|V|/2) with Audoly-Neukirch's V = sqrt(12(1-v^2)) w^2 k/h."""
    return (3.0 * (1.0 - v**2)) ** 0.25 * math.sqrt(abs(beta))


def _psi_derivs(q):
    """Psi(q) = (cosh q - cos q) / (q (sinh q + sin q)) and its first two
    derivatives; series below q = 1, exp(-q)-scaled closed form above."""
    q = abs(q)
    if q < 1.0:
        t = q**4
        p = sum(a * t**n for n, a in enumerate(_PSI_SERIES))
        dp = sum(4 * n * a * q**(4 * n - 1) for n, a in enumerate(_PSI_SERIES) if n > 0)
        ddp = sum(4 * n * (4 * n - 1) * a * q**(4 * n - 2) for n, a in enumerate(_PSI_SERIES) if n > 0)
        return p, dp, ddp
    e1, e2 = math.exp(-q), math.exp(-2 * q)
    N = 0.5 * (1 + e2) - math.cos(q) * e1          # (cosh - cos) e^-q
    S = 0.5 * (1 - e2) + math.sin(q) * e1          # (sinh + sin) e^-q
    C = 0.5 * (1 + e2) + math.cos(q) * e1          # (cosh + cos) e^-q
    Sm = 0.5 * (1 - e2) - math.sin(q) * e1         # (sinh - sin) e^-q
    r = N / S
    c = C / S
    dr = 1.0 - r * c
    dc = Sm / S - c * c
    ddr = -(dr * c + r * dc)
    p = r / q
    dp = dr / q - r / q**2
    ddp = ddr / q - 2 * dr / q**2 + 2 * r / q**3
    return p, dp, ddp


def anticlastic_ratios(beta, v):
    """Return (energy, secant, tangent) ratios to D w (section 3):
       energy : 2 Phi / (D w k^2)   = 1 - 2 v^2 Psi
       secant : M / (D w k)         = 1 - v^2 (2 Psi + q Psi'/2)
       tangent: dM/dk / (D w)       = 1 - v^2 (2 Psi + 7/4 q Psi' + q^2 Psi''/4)
    All tend to 1 - v^2 (i.e. E w h^3/12) as beta -> 0 and to 1 (D w) as beta -> inf."""
    q = searle_q(beta, v)
    p, dp, ddp = _psi_derivs(q)
    energy = 1.0 - 2.0 * v**2 * p
    secant = 1.0 - v**2 * (2.0 * p + 0.5 * q * dp)
    tangent = 1.0 - v**2 * (2.0 * p + 1.75 * q * dp + 0.25 * q * q * ddp)
    return energy, secant, tangent


def anticlastic_moment(kappa1, w, h, E, v):
    """M(kappa1) = D w kappa1 * secant ratio (zero axial force, other resultants zero)."""
    beta = w**2 * kappa1 / h
    return plate_D(E, v, h) * w * kappa1 * anticlastic_ratios(beta, v)[1]


def anticlastic_energy(kappa1, w, h, E, v):
    beta = w**2 * kappa1 / h
    return 0.5 * plate_D(E, v, h) * w * kappa1**2 * anticlastic_ratios(beta, v)[0]


# ---------------------------------------------------------------------------
# section 4: finite twist (Buckley / Green), membrane theory
def twist_cubic_coefficient(w, h, E, free_stretch=True):
    """T = GJ tau + c3 tau^3 + ...: c3 = E h w^5/360 at zero axial force,
    E h w^5/160 at fixed stretch nu3 = 1."""
    return E * h * w**5 / (360.0 if free_stretch else 160.0)


def twist_shortening(tau, w):
    """nu3 - 1 = -w^2 tau^2 / 24 at zero axial force (leading order)."""
    return -w**2 * tau**2 / 24.0


def twist_axial_force_fixed_stretch(tau, w, h, E):
    """n3 = E h w^3 tau^2 / 24 (tension) needed to keep nu3 = 1."""
    return E * h * w**3 * tau**2 / 24.0


# ---------------------------------------------------------------------------
# section 5: literature ribbon energies W(kappa1, tau) per unit length
def W_kirchhoff(k, t, w, h, E, v, ks=None):
    """1/2 (E w h^3/12) k^2 + 1/2 (G w h^3/3) t^2 (narrow-rod stiffnesses).
    With ks given, GJ is replaced by the Naghdi value GJ_naghdi."""
    G = shear_modulus(E, v)
    GJ = G * w * h**3 / 3.0 if ks is None else GJ_naghdi(w, h, E, v, ks)
    return 0.5 * E * w * h**3 / 12.0 * np.square(k) + 0.5 * GJ * np.square(t)


def W_sadowsky(k, t, w, h, E, v):
    """D w (k^2 + t^2)^2 / (2 k^2); +inf where k = 0 and t != 0, 0 where both vanish."""
    k = np.asarray(k, float)
    t = np.asarray(t, float)
    num = (k**2 + t**2) ** 2
    with np.errstate(divide='ignore', invalid='ignore'):
        W = plate_D(E, v, h) * w * num / (2.0 * k**2)
    W = np.where(k == 0, np.where(t == 0, 0.0, np.inf), W)
    return W[()] if W.ndim == 0 else W


def W_wunderlich(k, t, w, h, E, v, eta_prime=0.0):
    """Wunderlich (Dias & Audoly 2015): D/2 k^2 (1 + eta^2)^2 (1/(w eta')) ln((1 + w eta'/2)/(1 - w eta'/2)),
    eta = t/k.  On uniform states (eta' = 0) the log factor is w and W = Sadowsky."""
    x = w * eta_prime / 2.0
    if abs(x) < 1e-8:
        factor = w * (1.0 + x * x / 3.0)
    else:
        factor = math.log((1.0 + x) / (1.0 - x)) / eta_prime
    return W_sadowsky(k, t, w, h, E, v) * factor / w


def _phi_an(V):
    """Audoly-Neukirch Phi(V) = (4/V^2)[1/2 - Psi(q)], q = sqrt(|V|/2); Phi(0) = 1/360."""
    q = math.sqrt(abs(V) / 2.0)
    if q < 1.0:   # 1/2 - Psi = -sum_{n>=1} a_n q^(4n); q^4 = V^2/4
        return -sum(a * (q**4) ** (n - 1) for n, a in enumerate(_PSI_SERIES) if n > 0)
    return 4.0 / V**2 * (0.5 - _psi_derivs(q)[0])


def phi_audoly_neukirch(V):
    V = np.asarray(V, float)
    out = np.vectorize(_phi_an, otypes=[float])(V)
    return out[()] if out.ndim == 0 else out


def W_audoly_neukirch(k, t, w, h, E, v):
    """Audoly & Neukirch (JMPS 2021):
    1/2 (E w h^3/12) k^2 + 1/2 (G w h^3/3) t^2 + (E h w^5/4)(v k^2 + t^2)^2 Phi(V),
    V = sqrt(12(1-v^2)) w^2 k / h."""
    k = np.asarray(k, float)
    t = np.asarray(t, float)
    G = shear_modulus(E, v)
    V = math.sqrt(12.0 * (1.0 - v**2)) * w**2 * k / h
    return (0.5 * E * w * h**3 / 12.0 * k**2 + 0.5 * G * w * h**3 / 3.0 * t**2
            + E * h * w**5 / 4.0 * (v * k**2 + t**2) ** 2 * phi_audoly_neukirch(V))


MODELS = {
    'kirchhoff': W_kirchhoff,
    'sadowsky': W_sadowsky,
    'wunderlich': W_wunderlich,
    'audoly_neukirch': W_audoly_neukirch,
}


def moments(model, k, t, w, h, E, v, rel=1e-6):
    """(m1, m3) = dW/d(k, t) by central differences (step rel * max(|k|,|t|, h/w^2))."""
    f = MODELS[model]
    d = rel * max(abs(k), abs(t), h / w**2)
    m1 = (f(k + d, t, w, h, E, v) - f(k - d, t, w, h, E, v)) / (2 * d)
    m3 = (f(k, t + d, w, h, E, v) - f(k, t - d, w, h, E, v)) / (2 * d)
    return float(m1), float(m3)


# ---------------------------------------------------------------------------
# command line
def print_table(w=1.0, h=0.01, E=1.0, v=0.3):
    print(f'# energy per unit length, w={w} h={h} E={E} v={v}; '
          f'beta = w^2 kappa1/h, theta = tau w^2/h')
    print(f"{'kappa1':>10} {'kappa3':>10} {'beta':>7} {'theta':>7} "
          + ' '.join(f'{m:>16}' for m in MODELS))
    for beta in (0.0, 1.0, 10.0, 100.0):
        for theta in (0.0, 1.0, 10.0):
            k, t = beta * h / w**2, theta * h / w**2
            vals = [float(MODELS[m](k, t, w, h, E, v)) for m in MODELS]
            print(f'{k:10.4g} {t:10.4g} {beta:7.3g} {theta:7.3g} '
                  + ' '.join(f'{x:16.9e}' for x in vals))


def print_references(E=1.0, v=0.3):
    G = shear_modulus(E, v)
    print('# small-strain stiffness of the Naghdi strip (E=1, v=0.3, ks=5/6)')
    for (w, h) in ((1.0, 0.05), (1.0, 0.01), (1.0, 0.1), (1.0, 0.025)):
        K = np.diag(small_strain_stiffness(w, h, E, v))
        print(f'w={w} h={h}: K_nu1={K[0]:.10e} K_nu2={K[1]:.10e} EA={K[2]:.10e} '
              f'K_k1={K[3]:.10e} EI2={K[4]:.10e}')
        print(f'   GJ exact={K[5]:.10e}  expansion={GJ_naghdi_expansion(w, h, E, v):.10e}  '
              f'G w h^3/3={G*w*h**3/3:.10e}  3D Saint-Venant={GJ_saint_venant_rectangle(w, h, E, v):.10e}')
    print('\n# anticlastic bending, v = %.2f: ratios to D w (narrow limit 1 - v^2 = %.4f)' % (v, 1 - v * v))
    print(f"{'beta':>8} {'q':>10} {'2Phi/(Dwk^2)':>14} {'M/(Dwk)':>14} {'dM/dk/(Dw)':>14}")
    for beta in (0.1, 1.0, 3.0, 10.0, 30.0, 100.0, 1000.0):
        en, se, ta = anticlastic_ratios(beta, v)
        print(f'{beta:8.4g} {searle_q(beta, v):10.6f} {en:14.10f} {se:14.10f} {ta:14.10f}')
    print('\n# finite twist (w=1, h=0.05, E=1): c3 free = %.10e, c3 fixed = %.10e'
          % (twist_cubic_coefficient(1, 0.05, 1), twist_cubic_coefficient(1, 0.05, 1, False)))


def plot(models_csv=None, out='ribbons.png', w=1.0, h=0.01, E=1.0, v=0.3, tol=1e-12):
    """Energies and moments of all models against beta = w^2 k/h (tau = 0) and
    theta = tau w^2/h (k = 0).  models_csv: optional CSV from the application with
    columns kappa1, kappa3, energy (extra columns ignored); rows with kappa3 = 0
    go to the bending panels, rows with kappa1 = 0 to the twist panels."""
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt

    D = plate_D(E, v, h)
    G = shear_modulus(E, v)
    GJ0 = G * w * h**3 / 3.0
    styles = {'kirchhoff': '-', 'sadowsky': '--', 'wunderlich': ':', 'audoly_neukirch': '-.'}
    fig, ax = plt.subplots(2, 3, figsize=(16, 8))
    betas = np.logspace(-1, 3, 200)
    thetas = np.linspace(0.0, 20.0, 200)[1:]
    for m in MODELS:
        ks = betas * h / w**2
        W = np.array([float(MODELS[m](k, 0.0, w, h, E, v)) for k in ks])
        M = np.array([moments(m, k, 0.0, w, h, E, v)[0] for k in ks])
        ax[0, 0].semilogx(betas, W / (0.5 * D * w * ks**2), styles[m], label=m)
        ax[1, 0].semilogx(betas, M / (D * w * ks), styles[m], label=m)
        if m in ('sadowsky', 'wunderlich'):
            continue   # infinite at kappa1 = 0, tau != 0
        ts = thetas * h / w**2
        W = np.array([float(MODELS[m](0.0, t, w, h, E, v)) for t in ts])
        T = np.array([moments(m, 0.0, t, w, h, E, v)[1] for t in ts])
        ax[0, 1].plot(thetas, W / (0.5 * GJ0 * ts**2), styles[m], label=m)
        ax[1, 1].plot(thetas, T / (GJ0 * ts), styles[m], label=m)
    en = np.array([anticlastic_ratios(b, v) for b in betas])
    ax[1, 0].semilogx(betas, en[:, 2], 'k', lw=0.8, label='tangent dM/dk (FW)')
    if models_csv:
        with open(models_csv) as f:
            rows = [r for r in csv.DictReader(f)]
        k1 = np.array([float(r['kappa1']) for r in rows])
        k3 = np.array([float(r['kappa3']) for r in rows])
        Wc = np.array([float(r['energy']) for r in rows])
        sel = (np.abs(k3) <= tol) & (np.abs(k1) > 0)
        if sel.any():
            ax[0, 0].semilogx(w**2 * k1[sel] / h, Wc[sel] / (0.5 * D * w * k1[sel]**2), 'o', ms=4,
                              mfc='none', label='strip (csv)')
        sel = (np.abs(k1) <= tol) & (np.abs(k3) > 0)
        if sel.any():
            ax[0, 1].plot(w**2 * k3[sel] / h, Wc[sel] / (0.5 * GJ0 * k3[sel]**2), 'o', ms=4,
                          mfc='none', label='strip (csv)')
        for name in ('m1', 'm3'):
            if rows and name in rows[0]:
                mv = np.array([float(r[name]) for r in rows])
                if name == 'm1':
                    sel = (np.abs(k3) <= tol) & (np.abs(k1) > 0)
                    ax[1, 0].semilogx(w**2 * k1[sel] / h, mv[sel] / (D * w * k1[sel]), 'o', ms=4,
                                      mfc='none', label='strip (csv)')
                else:
                    sel = (np.abs(k1) <= tol) & (np.abs(k3) > 0)
                    ax[1, 1].plot(w**2 * k3[sel] / h, mv[sel] / (GJ0 * k3[sel]), 'o', ms=4,
                                  mfc='none', label='strip (csv)')
        # Every row, on the axes and off them: the table's energy against
        # Audoly-Neukirch's, within the torsion boundary layer's
        # eps = h/(w sqrt(3 ks)) (tests/ribbon_comparison.py).
        eps = h / (w * math.sqrt(3.0 * KS))
        rel = np.array([W / W_audoly_neukirch(k, t, w, h, E, v) - 1 if (k or t) else np.nan
                        for k, t, W in zip(k1, k3, Wc)])
        for t in sorted(set(k3)):
            sel = (k3 == t) & (k1 > 0)
            if sel.any():
                ax[0, 2].semilogx(w**2 * k1[sel] / h, rel[sel] / eps, '.-', ms=4, lw=0.8,
                                  label=r'$\tau w^2/h$ = %.3g' % (t * w**2 / h))
        for k in sorted(set(k1)):
            sel = (k1 == k) & (k3 > 0)
            if sel.any():
                ax[1, 2].plot(w**2 * k3[sel] / h, rel[sel] / eps, '.-', ms=4, lw=0.8,
                              label=r'$\beta$ = %.3g' % (k * w**2 / h))
        for a in (ax[0, 2], ax[1, 2]):
            a.axhline(-1, color='k', lw=0.6, ls='--')
            a.axhline(1, color='k', lw=0.6, ls='--')
        worst = np.nanmax(np.abs(rel))
        ax[0, 2].set(xlabel=r'$\beta = w^2\kappa_1/h$', ylabel=r'$(W/W_{AN} - 1)/\epsilon$',
                     title='all rows vs Audoly-Neukirch: max %.2f eps' % (worst / eps))
        ax[1, 2].set(xlabel=r'$\tau w^2/h$', ylabel=r'$(W/W_{AN} - 1)/\epsilon$',
                     title=r'$\epsilon = h/(w\sqrt{3 k_s})$ = %.2g (dashed: $\pm\epsilon$)' % eps)
    else:
        for a in (ax[0, 2], ax[1, 2]):
            a.set_visible(False)
    ax[0, 0].set(xlabel=r'$\beta = w^2\kappa_1/h$', ylabel=r'$2W/(D w \kappa_1^2)$', title=r'bending, $\tau = 0$')
    ax[1, 0].set(xlabel=r'$\beta$', ylabel=r'$m_1/(D w \kappa_1)$')
    ax[0, 1].set(xlabel=r'$\tau w^2/h$', ylabel=r'$2W/(G w h^3 \tau^2/3)$', title=r'twist, $\kappa_1 = 0$')
    ax[1, 1].set(xlabel=r'$\tau w^2/h$', ylabel=r'$m_3/(G w h^3 \tau/3)$')
    for a in ax.flat:
        if a.get_visible():
            a.grid(alpha=0.3)
            a.legend(fontsize=7, ncol=2 if a in (ax[0, 2], ax[1, 2]) else 1)
    fig.suptitle(f'ribbon models, w={w}, h={h}, E={E}, v={v}')
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    return out


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--table', action='store_true', help='energies of all models on a small grid')
    p.add_argument('--references', action='store_true', help='reference numbers for the tests')
    p.add_argument('--plot', nargs='?', const='', default=None, metavar='CSV',
                   help='write the figure (optionally overlaying a CSV kappa1,kappa3,energy[,m1,m3])')
    p.add_argument('--out', default='ribbons.png')
    p.add_argument('--w', type=float, default=1.0)
    p.add_argument('--h', type=float, default=0.01)
    p.add_argument('--E', type=float, default=1.0)
    p.add_argument('--v', type=float, default=0.3)
    a = p.parse_args(argv)
    if a.table:
        print_table(a.w, a.h, a.E, a.v)
    if a.references:
        print_references(a.E, a.v)
    if a.plot is not None:
        print(plot(a.plot or None, a.out, a.w, a.h, a.E, a.v))
    if not (a.table or a.references or a.plot is not None):
        p.print_help()
    return 0


if __name__ == '__main__':
    sys.exit(main())

#ifndef cosmo_analysis_plate_rod_thresholds_h
#define cosmo_analysis_plate_rod_thresholds_h

/**
 * Closed forms of part 3 (doc/specification/plate-rod.md, "Critical growth, analytically"):
 * a flat circular Kirchhoff plate (radius R, thickness h, E, Poisson v)
 * welded to a rim rod (EA, out-of-plane bending EI1 about the radial axis,
 * in-plane bending EI2 about the plate normal, torsion GJ about the
 * tangent), with isotropic in-plane
 * growth strain of the plate and axial growth strain of the rod, in the
 * small-strain pre-buckled state. Derivations: doc/theory-plate-rod.md.
 */
namespace cosmo
{
  namespace analysis
  {
    struct PlateRod
    {
      double radius = 1, thickness = 0.01, young = 1, poisson = 0.3;
      double rod_EA = 1, rod_EI1 = 1, rod_EI2 = 1;
      /// Torsional stiffness of the rim about its tangent d3 = e_theta.
      double rod_GJ = 1;

      /// Plate bending stiffness D = E h^3 / (12 (1 - v^2)).
      double
      plate_D() const;
      /// In-plane radial stiffness of the disc's edge per unit rim length,
      /// k = R E h / (1 - v): the membrane force is k/R times the radial strain.
      double
      edge_stiffness() const;
    };

    /**
     * The growth mismatch Delta = g_p / g_r - 1 of a plate growing by the
     * factor g_p and a rim by g_r (both uniform and isotropic).
     */
    inline double
    growth_mismatch(const double plate_growth, const double rod_growth)
    {
      return plate_growth / rod_growth - 1;
    }

    /**
     * The load parameter t at which the linear ramps g_p = 1 + t a,
     * g_r = 1 + t b reach the mismatch Delta: t = Delta / (a - b (1 + Delta)).
     */
    inline double
    load_parameter_at_mismatch(const double Delta, const double a, const double b)
    {
      return Delta / (a - b * (1 + Delta));
    }

    /// The flat pre-buckled (Lame) state for plate growth strain ep and rod growth strain er.
    struct PrebuckledState
    {
      double radial_strain  = 0; ///< uniform u_r / r of plate and rim
      double membrane_force = 0; ///< N_rr = N_tt, per unit length (negative: compression)
      double hoop_force     = 0; ///< rod axial force T (negative: compression)
    };
    PrebuckledState
    prebuckled_state(const PlateRod &p, double plate_growth_strain, double rod_growth_strain);

    /**
     * Axisymmetric out-of-plane buckling of the plate under the uniform
     * compression P = -N, its edge restrained against rotation by the
     * rim's rolling stiffness EI1/R^2 per unit length: the smallest root x
     * of x J0(x) - (1 - v - rho) J1(x) = 0, rho = EI1 / (R D), and
     * P_cr = x^2 D / R^2. Limits: rho = 0 simply supported (x^2 = 4.198 at
     * v = 0.3), rho -> inf clamped (x = j_{1,1}, x^2 = 14.68).
     */
    double
    axisymmetric_load_factor(double poisson, double rho);

    /// The growth mismatch Delta = ep - er at which the flat state buckles axisymmetrically.
    double
    axisymmetric_critical_mismatch(const PlateRod &p);

    /**
     * Planar n-lobed buckling of the rim in the limit of a plate without
     * in-plane stiffness against lobing (a ring under the plate's
     * hydrostatic-like load): hoop force T_cr = -(n^2 - 1) EI2 / R^2, the
     * mismatch (negative: the rim outgrows the plate) that produces it.
     * This is the fluid-film (surface-tension) limit; the coupled model of
     * planar_critical_mismatch() tends to a different constant as E h -> 0
     * (doc/theory-plate-rod.md, section 3).
     */
    double
    planar_critical_mismatch_soft_plate(const PlateRod &p, unsigned int n);

    /**
     * Planar n-lobed buckling (n >= 2) of the coupled system for Delta < 0:
     * linearized (initial-stress) stability of the flat Lame state, rim in
     * compression T < 0, plate in equi-biaxial tension N = -T/R. Model: the
     * second variation of plate + rim energy,
     *  - plate: (1/2) int [lambda (div u)^2 + 2 mu eps:eps + N |grad u|^2] dA
     *    (plane-stress membrane, lambda = E h v/(1 - v^2), mu = E h/(2(1+v));
     *    N |grad u|^2 / 2 is the initial-stress term of the exact membrane
     *    strain (F^T F - I)/2),
     *  - rim (Kirchhoff ring, extensible): (1/2) int [EA e^2 + EI2 (phi'/R)^2
     *    + T phi^2] R dtheta, e = (u_r + u_t')/R, phi = (u_r' - u_t)/R (the
     *    in-plane rotation; T phi^2/2 is the second-order part of the exact
     *    stretch |r'|),
     * with u_plate(R, theta) = u_rim(theta). The disc's mode n (Navier
     * polynomials r^{n-1}, r^{n+1}) is condensed onto the rim displacement;
     * the hoop force T_cr is the first zero of the 2x2 determinant below 0,
     * converted with the Lame relation T = EA k Delta/(EA + k). The value is
     * negative (the rim outgrows the plate). Soft-plate limit (E h -> 0 at
     * fixed T, inextensible rim): T_cr = -n^2 (n^2 - 1)/(n^2 - n - 1) EI2/R^2
     * (the prestressed plate still resists by N |grad u|^2 / 2); see the doc
     * for the hydrostatic (n^2 - 1) and dead-load (n^2) variants.
     */
    double
    planar_critical_mismatch(const PlateRod &p, unsigned int n);

    /// Hoop force T_cr (< 0) of planar_critical_mismatch().
    double
    planar_critical_hoop_force(const PlateRod &p, unsigned int n);

    /**
     * Out-of-plane n-lobed buckling (n >= 2) for Delta < 0: plate deflection
     * w = f(r) cos(n theta) under the tension N = -T/R (D lap^2 w - N lap w = 0,
     * f = a (r/R)^n + b I_n(mu r)/I_n(mu R), mu^2 = N/D), welded to a Kirchhoff
     * ring with out-of-plane bending EI1 (kappa_1 = (w'' - R beta)/R^2), torsion
     * GJ (kappa_3 = (R beta' + w')/R^2), beta = -dw/dr at the rim (rotation about
     * e_theta) and the compressive prestress term T (w'/R)^2/2. With
     * x = mu R, e1 = EI1/(R D), g = GJ/(R D), chi = x I_n(x)/I_{n+1}(x), the
     * threshold is the smallest root x of
     *   chi [n(n-1)(e1+g) + 2n(1-v)] + n(n+1)[e1 g (n^2-1) + (1-v)(e1+g) - (1-v)^2]
     *     - x^2 [chi - (1-v) + e1 + g n^2] = 0,
     * T_cr = -D x^2/R; returned as the (negative) mismatch. n = 0 and n = 1
     * (beyond the rigid tilt) are stable under T < 0; see the doc.
     */
    double
    out_of_plane_critical_mismatch(const PlateRod &p, unsigned int n);

    /// The determinant above (divided by n(n-1)), for tests.
    double
    out_of_plane_determinant(double poisson, double e1, double g, unsigned int n, double x);

    /// Its smallest positive root x = mu R (throws std::domain_error if none below 1e9).
    double
    out_of_plane_load_parameter(double poisson, double e1, double g, unsigned int n);

    /// x I_n(x) / I_{n+1}(x) for x > 0, overflow-free (-> 2(n+1) as x -> 0, ~ x + 1/2 + n as x -> inf).
    double
    bessel_i_chi(unsigned int n, double x);

    /**
     * The first mode of a family over n = 2..n_max: the mismatch closest to 0.
     * With n_step > 1 only the multiples of n_step (from max(2, n_step)):
     * the mode numbers a sector pi/n_step admits.
     * at_n_max is set when that is n = n_max: the family's minimum may lie
     * beyond (planar lobes of an extensible rim on a stiff plate wrinkle at
     * high n, n ~ R (E h / EI2)^{1/3}; see the doc), search further.
     */
    struct LobedThreshold
    {
      unsigned int n        = 0;
      double       mismatch = 0;
      bool         at_n_max = false;
    };
    LobedThreshold
    first_planar(const PlateRod &p, unsigned int n_max = 12, unsigned int n_step = 1);
    LobedThreshold
    first_out_of_plane(const PlateRod &p, unsigned int n_max = 12, unsigned int n_step = 1);
  } // namespace analysis
} // namespace cosmo

#endif

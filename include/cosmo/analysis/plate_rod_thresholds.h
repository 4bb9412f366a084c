#ifndef cosmo_analysis_plate_rod_thresholds_h
#define cosmo_analysis_plate_rod_thresholds_h

/**
 * Closed forms of part 3 (plate-rod.md, "Critical growth, analytically"):
 * a flat circular Kirchhoff plate (radius R, thickness h, E, Poisson v)
 * welded to a rim rod (EA, out-of-plane bending EI1 about the radial axis,
 * in-plane bending EI2 about the plate normal), with isotropic in-plane
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

      /// Plate bending stiffness D = E h^3 / (12 (1 - v^2)).
      double
      plate_D() const;
      /// In-plane radial stiffness of the disc's edge per unit rim length,
      /// k = R E h / (1 - v): the membrane force is k/R times the radial strain.
      double
      edge_stiffness() const;
    };

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
     */
    double
    planar_critical_mismatch_soft_plate(const PlateRod &p, unsigned int n);
  } // namespace analysis
} // namespace cosmo

#endif

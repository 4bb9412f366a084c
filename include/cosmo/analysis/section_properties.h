#ifndef cosmo_analysis_section_properties_h
#define cosmo_analysis_section_properties_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/full_matrix.h>

#include <cosmo/io/output.h>

#include <array>
#include <functional>

/**
 * Cross-section properties as the beam-section tools report them (BECAS,
 * VABS, sectionproperties), in two independent ways
 * (doc/theory-rod-cross-section.md, "Section properties"):
 *
 * 1. linear_section_properties(): the linear-elastic Saint-Venant problems of
 *    the reference section with the small-strain moduli of each region --
 *    modulus-weighted (elastic) centre, bending stiffnesses and principal
 *    axes, the torsion warping function (torsional stiffness GJ, Trefftz's
 *    shear centre) and the flexure warping functions (shear centre, shear
 *    stiffnesses and correction factors; with the Poisson effect in the
 *    flexure neglected, as in Trefftz's definition, exact for nu = 0).
 * 2. analyse_stiffness(): what a 6x6 stiffness (of the reference or of any
 *    grown, prestressed state) says: its compliance, tension centre, the
 *    shear centre as the point where a shear force causes no twist, the
 *    principal bending axes, the condensed (all other resultants zero)
 *    stiffnesses, and the 6x6 about the tension centre in principal axes.
 *
 * Strains and resultants in the order nu1, nu2, nu3, kappa1, kappa2, kappa3
 * and n1, n2, n3, m1, m2, m3, components in the section's axes (E1, E2, E3).
 */
namespace cosmo
{
  namespace analysis
  {
    using namespace dealii;

    /// Small-strain moduli of a region.
    struct RegionModuli
    {
      double young   = 1;
      double shear   = 1.0 / 2.6;
      double density = 1;
    };

    struct LinearSectionProperties
    {
      double   area = 0;
      Point<2> centroid;        ///< geometric
      double   EA = 0;          ///< int E dA
      double   GA = 0;          ///< int G dA (uncorrected shear stiffness)
      Point<2> elastic_centre;  ///< E-weighted centroid (tension centre)
      /// About the elastic centre: EI11 = int E X2^2, EI22 = int E X1^2, EI12 = int E X1 X2.
      double EI11 = 0, EI22 = 0, EI12 = 0;
      /// Angle (rad, from E1 counterclockwise) of the principal axis of the
      /// larger bending stiffness; NaN if both are equal to 1e-9 (every axis is principal).
      double                principal_angle = 0;
      std::array<double, 2> principal_bending{{0, 0}}; ///< larger, smaller
      double                GJ = 0;                    ///< Saint-Venant torsional stiffness
      /// Vlasov's warping stiffness E Gamma = int E omega^2 (omega the torsion
      /// warping about the shear centre, zero E-weighted mean; E Cw for one material).
      double EGamma = 0;
      Point<2>              shear_centre_trefftz;
      Point<2>              shear_centre_flexure;
      /// Shear stiffness matrix (forces n1, n2 against shear strains), from the flexure warping.
      FullMatrix<double> shear_stiffness{2, 2};
      /// k_a = shear_stiffness(a, a) / GA.
      std::array<double, 2> shear_factors{{0, 0}};
      /// Mass per unit length, mass centre, and the mass moments of inertia
      /// per length about it: rho11 = int rho X2^2, rho22 = int rho X1^2,
      /// rho12 = int rho X1 X2, polar = rho11 + rho22 (rotary inertia of the rod).
      double                mass = 0;
      Point<2>              mass_centre;
      double                mass_moment11 = 0, mass_moment22 = 0, mass_moment12 = 0;
      unsigned int          n_dofs = 0;

      io::JSON
      to_json() const;
    };

    /**
     * Solve the section's Saint-Venant problems with FE_Q(degree) on `tria`
     * (mapped by `mapping`); `moduli` gives E and G of each region
     * (material id).
     */
    LinearSectionProperties
    linear_section_properties(const Triangulation<2> &                                 tria,
                              const Mapping<2> &                                       mapping,
                              unsigned int                                             degree,
                              const std::function<RegionModuli(types::material_id)> &moduli);

    /**
     * The 6x6 stiffness about the reference line moved to `c` (section
     * coordinates) with axes rotated by `angle` (rad) about E3: with
     * e' = T e, nu' = nu + kappa x c, kappa' = kappa, and the components
     * rotated, K' = T^-T K T^-1 (the energy is unchanged; the resultants
     * become n' = n, m' = m - c x n).
     */
    FullMatrix<double>
    transform_stiffness(const FullMatrix<double> &K, const Point<2> &c, double angle);

    struct StiffnessAnalysis
    {
      bool               invertible = false;
      FullMatrix<double> compliance{6, 6};
      /// Where an axial force causes no bending curvature.
      Point<2> tension_centre;
      /// Where a shear force causes no twist (compliance: C'(kappa3, nu_a) = 0).
      Point<2> shear_centre;
      /// Principal bending axes: angle (rad) of the stiffer one, and the
      /// bending stiffnesses 1/eigenvalues of the bending compliance.
      double                principal_angle = 0;
      std::array<double, 2> principal_bending{{0, 0}};
      /// 1/C(k,k): each stiffness with every other resultant zero (e.g. the
      /// torsional stiffness of the free section is condensed[5]).
      std::array<double, 6> condensed{{0, 0, 0, 0, 0, 0}};
      /// The 6x6 about the tension centre in the principal axes.
      FullMatrix<double> principal_stiffness{6, 6};
      /// Largest |K_ab| / sqrt(K_aa K_bb), a != b, of the given matrix.
      double largest_coupling = 0;

      io::JSON
      to_json() const;
    };

    StiffnessAnalysis
    analyse_stiffness(const FullMatrix<double> &K);
  } // namespace analysis
} // namespace cosmo

#endif

#ifndef cosmo_materials_rod_laws_quadratic_h
#define cosmo_materials_rod_laws_quadratic_h

#include <cosmo/materials/rod_law.h>

/**
 * The quadratic rod law, registered as 'quadratic':
 *
 *   psi(e) = 1/2 (GA1 e1^2 + GA2 e2^2 + EA e3^2 + EI1 e4^2 + EI2 e5^2 + GJ e6^2)
 *            + sum_{i<j} K_ij e_i e_j
 *
 * with the couplings K_ij of a full symmetric 6x6 (zero by default), e.g.
 * the stiffness a part-1 computation gives for the rod's cross-section at
 * its natural state (an eccentric or unsymmetric section couples extension
 * and bending, a shear centre off the line shear and twist: never
 * diagonalized).
 */
namespace cosmo
{
  namespace materials
  {
    class QuadraticRodLaw : public RodLaw
    {
    public:
      /// GA1, GA2, EA, EI1, EI2, GJ in the order of the strains.
      std::array<double, 6> stiffness{{1, 1, 1, 1, 1, 1}};
      /// Off-diagonal stiffnesses K_ij (set both halves with set_coupling();
      /// the diagonal is `stiffness`).
      std::array<std::array<double, 6>, 6> coupling{};
      /// The part-1 summary.json the stiffness was read from (empty: the entries).
      std::string stiffness_file;

      static void
      declare_parameters(ParameterHandler &prm);
      /// 'Stiffnesses', or the 6x6 of 'Stiffness file' (symmetric positive definite).
      void
      parse_parameters(ParameterHandler &prm, const std::string &section) override;

      void
      set_coupling(const unsigned int i, const unsigned int j, const double value)
      {
        if (i != j)
          coupling[i][j] = coupling[j][i] = value;
      }
      /// The largest coupling |K_ij| / sqrt(K_ii K_jj).
      double
      largest_coupling() const;

      void
      energy_derivatives(const std::array<double, 6> &e,
                         bool                         with_hessian,
                         double &                     W,
                         std::array<double, 6> &      dW,
                         std::array<double, 36> &     ddW) const override;
      std::string
      description() const override;
    };
  } // namespace materials
} // namespace cosmo

#endif

#ifndef cosmo_materials_rod_law_h
#define cosmo_materials_rod_law_h

#include <algorithm>
#include <array>
#include <cmath>

/**
 * A special Cosserat rod with a quadratic law in its six strains and axial
 * growth (doc/specification/plate-rod.md): with reference strains (nu0, kappa0) and growth g,
 * the stress-free rod has strains g nu0 and kappa0 (a ring of radius R grows
 * to radius g R: the curvature per reference length stays 1/R), and the
 * energy per reference length is
 *
 *   g psi(nu/g - nu0, kappa/g - kappa0/g),
 *   psi(a, b) = 1/2 (GA1 a1^2 + GA2 a2^2 + EA a3^2 + EI1 b1^2 + EI2 b2^2 + GJ b3^2)
 *               + sum_{i<j} K_ij e_i e_j   (e = (a, b); couplings, zero by default).
 *
 * The stiffnesses may be given or taken from a part-1 computation of the
 * rod's cross-section (its full 6x6 stiffness at the natural state: the
 * couplings of an eccentric or unsymmetric section, e.g. shear-twist about
 * a shear centre off the reference line). Templated on the number type for Sacado.
 */
namespace cosmo
{
  namespace materials
  {
    struct QuadraticRodLaw
    {
      /// GA1, GA2, EA, EI1, EI2, GJ in the order of the strains.
      std::array<double, 6> stiffness{{1, 1, 1, 1, 1, 1}};
      std::array<double, 6> reference_strains{{0, 0, 1, 0, 0, 0}};
      /// Off-diagonal stiffnesses K_ij, i < j (set both halves with
      /// set_coupling(); the diagonal is `stiffness`).
      std::array<std::array<double, 6>, 6> coupling{};

      void
      set_coupling(const unsigned int i, const unsigned int j, const double value)
      {
        if (i != j)
          coupling[i][j] = coupling[j][i] = value;
      }

      /// Whether any coupling is non-zero.
      bool
      coupled() const
      {
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = 0; j < 6; ++j)
            if (i != j && coupling[i][j] != 0)
              return true;
        return false;
      }

      /// Scale strain k's stiffness row and column by f (K -> D K D with
      /// D_kk = sqrt(f)): the diagonal by f, its couplings by sqrt(f), which
      /// keeps K positive definite (the Kirchhoff penalty on GA1, GA2).
      void
      scale_strain(const unsigned int k, const double f)
      {
        stiffness[k] *= f;
        for (unsigned int j = 0; j < 6; ++j)
          if (j != k)
            {
              coupling[k][j] *= std::sqrt(f);
              coupling[j][k] *= std::sqrt(f);
            }
      }

      template <typename Number>
      Number
      energy(const std::array<Number, 6> &strains, const double growth) const
      {
        Number                W = 0. * strains[0];
        std::array<Number, 6> e;
        for (unsigned int k = 0; k < 6; ++k)
          {
            // nu/g - nu0 (k < 3); kappa/g - kappa0/g (k >= 3)
            e[k] = k < 3 ? Number(strains[k] / growth - reference_strains[k]) :
                           Number((strains[k] - reference_strains[k]) / growth);
            W += 0.5 * stiffness[k] * e[k] * e[k];
          }
        for (unsigned int i = 0; i < 6; ++i)
          for (unsigned int j = i + 1; j < 6; ++j)
            if (coupling[i][j] != 0)
              W += coupling[i][j] * e[i] * e[j];
        return growth * W;
      }

      /**
       * The resultants (n, m) = dW/d(nu, kappa) of energy(): r = K e with
       * e_k = strain_k / g - e0_k (nu), (strain_k - e0_k) / g (kappa), e.g.
       * uncoupled n_k = K_k (e_k / g - e0_k), m_k = K_k (e_k - e0_k) / g. The
       * output writes these; nothing re-derives the law.
       */
      std::array<double, 6>
      resultants(const std::array<double, 6> &strains, const double growth) const
      {
        std::array<double, 6> e, r;
        for (unsigned int k = 0; k < 6; ++k)
          e[k] = k < 3 ? strains[k] / growth - reference_strains[k] :
                         (strains[k] - reference_strains[k]) / growth;
        for (unsigned int i = 0; i < 6; ++i)
          {
            r[i] = stiffness[i] * e[i];
            for (unsigned int j = 0; j < 6; ++j)
              if (j != i)
                r[i] += coupling[std::min(i, j)][std::max(i, j)] * e[j];
          }
        return r;
      }
    };
  } // namespace materials
} // namespace cosmo

#endif

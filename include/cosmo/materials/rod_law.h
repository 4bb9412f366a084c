#ifndef cosmo_materials_rod_law_h
#define cosmo_materials_rod_law_h

#include <array>

/**
 * A special Cosserat rod with a quadratic law in its six strains and axial
 * growth (doc/specification/plate-rod.md): with reference strains (nu0, kappa0) and growth g,
 * the stress-free rod has strains g nu0 and kappa0 (a ring of radius R grows
 * to radius g R: the curvature per reference length stays 1/R), and the
 * energy per reference length is
 *
 *   g psi(nu/g - nu0, kappa/g - kappa0/g),
 *   psi(a, b) = 1/2 (GA1 a1^2 + GA2 a2^2 + EA a3^2 + EI1 b1^2 + EI2 b2^2 + GJ b3^2).
 *
 * The stiffnesses may be given or taken from a part-1 computation of the
 * rod's cross-section (its 6x6 stiffness at the natural state, diagonal
 * part). Templated on the number type for Sacado.
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

      template <typename Number>
      Number
      energy(const std::array<Number, 6> &strains, const double growth) const
      {
        Number W = 0. * strains[0];
        for (unsigned int k = 0; k < 6; ++k)
          {
            // nu/g - nu0 (k < 3); kappa/g - kappa0/g (k >= 3)
            const Number e = k < 3 ? Number(strains[k] / growth - reference_strains[k]) :
                                     Number((strains[k] - reference_strains[k]) / growth);
            W += 0.5 * stiffness[k] * e * e;
          }
        return growth * W;
      }

      /**
       * The resultants (n, m) = dW/d(nu, kappa) of energy():
       * n_k = K_k (e_k / g - e0_k), m_k = K_k (e_k - e0_k) / g. The output
       * writes these; nothing re-derives the law.
       */
      std::array<double, 6>
      resultants(const std::array<double, 6> &strains, const double growth) const
      {
        std::array<double, 6> r;
        for (unsigned int k = 0; k < 6; ++k)
          r[k] = k < 3 ? stiffness[k] * (strains[k] / growth - reference_strains[k]) :
                         stiffness[k] * (strains[k] - reference_strains[k]) / growth;
        return r;
      }
    };
  } // namespace materials
} // namespace cosmo

#endif

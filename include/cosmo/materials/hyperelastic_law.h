#ifndef cosmo_materials_hyperelastic_law_h
#define cosmo_materials_hyperelastic_law_h

#include <array>
#include <cmath>
#include <string>

/**
 * Isotropic hyperelastic stored-energy functions W(F), templated on the
 * number type so that Sacado differentiates them. F is passed row-major as
 * nine numbers (F[3*i+j] = F_ij) rather than as a dealii::Tensor: the static
 * Sacado types used in the hot loop have no dealii::ProductType
 * specializations, and the laws need nothing but arithmetic.
 */
namespace cosmo
{
  namespace materials
  {
    enum class HyperelasticModel
    {
      neo_hookean,
      saint_venant_kirchhoff
    };

    /// Parse "neo-Hookean" / "Saint Venant-Kirchhoff"; throws on other names.
    HyperelasticModel
    hyperelastic_model_from_string(const std::string &name);
    /// The pattern string of allowed names, for ParameterHandler.
    std::string
    hyperelastic_model_names();

    struct HyperelasticLaw
    {
      HyperelasticModel model  = HyperelasticModel::neo_hookean;
      double            mu     = 0; ///< shear modulus (small-strain)
      double            lambda = 0; ///< first Lame parameter (small-strain)

      static HyperelasticLaw
      from_young_poisson(HyperelasticModel model, double young, double poisson);

      double
      young() const
      {
        return mu * (3 * lambda + 2 * mu) / (lambda + mu);
      }
      double
      poisson() const
      {
        return lambda / (2 * (lambda + mu));
      }

      /**
       * W(F). Compressible neo-Hookean: mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2;
       * Saint-Venant-Kirchhoff: lambda/2 (tr E)^2 + mu E:E, E = (F^T F - I)/2.
       * For J <= 0 the neo-Hookean energy is +infinity (an inadmissible state).
       */
      template <typename Number>
      Number
      energy(const std::array<Number, 9> &F) const
      {
        if (model == HyperelasticModel::neo_hookean)
          {
            using std::log;
            const Number J =
              F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
              F[2] * (F[3] * F[7] - F[4] * F[6]);
            if (!(J > 0.))
              return Number(std::numeric_limits<double>::infinity());
            Number I1 = F[0] * F[0];
            for (unsigned int k = 1; k < 9; ++k)
              I1 += F[k] * F[k];
            const Number lnJ = log(J);
            return 0.5 * mu * (I1 - 3. - 2. * lnJ) + 0.5 * lambda * lnJ * lnJ;
          }
        else
          {
            // E = (F^T F - I)/2, symmetric: six independent entries.
            std::array<Number, 9> E;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = i; j < 3; ++j)
                {
                  Number c = F[i] * F[j];
                  c += F[3 + i] * F[3 + j];
                  c += F[6 + i] * F[6 + j];
                  E[3 * i + j] = 0.5 * (c - (i == j ? 1. : 0.));
                  E[3 * j + i] = E[3 * i + j];
                }
            const Number trE = E[0] + E[4] + E[8];
            Number       EE  = E[0] * E[0];
            for (unsigned int k = 1; k < 9; ++k)
              EE += E[k] * E[k];
            return 0.5 * lambda * trE * trE + mu * EE;
          }
      }
    };
  } // namespace materials
} // namespace cosmo

#include <limits>

#endif

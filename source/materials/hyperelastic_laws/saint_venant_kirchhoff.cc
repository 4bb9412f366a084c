// The Saint Venant-Kirchhoff law lambda/2 (tr E)^2 + mu E:E, E = (Fe^T Fe - I)/2.
#include <cosmo/materials/hyperelastic_law.h>

namespace cosmo
{
  namespace materials
  {
    class SaintVenantKirchhoff : public HyperelasticLawOf<SaintVenantKirchhoff>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      std::string
      name() const override
      {
        return "Saint Venant-Kirchhoff";
      }
      template <typename Number>
      Number
      energy_of(const std::array<Number, 9> &F) const
      {
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
    };

    COSMO_REGISTER_PLUGIN(HyperelasticLaw,
                          SaintVenantKirchhoff,
                          "Saint Venant-Kirchhoff",
                          "lambda/2 (tr E)^2 + mu E:E.")
  } // namespace materials
} // namespace cosmo

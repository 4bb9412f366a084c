// The compressible neo-Hookean law mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2.
#include <cosmo/materials/hyperelastic_law.h>

#include <cmath>
#include <limits>

namespace cosmo
{
  namespace materials
  {
    class NeoHookean : public HyperelasticLawOf<NeoHookean>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      std::string
      name() const override
      {
        return "neo-Hookean";
      }
      template <typename Number>
      Number
      energy_of(const std::array<Number, 9> &F) const
      {
        using std::log;
        const Number J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                         F[2] * (F[3] * F[7] - F[4] * F[6]);
        if (!(J > 0.))
          return Number(std::numeric_limits<double>::infinity());
        Number I1 = F[0] * F[0];
        for (unsigned int k = 1; k < 9; ++k)
          I1 += F[k] * F[k];
        const Number lnJ = log(J);
        return 0.5 * mu * (I1 - 3. - 2. * lnJ) + 0.5 * lambda * lnJ * lnJ;
      }
    };

    COSMO_REGISTER_PLUGIN(HyperelasticLaw,
                          NeoHookean,
                          "neo-Hookean",
                          "compressible neo-Hookean mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2.")
  } // namespace materials
} // namespace cosmo

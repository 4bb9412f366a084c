#include <cosmo/materials/rod_law.h>

#include <algorithm>
#include <cmath>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::RodLaw>;
  } // namespace plugins

  namespace materials
  {
    std::array<double, 36>
    RodLaw::natural_stiffness() const
    {
      double                 W = 0;
      std::array<double, 6>  dW{};
      std::array<double, 36> K{};
      energy_derivatives(std::array<double, 6>{}, true, W, dW, K);
      return K;
    }

    double
    largest_coupling(const std::array<double, 36> &K)
    {
      double c = 0;
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          if (a != b)
            c = std::max(c, std::abs(K[6 * a + b]) / std::sqrt(std::abs(K[7 * a] * K[7 * b])));
      return c;
    }

    std::array<double, 6>
    grown_rod_resultants(const RodLaw &law, const std::array<double, 6> &strains, const RodNaturalState &n)
    {
      double                 W = 0;
      std::array<double, 6>  dW{};
      std::array<double, 36> ddW{};
      law.energy_derivatives_at(n.parameter, elastic_rod_strains(strains, n), false, W, dW, ddW);
      // d(g psi)/dnu_k = g psi_k w_k / g, d(g psi)/dkappa_k = g psi_k w_k / g.
      for (unsigned int k = 0; k < 6; ++k)
        dW[k] *= n.weights[k];
      return dW;
    }

    void
    declare_rod_law_parameters(ParameterHandler &prm)
    {
      using Laws = plugins::Registry<RodLaw>;
      prm.declare_entry("Law", "quadratic", Patterns::Selection(Laws::names()),
                        "The rod's law, an energy per unit length in its six strains measured "
                        "from the natural state (the registered laws, "
                        "source/materials/rod_laws/). " +
                          Laws::documentation());
      Laws::declare_parameters(prm);
    }

    std::unique_ptr<RodLaw>
    create_rod_law(ParameterHandler &prm, const std::string &section)
    {
      auto law = plugins::Registry<RodLaw>::create(prm.get("Law"));
      law->parse_parameters(prm, section);
      return law;
    }
  } // namespace materials
} // namespace cosmo

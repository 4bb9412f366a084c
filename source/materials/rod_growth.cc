#include <cosmo/materials/rod_growth.h>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::RodGrowthLaw>;
  } // namespace plugins

  namespace materials
  {
    void
    declare_rod_growth_parameters(ParameterHandler &prm)
    {
      using Laws = plugins::Registry<RodGrowthLaw>;
      prm.declare_entry("Growth kind", "uniform", Patterns::Selection(Laws::names()),
                        "The rod's growth (the registered laws, "
                        "source/materials/rod_growth_laws/). " +
                          Laws::documentation());
      Laws::declare_parameters(prm);
    }

    std::unique_ptr<RodGrowthLaw>
    create_rod_growth(ParameterHandler &prm, const std::string &section)
    {
      auto law = plugins::Registry<RodGrowthLaw>::create(prm.get("Growth kind"));
      law->parse_parameters(prm, section);
      return law;
    }
  } // namespace materials
} // namespace cosmo

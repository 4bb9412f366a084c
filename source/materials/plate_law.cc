#include <cosmo/io/parameters.h>
#include <cosmo/materials/plate_law.h>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::PlateLaw>;
  } // namespace plugins

  namespace materials
  {
    PlateStrains<double>
    PlateLawAt::resultants(const PlateStrains<double> &s) const
    {
      std::array<double, plate_measures>                  dW{}, sum{};
      std::array<double, plate_measures * plate_measures> ddW{};
      double                                              W = 0;
      for (const PlatePart part : {PlatePart::membrane_and_bending, PlatePart::transverse_shear})
        {
          derivatives(measures_of(s), part, false, W, dW, ddW);
          for (unsigned int k = 0; k < plate_measures; ++k)
            sum[k] += dW[k];
        }
      // dW/de_12 counts the pair 12, 21: the tensor component is half of it.
      return {{{sum[0], sum[1], 0.5 * sum[2]}}, {{sum[3], sum[4], 0.5 * sum[5]}}, {{sum[6], sum[7]}}};
    }

    void
    declare_plate_law_parameters(ParameterHandler &prm)
    {
      using Laws = plugins::Registry<PlateLaw>;
      prm.enter_subsection("Plate material");
      prm.declare_entry("Law", "linear isotropic", Patterns::Selection(Laws::names()),
                        "The plate's law, an energy per unit area in its membrane, bending "
                        "and shear strains (the registered laws, source/materials/plate_laws/). " +
                          Laws::documentation());
      Laws::declare_parameters(prm);
      prm.leave_subsection();
    }

    std::unique_ptr<PlateLaw>
    create_plate_law(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate material");
      auto law = plugins::Registry<PlateLaw>::create(prm.get("Law"));
      law->parse_parameters(prm);
      prm.leave_subsection();
      return law;
    }
  } // namespace materials
} // namespace cosmo

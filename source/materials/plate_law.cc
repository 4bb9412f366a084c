#include <cosmo/io/parameters.h>
#include <cosmo/materials/plate_law.h>

namespace cosmo
{
  namespace materials
  {
    void
    NaghdiPlateLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate material");
      prm.declare_entry("Young's modulus", "1", Patterns::Double(0),
                        "E of the plate (units of stress).");
      prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-0.999, 0.49999),
                        "Poisson's ratio v of the plate.");
      prm.declare_entry("Shear correction factor", "0.833333333333333", Patterns::Double(0),
                        "ks of the transverse shear energy ks G h/2 |gamma|^2 (5/6).");
      prm.leave_subsection();
    }

    void
    NaghdiPlateLaw::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate material");
      young        = prm.get_double("Young's modulus");
      poisson      = prm.get_double("Poisson's ratio");
      shear_factor = prm.get_double("Shear correction factor");
      if (!(young > 0 && young <= 1e100))
        throw io::InputError("Plate material", "Young's modulus", prm.get("Young's modulus"),
                             "must be positive and at most 1e100 (its products with itself "
                             "and the lengths must stay finite in double precision)");
      if (!(shear_factor > 0))
        throw io::InputError("Plate material", "Shear correction factor",
                             prm.get("Shear correction factor"), "must be positive");
      prm.leave_subsection();
    }
  } // namespace materials
} // namespace cosmo

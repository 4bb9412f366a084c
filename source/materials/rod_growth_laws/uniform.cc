// Uniform rod growth: a constant axial factor and a constant change of the
// stress-free curvature along the rod, both ramped by the load t.
#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>
#include <cosmo/materials/rod_growth.h>

namespace cosmo
{
  namespace materials
  {
    class UniformRodGrowth : public RodGrowthLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Natural curvature", "0, 0, 0", Patterns::Anything(),
                          "Change of the rod's stress-free curvature reached at t = 1 (ramped "
                          "as t dk) from its own growth through its section: dk1, dk2, dk3 in "
                          "its frame, for the rim d1 = e_r, d2 = E3, d3 = -e_theta (dk1 bends "
                          "the rim out of the plate's plane, dk2 changes its in-plane "
                          "curvature, dk3 is a natural twist), per unit length.");
        prm.declare_entry("Growth factor", "1", Patterns::Double(0),
                          "Axial growth g of the rod at t = 1 (ramped as 1 + t (g - 1)); the "
                          "stress-free rim is a ring of radius g R.");
      }
      void
      parse_parameters(ParameterHandler &prm, const std::string &section) override
      {
        const auto k = io::get_double_list(prm, "Natural curvature", 3, section);
        for (unsigned int i = 0; i < 3; ++i)
          curvature[i] = k[i];
        g = prm.get_double("Growth factor");
        if (!(g > 0))
          throw io::InputError(section, "Growth factor", prm.get("Growth factor"),
                               "must be positive");
      }
      double
      factor(const double t) const override
      {
        return growth_ramp(t, g);
      }
      std::array<double, 3>
      natural_curvature(const double t) const override
      {
        return {{t * curvature[0], t * curvature[1], t * curvature[2]}};
      }

    private:
      double                g = 1;
      std::array<double, 3> curvature{{0., 0., 0.}};
    };

    COSMO_REGISTER_PLUGIN(RodGrowthLaw,
                          UniformRodGrowth,
                          "uniform",
                          "the same 'Growth factor' and 'Natural curvature' all along the rod, "
                          "ramped by t.")
  } // namespace materials
} // namespace cosmo

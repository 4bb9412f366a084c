#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>
#include <cosmo/materials/plate_growth.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::PlateGrowthLaw>;
  } // namespace plugins

  namespace materials
  {
    void
    PlateGrowth::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate growth");
      using Laws = plugins::Registry<PlateGrowthLaw>;
      prm.declare_entry("Kind", "none", Patterns::Selection(Laws::names()),
                        "In-plane growth G of the plate (the registered laws, "
                        "source/materials/plate_growth_laws/). " + Laws::documentation());
      prm.declare_entry("Radial growth factor", "1", Patterns::Anything(),
                        "g_r (or g, isotropic) as a muparser expression of the radius r.");
      prm.declare_entry("Circumferential growth factor", "1", Patterns::Anything(),
                        "g_t as a muparser expression of the radius r (polar growth).");
      Laws::declare_parameters(prm);
      prm.leave_subsection();
    }

    std::shared_ptr<FunctionParser<1>>
    parse_expression_of_r(const std::string &text, const std::string &entry)
    {
      auto f = std::make_shared<FunctionParser<1>>(1);
      try
        {
          f->initialize("r", text, {{"pi", M_PI}});
          f->value(Point<1>(0.123));
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw io::InputError("Plate growth", entry, text,
                               "a muparser expression of r (and pi); the parser said: " +
                                 info.str());
        }
      return f;
    }

    void
    PlateGrowth::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate growth");
      auto l = plugins::Registry<PlateGrowthLaw>::create(prm.get("Kind"));
      l->parse_parameters(prm);
      law                  = std::move(l);
      radial_text          = prm.get("Radial growth factor");
      circumferential_text = prm.get("Circumferential growth factor");
      prm.leave_subsection();
    }

    void
    PlateGrowth::check_positive(const double radius) const
    {
      for (const double t : {0., 1.})
        for (unsigned int i = 0; i <= 20; ++i)
          {
            const auto g = factors(radius * i / 20., t);
            if (!(g[0] > 0) || !(g[1] > 0))
              throw io::InputError("Plate growth",
                                   g[0] > 0 ? "Circumferential growth factor" : "Radial growth factor",
                                   g[0] > 0 ? circumferential_text : radial_text,
                                   "growth factors must be positive for 0 <= r <= R (not at r = " +
                                     std::to_string(radius * i / 20.) + ")");
          }
    }

    std::array<double, 2>
    PlateGrowth::factors(const double r, const double t) const
    {
      return law ? law->factors(r, t) : std::array<double, 2>{{1., 1.}};
    }

    std::array<std::array<double, 2>, 2>
    PlateGrowth::value(const Point<2> &X, const double t) const
    {
      const double r = X.norm();
      const auto   g = factors(r, t);
      if (r == 0 || g[0] == g[1])
        return {{{{g[0], 0.}}, {{0., g[0]}}}};
      const double c = X[0] / r, s = X[1] / r;
      // g_r e_r e_r^T + g_t e_t e_t^T, e_r = (c, s), e_t = (-s, c)
      return {{{{g[0] * c * c + g[1] * s * s, (g[0] - g[1]) * c * s}},
               {{(g[0] - g[1]) * c * s, g[0] * s * s + g[1] * c * c}}}};
    }
  } // namespace materials
} // namespace cosmo

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>
#include <cosmo/materials/plate_growth.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace materials
  {
    void
    PlateGrowth::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate growth");
      prm.declare_entry("Kind", "none", Patterns::Selection("none|isotropic|polar"),
                        "none: G = I. isotropic: g I with g = 'Radial growth factor'. "
                        "polar: g_r e_r (x) e_r + g_t e_t (x) e_t.");
      prm.declare_entry("Radial growth factor", "1", Patterns::Anything(),
                        "g_r (or g, isotropic) as a muparser expression of the radius r.");
      prm.declare_entry("Circumferential growth factor", "1", Patterns::Anything(),
                        "g_t as a muparser expression of the radius r (polar growth).");
      prm.leave_subsection();
    }

    namespace
    {
      std::shared_ptr<FunctionParser<1>>
      parse_of_r(const std::string &text, const std::string &entry)
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
    } // namespace

    void
    PlateGrowth::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate growth");
      kind = prm.get("Kind");
      radial.reset();
      circumferential.reset();
      if (kind != "none")
        radial = parse_of_r(prm.get("Radial growth factor"), "Radial growth factor");
      if (kind == "polar")
        circumferential =
          parse_of_r(prm.get("Circumferential growth factor"), "Circumferential growth factor");
      prm.leave_subsection();
    }

    std::array<double, 2>
    PlateGrowth::factors(const double r, const double t) const
    {
      auto ramp = [t](const double g) { return growth_ramp(t, g); };
      if (kind == "none")
        return {{1., 1.}};
      const double gr = ramp(radial->value(Point<1>(r)));
      return {{gr, kind == "polar" ? ramp(circumferential->value(Point<1>(r))) : gr}};
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

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>
#include <cosmo/materials/growth_admissibility.h>
#include <cosmo/materials/plate_growth.h>

#include <deal.II/lac/vector.h>

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
      prm.declare_entry("Natural curvature", "0; 0; 0", Patterns::Anything(),
                        "Natural (target) curvature of the plate reached at t = 1 (ramped as "
                        "t k0): three muparser expressions k11; k22; k12 of x, y and r, "
                        "separated by ';', in the plate's axes, per unit grown length. The "
                        "bending strain is measured from it, in every model: a plate whose "
                        "growth (or temperature) varies through the thickness, e.g. "
                        "'c; c; 0' for the isotropic curvature c of a heated bilayer disc.");
      Laws::declare_parameters(prm);
      prm.leave_subsection();
    }

    std::shared_ptr<FunctionParser<3>>
    parse_expression_of_position(const std::string &text,
                                 const std::string &section,
                                 const std::string &entry,
                                 const unsigned int n_components)
    {
      auto f = std::make_shared<FunctionParser<3>>(n_components);
      try
        {
          f->initialize("x,y,r", text, {{"pi", M_PI}});
          Vector<double> v(n_components);
          f->vector_value(Point<3>(0.1, 0.2, 0.3), v);
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw io::InputError(section, entry, text,
                               std::to_string(n_components) +
                                 " muparser expression(s) of x, y, r (and pi), separated by "
                                 "';'; the parser said: " +
                                 info.str());
        }
      return f;
    }

    std::array<double, 3>
    PlateGrowth::natural_curvature(const Point<2> &X, const double t) const
    {
      if (!curvature)
        return {{0., 0., 0.}};
      Vector<double> v(3);
      curvature->vector_value(Point<3>(X[0], X[1], X.norm()), v);
      return {{t * v[0], t * v[1], t * v[2]}};
    }

    void
    PlateGrowth::check_natural_curvature(const std::vector<Point<2>> &points) const
    {
      for (const auto &X : points)
        {
          const auto k = natural_curvature(X, 1.);
          if (!std::isfinite(k[0]) || !std::isfinite(k[1]) || !std::isfinite(k[2]))
            throw io::InputError("Plate growth", "Natural curvature", curvature_text,
                                 "must be finite on the plate (not at x = " +
                                   std::to_string(X[0]) + ", y = " + std::to_string(X[1]) + ")");
        }
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
      curvature_text       = prm.get("Natural curvature");
      curvature            = parse_expression_of_position(curvature_text, "Plate growth",
                                                 "Natural curvature", 3);
      // Only zeros, separators and blanks (the default "0; 0; 0"): no natural curvature, and
      // no parser evaluation per point.
      if (curvature_text.find_first_not_of("0; .") == std::string::npos)
        curvature.reset();
      prm.leave_subsection();
    }

    void
    PlateGrowth::check_admissible(const std::vector<Point<2>> &points, const MPI_Comm comm) const
    {
      for (const unsigned int k : {0u, 1u})
        check_growth_admissible(
          points,
          [this, k](const Point<2> &X, const double t) {
            return std::vector<double>{factors(X.norm(), t)[k]};
          },
          {"Plate growth", k == 0 ? "Radial growth factor" : "Circumferential growth factor",
           k == 0 ? radial_text : circumferential_text,
           k == 0 ? "the radial growth factor" : "the circumferential growth factor"},
          comm);
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

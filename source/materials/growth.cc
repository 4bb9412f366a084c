#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace materials
  {
    void
    GrowthTensor::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Growth kind",
                        "none",
                        Patterns::Selection(
                          "none|isotropic|axial|fibre|helical fibre|orthotropic"),
                        "Kind of bulk growth Fg. none: Fg = I. isotropic: g I. "
                        "axial: I + (g-1) E3 (x) E3 (growth along the rod axis). "
                        "fibre: I + (g-1) f (x) f, f from 'Fibre direction'. "
                        "helical fibre: as fibre with f = cos(a) E3 + sin(a) E_theta, "
                        "a = 'Fibre angle' (active filaments wound about the axis). "
                        "orthotropic: diag(g1, g2, g3) from 'Growth factor' given as "
                        "three expressions separated by ';'.");
      prm.declare_entry("Growth factor",
                        "1",
                        Patterns::Anything(),
                        "Growth factor g (dimensionless, 1 = no growth) as an "
                        "expression of the reference cross-section coordinates x, y "
                        "(muparser syntax, e.g. '1 + 0.3*x'); for orthotropic growth "
                        "three expressions 'g1; g2; g3'. The continuation driver ramps "
                        "each factor as 1 + t (g - 1), t from 0 to 1.");
      prm.declare_entry("Fibre direction",
                        "0; 0; 1",
                        Patterns::Anything(),
                        "Fibre direction f for 'fibre' growth: three expressions of "
                        "x, y separated by ';' (normalised to unit length pointwise).");
      prm.declare_entry("Fibre angle",
                        "0",
                        Patterns::Double(-90, 90),
                        "Angle a (degrees) of helical fibres to the rod axis: "
                        "f = cos(a) E3 + sin(a) E_theta; positive a winds right-handed.");
    }

    std::unique_ptr<FunctionParser<2>>
      parse_expressions(const std::string &text,
                  unsigned int       n_components,
                  const std::string &where,
                  const std::string &entry)
      {
        const auto parts = Utilities::split_string_list(text, ';');
        if (parts.size() != n_components)
          throw io::InputError(where, entry, text,
                               "expected " + std::to_string(n_components) +
                                 " expression(s) separated by ';'");
        auto f = std::make_unique<FunctionParser<2>>(n_components);
        try
          {
            f->initialize("x,y", parts, {{"pi", M_PI}});
            // muparser only reports some errors (unknown variables) at evaluation.
            Vector<double> v(n_components);
            f->vector_value(Point<2>(0.1234, 0.2345), v);
          }
        catch (ExceptionBase &e)
          {
            // print_info: the message without deal.II's stack trace.
            std::ostringstream info;
            e.print_info(info);
            throw io::InputError(where, entry, text,
                                 "a muparser expression of x and y (and pi); the parser said: " +
                                   info.str());
          }
        catch (std::exception &e)
          {
            throw io::InputError(where, entry, text,
                                 "a muparser expression of x and y (and pi); the parser said: " +
                                   std::string(e.what()));
          }
        return f;
      }

    void
    GrowthTensor::parse_parameters(ParameterHandler &prm, const std::string &where)
    {
      const std::string kind = prm.get("Growth kind");
      if (kind == "none")
        growth_kind = Kind::none;
      else if (kind == "isotropic")
        growth_kind = Kind::isotropic;
      else if (kind == "axial")
        growth_kind = Kind::axial;
      else if (kind == "fibre")
        growth_kind = Kind::fibre;
      else if (kind == "helical fibre")
        growth_kind = Kind::helical_fibre;
      else
        growth_kind = Kind::orthotropic;

      factor_text = prm.get("Growth factor");
      fibre_text  = prm.get("Fibre direction");
      fibre_angle = prm.get_double("Fibre angle") * M_PI / 180.;
      factor.reset();
      fibre.reset();
      if (growth_kind == Kind::none)
        return;
      factor = parse_expressions(factor_text,
                           growth_kind == Kind::orthotropic ? 3 : 1,
                           where,
                           "Growth factor");
      if (growth_kind == Kind::fibre)
        fibre = parse_expressions(fibre_text, 3, where, "Fibre direction");
    }

    Tensor<2, 3>
    GrowthTensor::value(const Point<2> &X, const double t) const
    {
      Tensor<2, 3> Fg = unit_symmetric_tensor<3>();
      if (growth_kind == Kind::none)
        return Fg;
      auto ramp = [t](const double g) { return growth_ramp(t, g); };
      if (growth_kind == Kind::orthotropic)
        {
          for (unsigned int i = 0; i < 3; ++i)
            Fg[i][i] = ramp(factor->value(X, i));
          return Fg;
        }
      const double g = ramp(factor->value(X));
      Tensor<1, 3> f;
      switch (growth_kind)
        {
          case Kind::isotropic:
            return g * Fg;
          case Kind::axial:
            f[2] = 1;
            break;
          case Kind::fibre:
            for (unsigned int i = 0; i < 3; ++i)
              f[i] = fibre->value(X, i);
            AssertThrow(f.norm() > 0,
                        ExcMessage("The fibre direction vanishes at (" +
                                   std::to_string(X[0]) + ", " + std::to_string(X[1]) +
                                   "): '" + fibre_text + "'"));
            f /= f.norm();
            break;
          case Kind::helical_fibre:
            {
              // E_theta is undefined on the axis; there the fibre is axial.
              const double r = X.norm();
              f[2]           = std::cos(fibre_angle);
              if (r > 0)
                {
                  f[0] = -std::sin(fibre_angle) * X[1] / r;
                  f[1] = std::sin(fibre_angle) * X[0] / r;
                }
              else
                f[2] = 1;
              break;
            }
          default:
            Assert(false, ExcInternalError());
        }
      return Fg + (g - 1.) * outer_product(f, f);
    }

    std::string
    GrowthTensor::description() const
    {
      std::ostringstream s;
      switch (growth_kind)
        {
          case Kind::none:
            return "no growth";
          case Kind::isotropic:
            s << "isotropic, g = " << factor_text;
            break;
          case Kind::axial:
            s << "axial, g = " << factor_text;
            break;
          case Kind::fibre:
            s << "fibre, g = " << factor_text << ", f = (" << fibre_text << ")";
            break;
          case Kind::helical_fibre:
            s << "helical fibre, g = " << factor_text << ", angle "
              << fibre_angle * 180 / M_PI << " deg";
            break;
          case Kind::orthotropic:
            s << "orthotropic, (g1; g2; g3) = (" << factor_text << ")";
            break;
        }
      return s.str();
    }
  } // namespace materials
} // namespace cosmo

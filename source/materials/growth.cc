#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/growth.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::BulkGrowthLaw>;
  } // namespace plugins

  namespace materials
  {
    void
    GrowthTensor::declare_parameters(ParameterHandler &prm)
    {
      using Laws = plugins::Registry<BulkGrowthLaw>;
      prm.declare_entry("Growth kind",
                        "none",
                        Patterns::Selection(Laws::names()),
                        "Kind of bulk growth Fg (the registered growth laws, "
                        "source/materials/growth_laws/). " + Laws::documentation());
      prm.declare_entry("Growth factor",
                        "1",
                        Patterns::Anything(),
                        "Growth factor g (dimensionless, 1 = no growth) as an "
                        "expression of the reference cross-section coordinates x, y "
                        "(muparser syntax, e.g. '1 + 0.3*x'); for orthotropic growth "
                        "three expressions 'g1; g2; g3'. The continuation driver ramps "
                        "each factor as 1 + t (g - 1), t from 0 to 1.");
      Laws::declare_parameters(prm);
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
    GrowthFactors::parse(ParameterHandler &prm, const std::string &where, const unsigned int n)
    {
      expression_text = prm.get("Growth factor");
      expressions     = parse_expressions(expression_text, n, where, "Growth factor");
    }

    double
    GrowthFactors::ramped(const Point<2> &X, const double t, const unsigned int component) const
    {
      return growth_ramp(t, expressions->value(X, component));
    }

    void
    ScalarFactorGrowthLaw::parse_parameters(ParameterHandler &prm, const std::string &where)
    {
      factor.parse(prm, where, 1);
    }

    void
    GrowthTensor::parse_parameters(ParameterHandler &prm, const std::string &where)
    {
      factor_text = prm.get("Growth factor");
      law         = plugins::Registry<BulkGrowthLaw>::create(prm.get("Growth kind"));
      law->parse_parameters(prm, where);
    }
  } // namespace materials
} // namespace cosmo

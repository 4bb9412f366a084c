#ifndef cosmo_materials_growth_h
#define cosmo_materials_growth_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <memory>
#include <string>

/**
 * Growth tensors Fg(X1, X2) of the multiplicative decomposition F = Fe Fg.
 *
 * Kinds (doc/specification/rod-cross-section.md): isotropic g I; axial I + (g-1) E3 (x) E3;
 * fibre I + (g-1) f (x) f with a unit field f given by expressions, or helical
 * fibres f = cos(a) E3 + sin(a) E_theta (active filaments); orthotropic
 * diag(g1, g2, g3). Factors are expressions of x, y (the cross-section
 * coordinates X1, X2), so that differential growth is a formula in the .prm.
 *
 * Growth is ramped by the load parameter t in [0, 1] of the continuation
 * driver: every factor g is applied as 1 + t (g - 1), a convex combination of
 * 1 and g, so det Fg > 0 along the whole ramp if it is at t = 1.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /**
     * The growth ramp: a factor g given for t = 1 applies as 1 + t (g - 1)
     * at load t (no growth at t = 0). A convex combination of 1 and g for t
     * in [0, 1], so a factor positive at t = 1 is positive along the path.
     * Every growth law (bulk, surface, plate, rim) ramps through this.
     */
    inline double
    growth_ramp(const double t, const double g)
    {
      return 1. + t * (g - 1.);
    }

    /**
     * `n_components` muparser expressions of x, y (and the constant pi)
     * separated by ';', as given in entry `entry` of section `where`; an
     * io::InputError names both if the text does not parse.
     */
    std::unique_ptr<FunctionParser<2>>
    parse_expressions(const std::string &text,
                      unsigned int       n_components,
                      const std::string &where,
                      const std::string &entry);

    class GrowthTensor
    {
    public:
      enum class Kind
      {
        none,
        isotropic,
        axial,
        fibre,
        helical_fibre,
        orthotropic
      };

      static void
      declare_parameters(ParameterHandler &prm);
      /// `where` names the section for error messages.
      void
      parse_parameters(ParameterHandler &prm, const std::string &where);

      /// Fg at X for load parameter t (t = 1: the full growth of the .prm).
      Tensor<2, 3>
      value(const Point<2> &X, double t) const;

      /// The 'Growth factor' entry as given.
      const std::string &
      factor_expression() const
      {
        return factor_text;
      }
      /// One line for logs and summary.json.
      std::string
      description() const;

    private:
      Kind                                 growth_kind = Kind::none;
      std::unique_ptr<FunctionParser<2>>   factor;       // g (1 comp) or g1,g2,g3 (3)
      std::unique_ptr<FunctionParser<2>>   fibre;        // f (3 comps), normalised
      double                               fibre_angle = 0; // radians, helical fibres
      std::string                          factor_text, fibre_text;
    };
  } // namespace materials
} // namespace cosmo

#endif

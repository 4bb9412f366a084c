#ifndef cosmo_materials_growth_h
#define cosmo_materials_growth_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cosmo/base/plugins.h>

#include <memory>
#include <string>

/**
 * Growth tensors Fg(X1, X2) of the multiplicative decomposition F = Fe Fg.
 *
 * Laws (doc/specification/rod-cross-section.md; each a registered
 * BulkGrowthLaw in source/materials/growth_laws/): isotropic g I; axial
 * I + (g-1) E3 (x) E3; fibre I + (g-1) f (x) f with a unit field f given by
 * expressions, or helical fibres f = cos(a) E3 + sin(a) E_theta (active
 * filaments); orthotropic diag(g1, g2, g3). Factors are expressions of x, y (the cross-section
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

    /**
     * The 'Growth factor' entry of a growth law: n expressions of x, y
     * separated by ';', parsed (an io::InputError names the section and the
     * entry) and evaluated ramped to the load t.
     */
    class GrowthFactors
    {
    public:
      void
      parse(ParameterHandler &prm, const std::string &where, unsigned int n_components);
      /// growth_ramp(t, g_c(X)) = 1 + t (g_c(X) - 1).
      double
      ramped(const Point<2> &X, double t, unsigned int component = 0) const;
      /// The entry's text, as given.
      const std::string &
      text() const
      {
        return expression_text;
      }

    private:
      std::string                        expression_text;
      std::unique_ptr<FunctionParser<2>> expressions;
    };

    /**
     * A bulk growth law: Fg(X, t) on the cross-section. Implementations
     * register themselves by name (COSMO_REGISTER_PLUGIN(BulkGrowthLaw, ...),
     * base/plugins.h), one file each in source/materials/growth_laws/; the
     * names are the values of the material's 'Growth kind' (doc/cookbook.md).
     */
    class BulkGrowthLaw
    {
    public:
      virtual ~BulkGrowthLaw() = default;
      /**
       * Reads its entries in the material's section (entered). 'Growth
       * factor' is common to every law (declared by GrowthTensor); `where`
       * names the section for io::InputError.
       */
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &where) = 0;
      /// Fg at X and load t; every factor ramps as growth_ramp(t, g).
      virtual Tensor<2, 3>
      value(const Point<2> &X, double t) const = 0;
      /// One line for the log, e.g. "axial, g = 1 + 0.3*x".
      virtual std::string
      description() const = 0;
    };

    /**
     * A base of the laws with one scalar factor g(X), the 'Growth factor'
     * (isotropic, axial, fibre, ...): parses it and gives it ramped to the
     * load. A derived law that has entries of its own parses them after
     * calling this class's parse_parameters.
     */
    class ScalarFactorGrowthLaw : public BulkGrowthLaw
    {
    public:
      /// No entries of its own ('Growth factor' is common to all laws).
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      parse_parameters(ParameterHandler &prm, const std::string &where) override;

    protected:
      /// growth_ramp(t, g(X)) = 1 + t (g(X) - 1).
      double
      ramped_factor(const Point<2> &X, const double t) const
      {
        return factor.ramped(X, t);
      }
      /// The expression as given.
      const std::string &
      factor_text() const
      {
        return factor.text();
      }

    private:
      GrowthFactors factor;
    };

    /// Growth I + (g - 1) f (x) f along the unit vector f (fibre-type laws).
    inline Tensor<2, 3>
    fibre_growth(const double g, const Tensor<1, 3> &f)
    {
      return unit_symmetric_tensor<3>() + (g - 1.) * outer_product(f, f);
    }

    /**
     * The growth of a material: the registered BulkGrowthLaw its 'Growth
     * kind' names, with the common 'Growth factor'.
     */
    class GrowthTensor
    {
    public:
      /// 'Growth kind' (the registered laws), 'Growth factor' and the laws' own entries.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &where);

      Tensor<2, 3>
      value(const Point<2> &X, const double t) const
      {
        return law->value(X, t);
      }

      /// The 'Growth factor' text.
      const std::string &
      factor_expression() const
      {
        return factor_text;
      }
      std::string
      description() const
      {
        return law->description();
      }

    private:
      std::unique_ptr<BulkGrowthLaw> law;
      std::string                    factor_text;
    };
  } // namespace materials
} // namespace cosmo

namespace cosmo
{
  namespace plugins
  {
    // One registry of bulk growth laws per process (instantiated in source/materials/growth.cc).
    extern template class Registry<materials::BulkGrowthLaw>;
  } // namespace plugins
} // namespace cosmo

#endif

#ifndef cosmo_materials_hyperelastic_law_h
#define cosmo_materials_hyperelastic_law_h

#include <cosmo/base/plugins.h>
#include <cosmo/materials/energy_derivatives.h>

#include <array>
#include <memory>
#include <string>

/**
 * Hyperelastic stored energies W(Fe) per reference volume of the elastic
 * part Fe (row-major 3x3), with the small-strain Lame parameters mu and
 * lambda set from Young's modulus and Poisson's ratio. Implementations
 * register themselves by name (COSMO_REGISTER_PLUGIN, base/plugins.h), one
 * file each in source/materials/hyperelastic_laws/ (neo-Hookean, Saint
 * Venant-Kirchhoff); the names are the values of a material's 'Hyperelastic
 * law' (doc/cookbook.md).
 *
 * GrowingMaterial differentiates W twice by nested Sacado numbers in the 9
 * components of F (energy_derivatives.h): the interface has one virtual
 * overload per number type; an implementation writes its energy once as a
 * template energy_of<Number>(Fe) and derives from HyperelasticLawOf<Itself>.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    class HyperelasticLaw
    {
    public:
      virtual ~HyperelasticLaw() = default;

      double mu     = 0; ///< shear modulus (small-strain)
      double lambda = 0; ///< first Lame parameter (small-strain)

      /// The registered law `name` with the Lame parameters of (E, Poisson).
      static std::shared_ptr<const HyperelasticLaw>
      create(const std::string &name, double young, double poisson);

      double
      young() const
      {
        return mu * (3 * lambda + 2 * mu) / (lambda + mu);
      }
      double
      poisson() const
      {
        return lambda / (2 * (lambda + mu));
      }

      /// The name it is registered under.
      virtual std::string
      name() const = 0;

      /// W(Fe) (infinite where det Fe <= 0 if the law is not defined there).
      virtual double
      energy(const std::array<double, 9> &Fe) const = 0;
      virtual FirstOrderAD<9>
      energy(const std::array<FirstOrderAD<9>, 9> &Fe) const = 0;
      virtual SecondOrderAD<9>
      energy(const std::array<SecondOrderAD<9>, 9> &Fe) const = 0;
    };

    /// The overloads of HyperelasticLaw from Implementation::energy_of<Number>(Fe).
    template <class Implementation>
    class HyperelasticLawOf : public HyperelasticLaw
    {
    public:
      double
      energy(const std::array<double, 9> &Fe) const override
      {
        return self().energy_of(Fe);
      }
      FirstOrderAD<9>
      energy(const std::array<FirstOrderAD<9>, 9> &Fe) const override
      {
        return self().energy_of(Fe);
      }
      SecondOrderAD<9>
      energy(const std::array<SecondOrderAD<9>, 9> &Fe) const override
      {
        return self().energy_of(Fe);
      }

    private:
      const Implementation &
      self() const
      {
        return static_cast<const Implementation &>(*this);
      }
    };
  } // namespace materials

  namespace plugins
  {
    // One registry of hyperelastic laws per process (instantiated in source/materials/material.cc).
    extern template class Registry<materials::HyperelasticLaw>;
  } // namespace plugins
} // namespace cosmo

#endif

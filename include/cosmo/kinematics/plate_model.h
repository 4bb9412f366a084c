#ifndef cosmo_kinematics_plate_model_h
#define cosmo_kinematics_plate_model_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/base/plugins.h>
#include <cosmo/kinematics/plate_rod.h>
#include <cosmo/materials/plate_law.h>
#include <cosmo/materials/rod_law.h>

#include <cosmo/materials/energy_derivatives.h>

#include <array>
#include <string>

/**
 * A model of the plate bounded by a rod (doc/specification/plate-rod.md
 * "Models"): the strain measures of the plate and of the rim rod in terms of
 * the shared local variables (plate_rod.h), the factor on the transverse
 * shear stiffnesses.
 * Implementations register themselves by name (COSMO_REGISTER_PLUGIN,
 * base/plugins.h), one file each in source/kinematics/plate_models/
 * (cosserat, kirchhoff, von karman); the names are the values of plate_rod's
 * 'Model / Model' (doc/cookbook.md, "Add a plate model").
 *
 * The strains are differentiated by nested Sacado numbers in the assembly
 * (materials/energy_derivatives.h): the interface has one virtual overload
 * per number type the assembly uses (values, and first and second
 * derivatives in the 12 and 8 variables the plate and rim energies depend
 * on). An implementation writes its strains once, as templates, and
 * derives from PlateModelOf<Implementation>, which provides every overload.
 */
namespace cosmo
{
  namespace kinematics
  {
    using namespace dealii;

    // The Sacado numbers the assembly differentiates with (energy_derivatives.h).
    using materials::FirstOrderAD;
    using materials::SecondOrderAD;

#define COSMO_PLATE_MODEL_OVERLOADS(Number, qualifier)                                          \
  virtual materials::PlateStrains<Number> plate_strains(                                       \
    const std::array<Number, plate_local_variables> &z, const PlateGrowthAtPoint &g)           \
    const qualifier;                                                                           \
  virtual std::array<Number, 6> rim_strains(const std::array<Number, rim_local_variables> &z, \
                                            const RimFrame &                              f,   \
                                            const std::array<double, 3> &kappa0) const qualifier;
#define COSMO_PURE = 0
#define COSMO_OVERRIDE override
#define COSMO_PLATE_MODEL_FOR_EVERY_NUMBER(X, qualifier) \
  X(double, qualifier)                                   \
  X(FirstOrderAD<12>, qualifier)                         \
  X(SecondOrderAD<12>, qualifier)                        \
  X(FirstOrderAD<8>, qualifier)                          \
  X(SecondOrderAD<8>, qualifier)

    /**
     * The factor on the transverse shear stiffness of the stabilized shear
     * (Pitkaranta; Stenberg): fully integrated, with the shear stiffness
     * times t^2/(t^2 + alpha h_K^2), h_K the cell diameter and t^2 the
     * thickness squared over the model's shear_scale() (the Kirchhoff
     * penalty): locking-free, and without the spurious transverse mode that
     * reduced integration of Q2 leaves (doc/theory-plate-rod.md). Returns
     * shear_scale times that factor.
     */
    inline double
    stabilized_shear_scale(const double thickness,
                           const double shear_scale,
                           const double alpha,
                           const double h_K)
    {
      const double t2 = thickness * thickness / shear_scale;
      return shear_scale * t2 / (t2 + alpha * h_K * h_K);
    }

    class PlateModel
    {
    public:
      virtual ~PlateModel() = default;
      /// Reads its own entries (declared in the section 'Model'; entered).
      virtual void
      parse_parameters(ParameterHandler &)
      {}
      /// The name it is registered under.
      virtual std::string
      name() const = 0;
      /// Factor on the transverse shear stiffnesses of plate and rim (the
      /// Kirchhoff penalty; 1 otherwise).
      virtual double
      shear_scale() const
      {
        return 1.;
      }
      /**
       * plate_energy(z, g, law, *this, membrane_bending, shear_scale), its
       * gradient and (with_hessian) its Hessian in the 15 local variables
       * by the model's own chain rule, if it has one (true); false: the
       * assembly differentiates plate_energy() by nested AD instead.
       */
      virtual bool
      plate_energy_derivatives(const std::array<double, plate_local_variables> &,
                               const PlateGrowthAtPoint &,
                               const materials::PlateLawAt &,
                               bool /*membrane_bending*/,
                               double /*shear_scale*/,
                               bool /*with_hessian*/,
                               double &,
                               std::array<double, plate_local_variables> &,
                               std::array<double, plate_local_variables * plate_local_variables> &) const
      {
        return false;
      }
      /**
       * covariant_shear_strain(z, *this, jacobian, c), its gradient and
       * (with_hessian) Hessian in the 15 local variables by the model's own
       * chain rule, if it has one (true); false: nested AD instead.
       */
      virtual bool
      covariant_shear_strain_derivatives(const std::array<double, plate_local_variables> &,
                                         const Tensor<2, 2> &,
                                         unsigned int /*c*/,
                                         bool /*with_hessian*/,
                                         double &,
                                         std::array<double, plate_local_variables> &,
                                         std::array<double, plate_local_variables * plate_local_variables> &) const
      {
        return false;
      }
      /// The plate's director d at a point (for output).
      virtual Tensor<1, 3>
      director(const std::array<double, plate_local_variables> &z) const = 0;

      /// plate_strains(z, g): membrane, bending and shear strains of the
      /// plate (grown reference); rim_strains(z, f, kappa0): the rim rod's
      /// six strains (nu, kappa) with its reference curvature kappa0 added.
      COSMO_PLATE_MODEL_FOR_EVERY_NUMBER(COSMO_PLATE_MODEL_OVERLOADS, COSMO_PURE)
    };

#define COSMO_PLATE_MODEL_FORWARD(Number, qualifier)                                            \
  materials::PlateStrains<Number> plate_strains(                                               \
    const std::array<Number, plate_local_variables> &z, const PlateGrowthAtPoint &g)           \
    const qualifier                                                                            \
  {                                                                                            \
    return static_cast<const Implementation &>(*this).template plate_strains_of<Number>(z, g); \
  }                                                                                            \
  std::array<Number, 6> rim_strains(const std::array<Number, rim_local_variables> &z,         \
                                    const RimFrame &                              f,           \
                                    const std::array<double, 3> &kappa0) const qualifier      \
  {                                                                                            \
    return static_cast<const Implementation &>(*this).template rim_strains_of<Number>(z,       \
                                                                                      f,       \
                                                                                      kappa0); \
  }

    /**
     * The overloads of PlateModel from Implementation's templates
     * plate_strains_of<Number>(z, g) and rim_strains_of<Number>(z, f, kappa0).
     */
    template <class Implementation>
    class PlateModelOf : public PlateModel
    {
    public:
      COSMO_PLATE_MODEL_FOR_EVERY_NUMBER(COSMO_PLATE_MODEL_FORWARD, COSMO_OVERRIDE)
    };

#undef COSMO_PLATE_MODEL_OVERLOADS
#undef COSMO_PLATE_MODEL_FORWARD
#undef COSMO_PLATE_MODEL_FOR_EVERY_NUMBER
#undef COSMO_PURE
#undef COSMO_OVERRIDE

    /**
     * The model's plate strains with the natural curvature taken off the
     * bending strain (the elastic measures the law sees; growth through the
     * thickness, doc/theory-plate-rod.md section 6.3).
     */
    template <typename Number>
    materials::PlateStrains<Number>
    elastic_plate_strains(const std::array<Number, plate_local_variables> &z,
                          const PlateGrowthAtPoint &                      g,
                          const PlateModel &                              model)
    {
      auto s = model.plate_strains(z, g);
      for (unsigned int i = 0; i < 3; ++i)
        s.bending[i] -= g.natural_curvature[i];
      return s;
    }

    /**
     * Plate energy per reference area: det G times the plate law's membrane
     * and bending part (membrane_bending) or its transverse shear part times
     * shear_scale (the model's shear_scale(), possibly reduced further by the
     * shear stabilization).
     */
    template <typename Number>
    Number
    plate_energy(const std::array<Number, plate_local_variables> &z,
                 const PlateGrowthAtPoint &                      g,
                 const materials::PlateLawAt &               law,
                 const PlateModel &                              model,
                 const bool                                      membrane_bending,
                 const double                                    shear_scale)
    {
      const auto s = elastic_plate_strains(z, g, model);
      return g.det_G * (membrane_bending ? law.membrane_bending_energy(s) :
                                           Number(shear_scale * law.shear_energy(s)));
    }

    /**
     * The covariant transverse shear strain e_c = (dX/dxi_c) . gamma at a
     * point of a cell (the tying points of the assumed shear,
     * assembly/assumed_shear.h): gamma the model's shear strain in the
     * reference coordinates (growth is applied where the energy is
     * integrated), jacobian[b][c] = dX_b/dxi_c.
     */
    template <typename Number>
    Number
    covariant_shear_strain(const std::array<Number, plate_local_variables> &z,
                           const PlateModel &                              model,
                           const Tensor<2, 2> &                            jacobian,
                           const unsigned int                              c)
    {
      const auto s = model.plate_strains(z, PlateGrowthAtPoint());
      Number     e = jacobian[0][c] * s.shear[0];
      e += jacobian[1][c] * s.shear[1];
      return e;
    }

    /**
     * The plate's transverse shear energy per reference area from assumed
     * covariant shear strains e (assembly/assumed_shear.h): gamma = J^-T e
     * (inverse_jacobian[c][b] = dxi_c/dX_b), the growth's pull-back and det G
     * as in plate_energy, times shear_scale (the model's shear_scale()).
     */
    template <typename Number>
    Number
    assumed_shear_energy(const std::array<Number, 2> &     e,
                         const Tensor<2, 2> &              inverse_jacobian,
                         const PlateGrowthAtPoint &        g,
                         const materials::PlateLawAt & law,
                         const double                      shear_scale)
    {
      std::array<Number, 2> gamma;
      for (unsigned int b = 0; b < 2; ++b)
        {
          gamma[b] = inverse_jacobian[0][b] * e[0];
          gamma[b] += inverse_jacobian[1][b] * e[1];
        }
      materials::PlateStrains<Number> s;
      s.membrane.fill(Number(0.));
      s.bending.fill(Number(0.));
      for (unsigned int a = 0; a < 2; ++a)
        {
          s.shear[a] = g.G_inv[0][a] * gamma[0];
          s.shear[a] += g.G_inv[1][a] * gamma[1];
        }
      return g.det_G * shear_scale * law.shear_energy(s);
    }

    /**
     * Rim rod energy per reference length: the rod law with axial growth
     * (materials/rod_law.h). The natural state's reference curvature is the
     * discrete ring's (rim_reference_strains); natural_curvature (the rim's
     * own growth through its section, ramped by the caller) is added to the
     * stress-free curvature only, not to the ring's geometry.
     */
    template <typename Number>
    Number
    rim_rod_energy(const std::array<Number, rim_local_variables> &z,
                   const RimFrame &                              f,
                   const materials::RodLaw &                     law,
                   const materials::RodNaturalState &            ring,
                   const PlateModel &                            model,
                   const std::array<double, 3> &natural_curvature = {{0., 0., 0.}})
    {
      const std::array<double, 3> kappa0 = {
        {ring.reference_strains[3], ring.reference_strains[4], ring.reference_strains[5]}};
      auto stress_free = ring;
      for (unsigned int k = 0; k < 3; ++k)
        stress_free.reference_strains[3 + k] += natural_curvature[k];
      return materials::grown_rod_energy(law, model.rim_strains(z, f, kappa0), stress_free);
    }
  } // namespace kinematics

  namespace plugins
  {
    // One registry of plate models per process (instantiated in source/kinematics/plate_model.cc).
    extern template class Registry<kinematics::PlateModel>;
  } // namespace plugins
} // namespace cosmo

#endif

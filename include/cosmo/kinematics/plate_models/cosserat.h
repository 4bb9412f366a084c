#ifndef cosmo_kinematics_plate_models_cosserat_h
#define cosmo_kinematics_plate_models_cosserat_h

#include <cosmo/kinematics/plate_model.h>

namespace cosmo
{
  namespace kinematics
  {
    namespace internal
    {
      /**
       * plate_energy() of the exact strains (exact_plate_strains()) and its
       * gradient and (with_hessian) Hessian in the 15 local variables, by
       * the chain rule through the plate measures (plate_measures.h): the
       * director d, d1, d2 by nested AD in its six variables, V = (e1, e2,
       * d, f1, f2) linear in the rest. What nested AD of plate_energy() in
       * twelve variables gives, to round-off (tests/kinematics.cc), at a
       * fraction of the cost (benchmarks/README.md).
       */
      void
      exact_plate_energy_derivatives(const std::array<double, plate_local_variables> &z,
                                     const PlateGrowthAtPoint &                      g,
                                     const materials::PlateLawAt &               law,
                                     bool                                            membrane_bending,
                                     double                                          shear_scale,
                                     bool                                            with_hessian,
                                     double &                                        W,
                                     std::array<double, plate_local_variables> &     grad,
                                     std::array<double, plate_local_variables * plate_local_variables> &H);

      /**
       * covariant_shear_strain() of the exact strains, e = sum_b J_bc a_b . d,
       * and its gradient and (with_hessian) Hessian in the 15 local
       * variables: d(theta) by nested AD in theta alone, the rest bilinear.
       */
      void
      exact_covariant_shear_derivatives(const std::array<double, plate_local_variables> &z,
                                        const Tensor<2, 2> &                            jacobian,
                                        unsigned int                                    c,
                                        bool                                            with_hessian,
                                        double &                                        e,
                                        std::array<double, plate_local_variables> &     grad,
                                        std::array<double, plate_local_variables * plate_local_variables> &H);
    } // namespace internal

    /**
     * The kinematics of the Cosserat (Naghdi) plate bounded by a special
     * Cosserat rod: exact rotations of the director and of the rim's frame.
     * A CRTP base: the models "cosserat" and "kirchhoff"
     * (source/kinematics/plate_models/) derive from it.
     */
    template <class Implementation>
    class CosseratKinematics : public PlateModelOf<Implementation>
    {
    public:
      Tensor<1, 3>
      director(const std::array<double, plate_local_variables> &z) const override
      {
        return internal::exact_director(z);
      }
      bool
      plate_energy_derivatives(const std::array<double, plate_local_variables> &z,
                               const PlateGrowthAtPoint &                      g,
                               const materials::PlateLawAt &               law,
                               const bool                                      membrane_bending,
                               const double                                    shear_scale,
                               const bool                                      with_hessian,
                               double &                                        W,
                               std::array<double, plate_local_variables> &     grad,
                               std::array<double, plate_local_variables * plate_local_variables> &H)
        const override
      {
        internal::exact_plate_energy_derivatives(z, g, law, membrane_bending, shear_scale,
                                                 with_hessian, W, grad, H);
        return true;
      }
      bool
      covariant_shear_strain_derivatives(const std::array<double, plate_local_variables> &z,
                                         const Tensor<2, 2> &                            jacobian,
                                         const unsigned int                              c,
                                         const bool                                      with_hessian,
                                         double &                                        e,
                                         std::array<double, plate_local_variables> &     grad,
                                         std::array<double, plate_local_variables * plate_local_variables> &H)
        const override
      {
        internal::exact_covariant_shear_derivatives(z, jacobian, c, with_hessian, e, grad, H);
        return true;
      }
      template <typename Number>
      materials::PlateStrains<Number>
      plate_strains_of(const std::array<Number, plate_local_variables> &z,
                       const PlateGrowthAtPoint &                      g) const
      {
        return internal::exact_plate_strains(z, g);
      }
      template <typename Number>
      std::array<Number, 6>
      rim_strains_of(const std::array<Number, rim_local_variables> &z,
                     const RimFrame &                              f,
                     const std::array<double, 3> &                 kappa0) const
      {
        return internal::exact_rim_strains(z, f, kappa0);
      }
    };
  } // namespace kinematics
} // namespace cosmo

#endif

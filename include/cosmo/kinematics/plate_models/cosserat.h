#ifndef cosmo_kinematics_plate_models_cosserat_h
#define cosmo_kinematics_plate_models_cosserat_h

#include <cosmo/kinematics/plate_model.h>

namespace cosmo
{
  namespace kinematics
  {
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

// The example of doc/cookbook.md, "Add a plate model": a von Karman plate
// (moderate rotations, director E3 + beta) welded to a rim rod with exact
// rotations (a special Cosserat rod), composed from the strain measures of
// include/cosmo/kinematics/plate_rod.h. This file is the whole extension:
// compiled into an executable together with plate_rod's main.cc
// (tests/CMakeLists.txt, plate_rod_cookbook), the name
// 'von karman plate, cosserat rim' becomes a value of 'Model / Model'.
#include <cosmo/kinematics/plate_model.h>

namespace cosmo
{
  namespace kinematics
  {
    class VonKarmanPlateCosseratRim : public PlateModelOf<VonKarmanPlateCosseratRim>
    {
    public:
      /// Its own entries in the section 'Model' (none).
      static void
      declare_parameters(ParameterHandler &)
      {}
      std::string
      name() const override
      {
        return "von karman plate, cosserat rim";
      }
      /// The director E3 + beta, beta = theta x E3 = (theta2, -theta1, 0).
      Tensor<1, 3>
      director(const std::array<double, plate_local_variables> &z) const override
      {
        return internal::von_karman_director(z);
      }
      /// The strains as templates of the number type (the assembly
      /// differentiates them with nested Sacado numbers).
      template <typename Number>
      materials::PlateStrains<Number>
      plate_strains_of(const std::array<Number, plate_local_variables> &z,
                       const PlateGrowthAtPoint &                      g) const
      {
        return internal::von_karman_plate_strains(z, g);
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

    COSMO_REGISTER_PLUGIN(PlateModel,
                          VonKarmanPlateCosseratRim,
                          "von karman plate, cosserat rim",
                          "moderate rotations in the plate, exact ones in the rim "
                          "(doc/cookbook.md).")
  } // namespace kinematics
} // namespace cosmo

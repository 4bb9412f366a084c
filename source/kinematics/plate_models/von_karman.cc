// Moderate rotations: the von Karman plate (director E3 + beta, beta =
// theta x E3) and the rim rod with linearized rotations whose axial strain
// keeps the squares of both rotations of its tangent.
#include <cosmo/kinematics/plate_model.h>

namespace cosmo
{
  namespace kinematics
  {
    class VonKarmanPlateModel : public PlateModelOf<VonKarmanPlateModel>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      std::string
      name() const override
      {
        return "von karman";
      }
      Tensor<1, 3>
      director(const std::array<double, plate_local_variables> &z) const override
      {
        return internal::von_karman_director(z);
      }
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
        return internal::linearized_rim_strains(z, f, kappa0);
      }
    };

    COSMO_REGISTER_PLUGIN(PlateModel,
                          VonKarmanPlateModel,
                          "von karman",
                          "moderate rotations (doc/theory-plate-rod.md).")
  } // namespace kinematics
} // namespace cosmo

// The Cosserat (Naghdi) plate bounded by a special Cosserat rod: exact
// rotations of the director and of the rim's frame.
#include <cosmo/kinematics/plate_models/cosserat.h>

namespace cosmo
{
  namespace kinematics
  {
    class CosseratPlateModel : public CosseratKinematics<CosseratPlateModel>
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      std::string
      name() const override
      {
        return "cosserat";
      }
    };

    COSMO_REGISTER_PLUGIN(PlateModel,
                          CosseratPlateModel,
                          "cosserat",
                          "Naghdi plate and special Cosserat rod.")
  } // namespace kinematics
} // namespace cosmo

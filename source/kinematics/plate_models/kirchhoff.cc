// The Kirchhoff limit: the Cosserat model with the transverse shear
// stiffnesses of plate (ks G h) and rim (GA1, GA2) multiplied by a penalty,
// so that the shear strains nearly vanish.
#include <cosmo/kinematics/plate_models/cosserat.h>

namespace cosmo
{
  namespace kinematics
  {
    class KirchhoffPlateModel : public CosseratKinematics<KirchhoffPlateModel>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Shear penalty factor", "100", Patterns::Double(1),
                          "Factor on the shear stiffnesses in the kirchhoff model.");
      }
      void
      parse_parameters(ParameterHandler &prm) override
      {
        penalty = prm.get_double("Shear penalty factor");
      }
      std::string
      name() const override
      {
        return "kirchhoff";
      }
      double
      shear_scale() const override
      {
        return penalty;
      }
    private:
      double penalty = 100;
    };

    COSMO_REGISTER_PLUGIN(PlateModel,
                          KirchhoffPlateModel,
                          "kirchhoff",
                          "the cosserat model with the transverse shear stiffnesses (plate ks G "
                          "h, rod GA1, GA2) multiplied by 'Shear penalty factor' (the "
                          "shear-rigid limit).")
  } // namespace kinematics
} // namespace cosmo

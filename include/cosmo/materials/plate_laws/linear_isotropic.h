#ifndef cosmo_materials_plate_laws_linear_isotropic_h
#define cosmo_materials_plate_laws_linear_isotropic_h

#include <cosmo/materials/plate_law.h>

/**
 * The linear isotropic law of the Cosserat (Naghdi) plate
 * (doc/specification/strip.md), registered as 'linear isotropic': with the
 * membrane strain eps, the bending strain k and the shear gamma
 * (plate_law.h), the energy per unit area
 *
 *   psi = C/2 [v (tr eps)^2 + (1-v) eps:eps]
 *       + D/2 [v (tr k)^2 + (1-v) k:k] + ks G h/2 |gamma|^2,
 *
 * C = E h / (1 - v^2), D = C h^2 / 12, G = E / (2 (1 + v)).
 */
namespace cosmo
{
  namespace materials
  {
    class LinearIsotropicPlateLaw : public PlateLaw
    {
    public:
      double young_modulus = 1, poisson_ratio = 0.3, shear_factor = 5. / 6;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm) override;

      double
      young() const override
      {
        return young_modulus;
      }
      double
      poisson() const override
      {
        return poisson_ratio;
      }
      double
      shear_modulus() const
      {
        return young_modulus / (2 * (1 + poisson_ratio));
      }

      void
      energy_derivatives(const std::array<double, plate_measures> &s,
                         double                                    thickness,
                         PlatePart                                 part,
                         bool                                      with_hessian,
                         double &                                  W,
                         std::array<double, plate_measures> &      dW,
                         std::array<double, plate_measures * plate_measures> &ddW) const override;
    };
  } // namespace materials
} // namespace cosmo

#endif

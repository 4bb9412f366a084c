// The linear isotropic Cosserat plate law (plate_laws/linear_isotropic.h).
#include <cosmo/io/parameters.h>
#include <cosmo/materials/plate_laws/linear_isotropic.h>

namespace cosmo
{
  namespace materials
  {
    void
    LinearIsotropicPlateLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Young's modulus", "1", Patterns::Double(0),
                        "E of the plate (units of stress).");
      prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-0.999, 0.49999),
                        "Poisson's ratio v of the plate.");
      prm.declare_entry("Shear correction factor", "0.833333333333333", Patterns::Double(0),
                        "ks of the transverse shear energy ks G h/2 |gamma|^2 (5/6).");
    }

    void
    LinearIsotropicPlateLaw::parse_parameters(ParameterHandler &prm)
    {
      young_modulus = prm.get_double("Young's modulus");
      poisson_ratio = prm.get_double("Poisson's ratio");
      shear_factor  = prm.get_double("Shear correction factor");
      if (!(young_modulus > 0 && young_modulus <= 1e100))
        throw io::InputError("Plate material", "Young's modulus", prm.get("Young's modulus"),
                             "must be positive and at most 1e100 (its products with itself "
                             "and the lengths must stay finite in double precision)");
      if (!(shear_factor > 0))
        throw io::InputError("Plate material", "Shear correction factor",
                             prm.get("Shear correction factor"), "must be positive");
    }

    void
    LinearIsotropicPlateLaw::energy_derivatives(
      const std::array<double, plate_measures> &           s,
      const double                                         thickness,
      const PlatePart                                      part,
      const bool                                           with_hessian,
      double &                                             W,
      std::array<double, plate_measures> &                 dW,
      std::array<double, plate_measures * plate_measures> &ddW) const
    {
      dW.fill(0.);
      if (with_hessian)
        ddW.fill(0.);
      const double v = poisson_ratio;
      if (part == PlatePart::transverse_shear)
        {
          // ks G h/2 |gamma|^2
          const double k = shear_factor * shear_modulus() * thickness;
          W              = 0.5 * k * (s[6] * s[6] + s[7] * s[7]);
          for (const unsigned int a : {6u, 7u})
            {
              dW[a] = k * s[a];
              if (with_hessian)
                ddW[plate_measures * a + a] = k;
            }
          return;
        }
      // stiffness/2 [v (tr a)^2 + (1-v) a:a] of a = (a11, a22, a12) at measures
      // first..first+2: the membrane (C) and the bending (D) part.
      W = 0;
      for (const unsigned int first : {0u, 3u})
        {
          const double  c  = first == 0 ? membrane_stiffness(thickness) : bending_stiffness(thickness);
          const double *a  = &s[first];
          const double  tr = a[0] + a[1];
          W += 0.5 * c * (v * tr * tr + (1 - v) * (a[0] * a[0] + a[1] * a[1] + 2 * a[2] * a[2]));
          dW[first]     = c * (v * tr + (1 - v) * a[0]);
          dW[first + 1] = c * (v * tr + (1 - v) * a[1]);
          dW[first + 2] = 2 * c * (1 - v) * a[2];
          if (with_hessian)
            {
              auto H = [&](const unsigned int i, const unsigned int j) -> double & {
                return ddW[plate_measures * (first + i) + first + j];
              };
              H(0, 0) = H(1, 1) = c;
              H(0, 1) = H(1, 0) = c * v;
              H(2, 2)           = 2 * c * (1 - v);
            }
        }
    }

    COSMO_REGISTER_PLUGIN(PlateLaw,
                          LinearIsotropicPlateLaw,
                          "linear isotropic",
                          "the Naghdi plate's quadratic energy in its strains with Young's "
                          "modulus, Poisson's ratio and the shear correction factor "
                          "(doc/specification/strip.md).")
  } // namespace materials
} // namespace cosmo

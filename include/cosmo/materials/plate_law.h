#ifndef cosmo_materials_plate_law_h
#define cosmo_materials_plate_law_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>

/**
 * The geometrically exact five-parameter Cosserat (Naghdi) plate
 * (doc/specification/strip.md): mid-surface gradient Fp (3x2), unit director d, and the
 * strain measures
 *
 *   membrane  eps   = 1/2 (Fp^T Fp - I)
 *   bending   k     = 1/2 (Fp^T grad d + grad d^T Fp)   (flat reference)
 *   shear     gamma = Fp^T d
 *
 * with the energy per unit reference area
 *
 *   psi = Eh/(2(1-v^2)) [v (tr eps)^2 + (1-v) eps:eps]
 *       + Eh^3/(24(1-v^2)) [v (tr k)^2 + (1-v) k:k] + ks G h/2 |gamma|^2 .
 *
 * The energy is a template on the number type (Sacado differentiates it);
 * the measures are computed by plate_strains() from Fp, d and grad d, so
 * that part 2 (the strip) and part 3 (the plate) share both.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /// Symmetric 2x2 measures as (11, 22, 12) and the shear 2-vector.
    template <typename Number>
    struct PlateStrains
    {
      std::array<Number, 3> membrane;
      std::array<Number, 3> bending;
      std::array<Number, 2> shear;
    };

    /**
     * The measures from the columns of Fp (a1, a2), the director d and the
     * columns of grad d (d1, d2), all 3-vectors.
     */
    template <typename Number>
    PlateStrains<Number>
    plate_strains(const std::array<Number, 3> &a1,
                  const std::array<Number, 3> &a2,
                  const std::array<Number, 3> &d,
                  const std::array<Number, 3> &d1,
                  const std::array<Number, 3> &d2)
    {
      auto dot = [](const std::array<Number, 3> &x, const std::array<Number, 3> &y) {
        Number s = x[0] * y[0];
        s += x[1] * y[1];
        s += x[2] * y[2];
        return s;
      };
      PlateStrains<Number> s;
      s.membrane[0] = 0.5 * (dot(a1, a1) - 1.);
      s.membrane[1] = 0.5 * (dot(a2, a2) - 1.);
      s.membrane[2] = 0.5 * dot(a1, a2);
      s.bending[0]  = dot(a1, d1);
      s.bending[1]  = dot(a2, d2);
      s.bending[2]  = 0.5 * (dot(a1, d2) + dot(a2, d1));
      s.shear[0]    = dot(a1, d);
      s.shear[1]    = dot(a2, d);
      return s;
    }

    /**
     * The measures of a grown plate (F = Fe G, doc/specification/plate-rod.md): with the
     * in-plane growth G (2x2, of the reference plane) the elastic parts are
     * Fp G^-1 and grad d G^-1, i.e. the columns a_j, d_j replaced by
     * sum_i a_i (G^-1)_ij; the energy is then counted per grown area, det G
     * times per reference area (the caller multiplies).
     */
    template <typename Number>
    PlateStrains<Number>
    grown_plate_strains(const std::array<Number, 3> &          a1,
                        const std::array<Number, 3> &          a2,
                        const std::array<Number, 3> &          d,
                        const std::array<Number, 3> &          d1,
                        const std::array<Number, 3> &          d2,
                        const std::array<std::array<double, 2>, 2> &G_inv)
    {
      std::array<Number, 3> e1, e2, f1, f2;
      for (unsigned int c = 0; c < 3; ++c)
        {
          e1[c] = a1[c] * G_inv[0][0] + a2[c] * G_inv[1][0];
          e2[c] = a1[c] * G_inv[0][1] + a2[c] * G_inv[1][1];
          f1[c] = d1[c] * G_inv[0][0] + d2[c] * G_inv[1][0];
          f2[c] = d1[c] * G_inv[0][1] + d2[c] * G_inv[1][1];
        }
      return plate_strains(e1, e2, d, f1, f2);
    }

    class NaghdiPlateLaw
    {
    public:
      double young = 1, poisson = 0.3, thickness = 0.01, shear_factor = 5. / 6;

      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads the material entries; the thickness is set by the caller.
      void
      parse_parameters(ParameterHandler &prm);

      double
      shear_modulus() const
      {
        return young / (2 * (1 + poisson));
      }

      /// Membrane and bending energy (the part integrated fully).
      /// The membrane stiffness C = E h / (1 - nu^2).
      double
      membrane_stiffness() const
      {
        return young * thickness / (1 - poisson * poisson);
      }
      /// The bending stiffness D = C h^2 / 12.
      double
      bending_stiffness() const
      {
        return membrane_stiffness() * thickness * thickness / 12;
      }

      template <typename Number>
      Number
      membrane_bending_energy(const PlateStrains<Number> &s) const
      {
        return 0.5 * membrane_stiffness() * quadratic(s.membrane) +
               0.5 * bending_stiffness() * quadratic(s.bending);
      }

      /**
       * The membrane force N and the bending moment M of this law, tensor
       * components (11, 22, 12) from the strain components (11, 22, 12):
       * N = C ((nu tr e) I + (1 - nu) e), M likewise with D and k, so that
       * membrane_bending_energy = 1/2 (N : e + M : k) (the 12 components
       * counted twice). The output writes these; nothing re-derives the law.
       */
      std::array<double, 3>
      membrane_force(const std::array<double, 3> &e) const
      {
        return resultant(e, membrane_stiffness());
      }
      std::array<double, 3>
      bending_moment(const std::array<double, 3> &k) const
      {
        return resultant(k, bending_stiffness());
      }

      /// Transverse shear energy (integrated with fewer points against locking).
      template <typename Number>
      Number
      shear_energy(const PlateStrains<Number> &s) const
      {
        Number g2 = s.shear[0] * s.shear[0];
        g2 += s.shear[1] * s.shear[1];
        return 0.5 * shear_factor * shear_modulus() * thickness * g2;
      }

    private:
      std::array<double, 3>
      resultant(const std::array<double, 3> &a, const double stiffness) const
      {
        const double tr = a[0] + a[1];
        return {{stiffness * (poisson * tr + (1 - poisson) * a[0]),
                 stiffness * (poisson * tr + (1 - poisson) * a[1]),
                 stiffness * (1 - poisson) * a[2]}};
      }

      /// v (tr a)^2 + (1-v) a:a for a symmetric a = (a11, a22, a12).
      template <typename Number>
      Number
      quadratic(const std::array<Number, 3> &a) const
      {
        const Number tr = a[0] + a[1];
        Number       aa = a[0] * a[0];
        aa += a[1] * a[1];
        aa += 2. * a[2] * a[2];
        return poisson * tr * tr + (1 - poisson) * aa;
      }
    };
  } // namespace materials
} // namespace cosmo

#endif

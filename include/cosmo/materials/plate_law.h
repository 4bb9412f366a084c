#ifndef cosmo_materials_plate_law_h
#define cosmo_materials_plate_law_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/base/plugins.h>

#include <array>
#include <memory>
#include <string>
#include <type_traits>

/**
 * The geometrically exact five-parameter Cosserat (Naghdi) plate
 * (doc/specification/strip.md): mid-surface gradient Fp (3x2), unit director d, and the
 * strain measures
 *
 *   membrane  eps   = 1/2 (Fp^T Fp - I)
 *   bending   k     = 1/2 (Fp^T grad d + grad d^T Fp)   (flat reference)
 *   shear     gamma = Fp^T d
 *
 * and the interface of a plate law, an energy per unit area in these measures
 * (the linear isotropic law of doc/specification/strip.md is
 * plate_laws/linear_isotropic.h). The measures are computed by
 * plate_strains() from Fp, d and grad d, so that part 2 (the strip) and part
 * 3 (the plate) share them and every law.
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

    /// The value of a number of any (nested) Sacado type, or of a double.
    inline double
    value_of(const double x)
    {
      return x;
    }
    template <typename Number>
    double
    value_of(const Number &x)
    {
      return value_of(x.val());
    }

    /// The two parts of a plate law's energy, integrated apart (the
    /// transverse shear with the assumed strains or fewer points, against
    /// locking).
    enum class PlatePart
    {
      membrane_and_bending,
      transverse_shear
    };

    /// The eight measures (membrane 11, 22, 12; bending 11, 22, 12; shear
    /// 1, 2) of PlateStrains as one array, and back.
    constexpr unsigned int plate_measures = 8;
    template <typename Number>
    std::array<Number, plate_measures>
    measures_of(const PlateStrains<Number> &s)
    {
      return {{s.membrane[0], s.membrane[1], s.membrane[2], s.bending[0], s.bending[1],
               s.bending[2], s.shear[0], s.shear[1]}};
    }

    /**
     * A plate law: the energy per unit (grown) area of a plate of thickness
     * h in the eight measures s of PlateStrains, in two additive parts,
     * W(s) = W_mb(membrane, bending) + W_s(shear). Implementations register
     * themselves by name (COSMO_REGISTER_PLUGIN), one file each in
     * source/materials/plate_laws/; the names are the values of
     * 'Plate material / Law' (doc/cookbook.md, "Add a plate law").
     *
     * The law gives its value, gradient and Hessian in the measures at a
     * state; the kinematics composes them by the chain rule, or evaluates
     * the law on Sacado numbers through its second-order Taylor expansion
     * at the state (PlateLawAt), whose first and second derivatives there
     * are the law's. No kinematics knows a concrete law.
     */
    class PlateLaw
    {
    public:
      virtual ~PlateLaw() = default;
      /// Reads its entries in 'Plate material' (entered).
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;
      /// The small-strain Young's modulus and Poisson's ratio about the
      /// natural state: the scales of the output and of the closed forms.
      virtual double
      young() const = 0;
      virtual double
      poisson() const = 0;
      /**
       * The part's energy W per unit area at the measures s for thickness h,
       * its gradient dW (in the order of measures_of) and, with_hessian,
       * its Hessian ddW (8 x 8, row-major; zero outside the part's
       * measures). Every entry is written, and ddW is symmetric (the
       * Taylor form reads its upper triangle, the chain rule all of it).
       */
      virtual void
      energy_derivatives(const std::array<double, plate_measures> &s,
                         double                                    thickness,
                         PlatePart                                 part,
                         bool                                      with_hessian,
                         double &                                  W,
                         std::array<double, plate_measures> &      dW,
                         std::array<double, plate_measures * plate_measures> &ddW) const = 0;

      /// Membrane stiffness C = E h / (1 - nu^2) of the small-strain moduli.
      double
      membrane_stiffness(const double thickness) const
      {
        return young() * thickness / (1 - poisson() * poisson());
      }
      /// Bending stiffness D = C h^2 / 12 of the small-strain moduli.
      double
      bending_stiffness(const double thickness) const
      {
        return membrane_stiffness(thickness) * thickness * thickness / 12;
      }
    };

    /**
     * A plate law at a point: the law and the plate's thickness there. What
     * the kinematics and the output evaluate.
     */
    class PlateLawAt
    {
    public:
      PlateLawAt(const PlateLaw &law, const double thickness)
        : law(&law)
        , thickness(thickness)
      {}

      void
      derivatives(const std::array<double, plate_measures> &            s,
                  const PlatePart                                      part,
                  const bool                                           with_hessian,
                  double &                                             W,
                  std::array<double, plate_measures> &                 dW,
                  std::array<double, plate_measures * plate_measures> &ddW) const
      {
        law->energy_derivatives(s, thickness, part, with_hessian, W, dW, ddW);
      }

      /// The membrane and bending energy (the part integrated fully).
      template <typename Number>
      Number
      membrane_bending_energy(const PlateStrains<Number> &s) const
      {
        return energy(s, PlatePart::membrane_and_bending);
      }
      /// The transverse shear energy.
      template <typename Number>
      Number
      shear_energy(const PlateStrains<Number> &s) const
      {
        return energy(s, PlatePart::transverse_shear);
      }

      /**
       * The resultants of both parts, tensor components: the membrane force
       * N, the bending moment M (11, 22, 12) and the shear force Q, the
       * derivatives of W in the measures with the 12 components halved (W
       * counts the pair 12, 21), so that for a quadratic law
       * W = 1/2 (N : e + M : k + Q . gamma). The output writes these.
       */
      PlateStrains<double>
      resultants(const PlateStrains<double> &s) const;

      double
      young() const
      {
        return law->young();
      }
      double
      poisson() const
      {
        return law->poisson();
      }
      double
      membrane_stiffness() const
      {
        return law->membrane_stiffness(thickness);
      }
      double
      bending_stiffness() const
      {
        return law->bending_stiffness(thickness);
      }

    private:
      /**
       * W(s) on Sacado numbers: the second-order Taylor expansion of the
       * law at the value of s, W0 + dW . ds + 1/2 ds . ddW ds with ds = s -
       * value(s). Its value, gradient and Hessian at the point are the
       * law's (exact for a quadratic law), which is all that first- and
       * second-order AD see. The Hessian's zeros are skipped.
       */
      template <typename Number>
      Number
      energy(const PlateStrains<Number> &strains, const PlatePart part) const
      {
        const auto                                    x = measures_of(strains);
        std::array<double, plate_measures>            x0, dW{};
        std::array<double, plate_measures * plate_measures> ddW{};
        for (unsigned int k = 0; k < plate_measures; ++k)
          x0[k] = value_of(x[k]);
        double W = 0;
        if constexpr (std::is_same_v<Number, double>)
          {
            derivatives(x0, part, false, W, dW, ddW);
            return W;
          }
        else
          {
            derivatives(x0, part, true, W, dW, ddW);
            std::array<Number, plate_measures> dx;
            Number                             w(W); // no derivatives
            for (unsigned int k = 0; k < plate_measures; ++k)
              {
                dx[k] = x[k] - x0[k];
                if (dW[k] != 0)
                  w += dW[k] * dx[k];
              }
            for (unsigned int k = 0; k < plate_measures; ++k)
              for (unsigned int l = k; l < plate_measures; ++l)
                if (const double h = ddW[plate_measures * k + l]; h != 0)
                  w += (k == l ? 0.5 * h : h) * dx[k] * dx[l];
            return w;
          }
      }

      const PlateLaw *law;
      double          thickness;
    };

    /**
     * 'Plate material': the entry 'Law' (the registered plate laws) and
     * every law's entries.
     */
    void
    declare_plate_law_parameters(ParameterHandler &prm);
    /// The law selected in 'Plate material / Law', its entries read.
    std::unique_ptr<PlateLaw>
    create_plate_law(ParameterHandler &prm);
  } // namespace materials

  namespace plugins
  {
    // One registry of plate laws per process (instantiated in source/materials/plate_law.cc).
    extern template class Registry<materials::PlateLaw>;
  } // namespace plugins
} // namespace cosmo

#endif

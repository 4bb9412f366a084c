#ifndef cosmo_kinematics_helix_h
#define cosmo_kinematics_helix_h

#include <deal.II/base/tensor.h>

#include <cosmo/kinematics/rotation.h>

#include <array>
#include <string>

/**
 * The uniform-strain helix of a special Cosserat rod.
 *
 * Strains (nu, kappa) in the director frame, constant along the arc length s
 * of the reference axis, generate R(s) = exp(s [kappa]x) and
 * r(s) = int_0^s R(t) nu dt. Both are closed forms here, AD-safe at kappa = 0.
 */
namespace cosmo
{
  namespace kinematics
  {
    using namespace dealii;

    /// The six rod strains (nu1, nu2, nu3, kappa1, kappa2, kappa3).
    struct RodStrains
    {
      Tensor<1, 3> nu;
      Tensor<1, 3> kappa;

      RodStrains();
      explicit RodStrains(const std::array<double, 6> &e);
      std::array<double, 6> as_array() const;
      /// The reference (unstrained) state nu = E3, kappa = 0.
      static RodStrains reference();
    };

    /// Names of the six strains in the suite's order.
    extern const std::array<std::string, 6> strain_names;
    /// Names of the six resultants in the same order (n1..n3, m1..m3).
    extern const std::array<std::string, 6> resultant_names;

    /// R(s) = exp(s [kappa]x).
    template <typename Number>
    Tensor<2, 3, Number>
    helix_rotation(const Tensor<1, 3, Number> &kappa, const Number &s)
    {
      Tensor<1, 3, Number> theta;
      for (unsigned int i = 0; i < 3; ++i)
        theta[i] = s * kappa[i];
      return rotation_exp(theta);
    }

    /**
     * r(s) = s [I + s b(t) [kappa]x + s^2 c(t) [kappa]x^2] nu, t = |kappa| s,
     * the closed-form integral of R(t) nu (b, c the Rodrigues coefficients).
     */
    template <typename Number>
    Tensor<1, 3, Number>
    helix_position(const Tensor<1, 3, Number> &nu,
                   const Tensor<1, 3, Number> &kappa,
                   const Number &              s)
    {
      Tensor<1, 3, Number> k;
      for (unsigned int i = 0; i < 3; ++i)
        k[i] = s * kappa[i];
      const auto co = internal::rodrigues_coefficients<Number>(internal::squared_norm(k));
      const Tensor<1, 3, Number> kxnu   = cross_product_3d(k, nu);
      const Tensor<1, 3, Number> kxkxnu = cross_product_3d(k, kxnu);
      Tensor<1, 3, Number>       r;
      for (unsigned int i = 0; i < 3; ++i)
        r[i] = s * (nu[i] + co.b * kxnu[i] + co.c * kxkxnu[i]);
      return r;
    }

    /**
     * The rod's placement at X3 on the reference axis: x = r(X3) + R(X3) w
     * for a point w of the (deformed) section in the director frame, the
     * section swept along the helix (output of parts 1 and 2).
     */
    struct HelixPlacement
    {
      Tensor<2, 3> R;
      Tensor<1, 3> r;
      HelixPlacement(const RodStrains &strains, const double X3)
        : R(helix_rotation(strains.kappa, X3))
        , r(helix_position(strains.nu, strains.kappa, X3))
      {}
      /// x = r + R w.
      Tensor<1, 3>
      place(const Tensor<1, 3> &w) const
      {
        return r + R * w;
      }
    };

    /**
     * Geometry of the helix traced by the centreline: its axis is the
     * spatial angular velocity R kappa (constant), the centreline turns about
     * it at |kappa| per unit reference length, advancing nu.k per unit
     * length along it.
     */
    struct HelixGeometry
    {
      double       curvature_rate = 0; ///< |kappa|, turning rate of the frame
      double       radius         = 0; ///< 0 for a straight centreline
      double       pitch          = 0; ///< axial advance per full turn (infinite if kappa = 0)
      int          handedness     = 0; ///< +1 right-handed, -1 left-handed, 0 planar/straight
      Tensor<1, 3> axis;               ///< unit helix axis, in the frame at s = 0
      double       curvature      = 0; ///< curvature of the centreline curve
      double       torsion        = 0; ///< torsion of the centreline curve
      int          torsion_sign   = 1; ///< straight rods: sense of the twist of the frame
      std::string  description() const;
    };

    HelixGeometry
    helix_geometry(const RodStrains &strains);
  } // namespace kinematics
} // namespace cosmo

#endif

#ifndef cosmo_kinematics_rod_element_derivatives_h
#define cosmo_kinematics_rod_element_derivatives_h

#include <cosmo/kinematics/rod_element.h>

#include <array>

/**
 * First and second derivatives of the helicoidal element's maps
 * (doc/theory-rod.md 3), for the element's Hessian by the chain rule
 * through z = (theta, u) (the rod application's assembly):
 *  - u = R(q_a)^T c, the chord in node a's frame, in (c, q_a);
 *  - theta = log(conj(q_a) q_b s), the relative rotation vector (s a ring's
 *    seam), in (q_a, q_b);
 *  - the strains s(z): kappa h = theta, nu h = J_L(theta)^-1 u.
 * Each in closed form where the map is polynomial or rational (u; the
 * bilinear quaternion p of theta; s), with nested AD only in p's 4
 * variables and in gamma's one. They equal the nested AD of the same
 * formulas to round-off (tests/rod_validation.py 'chain_rule' compares the
 * elements' events; unit.kinematics the maps).
 */
namespace cosmo
{
  namespace kinematics
  {
    /**
     * u = R(q)^T c of x = (c, q) and, with_hessian, its second derivatives
     * (du: 3 x 7, ddu: 3 x (7 x 7) row-major, full).
     */
    void
    chord_in_frame_derivatives(const std::array<double, 7>           &x,
                               bool                                   with_hessian,
                               std::array<double, 3>                 &u,
                               std::array<std::array<double, 7>, 3>  &du,
                               std::array<std::array<double, 49>, 3> &ddu);

    /**
     * theta = log(conj(q_a) q_b s) of x = (q_a, q_b) (s = *seam, or none)
     * and its derivatives (dtheta: 3 x 8, ddtheta: 3 x (8 x 8), full).
     */
    void
    relative_rotation_derivatives(const std::array<double, 8>           &x,
                                  const Quaternion<double>              *seam,
                                  bool                                   with_hessian,
                                  std::array<double, 3>                 &theta,
                                  std::array<std::array<double, 8>, 3>  &dtheta,
                                  std::array<std::array<double, 64>, 3> &ddtheta);

    /**
     * The strains s(z) of z = (theta, u) (helicoidal_strains_of) and their
     * first derivatives s_z (6 x 6); add_second_derivatives() adds
     * sum_k c_k (s_k)_zz to a 6 x 6 Hessian (kappa is linear in z, so only
     * nu's terms).
     */
    struct HelicoidalStrainDerivatives
    {
      std::array<double, 6>                strains;
      std::array<std::array<double, 6>, 6> s_z{};
      void
      add_second_derivatives(const std::array<double, 6> &c, std::array<double, 36> &H) const;

      // (what the second derivatives need)
      std::array<double, 6> z;
      double                h = 1, gamma = 0, dgamma = 0, ddgamma = 0, tu = 0, t2 = 0;
      std::array<double, 3> b{};
    };

    HelicoidalStrainDerivatives
    helicoidal_strain_derivatives(const std::array<double, 6> &z, double h, bool with_hessian);
  } // namespace kinematics
} // namespace cosmo

#endif

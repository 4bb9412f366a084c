#ifndef cosmo_kinematics_plate_rod_h
#define cosmo_kinematics_plate_rod_h

#include <deal.II/base/point.h>

#include <cosmo/kinematics/rotation.h>
#include <cosmo/materials/plate_law.h>
#include <cosmo/materials/rod_law.h>

#include <array>

/**
 * Kinematics of a plate bounded by a rod (doc/specification/plate-rod.md), as energy densities
 * of local variables on which the finite-element DoFs act linearly (Sacado
 * differentiates them, as for the strip).
 *
 * Plate (reference: the plane X3 = 0): mid-surface phi = X + u, director
 * d = exp([theta]x) E3 with theta = (theta1, theta2, 0) (a rotation vector
 * without drilling: the plate's energy does not see rotations about d).
 *
 * Rim rod welded to the plate edge (exact parametrization, no multipliers):
 * its centreline is the plate's edge, r(S) = phi(X(S)), and its rotation is
 *
 *   Lambda = exp([theta]x) exp(alpha [E3]x) Lambda0,
 *
 * with Lambda0 = [d1 d2 d3] = [e_r, E3, -e_theta] (a proper rotation; the
 * rod runs clockwise so that kappa0 = (0, -1/R, 0) as in doc/specification/plate-rod.md) and
 * alpha the rod's rotation about the plate normal, a field that lives on
 * the rim only. Then Lambda E2 = exp([theta]x) E3 = d: the rod's d2 is the
 * plate's director for every value of the unknowns. Its strains are
 *
 *   nu    = Lambda^T r',
 *   kappa = Lambda0^T (exp(-alpha [E3]x) T(theta) theta' + alpha' E3) + kappa0,
 *
 * from Lambda^T Lambda' (T the right Jacobian of exp, rotation.h).
 *
 * The strain measures below are the building blocks of the plate models
 * (plate_model.h: registered implementations of kinematics::PlateModel,
 * one file each in source/kinematics/plate_models/). Three models share the
 * fields (doc/specification/plate-rod.md "Models"): the Cosserat plate
 * and rod; the same with the transverse shear stiffnesses multiplied by a
 * penalty (the Kirchhoff limit; reduced integration keeps it locking-free);
 * von Karman: d = E3 + beta, beta = theta x E3, membrane strain
 * sym grad v + 1/2 grad w (x) grad w, bending sym grad beta, shear
 * grad w + beta, and the rod with linearized rotations whose axial strain
 * keeps the squares of both rotations of its tangent (moderate rotations;
 * doc/theory-plate-rod.md).
 */
namespace cosmo
{
  namespace kinematics
  {
    /// Plate local variables: u (0-2), du/dX1 (3-5), du/dX2 (6-8), theta1, theta2 (9, 10),
    /// dtheta/dX1 (11, 12), dtheta/dX2 (13, 14).
    constexpr int plate_local_variables = 15;
    /// Rim rod local variables: u (0-2), du/dS (3-5), theta1, theta2 (6, 7), their S-derivatives
    /// (8, 9), alpha (10), dalpha/dS (11).
    constexpr int rim_local_variables = 12;

    /// In-plane growth at a point: G^-1 (2x2) and det G; and the natural curvature
    /// (k11, k22, k12) from which the bending strain is measured (growth through the thickness).
    struct PlateGrowthAtPoint
    {
      std::array<std::array<double, 2>, 2> G_inv{{{{1, 0}}, {{0, 1}}}};
      double                               det_G = 1;
      std::array<double, 3>                natural_curvature{{0, 0, 0}};

      /// From the growth tensor G (2x2, in-plane, G[i][j]).
      static PlateGrowthAtPoint
      of(const std::array<std::array<double, 2>, 2> &G)
      {
        PlateGrowthAtPoint g;
        g.det_G = G[0][0] * G[1][1] - G[0][1] * G[1][0];
        g.G_inv = {{{{G[1][1] / g.det_G, -G[0][1] / g.det_G}},
                    {{-G[1][0] / g.det_G, G[0][0] / g.det_G}}}};
        return g;
      }
    };

    namespace internal
    {
      /**
       * The exact director d = R E3 and its derivatives d_j = R (omega_j x E3),
       * omega_j = T(theta) dtheta/dX_j (T the right Jacobian of exp), from
       * theta = (theta1, theta2, 0) and dtheta[2 j + i] = dtheta_i/dX_j: the
       * only transcendental part of the plate's kinematics (the chain rule
       * of exact_plate_energy_derivatives() differentiates it in its own six
       * variables).
       */
      template <typename Number>
      void
      exact_director_and_gradient(const Number &         theta1,
                                  const Number &         theta2,
                                  const Number *         dtheta,
                                  std::array<Number, 3> &d,
                                  std::array<Number, 3> &d1,
                                  std::array<Number, 3> &d2)
      {
        Tensor<1, 3, Number> theta;
        theta[0]                     = theta1;
        theta[1]                     = theta2;
        const Tensor<2, 3, Number> R = rotation_exp(theta);
        const Tensor<2, 3, Number> T = rotation_dexp_right(theta);
        for (unsigned int i = 0; i < 3; ++i)
          d[i] = R[i][2];
        // d_j d = R (omega_j x E3), omega_j = T dtheta/dX_j; omega x E3 = (omega2, -omega1, 0).
        for (unsigned int j = 0; j < 2; ++j)
          {
            Number o1 = T[0][0] * dtheta[2 * j];
            o1 += T[0][1] * dtheta[2 * j + 1];
            Number o2 = T[1][0] * dtheta[2 * j];
            o2 += T[1][1] * dtheta[2 * j + 1];
            std::array<Number, 3> &dj = j == 0 ? d1 : d2;
            for (unsigned int i = 0; i < 3; ++i)
              {
                dj[i] = R[i][0] * o2;
                dj[i] -= R[i][1] * o1;
              }
          }
      }

      /// The exact plate strains (grown reference) from the local variables.
      template <typename Number>
      materials::PlateStrains<Number>
      exact_plate_strains(const std::array<Number, plate_local_variables> &z,
                          const PlateGrowthAtPoint &                      g)
      {
        using V = std::array<Number, 3>;
        const V a1 = {{1. + z[3], z[4], z[5]}};
        const V a2 = {{z[6], 1. + z[7], z[8]}};
        V       d, d1, d2;
        exact_director_and_gradient(z[9], z[10], &z[11], d, d1, d2);
        return materials::grown_plate_strains(a1, a2, d, d1, d2, g.G_inv);
      }

      /// The exact director d = exp([theta]x) E3 (theta = (z[9], z[10], 0)).
      inline Tensor<1, 3>
      exact_director(const std::array<double, plate_local_variables> &z)
      {
        Tensor<1, 3> theta;
        theta[0]     = z[9];
        theta[1]     = z[10];
        const auto Q = rotation_exp(theta);
        return Tensor<1, 3>({Q[0][2], Q[1][2], Q[2][2]});
      }

      /// The von Karman director d = E3 + beta, beta = theta x E3 = (theta2, -theta1, 0).
      inline Tensor<1, 3>
      von_karman_director(const std::array<double, plate_local_variables> &z)
      {
        return Tensor<1, 3>({z[10], -z[9], 1.});
      }

      /// Von Karman strains (grown reference: C -> G^-T C G^-1 etc.).
      template <typename Number>
      materials::PlateStrains<Number>
      von_karman_plate_strains(const std::array<Number, plate_local_variables> &z,
                               const PlateGrowthAtPoint &                      g)
      {
        // grad v (i: component, j: derivative), grad w, beta = (theta2, -theta1), grad beta.
        const Number gv[2][2] = {{z[3], z[6]}, {z[4], z[7]}};
        const Number gw[2]    = {z[5], z[8]};
        const Number beta[2]  = {z[10], -z[9]};
        const Number gb[2][2] = {{z[12], z[14]}, {-z[11], -z[13]}};
        Number       C[2][2], K[2][2];
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            {
              C[i][j] = gv[i][j] + gv[j][i] + gw[i] * gw[j];
              if (i == j)
                C[i][j] += 1.;
              K[i][j] = 0.5 * (gb[i][j] + gb[j][i]);
            }
        Number gamma[2] = {gw[0] + beta[0], gw[1] + beta[1]};
        const auto &Gi  = g.G_inv;
        // A -> Gi^T A Gi for symmetric 2x2 A; v -> Gi^T v.
        auto pull = [&Gi](const Number A[2][2], const unsigned int a, const unsigned int b) {
          Number s = 0. * A[0][0];
          for (unsigned int i = 0; i < 2; ++i)
            for (unsigned int j = 0; j < 2; ++j)
              s += Gi[i][a] * A[i][j] * Gi[j][b];
          return s;
        };
        materials::PlateStrains<Number> s;
        s.membrane[0] = 0.5 * (pull(C, 0, 0) - 1.);
        s.membrane[1] = 0.5 * (pull(C, 1, 1) - 1.);
        s.membrane[2] = 0.5 * pull(C, 0, 1);
        s.bending[0]  = pull(K, 0, 0);
        s.bending[1]  = pull(K, 1, 1);
        s.bending[2]  = pull(K, 0, 1);
        for (unsigned int a = 0; a < 2; ++a)
          {
            s.shear[a] = Gi[0][a] * gamma[0];
            s.shear[a] += Gi[1][a] * gamma[1];
          }
        return s;
      }
    } // namespace internal

    /// The rim's reference frame at one point: Lambda0 (columns d1, d2, d3) and the unit tangent
    /// dX/dS of the discrete rim there.
    struct RimFrame
    {
      Tensor<2, 3> Lambda0;
      Tensor<1, 3> tangent;
    };

    /**
     * The reference frame of the circular rim at X on it, with the discrete
     * unit tangent of the mesh's rim face (outward normal `normal`,
     * tangent clockwise): d1 = e_r, d2 = E3, d3 = d1 x d2 = -e_theta, the
     * columns of Lambda0.
     */
    inline RimFrame
    circular_rim_frame(const Point<2> &X, const Tensor<1, 2> &normal)
    {
      RimFrame     f;
      const double r = X.norm();
      const double c = X[0] / r, s = X[1] / r;
      f.Lambda0[0][0] = c, f.Lambda0[1][0] = s;
      f.Lambda0[2][1] = 1;
      f.Lambda0[0][2] = s, f.Lambda0[1][2] = -c;
      f.tangent[0]    = normal[1];
      f.tangent[1]    = -normal[0];
      return f;
    }

    /**
     * The rim's frame Lambda = exp([theta]x) exp(alpha [E3]x) Lambda0,
     * theta = (theta1, theta2, 0) (the plate's rotation at the weld) and
     * alpha the rim's own rotation about the plate normal (columns d1, d2,
     * d3; exact_rim_strains uses the same factors without forming it).
     */
    inline Tensor<2, 3>
    rim_rotation(const double theta1, const double theta2, const double alpha,
                 const Tensor<2, 3> &Lambda0)
    {
      Tensor<1, 3> theta, a;
      theta[0] = theta1;
      theta[1] = theta2;
      a[2]     = alpha;
      return rotation_exp(theta) * rotation_exp(a) * Lambda0;
    }

    /**
     * The reference strains of the discrete rim at X on it (so that the
     * reference ring is stress free, whatever the polygon of the mesh):
     * nu0 = Lambda0^T t, kappa0 = (0, t.e_theta / r, 0).
     */
    inline std::array<double, 6>
    rim_reference_strains(const Point<2> &X, const RimFrame &f)
    {
      std::array<double, 6> e{};
      for (unsigned int k = 0; k < 3; ++k)
        {
          double n0 = 0;
          for (unsigned int i = 0; i < 3; ++i)
            n0 += f.Lambda0[i][k] * f.tangent[i];
          e[k] = n0;
        }
      const double r = X.norm();
      e[4]           = (f.tangent[0] * (-X[1]) + f.tangent[1] * X[0]) / (r * r);
      return e;
    }

    namespace internal
    {
      /// The rim's r' = t + du/dS.
      template <typename Number>
      Tensor<1, 3, Number>
      rim_tangent(const std::array<Number, rim_local_variables> &z, const RimFrame &f)
      {
        Tensor<1, 3, Number> r1;
        for (unsigned int i = 0; i < 3; ++i)
          r1[i] = f.tangent[i] + z[3 + i];
        return r1;
      }

      /**
       * The rod's strains in its reference frame from the spatial vectors v
       * (of nu) and w (of kappa): nu_k = Lambda0^T v, kappa = Lambda0^T w +
       * kappa0.
       */
      template <typename Number>
      std::array<Number, 6>
      in_rim_frame(const RimFrame &             f,
                   const Number (&v)[3],
                   const Number (&w)[3],
                   const std::array<double, 3> &kappa0)
      {
        std::array<Number, 6> e;
        for (unsigned int k = 0; k < 3; ++k)
          {
            Number n = 0. * v[0], m = 0. * v[0];
            for (unsigned int i = 0; i < 3; ++i)
              {
                n += f.Lambda0[i][k] * v[i];
                m += f.Lambda0[i][k] * w[i];
              }
            e[k]     = n;
            e[3 + k] = m + kappa0[k];
          }
        return e;
      }

      /// The rod's six strains (nu, kappa) with moderate rotations (von Karman), kappa0 added.
      template <typename Number>
      std::array<Number, 6>
      linearized_rim_strains(const std::array<Number, rim_local_variables> &z,
                             const RimFrame &                              f,
                             const std::array<double, 3> &                 kappa0)
      {
        // Linearized rotation psi = theta + alpha E3: nu = Lambda0^T (r' - psi x t),
        // kappa = kappa0 + Lambda0^T psi'; the axial strain keeps the squares of the
        // in-plane and out-of-plane rotations of the tangent.
        const Tensor<1, 3, Number> r1      = rim_tangent(z, f);
        const Number               psi[3]  = {z[6], z[7], z[10]};
        const Number               dpsi[3] = {z[8], z[9], z[11]};
        const auto &               t       = f.tangent;
        const Number               v[3]    = {r1[0] - (psi[1] * t[2] - psi[2] * t[1]),
                                   r1[1] - (psi[2] * t[0] - psi[0] * t[2]),
                                   r1[2] - (psi[0] * t[1] - psi[1] * t[0])};
        std::array<Number, 6>      e       = in_rim_frame(f, v, dpsi, kappa0);
        Number                     q1 = 0. * z[0], q2 = 0. * z[0];
        for (unsigned int i = 0; i < 3; ++i)
          {
            q1 += f.Lambda0[i][0] * z[3 + i];
            q2 += f.Lambda0[i][1] * z[3 + i];
          }
        e[2] += 0.5 * (q1 * q1 + q2 * q2);
        return e;
      }

      /// The rod's six strains (nu, kappa) from the exact rotations, kappa0 added.
      template <typename Number>
      std::array<Number, 6>
      exact_rim_strains(const std::array<Number, rim_local_variables> &z,
                        const RimFrame &                              f,
                        const std::array<double, 3> &                 kappa0)
      {
        const Tensor<1, 3, Number> r1 = rim_tangent(z, f);
        Tensor<1, 3, Number>       theta;
        theta[0]                     = z[6];
        theta[1]                     = z[7];
        const Tensor<2, 3, Number> A = rotation_exp(theta);
        const Tensor<2, 3, Number> T = rotation_dexp_right(theta);
        using std::cos;
        using std::sin;
        const Number c = cos(z[10]), s = sin(z[10]);
        // B = exp(alpha [E3]x); w = B^T (T theta') + alpha' E3; v = B^T A^T r'.
        Number wA[3], Ar[3];
        for (unsigned int i = 0; i < 3; ++i)
          {
            wA[i] = T[i][0] * z[8];
            wA[i] += T[i][1] * z[9];
            Ar[i] = A[0][i] * r1[0];
            Ar[i] += A[1][i] * r1[1];
            Ar[i] += A[2][i] * r1[2];
          }
        const Number w[3] = {c * wA[0] + s * wA[1], -s * wA[0] + c * wA[1], wA[2] + z[11]};
        const Number v[3] = {c * Ar[0] + s * Ar[1], -s * Ar[0] + c * Ar[1], Ar[2]};
        return in_rim_frame(f, v, w, kappa0);
      }
    } // namespace internal

  } // namespace kinematics
} // namespace cosmo

#endif

#ifndef cosmo_kinematics_plate_measures_h
#define cosmo_kinematics_plate_measures_h

#include <cosmo/materials/plate_law.h>

#include <array>

/**
 * The chain rule through the plate measures, shared by the strip and the
 * Cosserat plate (doc/theory-strip.md, doc/theory-plate-rod.md): an energy
 * w(s(V)) of the eight measures s of plate_strains() (membrane 11, 22, 12;
 * bending 11, 22, 12; shear 1, 2), where V = (a1, a2, d, d1, d2) are the
 * five vectors plate_strains() takes. Each measure is a dot product of two
 * of the vectors (plus a constant), so its Hessian in V does not depend on
 * V: nested AD is needed only in the law (eight measures) and, by the
 * caller, in the director. The caller composes with V(z):
 * g = V_z^T w_V, H = V_z^T w_VV V_z + sum_i w_{V_i} (V_i)_zz
 * (add_pull_back() the first two terms).
 */
namespace cosmo
{
  namespace kinematics
  {
    namespace plate_measures
    {
      constexpr int n_measures = 8;  // membrane (11, 22, 12), bending (11, 22, 12), shear (1, 2)
      constexpr int n_vectors  = 15; // a1, a2, d, d1, d2 (plate_strains' arguments)

      /// Which part of the plate law, with which factor and natural curvature.
      struct Energy
      {
        const materials::PlateLawAt *law = nullptr;
        /// Membrane and bending (true), or the transverse shear (false).
        bool membrane_bending = true;
        /// Factor on the energy (det G; for the shear also the model's shear scale).
        double factor = 1;
        /// Taken off the bending measures (growth through the thickness).
        std::array<double, 3> natural_curvature{};
      };

      /**
       * W = factor w(s(V) - natural curvature), its gradient w_V and (with
       * the Hessian) w_VV in V, 15 x 15 row-major.
       */
      void
      energy_in_vectors(const std::array<double, n_vectors> &            V,
                        const Energy &                                   energy,
                        bool                                             with_hessian,
                        double &                                         W,
                        std::array<double, n_vectors> &                  wV,
                        std::array<double, n_vectors * n_vectors> &      wVV);

      /// C += A B for row-major A (M x K), B (K x N), skipping the zeros of A
      /// (V_z and the law's Hessian are mostly zeros).
      template <int M, int K, int N>
      void
      add_product(const std::array<double, M * K> &A,
                  const std::array<double, K * N> &B,
                  std::array<double, M * N> &      C)
      {
        for (int i = 0; i < M; ++i)
          for (int l = 0; l < K; ++l)
            if (A[K * i + l] != 0)
              for (int j = 0; j < N; ++j)
                C[N * i + j] += A[K * i + l] * B[N * l + j];
      }

      /**
       * g = V_z^T w_V and (with the Hessian) H = V_z^T w_VV V_z, for V_z
       * (15 x NZ, row-major): the terms of the chain rule that do not need
       * the second derivatives of V(z).
       */
      template <int NZ>
      void
      pull_back(const std::array<double, n_vectors * NZ> &            Vz,
                const std::array<double, n_vectors> &                 wV,
                const std::array<double, n_vectors * n_vectors> &     wVV,
                const bool                                            with_hessian,
                std::array<double, NZ> &                              g,
                std::array<double, NZ * NZ> &                         H)
      {
        g.fill(0.);
        for (int a = 0; a < n_vectors; ++a)
          if (wV[a] != 0)
            for (int c = 0; c < NZ; ++c)
              g[c] += Vz[NZ * a + c] * wV[a];
        if (!with_hessian)
          return;
        std::array<double, n_vectors * NZ> wVV_Vz{};
        add_product<n_vectors, n_vectors, NZ>(wVV, Vz, wVV_Vz);
        H.fill(0.);
        for (int a = 0; a < n_vectors; ++a)
          for (int r = 0; r < NZ; ++r)
            if (Vz[NZ * a + r] != 0)
              for (int c = 0; c < NZ; ++c)
                H[NZ * r + c] += Vz[NZ * a + r] * wVV_Vz[NZ * a + c];
      }
    } // namespace plate_measures
  }   // namespace kinematics
} // namespace cosmo

#endif

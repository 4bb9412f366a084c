// The chain rule through the plate measures (kinematics/plate_measures.h):
// their constant Hessians once by nested AD of plate_strains(), the measures
// and their gradient from those (the measures are bilinear), the law by
// nested AD in the eight measures.
#include <cosmo/kinematics/plate_measures.h>
#include <cosmo/materials/energy_derivatives.h>

#include <utility>
#include <vector>

namespace cosmo
{
  namespace kinematics
  {
    namespace plate_measures
    {
      namespace
      {
        /// The eight measures of plate_strains() from V = (a1, a2, d, d1, d2).
        template <typename Number>
        std::array<Number, n_measures>
        measures_of(const std::array<Number, n_vectors> &V)
        {
          auto part = [&V](const int k) {
            return std::array<Number, 3>{{V[3 * k], V[3 * k + 1], V[3 * k + 2]}};
          };
          const auto s = materials::plate_strains(part(0), part(1), part(2), part(3), part(4));
          return {{s.membrane[0], s.membrane[1], s.membrane[2], s.bending[0], s.bending[1],
                   s.bending[2], s.shear[0], s.shear[1]}};
        }

        template <typename Number>
        materials::PlateStrains<Number>
        strains_of(const std::array<Number, n_measures> &x)
        {
          materials::PlateStrains<Number> s;
          for (unsigned int k = 0; k < 3; ++k)
            {
              s.membrane[k] = x[k];
              s.bending[k]  = x[3 + k];
            }
          s.shear[0] = x[6];
          s.shear[1] = x[7];
          return s;
        }

        /**
         * The Hessians of the measures in V. Each measure is a dot product of
         * two of the vectors (plus a constant), so they do not depend on V:
         * computed once, by nested AD of plate_strains() at V = 0, so that
         * the measures are written in one place only. (If plate_strains()
         * ever stopped being bilinear, the comparisons with nested AD in
         * tests/kinematics.cc would fail.)
         */
        const std::array<std::array<double, n_vectors * n_vectors>, n_measures> &
        measure_hessians()
        {
          static const auto hessians = []() {
            const auto s =
              measures_of(materials::internal::independent_second_order<n_vectors>({}));
            std::array<std::array<double, n_vectors * n_vectors>, n_measures> h;
            for (int k = 0; k < n_measures; ++k)
              for (int a = 0; a < n_vectors; ++a)
                for (int b = 0; b < n_vectors; ++b)
                  h[k][n_vectors * a + b] = s[k].dx(a).dx(b);
            return h;
          }();
          return hessians;
        }

        /**
         * The same Hessians as lists of their nonzero entries (at most 12 of
         * 225 per measure), and the measures at V = 0: each measure being
         * bilinear, s_k(V) = s_k(0) + V.H_k V / 2 and s_k,V = H_k V exactly,
         * with no AD per point (which cost 15 % of a plate residual).
         */
        struct MeasuresInVectors
        {
          std::array<double, n_measures>                                s0;
          std::array<std::vector<std::pair<std::array<int, 2>, double>>, n_measures> entries;
        };

        const MeasuresInVectors &
        measures_in_vectors()
        {
          static const auto m = []() {
            MeasuresInVectors m;
            m.s0          = measures_of(std::array<double, n_vectors>{});
            const auto &h = measure_hessians();
            for (int k = 0; k < n_measures; ++k)
              for (int a = 0; a < n_vectors; ++a)
                for (int b = 0; b < n_vectors; ++b)
                  if (h[k][n_vectors * a + b] != 0)
                    m.entries[k].push_back({{{a, b}}, h[k][n_vectors * a + b]});
            return m;
          }();
          return m;
        }
      } // namespace

      void
      energy_in_vectors(const std::array<double, n_vectors> &       V,
                        const Energy &                              energy,
                        const bool                                  with_hessian,
                        double &                                    W,
                        std::array<double, n_vectors> &             wV,
                        std::array<double, n_vectors * n_vectors> & wVV)
      {
        // The measures and their gradient in V: s_k,V = H_k V, s_k = s_k(0) + V.s_k,V / 2.
        std::array<double, n_measures>             s;
        std::array<double, n_measures * n_vectors> sV{};
        {
          const auto &m = measures_in_vectors();
          for (int k = 0; k < n_measures; ++k)
            {
              double *const g = &sV[n_vectors * k];
              for (const auto &e : m.entries[k])
                g[e.first[0]] += e.second * V[e.first[1]];
              double q = 0;
              for (int a = 0; a < n_vectors; ++a)
                q += V[a] * g[a];
              s[k] = m.s0[k] + 0.5 * q;
            }
        }

        // The law in the measures (its own derivatives), times the factor.
        std::array<double, n_measures>              ws;
        std::array<double, n_measures * n_measures> wss;
        for (unsigned int k = 0; k < 3; ++k)
          s[3 + k] -= energy.natural_curvature[k];
        energy.law->derivatives(s,
                                energy.membrane_bending ? materials::PlatePart::membrane_and_bending :
                                                          materials::PlatePart::transverse_shear,
                                with_hessian, W, ws, wss);
        W *= energy.factor;
        for (auto &w : ws)
          w *= energy.factor;
        if (with_hessian)
          for (auto &w : wss)
            w *= energy.factor;

        // w_V = s_V^T w_s.
        wV.fill(0.);
        for (int k = 0; k < n_measures; ++k)
          for (int a = 0; a < n_vectors; ++a)
            wV[a] += ws[k] * sV[n_vectors * k + a];
        if (!with_hessian)
          return;

        // w_VV = s_V^T w_ss s_V + sum_k w_{s_k} s_k,VV.
        const auto &                               sVV = measure_hessians();
        std::array<double, n_measures * n_vectors> wss_sV{};
        add_product<n_measures, n_measures, n_vectors>(wss, sV, wss_sV);
        wVV.fill(0.);
        for (int k = 0; k < n_measures; ++k)
          for (int a = 0; a < n_vectors; ++a)
            {
              const double ska = sV[n_vectors * k + a];
              for (int b = 0; b < n_vectors; ++b)
                wVV[n_vectors * a + b] += ska * wss_sV[n_vectors * k + b] + ws[k] * sVV[k][n_vectors * a + b];
            }
      }
    } // namespace plate_measures
  }   // namespace kinematics
} // namespace cosmo

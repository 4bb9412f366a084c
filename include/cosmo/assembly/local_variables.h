#ifndef cosmo_assembly_local_variables_h
#define cosmo_assembly_local_variables_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <vector>

/**
 * Assembly through local variables (the strip and the plate with its rim):
 * at a quadrature point the energy density is a function W(z) of a few local
 * variables z (values and derivatives of the fields, the rod strains), which
 * Sacado differentiates (materials/energy_derivatives.h) into its gradient g
 * and Hessian H. Each shape function i drives a few of them linearly,
 * z[var_p] += U_i w_p (its "drive"), so with B the matrix of the drives the
 * cell's residual and stiffness are r += B g dA and K += B H B^T dA; the
 * columns of H that belong to the rod strains give the field-strain block.
 * Part 1's section is assembled with its own hand derivatives of Fbar
 * (application rod_cross_section), not through local variables.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    /// Which local variables a shape function drives (at most three) and with what weight.
    struct Drive
    {
      unsigned int n = 0;
      unsigned int var[3];
      double       w[3];
    };

    /// z[var_p] += U_i w_p over the shape functions i.
    template <int N>
    void
    gather_local_variables(const std::vector<Drive> & drives,
                           const std::vector<double> &U_local,
                           std::array<double, N> &    z)
    {
      for (unsigned int i = 0; i < drives.size(); ++i)
        for (unsigned int p = 0; p < drives[i].n; ++p)
          z[drives[i].var[p]] += U_local[i] * drives[i].w[p];
    }

    /**
     * One quadrature point: r += B g dA and, if jacobian, K += B H B^T dA,
     * with B the (sparse) drives; H is symmetric.
     */
    template <int N>
    void
    add_point(const std::vector<Drive> &       drives,
              const std::array<double, N> &    g,
              const std::array<double, N * N> &H,
              const double                     dA,
              const bool                       jacobian,
              Vector<double> &                 r,
              FullMatrix<double> &             K)
    {
      const unsigned int n = drives.size();
      for (unsigned int i = 0; i < n; ++i)
        {
          const Drive &a = drives[i];
          double       s = 0;
          for (unsigned int p = 0; p < a.n; ++p)
            s += g[a.var[p]] * a.w[p];
          r[i] += s * dA;
        }
      if (!jacobian)
        return;
      // Local variables whose row of H vanishes (the plate's displacement values, on which
      // its energy does not depend) are left out of the drives: every sum below is then the
      // same (a zero product adds nothing) for a third less work on the displacement DoFs.
      std::array<int, N> live;
      int                n_live = 0;
      std::array<bool, N> is_live;
      for (int a = 0; a < N; ++a)
        {
          bool l = false;
          for (int b = 0; b < N && !l; ++b)
            l = H[N * a + b] != 0; // (NaN counts as nonzero: it propagates)
          is_live[a] = l;
          if (l)
            live[n_live++] = a;
        }
      thread_local std::vector<Drive> compact;
      compact.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          compact[i].n = 0;
          for (unsigned int p = 0; p < drives[i].n; ++p)
            if (is_live[drives[i].var[p]])
              {
                compact[i].var[compact[i].n] = drives[i].var[p];
                compact[i].w[compact[i].n++] = drives[i].w[p];
              }
        }
      // First B H (its live columns), then the upper triangle of (B H) B^T, mirrored.
      thread_local std::vector<std::array<double, N>> BH;
      BH.resize(n);
      for (unsigned int i = 0; i < n; ++i)
        {
          const Drive &a = compact[i];
          for (int c = 0; c < n_live; ++c)
            {
              const int b = live[c];
              double    s = 0;
              for (unsigned int p = 0; p < a.n; ++p)
                s += a.w[p] * H[N * a.var[p] + b];
              BH[i][b] = s * dA;
            }
        }
      for (unsigned int i = 0; i < n; ++i)
        {
          if (compact[i].n == 0)
            continue;
          for (unsigned int j = i; j < n; ++j)
            {
              const Drive &b = compact[j];
              double       k = 0;
              for (unsigned int q = 0; q < b.n; ++q)
                k += BH[i][b.var[q]] * b.w[q];
              K(i, j) += k;
              if (j != i)
                K(j, i) += k;
            }
        }
    }

    /**
     * The field-strain and strain-strain blocks of one quadrature point, the
     * strains being the local variables first_strain, ..., first_strain +
     * n_strains - 1: B(i, k) += (B H)_{i, k} dA, E(k, l) += H_{k l} dA.
     */
    template <int N>
    void
    add_strain_blocks(const std::vector<Drive> &       drives,
                      const std::array<double, N * N> &H,
                      const double                     dA,
                      const unsigned int               first_strain,
                      const unsigned int               n_strains,
                      FullMatrix<double> &             B,
                      FullMatrix<double> &             E)
    {
      for (unsigned int i = 0; i < drives.size(); ++i)
        for (unsigned int k = 0; k < n_strains; ++k)
          {
            double s = 0;
            for (unsigned int p = 0; p < drives[i].n; ++p)
              s += H[N * drives[i].var[p] + first_strain + k] * drives[i].w[p];
            B(i, k) += s * dA;
          }
      for (unsigned int k = 0; k < n_strains; ++k)
        for (unsigned int l = 0; l < n_strains; ++l)
          E(k, l) += H[N * (first_strain + k) + first_strain + l] * dA;
    }
  } // namespace assembly
} // namespace cosmo

#endif

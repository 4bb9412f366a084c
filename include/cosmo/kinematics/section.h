#ifndef cosmo_kinematics_section_h
#define cosmo_kinematics_section_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>

/**
 * Kinematics of the helical Cauchy-Born cross-section (part 1,
 * doc/theory-rod-cross-section.md): a section point X of the reference
 * section goes to w(X) = X + u(X) in the director frame, and the rod's
 * uniform strains (nu, kappa) carry the section along the helix, so that the
 * deformation gradient of the rod is, in the director frame,
 *
 *   Fbar = [dw/dX1 | dw/dX2 | nu + kappa x w],
 *
 * and on a boundary curve with unit tangent T (arc length S) the surface
 * deformation gradient of a surface layer is Fs = [dw/dS | nu + kappa x w].
 * Both depend on the strains only through their last column b = nu +
 * kappa x w; the derivatives below are those the assembly needs.
 */
namespace cosmo
{
  namespace kinematics
  {
    using namespace dealii;

    /// The placement w = X + u of the section point X (X3 = 0) with displacement u.
    inline Tensor<1, 3>
    section_placement(const Point<2> &X, const Tensor<1, 3> &u)
    {
      return Tensor<1, 3>({X[0] + u[0], X[1] + u[1], u[2]});
    }

    /// b = nu + kappa x w, the column along the rod axis.
    inline Tensor<1, 3>
    axial_column(const Tensor<1, 3> &w, const Tensor<1, 3> &nu, const Tensor<1, 3> &kappa)
    {
      return nu + cross_product_3d(kappa, w);
    }

    /**
     * Fbar = [dw/dX1 | dw/dX2 | nu + kappa x w] from the displacement
     * gradient grad_u (its columns 0 and 1: du/dX1, du/dX2; column 2 unused).
     */
    inline Tensor<2, 3>
    section_deformation_gradient(const Tensor<2, 3> &grad_u,
                                 const Tensor<1, 3> &w,
                                 const Tensor<1, 3> &nu,
                                 const Tensor<1, 3> &kappa)
    {
      Tensor<2, 3>       F;
      const Tensor<1, 3> b = axial_column(w, nu, kappa);
      for (unsigned int r = 0; r < 3; ++r)
        {
          F[r][0] = grad_u[r][0] + (r == 0 ? 1. : 0.);
          F[r][1] = grad_u[r][1] + (r == 1 ? 1. : 0.);
          F[r][2] = b[r];
        }
      return F;
    }

    /**
     * Fs = [dw/dS | nu + kappa x w], row-major 3x2, at a boundary point with
     * placement w, tangential derivative du/dS of the displacement and unit
     * tangent T (dX/dS = T).
     */
    inline std::array<double, 6>
    surface_deformation_gradient(const Tensor<1, 3> &w,
                                 const Tensor<1, 3> &du_dS,
                                 const Tensor<1, 2> &T,
                                 const Tensor<1, 3> &nu,
                                 const Tensor<1, 3> &kappa)
    {
      const Tensor<1, 3>    b = axial_column(w, nu, kappa);
      std::array<double, 6> Fs;
      for (unsigned int r = 0; r < 3; ++r)
        {
          Fs[2 * r]     = du_dS[r] + (r < 2 ? T[r] : 0.);
          Fs[2 * r + 1] = b[r];
        }
      return Fs;
    }

    /// The unit tangent T = (-N2, N1) of a boundary curve with outward normal N (the energy is even in T).
    inline Tensor<1, 2>
    boundary_tangent(const Tensor<1, 2> &N)
    {
      return Tensor<1, 2>({-N[1], N[0]});
    }

    /// db/d(strain k) at w: e_k for nu_k (k < 3), e_{k-3} x w for kappa_{k-3}.
    inline Tensor<1, 3>
    axial_column_strain_derivative(const unsigned int k, const Tensor<1, 3> &w)
    {
      Tensor<1, 3> e;
      if (k < 3)
        {
          e[k] = 1;
          return e;
        }
      e[k - 3] = 1;
      return cross_product_3d(e, w);
    }

    /// d2 b / d(kappa_m) d(w_c) = e_m x e_c, the mixed second derivative.
    inline Tensor<1, 3>
    axial_column_mixed_derivative(const unsigned int m, const unsigned int c)
    {
      Tensor<1, 3> a, e;
      a[m] = 1;
      e[c] = 1;
      return cross_product_3d(a, e);
    }
  } // namespace kinematics
} // namespace cosmo

#endif

#ifndef cosmo_assembly_assumed_shear_h
#define cosmo_assembly_assumed_shear_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

/**
 * Assumed transverse shear strains of the MITC family (Bathe and Dvorkin
 * 1985; Bucalem and Bathe 1993, MITC9 for p = 2) for FE_Q(p) plates: the
 * covariant shear strains e_c = (dX/dxi_c) . gamma (gamma the model's
 * shear strain in the reference coordinates, c = 0, 1 the cell's unit
 * coordinates) are sampled at tying points and interpolated,
 *
 *   e_0: p Gauss points in xi_0 times p + 1 Gauss points in xi_1,
 *        interpolated in Q_{p-1, p} (Lagrange through them),
 *   e_1: the same with the directions exchanged,
 *
 * and the shear energy is integrated with the full p + 1 Gauss points from
 * gamma = J^-T e. For p = 2 these are the tying points of MITC9. On affine
 * cells the interpolation is the projection onto the rotated
 * Raviart-Thomas-type space Q_{p-1,p} x Q_{p,p-1} that makes the element
 * free of shear locking without spurious modes and with the optimal order
 * (Brezzi, Fortin, Stenberg 1991; Bathe, Brezzi, Cho 1989):
 * doc/theory-plate-rod.md section 7.
 *
 * This class holds the tying points on the unit cell and the interpolation
 * weights at the points of a quadrature; the assembly (application
 * plate_rod) differentiates the shear at the tying points and chains.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    class AssumedShear
    {
    public:
      /// The tying points of FE_Q(degree) (degree >= 1).
      explicit AssumedShear(unsigned int degree);

      /// All tying points on the unit cell, those of e_0 first (weights 1, unused).
      const Quadrature<2> &
      tying_points() const
      {
        return points;
      }
      unsigned int
      n_tying_points() const
      {
        return points.size();
      }
      /// The covariant component tied at tying point k (0 or 1).
      unsigned int
      component(const unsigned int k) const
      {
        return k < n_per_component ? 0 : 1;
      }
      /**
       * The interpolation weights at the points of q: N(i, k) is the weight
       * of tying point k in the assumed e_component(k) at q's point i.
       */
      FullMatrix<double>
      interpolation(const Quadrature<2> &q) const;

    private:
      unsigned int          n_per_component;
      std::vector<double>   low, high; ///< the p and p + 1 Gauss points on [0, 1]
      Quadrature<2>         points;
    };
  } // namespace assembly
} // namespace cosmo

#endif

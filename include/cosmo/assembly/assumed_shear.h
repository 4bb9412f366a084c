#ifndef cosmo_assembly_assumed_shear_h
#define cosmo_assembly_assumed_shear_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

/**
 * Assumed transverse shear strains of the MITC family for FE_Q(p) plates:
 * the covariant shear strains e_c = (dX/dxi_c) . gamma (gamma the model's
 * shear strain in the reference coordinates, c = 0, 1 the cell's unit
 * coordinates) are reduced to the rotated Raviart-Thomas-type space
 *
 *   e_0 in Q_{p-1, p},  e_1 in Q_{p, p-1},
 *
 * and the shear energy is integrated with the full p + 1 Gauss points from
 * gamma = J^-T e. Along its low direction (xi_0 for e_0) a component is
 * interpolated through its values at the p Gauss points (for a degree-p
 * polynomial, its L2 projection onto P_{p-1}). Along the other direction
 * it is determined by one of two tyings:
 *
 * - edge tying (the default): the values on the two edges where e_c is
 *   the tangential strain, and the moments against P_{p-2} (p Gauss
 *   points). This is the canonical interpolation of the rotated
 *   Raviart-Thomas (Nedelec) space, with the tangential shear continuous
 *   from cell to cell: the plate element of Bathe, Brezzi and Cho (1989),
 *   MITC9 for p = 2, whose convergence is uniform in the thickness on
 *   affine meshes (Brezzi, Fortin, Stenberg 1991). On the distorted
 *   (non-affine) coarse cells of a disc its error, measured, does not grow
 *   as the plate thins (doc/theory-plate-rod.md sections 7 and 9);
 * - interior tying: the values at the p + 1 Gauss points (the MITC9 shell
 *   element of Bucalem and Bathe 1993): the same space, and on
 *   parallelograms the same strains for the linear plate (the discrete
 *   fields' covariant strain is then of degree p along the tied direction,
 *   which both tyings reproduce), but the shear is not tangentially
 *   continuous, and on the coarse distorted cells of a disc its error grew
 *   8 to 11 times from h/R = 0.01 to 0.001. Kept for comparison with
 *   earlier results.
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
      /// The tying points of FE_Q(degree) (degree >= 1), on the edges or interior.
      explicit AssumedShear(unsigned int degree, bool edge_tying = true);

      /**
       * The distinct locations of the tying points on the unit cell (weights
       * 1, unused): with edge tying, e_0 and e_1 share their interior points,
       * so a cell evaluates its fields at 4 p + p^2 locations for 2 p (p + 2)
       * tied strains (p >= 2; p = 1: 4 of each).
       */
      const Quadrature<2> &
      tying_points() const
      {
        return points;
      }
      /// The number of tied strains (those of e_0 first).
      unsigned int
      n_tying_points() const
      {
        return location.size();
      }
      /// The location (index into tying_points()) of tied strain k.
      unsigned int
      location_of(const unsigned int k) const
      {
        return location[k];
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
      /// Edge tying: the points along the tied direction (0, 1, then the
      /// interior Gauss points of the moments) and the map from the values
      /// there to the coefficients of the degree-p polynomial (monomials).
      bool                  edges;
      std::vector<double>   along;
      FullMatrix<double>    coefficients;
      std::vector<Point<2>> tied; ///< the point of each tied strain
      std::vector<unsigned int> location;
      Quadrature<2>         points;
    };
  } // namespace assembly
} // namespace cosmo

#endif

#ifndef cosmo_assembly_self_contact_h
#define cosmo_assembly_self_contact_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <utility>
#include <vector>

/**
 * Penalty self-contact of a rod of radius a (doc/theory-rod.md 9): the
 * double integral, over the pairs of centreline points farther apart than
 * pi a along the rod, of a repulsive potential of their distance d,
 *
 *     E_c = int int_{|s - s'| > pi a} (k/3) <2a - |r(s) - r(s')|>_+^3 ds ds',
 *
 * by the nodes' trapezoidal rule (pairs i < j weighted w_i w_j). The cube
 * makes the energy C2: its Hessian is continuous when a pair touches, so
 * that the inertia count changes only where an eigenvalue crosses zero.
 * Points closer than pi a along the rod are never in contact: a tube of
 * radius a whose centreline's curvature is at most 1/a does not meet
 * itself there.
 *
 * The pairs are found by a grid of cells of the search distance, in a time
 * linear in the number of nodes.
 */
namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    class SelfContact
    {
    public:
      /**
       * `weights`: each node's share of the arclength (trapezoidal);
       * `arclength`: each node's s; `ring_length` > 0 for a closed rod, whose
       * arclength distances go the shorter way round.
       */
      SelfContact(double radius, double stiffness, std::vector<double> weights, std::vector<double> arclength,
                  double ring_length);

      double
      radius() const
      {
        return a;
      }

      /// The pairs (i < j) apart more than pi a along the rod and closer than `distance` in space.
      std::vector<std::pair<unsigned int, unsigned int>>
      pairs_within(const std::vector<Tensor<1, 3>> &x, double distance) const;

      /// A pair in contact: its energy, the force on node i (node j's is its
      /// opposite) and the Hessian block K of node i (blocks [[K, -K], [-K, K]]).
      struct Term
      {
        unsigned int i, j;
        double       energy;
        Tensor<1, 3> gradient_i; ///< dE/dx_i (dE/dx_j = -gradient_i)
        Tensor<2, 3> hessian;    ///< d2E/dx_i2
      };

      /// The pairs in contact (d < 2a) and their terms.
      std::vector<Term>
      terms(const std::vector<Tensor<1, 3>> &x) const;

      /// The smallest distance minus 2a over the pairs apart more than pi a
      /// along the rod (searched within 4a: +infinity if none is that close).
      double
      smallest_gap(const std::vector<Tensor<1, 3>> &x) const;

    private:
      double              a, k, ring;
      std::vector<double> w, s;
      bool
      excluded(unsigned int i, unsigned int j) const;
    };
  } // namespace assembly
} // namespace cosmo

#endif

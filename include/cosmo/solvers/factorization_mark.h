#ifndef cosmo_solvers_factorization_mark_h
#define cosmo_solvers_factorization_mark_h

#include <deal.II/lac/vector.h>

#include <cosmo/solvers/newton.h>

namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /**
     * The state and load parameter at which a problem's Jacobian was last
     * factorized. A converged state's inertia and condensed quantities, and
     * Newton's first Jacobian of the next solve, are often asked at exactly
     * that point: then the factorization in place is theirs and is reused.
     * A hit is the same state bitwise (same_point) and the same load.
     */
    struct FactorizationMark
    {
      Vector<double> at;       ///< the state (empty: no valid factorization)
      double         load = 0; ///< the load parameter
      /// The next report takes the last factorization as that of its state: a
      /// continued critical point, whose last Newton iterate differs from the
      /// located point by an update below the located precision
      /// (solvers/critical_point.h).
      bool with_last = false;

      /// Whether the factorization in place is that of U at load t.
      bool
      here(const Vector<double> &U, const double t) const
      {
        return load == t && same_point(U, at);
      }
      void
      set(const Vector<double> &U, const double t)
      {
        at   = U;
        load = t;
      }
      /// The matrix changed: the factorization no longer matches it.
      void
      clear()
      {
        at.reinit(0);
      }
    };
  } // namespace solvers
} // namespace cosmo

#endif

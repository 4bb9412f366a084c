#ifndef cosmo_solvers_chord_newton_h
#define cosmo_solvers_chord_newton_h

#include <cosmo/solvers/newton.h>

namespace cosmo
{
  namespace solvers
  {
    /**
     * newton_solve() with chord steps (NewtonSettings::reuse_factorization)
     * whose first step keeps the factorization in place: that of a nearby
     * state, e.g. the last converged state of a path, from which U is a
     * predictor (doc/theory-continuation.md 1). A step with it contracts
     * the residual by about the distance between the two states; where it
     * fails, or contracts less than tenfold, the Jacobian is set up at the
     * iterate as in newton_solve(), so the result is the same solution to
     * the tolerance, whatever factorization was in place. The system's
     * solve_with_jacobian() must be valid before the first setup_jacobian()
     * (solve with the factorization in place). The factorization in place
     * afterwards may be any iterate's, or still the nearby state's.
     */
    NewtonResult
    newton_solve_from_factorization(NonlinearSystem &system, Vector<double> &U, const NewtonSettings &settings);
  } // namespace solvers
} // namespace cosmo

#endif

#ifndef cosmo_solvers_newton_h
#define cosmo_solvers_newton_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

/**
 * Checked Newton: SUNDIALS KINSOL (Newton with line search) through deal.II,
 * with the application's exact Jacobian and direct solver.
 *
 * KINSOL's failures are silent in Release builds of deal.II 9.4 (they are
 * Asserts), so the residual is recomputed after every solve and a failure
 * becomes a NewtonFailure exception, which the continuation driver catches
 * and answers by cutting the step back.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /// What a Newton solver needs from a problem: R(U), and J(U) for solves.
    class NonlinearSystem
    {
    public:
      virtual ~NonlinearSystem() = default;
      virtual unsigned int
      n_unknowns() const = 0;
      /// R(U). Return 0 on success, >0 if U is inadmissible (e.g. det F <= 0).
      virtual int
      residual(const Vector<double> &U, Vector<double> &R) = 0;
      /// Assemble and factorize J(U). Return 0 on success, >0 on failure.
      virtual int
      setup_jacobian(const Vector<double> &U) = 0;
      /// dst = J^-1 rhs with the last factorization.
      virtual int
      solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) = 0;
      /**
       * Whether solve_with_jacobian() solves J dst = rhs exactly (a direct
       * solve of the Jacobian of residual(), no constraints that the solve
       * imposes and the residual does not). Then J p, which KINSOL needs once
       * per iteration for its line search and would approximate by one more
       * residual at u + sigma p, is known without it: the right-hand side
       * of the solve that gave p (newton_solve).
       */
      virtual bool
      solves_exactly() const
      {
        return false;
      }
      /**
       * Weights w (one per equation) that make the residual dimensionless:
       * Newton converges when max_i |w_i R_i| < relative tolerance. Rows of
       * different kinds (nodal forces, constraints, resultants) have
       * different units, so one absolute tolerance would be wrong for some.
       */
      virtual void
      residual_weights(Vector<double> &w) const
      {
        w.reinit(n_unknowns());
        w = 1.;
      }
    };

    class NewtonFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    /// A failure of the drivers (NewtonFailure, io::RunFailure) or of MUMPS
    /// (FactorizationFailure): on a distributed mesh every rank meets it at
    /// the same point (io::RunRecord::set_lockstep).
    bool
    is_driver_failure(const std::exception &e);

    struct NewtonSettings
    {
      double       relative_tolerance = 1e-10;
      unsigned int max_iterations     = 25;
      /**
       * Keep the factorization while Newton converges fast (newton_solve():
       * chord steps). Not a parameter of this section: the drivers that may
       * reuse it set it (NaturalParameterContinuation, from 'Continuation /
       * Reuse factorization'); the arclength driver and the critical-point
       * locator analyse the factorization at the last iterate and keep it
       * false.
       */
      bool reuse_factorization = false;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    struct NewtonResult
    {
      unsigned int iterations    = 0;
      double       residual_norm = 0; ///< weighted max-norm of R at the solution
      /// KINSOL's products J p answered from the solve (solves_exactly()).
      unsigned int exact_jacobian_products = 0;
      /// Of the iterations, those made with an earlier iterate's
      /// factorization (reuse_factorization: chord steps).
      unsigned int chord_steps = 0;
    };

    /**
     * Whether v = u + sigma p with KINSOL's difference-quotient sigma (of u
     * and p), to the rounding of the sum; that sigma on return.
     */
    bool
    dq_point_of(const Vector<double> &v, const Vector<double> &u, const Vector<double> &p, double &sigma);

    /**
     * Whether a and b are the same point: the same size and every entry
     * equal. How a cached residual or factorization is matched to the state
     * asked for (a state that differs in the last bit is another state).
     */
    bool
    same_point(const Vector<double> &a, const Vector<double> &b);

    /**
     * The last two residuals a problem assembled, each with its state, load
     * parameter and any scalars the assembly gave with it (energies). A
     * Jacobian assembly yields the residual at its state for little more, and
     * the drivers ask again for residuals they had: KINSOL's last iterate is
     * the first R(U) of the critical-point Newton, and each later iterate's
     * R(U) follows the Jacobian there. A hit is the same state bitwise
     * (same_point) and the same load parameter; the problem clears the cache
     * when anything else its residual depends on changes. A residual from a
     * Jacobian assembly may differ from a residual-only assembly's in the
     * last bits (second- against first-order AD): which one a driver gets
     * depends on the calls before, which the inputs determine, never on
     * the threads (test plate_rod.tangent_fd compares the two).
     */
    class ResidualCache
    {
    public:
      struct Entry
      {
        Vector<double>      U, R;
        double              load = 0;
        std::vector<double> scalars;
      };
      /// The entry at (U, load), or nullptr.
      const Entry *
      find(const Vector<double> &U, double load) const;
      /// Keep R(U) at load, replacing the entry of that state or the older one.
      void
      store(const Vector<double> &U, double load, const Vector<double> &R,
            const std::vector<double> &scalars = {});
      void
      clear();

    private:
      std::array<Entry, 2> entries;
      std::array<bool, 2>  valid{{false, false}};
      unsigned int         newest = 0;
    };

    /// max_i |w_i R_i| with the system's residual_weights(): its stopping test.
    double
    scaled_residual_norm(const NonlinearSystem &system, const Vector<double> &R);

    /**
     * Solve R(U) = 0 from the initial guess U; throws NewtonFailure.
     * take_guess: a guess that passes the stopping test (the weighted
     * max-norm of R at most the tolerance) is returned as it is, with 0
     * iterations and no factorization (KINSOL itself takes a guess only at
     * 1/100 of the tolerance). Only for a caller that then makes a Newton
     * step of its own with the factorization it needs there anyway (the
     * arclength corrector): the tolerance alone can leave a state short of
     * what Newton's last, quadratic step gives (a thin plate's buckled
     * state, doc/theory-continuation.md 1).
     * settings.reuse_factorization: Newton steps that keep the last
     * factorization while the residual contracts at least tenfold a step
     * (chord steps, doc/theory-continuation.md 1), KINSOL from where they
     * stop if they do not converge. The factorization in place afterwards
     * may then be an earlier iterate's.
     */
    NewtonResult
    newton_solve(NonlinearSystem &      system,
                 Vector<double> &       U,
                 const NewtonSettings & settings,
                 bool                   take_guess = false);
  } // namespace solvers
} // namespace cosmo

#endif

#ifndef cosmo_solvers_arclength_h
#define cosmo_solvers_arclength_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/solvers/continuation.h>
#include <cosmo/solvers/newton.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

/**
 * Pseudo-arclength continuation with stability tracking, event location and
 * branch switching (doc/specification/continuation.md).
 *
 * The branch (U(s), lambda(s)) of R(U, lambda) = 0 is followed in its
 * arclength s, ds^2 = theta |dU|^2 + dlambda^2 (theta = 1/n by default), so
 * that folds, where lambda turns back, are passed. Each step: the tangent
 * (one solve with the factorized Jacobian J), a predictor along it, and a
 * checked Newton corrector on the augmented system
 *
 *   R(U, lambda) = 0,   theta t_U.(U - U_p) + t_lambda (lambda - lambda_p) = 0
 *
 * solved by bordering with the problem's own factorization (two solves per
 * iteration). After every converged step the problem reports the number of
 * negative eigenvalues of its Hessian on the constrained space (for an
 * LDL^T factorization this is the inertia, which comes free). A change of
 * that count between two steps is an event, classified as a fold (lambda
 * turns: the lambda-component of the tangent changes sign) or a branch point:
 * the count is bisected until each bracket holds one crossing, which is then
 * located by Newton on a minimally augmented system (critical_point.h, with
 * the null vector phi of J), or, where that fails, by bisection to a
 * tolerance (doc/theory-continuation.md). At a simple branch point the new
 * branch starts at U* + a phi with the corrector condition phi.(U - U*) = a
 * (orthogonal to the old branch) and is followed like the first, to the
 * depth the settings allow.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /**
     * A problem whose branches can be followed: a ContinuationProblem (R(U) at
     * the load parameter last set, its Jacobian and solves) with dR/dlambda
     * and the stability indicator.
     */
    class BifurcationProblem : public ContinuationProblem
    {
    public:
      /**
       * dR/dlambda at U and the current load parameter. The default is a
       * central difference with step 1e-6 (1 + |lambda|); it restores lambda.
       */
      virtual int
      load_derivative(const Vector<double> &U, double lambda, Vector<double> &dR_dlambda);

      /**
       * Number of negative eigenvalues of the Hessian on the constrained space
       * at the state of the last setup_jacobian(); -1 if unknown.
       */
      virtual int
      n_negative_eigenvalues() = 0;

      /**
       * 1 for the unknowns that carry a mode shape (field DoFs), 0 for those
       * that do not (Lagrange multipliers, bordered unknowns, DoFs whose
       * values constraints determine). Used for the null vector at a branch
       * point, the border of the critical-point system (which must vanish on
       * constrained DoFs for the bordered test function to be symmetric) and
       * the arclength norm. Default: all 1.
       */
      virtual void
      mode_mask(Vector<double> &mask) const;

      /**
       * 1 for the unknowns whose Hessian the estimate of a critical point
       * examines (critical_estimate.h): the mode unknowns, and those the
       * energy is minimized over besides (a rod's free strains, which a
       * twisted section's critical mode moves: at growth 1.4, left out, its
       * estimate was 26 % high, in, 0.1 %). 0 for multipliers and for unknowns that
       * constraints determine. Default: mode_mask().
       */
      virtual void
      stability_mask(Vector<double> &mask) const;

      /**
       * Complete a mode whose constrained unknowns the mask zeroed: set each
       * unknown that homogeneous constraints determine (u_s = sum_m w_m u_m)
       * from its masters. The driver calls it on every null vector it keeps
       * (a branch point's mode, written out and used as a new branch's
       * direction), so that U* + a phi satisfies the constraints as U* does.
       * A mode left with zero slaves is a symmetry-breaking imperfection: on
       * a sector's oblique mirror edge (u_y = tan(pi/n) u_x) the switched
       * branch slipped along the edge by O(a) and started below its branch
       * point. Default: nothing (no constraints of that kind).
       */
      virtual void
      complete_mode(Vector<double> & /*v*/) const
      {}

      /**
       * A size of the mode unknowns at which the problem is noticeably
       * nonlinear (a length for displacements; rotations are O(1)): the
       * difference steps of the critical-point location's second derivatives
       * are 1e-4 of it. Default: max(|U|_inf on the mode unknowns, 1).
       */
      virtual double
      unknowns_scale(const Vector<double> &U) const;

      /**
       * |v|^T |J| |v| = sum_ij |J_ij| |v_i| |v_j| for the Jacobian last set up:
       * a componentwise backward-stable factorization perturbs v.Jv by at
       * most ~eps times this, which is the round-off resolution of a located
       * critical point's test function. Negative if unknown.
       */
      virtual double
      jacobian_abs_form(const Vector<double> & /*v*/) const
      {
        return -1;
      }

      /**
       * Products with the Jacobian at states beside the factorized one, from
       * assembled matrices: the critical-point estimate's Hessians along the
       * path (critical_estimate.h), which otherwise cost two residuals a
       * product, by differences. store_jacobian assembles J(U) at the
       * current load into copy `slot` (0, 1 or 2) and returns true, the
       * factorization and the assembled system left as they were; false:
       * the problem has none (the default, a distributed mesh), and the
       * estimate takes differences of residuals.
       */
      virtual bool
      store_jacobian(const Vector<double> & /*U*/, unsigned int /*slot*/)
      {
        return false;
      }
      /// y = J x with copy `slot` (the rows the mode mask drops may be anything).
      virtual void
      stored_jacobian_vmult(unsigned int /*slot*/, const Vector<double> & /*x*/, Vector<double> & /*y*/) const
      {}
      /// Free the copies.
      virtual void
      release_stored_jacobians()
      {}

      /**
       * Whether the arclength corrector may converge this problem's states
       * by chord steps on the last state's factorization ('Arclength
       * continuation / Reuse factorization'): where its weighted residual
       * below the tolerance means every unknown is converged. Opt-in: the
       * sections and the strips (ReducedRodProblem). The plate-rod problem
       * keeps exact Newton: its weights make the bending equations (h/R)^2
       * of the membrane ones, and with chord steps its switched branches
       * did not follow the buckled states at h/R = 0.01 and 0.001
       * (plate_rod.shear_convergence); so does the rod, whose overwinding
       * path stopped short of its end with chord steps on every branch
       * (validation.rod_overwinding).
       */
      virtual bool
      chord_steps_on_path() const
      {
        return false;
      }

      /**
       * Project v onto the fixed-point space of one reflection of the
       * problem's symmetry (v = (v + S v)/2) and return true; false (v
       * untouched) if the problem has none. At a double eigenvalue of a
       * D_n-symmetric problem (the full disc: cos n theta and sin n theta) the
       * eigenvalue is simple in that space (equivariant branching lemma), so
       * the driver locates it and switches onto the symmetric representative
       * there.
       */
      virtual bool
      project_to_fixed_point_space(Vector<double> & /*v*/) const
      {
        return false;
      }

      /// Called at every located event with the state there and, for a branch point, its mode.
      struct Event
      {
        enum class Kind
        {
          fold,
          branch_point
        };
        Kind         kind;
        double       lambda        = 0;
        double       arclength     = 0;
        unsigned int branch        = 0;
        int          n_negative_before = 0, n_negative_after = 0;
        double       eigenvalue    = 0; ///< of J along the mode (branch points)
        /// How lambda was located: by Newton on the minimally augmented system
        /// (critical_point.h) or, where that failed, by bisection of the count.
        bool         located_by_newton = false;
        unsigned int newton_iterations = 0; ///< of the augmented system
        unsigned int factorizations    = 0; ///< spent between detection and location
        double       residual_norm     = 0; ///< weighted max-norm of R at the located point
        double       test_function     = 0; ///< g of the bordered system there
        double       unfolding         = 0; ///< mu of the branch-point system (0: exact)
        double       precision         = 0; ///< Newton: CriticalPoint::lambda_update; bisection: half the bracket
        double       resolution        = -1; ///< eps |v|.|J||v| / |dg/dlambda| (-1: unknown)
        double       lambda_lo = 0, lambda_hi = 0; ///< the detection bracket
        unsigned int multiplicity      = 1; ///< |change of the count| at this point
        std::string  message;              ///< why Newton location failed, if it did
        std::string
        name() const
        {
          return kind == Kind::fold ? "fold" : "branch point";
        }
      };
      virtual void
      located_event(const Event &, const Vector<double> & /*U*/, const Vector<double> * /*mode*/)
      {}
    };

    /// problem.located_event(), then its postprocessors: how the driver
    /// reports a located fold or branch point.
    void
    report_located_event(BifurcationProblem &              problem,
                         const BifurcationProblem::Event &e,
                         const Vector<double> &            U,
                         const Vector<double> *            mode);

    /**
     * The eigenvalue of smallest magnitude of the problem's factorized
     * Jacobian on the mode unknowns (mask), and its unit eigenvector, by
     * inverse iteration with the last factorization (rhs and iterates are
     * masked, so bordered multipliers and strains act as constraints). Near a
     * loss of stability it is the eigenvalue that crosses zero. Iterates are
     * kept orthogonal (masked) to the vectors orthogonal_to: modes already
     * known, e.g. of a crossing just located in the same step. The
     * iteration stops when the unit iterate moves by less than tolerance;
     * the eigenvalue (a Rayleigh quotient) is then accurate to about its
     * square, relative.
     */
    double
    smallest_eigenvalue(BifurcationProblem &               problem,
                        const Vector<double> &             mask,
                        Vector<double> &                   mode,
                        unsigned int                       max_iterations = 100,
                        const std::vector<Vector<double>> &orthogonal_to  = {},
                        double                             tolerance      = 1e-12);

    /**
     * How an event was located, for summary.json: "location": {"method",
     * "factorizations", "last_update" (Event::precision), "resolution"
     * (event_resolution), "bracket", "multiplicity", and for Newton
     * "newton_iterations", "residual", "test_function", "unfolding", for
     * bisection "arclength_interval"; "message" where Newton failed}.
     */
    void
    add_location_to_json(const BifurcationProblem::Event &e, io::JSON &event);

    /**
     * How far the located lambda can move under round-off (threads, CPU,
     * inputs perturbed at 1e-14): the larger of the a-priori resolution and
     * the precision of the Newton iteration (CriticalPoint::lambda_update),
     * or half the bisection bracket. Regression
     * tolerances on event loads stand above this ("resolution" in
     * summary.json's event location, "t_resolution" in sweep.csv).
     */
    double
    event_resolution(const BifurcationProblem::Event &e);

    /**
     * The negative eigenvalues at a located point other than the critical
     * one: the count of the last factorization less the critical eigenvalue
     * where that factorization put it on the negative side (its sign is
     * round-off at the critical point; the Rayleigh quotient eigenvalue is
     * of the same factorization). A count alone cannot tell the two apart.
     */
    int
    other_negative_modes(const BifurcationProblem::Event &e);

    struct ArclengthSettings
    {
      bool         enabled            = false; ///< "Path following / Method = arclength"
      double       initial_step       = 0.05;
      double       minimum_step       = 1e-8;
      double       maximum_step       = 0.2;
      unsigned int maximum_steps      = 200; ///< per branch
      unsigned int easy_iterations    = 4;
      double       growth_factor      = 1.5;
      double       lambda_min         = -1e300; ///< a branch stops when lambda leaves
      double       lambda_max         = 1e300;  ///< [lambda_min, lambda_max]
      double       direction          = 1;      ///< initial sign of dlambda/ds
      double       theta              = 0;      ///< 0: 1/(number of mode unknowns)
      double       event_tolerance    = 1e-8;   ///< arclength interval of a bisected event
      bool         newton_location    = true;   ///< "Event location = newton" (else bisection)
      bool         switch_branches    = true;
      bool         both_directions    = true;  ///< follow +phi and -phi
      double       switch_amplitude   = 1e-2;  ///< a in U* + a phi (phi unit in the theta norm)
      unsigned int maximum_branches   = 4;
      unsigned int maximum_depth      = 1;     ///< switch on branches of depth < this
      bool         follow_mirror_images = false; ///< follow -phi when it mirrors +phi
      /// End the run at the first located event ("Stop at first event"):
      /// what a study of critical points needs of each run.
      bool         stop_at_first_event = false;
      /// With stop_at_first_event: the first event from one eigenproblem at
      /// the stable start ("First event by estimate", critical_estimate.h),
      /// the path followed where it does not hold.
      bool         first_event_by_estimate = true;
      /// A second-order estimate refined with the start's factorization
      /// alone before Newton on the augmented system ("Refine estimate",
      /// refine_critical_estimate()): fewer factorizations, more solves.
      bool         refine_estimate = false;
      /// The corrector's Newton starts with chord steps on the last state's
      /// factorization ("Reuse factorization", chord_newton.h).
      bool         reuse_factorization = true;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /// One converged state of a path, for path_summary().
    struct PathRow
    {
      unsigned int branch     = 0;
      double       t          = 0;
      int          n_negative = -1; ///< -1: not computed
    };

    /**
     * The end-of-run table of a path: per branch the number of states, the
     * range of t, how many states are stable (no negative eigenvalue) and
     * the largest count of negative eigenvalues; then every event (kind, t,
     * branch, the count before and after). `extra(k)` may add words to event k.
     */
    std::string
    path_summary(const std::vector<PathRow> &                           rows,
                 const std::vector<BifurcationProblem::Event> &         events,
                 const std::function<std::string(unsigned int)> &       extra = {});

    /**
     * The share of a path done at a step, for an ETA: t of a natural-parameter
     * path to t = 1; on the first branch of an arclength path, t/lambda_max
     * when the parameter range ends at a finite positive lambda_max; NaN
     * otherwise (the length of a branch is not known in advance).
     */
    double
    path_fraction(const StepReport &report, const ArclengthSettings &arclength);


    /// What the driver found: one record per located event.
    struct EventRecord
    {
      BifurcationProblem::Event event;
      std::vector<double>       state; ///< U at the event
      std::vector<double>       mode;  ///< null vector (branch points)

      /// For a checkpoint (io/checkpoint.h): every field, bitwise.
      void
      save(io::CheckpointWriter &w) const;
      void
      load(io::CheckpointReader &r);
    };

    class ArclengthContinuation
    {
    public:
      ArclengthContinuation(const ArclengthSettings &settings, const NewtonSettings &newton);

      std::function<void(const std::string &)> progress;

      /**
       * Called at the start of every branch and after every converged step
       * (after problem.converged_step()), where the driver can go on from
       * what save() writes: the application writes its checkpoint then
       * (io/checkpoint.h), the driver's state with its own.
       */
      std::function<void()> checkpoint;

      /// The driver's state at the last checkpoint() call.
      void
      save(io::CheckpointWriter &w) const;

      /**
       * Restore a state save() wrote: the next run() goes on from it (the
       * starting point and the steps, events and branches before it are not
       * done again, nor reported), and reaches what an uninterrupted run
       * reaches.
       */
      void
      load(io::CheckpointReader &r);

      /**
       * Follow the branch through (U, lambda), which must be (nearly) a
       * solution, then every branch switched to at a located simple branch
       * point (up to maximum_branches). Reports every converged state
       * through problem.converged_step() with its branch id (0: the first)
       * and stability count. Returns the located events.
       */
      std::vector<EventRecord>
      run(BifurcationProblem &problem, Vector<double> &U, double lambda);

      /**
       * Locate a critical point by Newton on the augmented system from a
       * guess (U, lambda) and a mode estimate, without a path to it: the
       * step of a critical curve, where the guess is the critical point at
       * the previous value of a second parameter. Reports it through
       * problem.located_event() (branch 0) and returns it; event.located_by_newton
       * is false, with the reason in event.message, if Newton failed.
       * n_negative_after is the count at the located point's last
       * factorization: on a stable branch it is 0 or 1 (the critical
       * eigenvalue's sign is round-off there); more means another mode
       * became critical first. relative_tolerance: of the located lambda
       * (critical_point.h; a curve needs far less than the 1e-13 of events);
       * resolution_fraction: CriticalPointSettings::resolution_fraction.
       */
      EventRecord
      locate_from(BifurcationProblem &  problem,
                  const Vector<double> &U,
                  double                lambda,
                  bool                  fold,
                  const Vector<double> &mode,
                  double                relative_tolerance  = 1e-13,
                  double                resolution_fraction = 0);

    private:
      struct State
      {
        Vector<double> U;
        double         lambda     = 0;
        Vector<double> tU;             ///< tangent, U part
        double         tlambda    = 0; ///< tangent, lambda part
        int            n_negative = -1;
        unsigned int   depth      = 0; ///< 0 the first branch, k+1 switched from depth k
        unsigned int   branch     = 0; ///< of a switch start: the branch it leaves
        double         sign       = 0; ///< of a switch start: +1 along +phi, -1 along -phi
        /// analyse() took the count from the predictor's factorization (correct()).
        bool factorized_at_predictor = false;
      };

      /// Where the run is: everything a resumed run needs to go on (save(), load()).
      struct Progress
      {
        std::vector<EventRecord> events;
        std::vector<State>       switches; ///< branch starts queued, depth first
        /// lambda of the first point of the +phi branch of each switch (mirror images).
        std::map<std::pair<unsigned int, double>, double> plus_lambda;
        unsigned int step       = 0;
        unsigned int branch     = 0;                 ///< being followed
        std::size_t  q          = no_switch;         ///< its entry in switches (no_switch: branch 0)
        std::size_t  queued     = 0;                 ///< switches.size() when it started
        bool         may_switch = false;
        State        s;                              ///< its last converged state
        double       ds = 0;                         ///< the next step length
        unsigned int k  = 0;                         ///< steps taken on it
        /// The next corrector starts from the factorization at s (at_state):
        /// a resumed run makes it again there.
        bool         chord_from_state = false;
        static constexpr std::size_t no_switch = static_cast<std::size_t>(-1);
      };
      Progress at;
      bool     resume = false; ///< load() was called: run() goes on from `at`

      ArclengthSettings settings;
      NewtonSettings    newton;
      double            theta = 1;
      Vector<double>    mask;
      unsigned int      factorizations = 0; ///< setup_jacobian calls made by the driver
      /**
       * A state correct() reached by one Newton step from a predictor that
       * passed the stopping test, with the factorization at the predictor
       * (still the problem's) and J^-1 dR/dlambda there: analyse() of that
       * state takes its count and tangent from them.
       */
      struct PredictorFactorization
      {
        Vector<double> U;
        double         lambda = 0;
        Vector<double> J_inv_R_lambda;
        bool           valid = false;
      } at_predictor;
      /**
       * The factorization analyse() made at a converged state (and J^-1
       * dR/dlambda there), while the driver has made no other since
       * (factorizations unchanged): the next step's corrector starts with
       * chord steps on it (settings.reuse_factorization).
       */
      struct StateFactorization
      {
        Vector<double> U;
        Vector<double> J_inv_R_lambda;
        unsigned int   factorizations = 0; ///< the driver's count after it
        bool           valid          = false;
        /// Whether it is of state s and still in place.
        bool
        of(const State &s, unsigned int count) const;
      } at_state;
      bool              stopped = false;    ///< the first branch stopped at its first event
      /// Branches that ended before their target (minimum step, failed switch): the run fails.
      std::vector<std::string> incomplete;

      void
      say(const std::string &s) const;
      /// The mode mask and the arclength weight theta of this problem.
      void
      set_mask_and_weight(BifurcationProblem &problem);
      /// Converge the augmented system from the predictor; throws NewtonFailure.
      NewtonResult
      correct(BifurcationProblem &problem,
              State &             s,
              const Vector<double> &direction_U,
              double               direction_lambda,
              const Vector<double> &predictor_U,
              double               predictor_lambda,
              bool                 from_state_factorization = false);
      /// settings.reuse_factorization, where the problem allows it.
      bool
      reuse_factorization(const BifurcationProblem &problem) const;
      /// Factorize at s, with J^-1 dR/dlambda there (at_state).
      void
      factorize_state(BifurcationProblem &problem, const State &s);
      /// Factorize at s, set its stability count and its unit tangent, oriented along (oU, ol).
      void
      analyse(BifurcationProblem &problem, State &s, const Vector<double> *oU, double ol);
      /// Follow one branch from s (already analysed); appends events, queues switches.
      void
      follow(BifurcationProblem &      problem,
             State                     s,
             unsigned int              branch,
             bool                      may_switch,
             std::vector<EventRecord> &events,
             std::vector<State> &      switches,
             unsigned int &            step,
             double                    ds,
             unsigned int              k0);
      /**
       * The crossings of the stability count between s and next (a step of
       * length ds along s's tangent): each isolated by bisection of the count
       * until it changes by one, then located by Newton on the augmented
       * system (or, failing that, by bisection to the tolerance). Returns
       * true if the run is to stop here (the first event located and
       * stop_at_first_event).
       */
      bool
      locate_events(BifurcationProblem &      problem,
                    const State &             s,
                    double                    ds,
                    const State &             next,
                    unsigned int              branch,
                    bool                      may_switch,
                    std::vector<EventRecord> &events,
                    std::vector<State> &      switches);
      /// Converge and analyse the point at arclength sigma along s's tangent (near sigma if exactly singular).
      bool
      point_on_step(BifurcationProblem &problem,
                    const State &       s,
                    double              sigma_lo,
                    double              sigma_hi,
                    State &             mid,
                    double &            sigma);
      double
      norm2(const Vector<double> &v) const;
      double
      dot(const Vector<double> &a, const Vector<double> &b) const;
    };
  } // namespace solvers
} // namespace cosmo

#endif

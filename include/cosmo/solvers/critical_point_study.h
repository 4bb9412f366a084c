#ifndef cosmo_solvers_critical_point_study_h
#define cosmo_solvers_critical_point_study_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/parameters.h>
#include <cosmo/solvers/arclength.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

/**
 * A study of critical points (doc/theory-continuation.md 7): the first
 * critical point of the first branch (the critical growth of a plate, the
 * critical twist of a strip, ...) at every value of a swept entry (section
 * Parameter sweep), in one of two ways:
 *
 * - independent runs: each value's path from its start to its first event;
 * - a critical curve ('Parameter sweep / Critical curve = true'): from the
 *   second value on, the critical points found so far predict the next one
 *   (CriticalCurvePredictor) and Newton on the minimally augmented system
 *   corrects it, with no path. A point where that fails, or where another
 *   mode has become critical first, is run independently; where the
 *   critical mode changes (the application's classification of the mode),
 *   the new mode is continued back to the previous value and the
 *   codimension-2 point where the two curves cross is estimated.
 *
 * Writes sweep.csv (and critical_curve.csv for a curve), one row per value,
 * rewritten after every point, each point's run in point-NN/, and
 * sweep-log.txt. An application says what one run is (CriticalPointRun) and
 * how it classifies a mode; the study is the same for all.
 */
namespace cosmo
{
  namespace solvers
  {
    using namespace dealii;

    /// A guess of a critical point: the next point of a critical curve.
    struct CriticalGuess
    {
      Vector<double> U, mode;
      double         t    = 0;
      bool           fold = false;
      /// The guess is the previous value's critical point itself (no
      /// extrapolation yet): converge R = 0 at fixed t first, since its
      /// residual is that of the change of the swept entry, and Newton on
      /// the augmented system from it can wander off (measured: a 10% change
      /// of axial growth sent the load to -11).
      bool           equilibrate = false;
    };

    /**
     * Locate the critical point of `problem` from the guess by Newton on the
     * augmented system (driver.locate_from at 1e-10 relative, a thousandth
     * of the 1e-7 a curve owes the independent study, or a tenth of the
     * point's round-off resolution R, whichever is larger: the located load
     * scatters by R/12 to R/26 in floating point, doc/theory-continuation.md
     * 4, so iterating further chases round-off). Throws
     * io::RunFailure if Newton fails or if another mode is critical below
     * the located point (the critical mode changed). The located point has
     * been reported through problem.located_event().
     */
    EventRecord
    locate_continued_critical_point(ArclengthContinuation &driver,
                                    BifurcationProblem &   problem,
                                    const CriticalGuess &  guess,
                                    const NewtonSettings & newton);

    /**
     * A study's point whose critical point is continued from a guess: it
     * is located (locate_continued_critical_point, with a driver of the
     * run's settings and its progress lines), `take_state` is given the
     * located state (the application keeps it as its solution, and says
     * what the report may reuse), and it is reported as the path's only
     * converged state: written whatever 'Steps between outputs'.
     */
    void
    locate_and_report_continued_critical_point(BifurcationProblem &                             problem,
                                               const CriticalGuess &                            guess,
                                               const ArclengthSettings &                        arclength,
                                               const NewtonSettings &                           newton,
                                               const std::function<void(const std::string &)> & progress,
                                               const std::function<void(const Vector<double> &)> &take_state);

    /// One run of a study, as the study sees it.
    class CriticalPointRun
    {
    public:
      virtual ~CriticalPointRun() = default;
      /// The run is to locate its critical point from g (no path).
      virtual void
      start_from_critical_point(const CriticalGuess &g) = 0;
      /// Run, writing the run's output directory; io::RunFailure if it fails.
      virtual void
      run(const io::RunOptions &options, const ParameterHandler &prm) = 0;
      /// The events the run located, in order.
      virtual const std::vector<EventRecord> &
      located_events() const = 0;
      virtual std::size_t
      n_dofs() const = 0;
      /// Factorizations of the Jacobian the run made (the cost of a point).
      virtual unsigned int
      factorizations() const = 0;
      /// The values of the study's mode columns for a critical mode.
      virtual std::vector<double>
      classify_mode(const Vector<double> &mode) const = 0;
      /// The values of the study's further columns at the critical point.
      virtual std::vector<double>
      further_columns(const EventRecord &critical_point) const = 0;
    };

    /**
     * The run of an application's problem class, which has
     * parse_parameters(prm), start_from_critical_point(g), run(options,
     * prm), event_records(), n_unknowns(), timings(),
     * classify_critical_mode(mode) and critical_point_columns(record).
     */
    template <class Problem>
    class CriticalPointRunOf : public CriticalPointRun
    {
    public:
      explicit CriticalPointRunOf(ParameterHandler &prm)
      {
        problem.parse_parameters(prm);
      }
      void
      start_from_critical_point(const CriticalGuess &g) override
      {
        problem.start_from_critical_point(g);
      }
      void
      run(const io::RunOptions &options, const ParameterHandler &prm) override
      {
        problem.run(options, prm);
      }
      const std::vector<EventRecord> &
      located_events() const override
      {
        return problem.event_records();
      }
      std::size_t
      n_dofs() const override
      {
        return problem.n_unknowns();
      }
      unsigned int
      factorizations() const override
      {
        return problem.timings().calls("factorization");
      }
      std::vector<double>
      classify_mode(const Vector<double> &mode) const override
      {
        return problem.classify_critical_mode(mode);
      }
      std::vector<double>
      further_columns(const EventRecord &e) const override
      {
        return problem.critical_point_columns(e);
      }

    private:
      Problem problem;
    };

    /// What an application tells the study.
    struct CriticalPointStudy
    {
      std::string application;
      /// Columns classifying the critical mode (a change of any value is a
      /// change of the critical mode), e.g. mode_number, mode_out_of_plane.
      std::vector<std::string> mode_columns;
      /// Further columns at the critical t, e.g. closed forms.
      std::vector<std::string> further_columns;
      /// The mode's classification in words, for the log.
      std::function<std::string(const std::vector<double> &)> describe_mode;
      /**
       * The runs follow their paths by the library's sections 'Path
       * following' and 'Arclength continuation': the study requires Method =
       * arclength and sets 'Stop at first event' (plate_rod, which has its
       * own 'Growth path', does not).
       */
      bool arclength_sections = true;
      /// A run of the problem that prm describes (parsed; InputError if refused).
      std::function<std::unique_ptr<CriticalPointRun>(ParameterHandler &)> make_run;
      /// The application's own declarations (its declare_parameters): each
      /// value runs on a copy of the study's parameters (io/parameter_copy.h).
      std::function<void(ParameterHandler &)> declare_parameters;
    };

    /**
     * Run the study (the sweep must be enabled). A point that fails is
     * recorded (converged = 0) and the study goes on; values refused by the
     * problem end it with io::InputError, values without a located critical
     * point with io::RunFailure (exit status 2), after every other point ran.
     */
    void
    run_critical_point_study(ParameterHandler &              prm,
                             const io::RunOptions &          options,
                             const io::ParameterSweep &      sweep,
                             const CriticalPointStudy &      study);
  } // namespace solvers
} // namespace cosmo

#endif

#ifndef cosmo_assembly_reduced_rod_records_h
#define cosmo_assembly_reduced_rod_records_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/rod_strain_control.h>
#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/solvers/arclength.h>

#include <array>
#include <functional>
#include <vector>

namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    /// The rod-level quantities of a converged state.
    struct ReducedRodState
    {
      double                t      = 0;
      double                energy = 0;        ///< Psi, energy per unit reference length
      std::array<double, 6> strains{};         ///< nu1..3, kappa1..3
      std::array<double, 6> resultants{};      ///< n1..3, m1..3 = dPsi/d(strains)
      std::array<double, 6> multipliers{};     ///< of the six gauge constraints
      FullMatrix<double>    stiffness;         ///< 6x6 d(n,m)/d(nu,kappa)
      int                   n_negative = -1;   ///< negative Hessian eigenvalues (constrained space)
      double                min_elastic_J = 0; ///< smallest det Fe (bulk problems)
    };

    /**
     * What a reduced rod's run has seen: every converged state at rod level
     * (the path, for the run's summary lines and the tests' branches) and the
     * located events with their strains, state and mode (a study's critical
     * points). They go into the run's checkpoints, so a resumed run reports
     * the whole path.
     */
    class ReducedRodRecords
    {
    public:
      using Event = solvers::BifurcationProblem::Event;

      /// A converged state of a run, at rod level.
      struct PathPoint
      {
        double                t;
        unsigned int          branch;
        double                energy;
        int                   n_negative;
        std::array<double, 6> strains;
        std::array<double, 6> resultants;
      };
      /// Every converged state of a run, in order (record_state()).
      const std::vector<PathPoint> &
      path() const
      {
        return visited;
      }
      /// Events located by arclength continuation.
      const std::vector<Event> &
      events() const
      {
        return located_events;
      }
      /// The strains at each event.
      const std::vector<std::array<double, 6>> &
      event_strains() const
      {
        return strains_at_events;
      }
      /// The events with the state and mode at each (a study's critical points).
      const std::vector<solvers::EventRecord> &
      event_records() const
      {
        return records;
      }

    protected:
      /// Append a converged state to path().
      void
      record_state(const solvers::StepReport &report, const ReducedRodState &s)
      {
        visited.push_back({report.t, report.branch, s.energy, s.n_negative, s.strains, s.resultants});
      }
      /// Append a located event, with the strains, state U and mode (may be null) there.
      void
      record_event(const Event &                e,
                   const std::array<double, 6> &strains,
                   const Vector<double> &       U,
                   const Vector<double> *       mode);
      /// The records, into a checkpoint and back.
      void
      save_records(io::CheckpointWriter &w) const;
      void
      load_records(io::CheckpointReader &r);

      std::vector<PathPoint>             visited;
      std::vector<Event>                 located_events;
      std::vector<std::array<double, 6>> strains_at_events;
      std::vector<solvers::EventRecord>  records;
    };

    /**
     * The rod-level keys of summary.json, shared by the applications:
     * energy, strains, resultants, multipliers, held resultants (resultant
     * control), stiffness (and its order), stability, events (kind, lambda,
     * branch, counts, eigenvalue, strains; `event_extra(k, entry)` may add
     * keys to event k).
     */
    void
    add_state_to_summary(io::JSON &                                           j,
                         const ReducedRodState &                              s,
                         const RodStrainControl &                             control,
                         const ReducedRodRecords &                            records,
                         const std::function<void(unsigned int, io::JSON &)> &event_extra = {});
  } // namespace assembly
} // namespace cosmo

#endif

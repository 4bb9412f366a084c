#ifndef cosmo_io_postprocessors_h
#define cosmo_io_postprocessors_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/base/plugins.h>
#include <cosmo/io/checkpoint.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

/**
 * Postprocessors (as ASPECT's Postprocess::Manager): registered plugins that
 * the continuation drivers call at every converged state and every located
 * event, and once at the end of the run. The run's own outputs are
 * postprocessors too: 'steps table' (steps.csv) and 'fields' (the VTU files
 * and their PVD collections), built in and selected by default, asking the
 * application what it shows of a state through io::StateSource. Each is one
 * file with
 * COSMO_REGISTER_PLUGIN(io::Postprocessor, ...), in the library, in an
 * application or in a user's shared library loaded through 'Additional
 * shared libraries' (io/shared_libraries.h). The run's file selects them in
 * section 'Postprocess', entry 'List of postprocessors'; each declares its
 * own entries in its own subsection of 'Postprocess' (named as registered).
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    /**
     * What an application shows of its converged states, for the built-in
     * postprocessors: steps.csv's columns and the last state's values, and
     * its fields written as VTU files. Every continuation problem is one
     * (solvers::ContinuationProblem); the defaults show nothing.
     */
    class StateSource
    {
    public:
      virtual ~StateSource() = default;
      /// steps.csv's columns: name and unit ("" for none), in order.
      virtual std::vector<std::pair<std::string, std::string>>
      quantity_columns() const
      {
        return {};
      }
      /// The last converged state's value of each column.
      virtual std::vector<double>
      quantity_values() const
      {
        return {};
      }
      /**
       * Writes the last converged state's fields into the run's directory,
       * one file per kind ("plate", "rim", ...) named `kind-tag.vtu` (or
       * .pvtu on a distributed mesh: collective then), and returns each kind
       * with the file name written.
       */
      virtual std::vector<std::pair<std::string, std::string>>
      write_fields(const std::string & /*tag*/) const
      {
        return {};
      }
      /**
       * Writes the fields of a located event's state U, and of its critical
       * mode if there is one, into the run's directory (e.g. event-01.vtu
       * and event-01-mode.vtu; `tag` numbers the run's events from 01), and
       * returns each kind with the file name written.
       */
      virtual std::vector<std::pair<std::string, std::string>>
      write_event_fields(const std::string & /*tag*/,
                         const Vector<double> & /*U*/,
                         const Vector<double> * /*mode*/) const
      {
        return {};
      }
    };

    /// What a postprocessor sees of a state.
    struct PostprocessedState
    {
      enum class Kind
      {
        converged_state,
        located_event,
        /// The last converged state of a path or branch that ended before its
        /// target (the run then fails), already given to execute(): it goes to
        /// Postprocessor::path_ended(), never to execute().
        path_end
      };
      Kind         kind = Kind::converged_state;
      unsigned int step = 0, branch = 0;
      /// The load parameter.
      double t = 0;
      /// Negative eigenvalues of the Hessian; -1 where not counted.
      int n_negative = -1;
      /// The event's name (located events), e.g. "branch point", "fold".
      std::string event;
      /// The unknowns (the application's DoF vector at this state).
      const Vector<double> *unknowns = nullptr;
      /// The critical mode at a located branch point (null otherwise).
      const Vector<double> *mode = nullptr;
      /// The application's quantities of this state by name: the columns
      /// of its steps.csv row (converged states; empty for events).
      std::vector<std::pair<std::string, double>> quantities;
      /// The run's output directory (each rank has its own under mpirun).
      std::string output_directory;
      /// The last state of the run's path (its target, a branch's end).
      bool final = false;
      /// The run stops at its first event (a threshold run): this state is
      /// only on the way there ('fields' writes none such by default).
      bool toward_first_event = false;
      /// The application, for what it shows of the state (null: nothing).
      const StateSource *source = nullptr;

      /// The quantity named `name`, NaN if the application has none so named.
      double
      quantity(const std::string &name) const;
    };

    class Postprocessor
    {
    public:
      virtual ~Postprocessor() = default;
      /// Reads its entries (in its own subsection of 'Postprocess', entered).
      virtual void
      parse_parameters(ParameterHandler &)
      {}
      /// Called at every converged state and every located event.
      virtual void
      execute(const PostprocessedState &state) = 0;
      /**
       * Called when a path or branch ends before its target, with its last
       * converged state (given to execute() before): what a postprocessor
       * writes of the last state only is written now, as the run fails.
       */
      virtual void
      path_ended(const PostprocessedState & /*last*/)
      {}
      /// Called once when the run's path is complete (not after a failure).
      virtual void
      finish(const std::string & /*output_directory*/)
      {}
      /// What it has gathered so far, for the run's checkpoint ...
      virtual void
      save(CheckpointWriter &) const
      {}
      /// ... and back, rewriting its files as they were then.
      virtual void
      load(CheckpointReader &, const std::string & /*output_directory*/)
      {}
    };

    /// The postprocessors a run selected, called in the order listed.
    class Postprocessors
    {
    public:
      /// Section 'Postprocess': the list and every registered one's subsection.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      bool
      empty() const
      {
        return selected.empty();
      }
      void
      execute(const PostprocessedState &state);
      void
      finish(const std::string &output_directory);
      /// Every selected one's state, by name, for the run's checkpoint.
      void
      save(CheckpointWriter &w) const;
      void
      load(CheckpointReader &r, const std::string &output_directory);

    private:
      std::vector<std::pair<std::string, std::unique_ptr<Postprocessor>>> selected;
    };
  } // namespace io

  namespace plugins
  {
    extern template class Registry<io::Postprocessor>;
  }
} // namespace cosmo

#endif

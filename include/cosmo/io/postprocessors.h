#ifndef cosmo_io_postprocessors_h
#define cosmo_io_postprocessors_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/base/plugins.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

/**
 * Postprocessors (as ASPECT's Postprocess::Manager): registered plugins that
 * the continuation drivers call at every converged state and every located
 * event, and once at the end of the run. Each is one file with
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

    /// What a postprocessor sees of a state.
    struct PostprocessedState
    {
      enum class Kind
      {
        converged_state,
        located_event
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
      /// The application's quantities of this state by name: the columns
      /// of its steps.csv row (converged states; empty for events).
      std::vector<std::pair<std::string, double>> quantities;
      /// The run's output directory (each rank has its own under mpirun).
      std::string output_directory;

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
      /// Called once when the run's path is complete (not after a failure).
      virtual void
      finish(const std::string & /*output_directory*/)
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

#ifndef cosmo_io_parameters_h
#define cosmo_io_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/output.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

/**
 * Parameter handling shared by every application: the command-line contract
 * (doc/specification/architecture.md), parsing with errors that name the file, the entry and
 * the allowed values, and the exit statuses (0 success, 1 bad input,
 * 2 a run that could not proceed, e.g. continuation below its minimum step).
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    /// Bad input detected after parsing (a value that fits its pattern but not the problem).
    class InputError : public std::runtime_error
    {
    public:
      InputError(const std::string &section,
                 const std::string &entry,
                 const std::string &value,
                 const std::string &allowed);
    };

    /// A run that cannot proceed (nonlinear failure below the minimum step, ...).
    class RunFailure : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    class Postprocessors;

    struct RunOptions
    {
      std::string parameter_file;
      bool        quiet = false;
      /// `--resume DIR`: continue the run whose checkpoint is in DIR (io/checkpoint.h).
      std::string resume_directory;
      /// The postprocessors the file selects ('Postprocess', io/postprocessors.h),
      /// parsed by run_application; an application attaches them to its problem.
      std::shared_ptr<Postprocessors> postprocessors;
    };

    struct ApplicationInfo
    {
      std::string name;
      std::string summary;
    };

    /**
     * The whole command-line contract of an application: `app file.prm`,
     * `--help`, `--version`, `--print-parameters [prm|json|xml]`, `--quiet`,
     * `--resume DIR` (DIR/parameters.prm, output into DIR).
     * `declare` declares all parameters, `run` parses them from the handler
     * (already filled from the file) and runs. Returns the exit status.
     * Every application has, besides its own, the top-level entry
     * 'Additional shared libraries' (loaded before anything is declared,
     * io/shared_libraries.h) and the section 'Postprocess'
     * (io/postprocessors.h, parsed into RunOptions::postprocessors).
     */
    int
    run_application(int                                                       argc,
                    char **                                                   argv,
                    const ApplicationInfo &                                   info,
                    const std::function<void(ParameterHandler &)> &           declare,
                    const std::function<void(ParameterHandler &, const RunOptions &)> &run);

    /// Parse a .prm file; errors become InputError-style messages with status 1.
    void
    parse_parameter_file(ParameterHandler &prm, const std::string &file);

    /**
     * The start of every run's output (doc/specification/architecture.md): create the
     * directory, write the parameters as read (parameters.prm, atomically)
     * and open the log (log_name in it, flushed line by line). `resume`:
     * continue the run there (its files kept, the log appended to).
     */
    std::unique_ptr<RunLog>
    open_run_directory(const std::string &     directory,
                       const ParameterHandler &prm,
                       bool                    quiet,
                       const std::string &     log_name = "log.txt",
                       bool                    resume   = false);

    /// Comma list of doubles of fixed length, with a clear error.
    std::vector<double>
    get_double_list(const ParameterHandler &prm,
                    const std::string &     entry,
                    unsigned int            n,
                    const std::string &     section);

    /// 'From, To, Number of values' (a table's axis, a study's range).
    struct Range
    {
      double       from = 0, to = 0;
      unsigned int n    = 1;
      /// The i-th of n equally spaced values (from if n = 1).
      double
      value(const unsigned int i) const
      {
        return n == 1 ? from : from + (to - from) * i / (n - 1);
      }
    };

    /// The entry as a Range: two finite numbers and a whole number of values
    /// in [1, 1e9] (a clear InputError otherwise, not an overflow).
    Range
    get_range(const ParameterHandler &prm, const std::string &entry, const std::string &section);
  } // namespace io
} // namespace cosmo

#endif

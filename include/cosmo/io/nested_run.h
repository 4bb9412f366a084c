#ifndef cosmo_io_nested_run_h
#define cosmo_io_nested_run_h

#include <cosmo/io/parameter_copy.h>
#include <cosmo/io/parameters.h>

#include <functional>
#include <string>

/**
 * One application's run inside another's process: the rod computes the
 * part-1 sections its law needs from a rod_cross_section parameter file,
 * so that one command goes from a grown section to the whole rod. The
 * nested run writes its usual files into a directory of the calling run
 * and is reused there while its parameters are the same (a cache keyed by
 * every parameter's value, written only once the run has finished, so that
 * a killed run is computed again).
 */
namespace cosmo
{
  namespace io
  {
    struct NestedRun
    {
      std::string directory; ///< where its output is
      bool        reused = false; ///< an earlier run's output with the same parameters
    };

    /**
     * Run `run` on `parameter_file` (declared by `declare` as
     * run_application declares it), its 'Output directory' set to
     * `directory`, quietly. io::InputError naming `section`/`entry` (the
     * caller's entry that names the file) if the file is not a valid one;
     * io::RunFailure if the nested run fails.
     */
    NestedRun
    run_nested(const DeclareParameters &                                           declare,
               const std::function<void(ParameterHandler &, const RunOptions &)> &run,
               const std::string &                                                 parameter_file,
               const std::string &                                                 directory,
               const std::string &                                                 section,
               const std::string &                                                 entry);
  } // namespace io
} // namespace cosmo

#endif

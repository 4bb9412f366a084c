#ifndef cosmo_io_shared_libraries_h
#define cosmo_io_shared_libraries_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

/**
 * Extension without forking (doc/cookbook.md, "Load a plugin at run time"):
 * the top-level entry 'Additional shared libraries' of every application
 * names shared libraries, built against the installed library
 * (find_package(cosmo)), that are loaded before the parameters are declared.
 * Their COSMO_REGISTER_PLUGIN lines then add growth laws, plate models,
 * section shapes or postprocessors to the registries, and so to the values
 * of the entries that select them, exactly as a file compiled into the
 * application would (as ASPECT's entry of the same name).
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    /// The entry's name, at the top level of every application's file.
    inline const std::string shared_libraries_entry = "Additional shared libraries";

    /// Declares 'Additional shared libraries' (run_application does it).
    void
    declare_shared_libraries_entry(ParameterHandler &prm);

    /**
     * Reads 'Additional shared libraries' alone from `parameter_file` (the
     * rest of the file is read later, when every plugin is registered) and
     * loads each library (a relative path from the working directory, as
     * the shell resolves it). A library that cannot be loaded, or that
     * registers a name already registered, is an io::InputError naming the
     * entry, the library and the loader's reason. Returns the libraries
     * loaded. A file that cannot be read loads nothing: its error is
     * reported by the full reading that follows.
     */
    std::vector<std::string>
    load_shared_libraries(const std::string &parameter_file);

    /**
     * The parameter file and every file it includes are regular files and
     * none includes itself through a chain (deal.II follows 'include' lines
     * without a guard, to a stack overflow): std::runtime_error naming the
     * file and the chain otherwise. Checked before any reading of the file
     * (source/io/parameters.cc, with parse_parameter_file()).
     */
    void
    check_parameter_file(const std::string &parameter_file);
  } // namespace io
} // namespace cosmo

#endif

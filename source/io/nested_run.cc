#include <cosmo/io/nested_run.h>
#include <cosmo/io/output.h>
#include <cosmo/io/postprocessors.h>
#include <cosmo/io/shared_libraries.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace cosmo
{
  namespace io
  {
    namespace
    {
      /// The text of a file ("" if it cannot be read).
      std::string
      text_of(const std::filesystem::path &file)
      {
        std::ifstream     in(file);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
      }
    } // namespace

    NestedRun
    run_nested(const DeclareParameters &                                           declare,
               const std::function<void(ParameterHandler &, const RunOptions &)> &run,
               const std::string &                                                 parameter_file,
               const std::string &                                                 directory,
               const std::string &                                                 section,
               const std::string &                                                 entry)
    {
      ParameterHandler prm;
      RunOptions       options;
      options.parameter_file = parameter_file;
      options.quiet          = true;
      try
        {
          load_shared_libraries(parameter_file);
          declare_application_parameters(prm, declare);
          parse_parameter_file(prm, parameter_file);
          options.postprocessors = std::make_shared<Postprocessors>();
          options.postprocessors->parse_parameters(prm);
        }
      catch (std::exception &e)
        {
          throw InputError(section, entry, parameter_file, std::string("a valid parameter file: ") + e.what());
        }
      prm.enter_subsection("Output");
      prm.set("Output directory", directory);
      prm.leave_subsection();
      // The key: every value, as a run of these parameters would read them.
      std::ostringstream key;
      prm.print_parameters(key, ParameterHandler::ShortPRM);
      const std::filesystem::path done = std::filesystem::path(directory) / "finished-parameters.prm";
      if (std::filesystem::exists(done) && text_of(done) == key.str())
        return {directory, true};
      std::filesystem::remove(done);
      try
        {
          run(prm, options);
          options.postprocessors->finish(directory);
        }
      catch (InputError &e)
        {
          throw InputError(section, entry, parameter_file, std::string("a valid parameter file: ") + e.what());
        }
      catch (RunFailure &e)
        {
          throw RunFailure("the run of " + parameter_file + " into " + directory + " failed: " + e.what());
        }
      write_file_atomically(done.string(), [&](std::ostream &out) { out << key.str(); });
      return {directory, false};
    }
  } // namespace io
} // namespace cosmo

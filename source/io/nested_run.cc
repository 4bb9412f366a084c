#include <cosmo/io/nested_run.h>
#include <cosmo/io/output.h>
#include <cosmo/io/postprocessors.h>
#include <cosmo/io/shared_libraries.h>

#include <filesystem>
#include <functional>
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

      /// For every value of the printed parameters that names a readable
      /// file (a section's gmsh .geo, a law's summary.json), a line with its
      /// size and a hash of its content: an edited file is a new key, so a
      /// cached result is never reused for the file it was not computed from.
      std::string
      named_files(const std::string &printed)
      {
        std::istringstream lines(printed);
        std::ostringstream out;
        for (std::string line; std::getline(lines, line);)
          {
            const auto equals = line.find('=');
            if (line.find("set ") == std::string::npos || equals == std::string::npos)
              continue;
            std::string value = line.substr(equals + 1);
            value.erase(0, value.find_first_not_of(' '));
            value.erase(value.find_last_not_of(' ') + 1);
            std::error_code error;
            if (value.empty() || !std::filesystem::is_regular_file(value, error))
              continue;
            const std::string content = text_of(value);
            out << "# file " << value << ": " << content.size() << " bytes, hash "
                << std::hash<std::string>{}(content) << "\n";
          }
        return out.str();
      }

      /**
       * The format of what the callers read of a nested run (summary.json,
       * sweep.csv, table.h5, outline.csv): a result written by a suite whose
       * outputs differ is computed again, not reused. 2: outline.csv with the
       * section's stress linearized in the strains.
       */
      constexpr unsigned int output_format = 2;
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
      key << named_files(key.str()) << "# outputs of format " << output_format << "\n";
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

#include <cosmo/base/plugins.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/shared_libraries.h>

#include <dlfcn.h>

#include <filesystem>

namespace cosmo
{
  namespace io
  {
    void
    declare_shared_libraries_entry(ParameterHandler &prm)
    {
      prm.declare_entry(shared_libraries_entry, "", Patterns::List(Patterns::FileName()),
                        "Shared libraries to load before the parameters are read, separated by "
                        "','; each registers its plugins (growth laws, plate models, section "
                        "shapes, postprocessors) with COSMO_REGISTER_PLUGIN, which then become "
                        "values of the entries that select them (doc/cookbook.md). A relative "
                        "path is taken from the working directory.");
    }

    std::vector<std::string>
    load_shared_libraries(const std::string &parameter_file)
    {
      ParameterHandler prm;
      declare_shared_libraries_entry(prm);
      try
        {
          check_parameter_file(parameter_file);
          prm.parse_input(parameter_file, "", /*skip_undefined=*/true, /*assert_all_set=*/false);
        }
      catch (...)
        {
          return {}; // reported by the full reading (parse_parameter_file)
        }
      const std::string text = prm.get(shared_libraries_entry);
      std::vector<std::string> loaded;
      for (const std::string &name : Utilities::split_string_list(text, ','))
        {
          if (name.empty())
            continue;
          // dlopen looks a name without '/' up in the system's directories:
          // a path is what the user means.
          const std::string path = name.find('/') == std::string::npos ? "./" + name : name;
          const std::size_t errors_before = plugins::registration_errors().size();
          if (dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL) == nullptr)
            {
              const char *why = dlerror();
              throw InputError("top level", shared_libraries_entry, text,
                               "the library '" + name + "' could not be loaded (" +
                                 (why ? std::string(why) : std::string("no reason given")) + ")");
            }
          const auto &errors = plugins::registration_errors();
          if (errors.size() > errors_before)
            throw InputError("top level", shared_libraries_entry, text,
                             "the library '" + name + "' registers a name already taken: " +
                               errors[errors_before] + " (choose another name)");
          loaded.push_back(name);
        }
      return loaded;
    }
  } // namespace io
} // namespace cosmo

#include <cosmo/config.h>
#include <cosmo/io/checkpoint.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace cosmo
{
  namespace io
  {
    namespace
    {
      const std::string magic          = "cosmo checkpoint\n";
      // 2: the study's parameters are the file's (each point runs on a copy),
      // and plate_rod and strip have the law entries (Plate material / Law,
      // Rim rod / Law, Growth kind): a checkpoint of version 1 is refused.
      // 3: steps.csv and the VTU collections are postprocessors' state
      // (io/postprocessors.h), saved by name after the application's.
      // 4: a constitutive table's checkpoint begins with the point header of
      // io/ranks.h, as a study's does (a table's checkpoint of version 3
      // would be misread).
      const std::uint64_t format_version = 4;

      std::string
      trim(const std::string &s)
      {
        const auto b = s.find_first_not_of(" \t");
        if (b == std::string::npos)
          return "";
        const auto e = s.find_last_not_of(" \t");
        return s.substr(b, e - b + 1);
      }

      /// "section/entry" of a line of checkpoint_parameters.
      std::string
      entry_of(const std::string &line)
      {
        return trim(line.substr(0, line.find(" = ")));
      }
    } // namespace

    std::string
    checkpoint_parameters(const ParameterHandler &prm)
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::ShortPRM | ParameterHandler::KeepDeclarationOrder);
      std::istringstream       in(text.str());
      std::vector<std::string> path;
      std::ostringstream       out;
      std::string              line;
      while (std::getline(in, line))
        {
          const std::string l = trim(line);
          if (l.rfind("subsection ", 0) == 0)
            path.push_back(trim(l.substr(11)));
          else if (l == "end")
            {
              if (!path.empty())
                path.pop_back();
            }
          else if (l.rfind("set ", 0) == 0)
            {
              const auto        eq    = l.find('=');
              const std::string entry = trim(l.substr(4, eq == std::string::npos ? std::string::npos : eq - 4));
              const std::string value = eq == std::string::npos ? "" : trim(l.substr(eq + 1));
              if (entry == "Output directory")
                continue;
              std::string p;
              for (const auto &s : path)
                p += s + "/";
              out << p << entry << " = " << value << "\n";
            }
        }
      return out.str();
    }

    void
    write_checkpoint(const std::string &     directory,
                     const std::string &     application,
                     const std::string &     parameters,
                     const CheckpointWriter &payload)
    {
      CheckpointWriter header;
      header.put(format_version);
      header.put(application);
      header.put(std::string(COSMO_VERSION));
      header.put(parameters);
      // (header.put(payload.bytes()) written in two parts: the same bytes
      // without a copy of the payload)
      header.put(std::uint64_t(payload.bytes().size()));
      write_file_atomically(directory + "/" + checkpoint_name, [&](std::ostream &o) {
        o << magic;
        o.write(header.bytes().data(), header.bytes().size());
        o.write(payload.bytes().data(), payload.bytes().size());
      });
    }

    CheckpointReader
    read_checkpoint(const std::string &directory,
                    const std::string &application,
                    const std::string &parameters)
    {
      const std::string path = directory + "/" + checkpoint_name;
      std::ifstream     in(path, std::ios::binary);
      if (!in)
        throw InputError("command line", "--resume", directory,
                         "a run directory with a checkpoint (" + checkpoint_name +
                           "): there is none, so the run there finished (its summary.json says "
                           "how) or never wrote one");
      std::ostringstream all;
      all << in.rdbuf();
      const std::string bytes = all.str();
      if (bytes.compare(0, magic.size(), magic) != 0)
        throw InputError("command line", "--resume", directory,
                         "a run directory whose " + checkpoint_name + " is a cosmo checkpoint");
      CheckpointReader r(bytes.substr(magic.size()));
      std::string      saved_application, saved_parameters, payload;
      try
        {
          if (r.get_size() != format_version)
            throw std::runtime_error("its format is of another version of cosmo");
          saved_application = r.get_string();
          (void)r.get_string(); // the version that wrote it
          saved_parameters = r.get_string();
          payload          = r.get_string();
        }
      catch (std::exception &e)
        {
          throw InputError("command line", "--resume", directory,
                           "a run directory with a readable checkpoint (" + std::string(e.what()) +
                             ")");
        }
      if (saved_application != application)
        throw InputError("command line", "--resume", directory,
                         "a run directory of " + application + " (its checkpoint is of " +
                           saved_application + ")");
      if (saved_parameters != parameters)
        {
          // Name the first entry that differs (both lists are in declaration order).
          std::istringstream a(saved_parameters), b(parameters);
          std::string        la, lb;
          while (true)
            {
              const bool ga = static_cast<bool>(std::getline(a, la));
              const bool gb = static_cast<bool>(std::getline(b, lb));
              if (!ga || !gb || la != lb)
                {
                  const std::string entry = entry_of(ga ? la : lb);
                  throw InputError(
                    "command line", "--resume", directory,
                    "the parameters its checkpoint was written with: '" + entry + "' was '" +
                      (ga ? trim(la.substr(la.find(" = ") + 3)) : std::string("(absent)")) +
                      "' and is now '" +
                      (gb ? trim(lb.substr(lb.find(" = ") + 3)) : std::string("(absent)")) +
                      "' (resume with the parameters of the interrupted run, or start a new run)");
                }
            }
        }
      return CheckpointReader(payload);
    }

    void
    remove_checkpoint(const std::string &directory)
    {
      std::error_code ec;
      std::filesystem::remove(directory + "/" + checkpoint_name, ec);
    }
  } // namespace io
} // namespace cosmo

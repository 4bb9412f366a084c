#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <cosmo/config.h>
#include <cosmo/io/parameter_copy.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/postprocessors.h>
#include <cosmo/io/shared_libraries.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/sparse_direct.h>

#include <filesystem>
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

namespace cosmo
{
  namespace io
  {
    InputError::InputError(const std::string &section,
                           const std::string &entry,
                           const std::string &value,
                           const std::string &allowed)
      : std::runtime_error("in section '" + section + "', entry '" + entry + "' = '" +
                           value + "': " + allowed)
    {}

    namespace
    {
      /**
       * A parser's message as a user reads it: the property-tree readers name
       * the file '<unspecified file>(N)'; that is line N of the file named
       * around it. Runs of blank lines and trailing space go.
       */
      std::string
      tidy_parser_message(std::string msg)
      {
        const std::string unnamed = "<unspecified file>(";
        for (std::size_t p = msg.find(unnamed); p != std::string::npos; p = msg.find(unnamed))
          {
            const std::size_t close = msg.find(')', p);
            if (close == std::string::npos)
              break;
            msg.replace(p, close + 1 - p, "line " + msg.substr(p + unnamed.size(), close - p - unnamed.size()));
          }
        // One line: newlines and runs of spaces become one space.
        std::string out;
        for (char c : msg)
          {
            if (c == '\n' || c == '\t')
              c = ' ';
            if (!(c == ' ' && (out.empty() || out.back() == ' ')))
              out += c;
          }
        while (!out.empty() && out.back() == ' ')
          out.pop_back();
        return out;
      }

      /**
       * The parameter file and every file it includes ('include name' lines
       * of a .prm, names relative to the working directory as deal.II reads
       * them) are regular files, and no file includes itself through a
       * chain: std::runtime_error naming the file, the line and the chain.
       */
      void
      check_includes(const std::string &file, std::vector<std::string> chain)
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (!fs::is_regular_file(file, ec))
          throw std::runtime_error(
            "the parameter file '" + file + "'" +
            (chain.empty() ? std::string() : " (included from '" + chain.back() + "')") +
            " is not a regular file" + (fs::is_directory(file, ec) ? " (a directory)" : "") +
            ": give a .prm, .json or .xml file");
        const std::string id = fs::weakly_canonical(file, ec).string();
        for (const auto &c : chain)
          if (fs::weakly_canonical(c, ec).string() == id)
            {
              std::string path;
              for (const auto &x : chain)
                path += "'" + x + "' includes ";
              throw std::runtime_error("include cycle in parameter files: " + path + "'" + file +
                                       "' again");
            }
        chain.push_back(file);
        const std::string ext = fs::path(file).extension().string();
        if (ext == ".json" || ext == ".xml")
          return; // no include directive in these formats
        std::ifstream in(file);
        std::string   line;
        while (std::getline(in, line))
          {
            line = line.substr(0, line.find('#'));
            line = Utilities::trim(line);
            if (line.rfind("include ", 0) == 0 || line.rfind("include\t", 0) == 0)
              check_includes(Utilities::trim(line.substr(8)), chain);
          }
      }
    } // namespace

    void
    check_parameter_file(const std::string &file)
    {
      check_includes(file, {});
    }

    void
    parse_parameter_file(ParameterHandler &prm, const std::string &file)
    {
      {
        std::ifstream in(file);
        if (!in)
          throw std::runtime_error("cannot open the parameter file '" + file + "'");
      }
      // deal.II follows 'include' lines itself, without a guard: a file that
      // includes itself recurses until the stack overflows, and a directory
      // opens as an empty file (all defaults). Check both first.
      check_includes(file, {});
      // deal.II's own messages name the file, line, entry and pattern; keep
      // only that part, not the assertion boilerplate around it.
      try
        {
          prm.parse_input(file, "", /*skip_undefined=*/false, /*assert_all_set=*/false);
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream s;
          e.print_info(s);
          throw std::runtime_error("in parameter file '" + file + "': " + tidy_parser_message(s.str()));
        }
      catch (std::exception &e)
        {
          // The XML and JSON readers (boost property trees) throw their own.
          throw std::runtime_error("in parameter file '" + file + "': " + tidy_parser_message(e.what()) +
                                   " (the file is not complete " +
                                   (file.size() > 4 && file.substr(file.size() - 4) == ".xml" ? "XML" : "JSON") +
                                   ")");
        }
    }

    std::unique_ptr<RunLog>
    open_run_directory(const std::string &     directory,
                       const ParameterHandler &prm,
                       const bool              quiet,
                       const std::string &     log_name,
                       const bool              resume)
    {
      std::error_code ec;
      const bool      existed = std::filesystem::exists(directory, ec);
      create_directory(directory);
      // Locked for this run, the earlier run's files moved into previous/.
      claim_run_directory(directory, !existed, resume);
      write_file_atomically(directory + "/parameters.prm", [&](std::ostream &o) {
        prm.print_parameters(o, ParameterHandler::KeepDeclarationOrder | ParameterHandler::PRM);
      });
      return std::make_unique<RunLog>(directory + "/" + log_name, quiet, resume);
    }

    std::vector<double>
    get_double_list(const ParameterHandler &prm,
                    const std::string &     entry,
                    const unsigned int      n,
                    const std::string &     section)
    {
      const std::string text = prm.get(entry);
      std::vector<double> v;
      try
        {
          v = Utilities::string_to_double(Utilities::split_string_list(text, ','));
        }
      catch (...)
        {
          throw InputError(section, entry, text, "expected " + std::to_string(n) +
                                                   " numbers separated by ','");
        }
      if (v.size() != n)
        throw InputError(section, entry, text, "expected " + std::to_string(n) +
                                                 " numbers separated by ','");
      for (const double x : v)
        if (!std::isfinite(x))
          throw InputError(section, entry, text, "expected " + std::to_string(n) +
                                                   " finite numbers separated by ',' (not nan or "
                                                   "inf)");
      return v;
    }

    Range
    get_range(const ParameterHandler &prm, const std::string &entry, const std::string &section)
    {
      const auto r = get_double_list(prm, entry, 3, section);
      if (!(r[2] >= 1 && r[2] <= 1e9 && r[2] == std::floor(r[2])))
        throw InputError(section, entry, prm.get(entry),
                         "From, To, Number of values with a whole number of values from 1 to 1e9");
      Range range;
      range.from = r[0];
      range.to   = r[1];
      range.n    = static_cast<unsigned int>(r[2]);
      return range;
    }

    namespace
    {
      void
      print_usage(const ApplicationInfo &info, std::ostream &out)
      {
        out << info.name << " " << COSMO_VERSION << " -- " << info.summary << "\n\n"
            << "Usage:\n"
            << "  " << info.name << " FILE.prm [--quiet]   run with the parameters in FILE.prm\n"
            << "  " << info.name << " --resume DIR [--quiet]\n"
            << "        continue the interrupted or killed run in DIR from its last checkpoint\n"
            << "        (with DIR/parameters.prm; FILE.prm, if given too, must match it)\n"
            << "  " << info.name << " --print-parameters [prm|json|xml] [FILE.prm]\n"
            << "        print every parameter with its documentation and default, or with\n"
            << "        the values FILE.prm sets (its errors are reported as for a run)\n"
            << "  " << info.name << " --help | --version\n\n"
            << "Exit status: 0 success, 1 bad input (file, entry, value), 2 the run\n"
            << "could not proceed (files written so far are kept and complete),\n"
            << "130/143 interrupted by SIGINT/SIGTERM (go on with --resume DIR).\n";
      }

      /**
       * --print-parameters [FORMAT] [FILE.prm] (args[i] the option): every
       * parameter, with a file its values (defaults for what it leaves
       * unset), as ASPECT's --output-json does. Returns the exit status.
       */
      int
      print_parameters(const std::vector<std::string> &               args,
                       unsigned int                                   i,
                       const ApplicationInfo &                        info,
                       const std::function<void(ParameterHandler &)> &declare_all,
                       RunOptions &                                   options)
      {
        std::string fmt = "prm";
        if (i + 1 < args.size() && (args[i + 1] == "prm" || args[i + 1] == "json" ||
                                    args[i + 1] == "xml"))
          fmt = args[++i];
        else if (i + 1 < args.size() && !args[i + 1].empty() && args[i + 1][0] != '-' &&
                 args[i + 1].find('.') == std::string::npos &&
                 !std::filesystem::exists(args[i + 1]))
          {
            std::cerr << info.name << ": --print-parameters takes prm, json or xml "
                      << "(then, optionally, a parameter file), not '" << args[i + 1]
                      << "'\n";
            return 1;
          }
        if (i + 1 < args.size() && !args[i + 1].empty() && args[i + 1][0] != '-')
          {
            options.parameter_file = args[++i];
            load_shared_libraries(options.parameter_file);
          }
        ParameterHandler prm;
        declare_all(prm);
        if (!options.parameter_file.empty())
          parse_parameter_file(prm, options.parameter_file);
        ParameterHandler::OutputStyle style =
          fmt == "json" ? ParameterHandler::JSON :
          fmt == "xml"  ? ParameterHandler::XML :
                          ParameterHandler::KeepDeclarationOrder | ParameterHandler::PRM;
        prm.print_parameters(std::cout, style);
        return 0;
      }

      /**
       * The command line: an exit status to return at once (--help,
       * --version, --print-parameters, a usage error), or none, with
       * `options` filled, for a run.
       */
      std::optional<int>
      read_command_line(const std::vector<std::string> &               args,
                        const ApplicationInfo &                        info,
                        const std::function<void(ParameterHandler &)> &declare_all,
                        RunOptions &                                   options)
      {
        for (unsigned int i = 0; i < args.size(); ++i)
          {
            const std::string &a = args[i];
            if (a == "--help" || a == "-h")
              {
                print_usage(info, std::cout);
                return 0;
              }
            else if (a == "--version")
              {
                std::cout << info.name << " " << COSMO_VERSION << " (deal.II "
                          << DEAL_II_PACKAGE_VERSION << ")\n";
                return 0;
              }
            else if (a == "--print-parameters")
              return print_parameters(args, i, info, declare_all, options);
            else if (a == "--quiet" || a == "-q")
              options.quiet = true;
            else if (a == "--resume")
              {
                if (i + 1 >= args.size() || args[i + 1].empty())
                  {
                    std::cerr << info.name << ": --resume takes the run directory to continue\n";
                    return 1;
                  }
                options.resume_directory = args[++i];
              }
            else if (!a.empty() && a[0] == '-')
              {
                std::cerr << info.name << ": unknown option '" << a << "'\n\n";
                print_usage(info, std::cerr);
                return 1;
              }
            else if (options.parameter_file.empty())
              options.parameter_file = a;
            else
              {
                std::cerr << info.name << ": more than one parameter file given ('"
                          << options.parameter_file << "', '" << a << "')\n";
                return 1;
              }
          }
        if (!options.resume_directory.empty() && options.parameter_file.empty())
          {
            options.parameter_file = options.resume_directory + "/parameters.prm";
            if (!std::filesystem::is_regular_file(options.parameter_file))
              {
                std::cerr << info.name << ": --resume " << options.resume_directory
                          << ": not a run directory (it has no parameters.prm)\n";
                return 1;
              }
          }
        if (options.parameter_file.empty())
          {
            print_usage(info, std::cerr);
            return 1;
          }

        return std::nullopt;
      }

      /// The run: the libraries loaded, the file read, the run in its
      /// directory (each rank in its own under mpirun), then the ranks' ends.
      void
      run_from_file(const std::function<void(ParameterHandler &)> &                    declare_all,
                    const std::function<void(ParameterHandler &, const RunOptions &)> &run,
                    RunOptions &                                                       options)
      {
        load_shared_libraries(options.parameter_file);
        ParameterHandler prm;
        declare_all(prm);
        parse_parameter_file(prm, options.parameter_file);
        options.postprocessors = std::make_shared<Postprocessors>();
        options.postprocessors->parse_parameters(prm);
        if (!options.resume_directory.empty())
          {
            // The run goes on where it was, wherever the directory now is.
            prm.enter_subsection("Output");
            prm.set("Output directory", options.resume_directory);
            prm.leave_subsection();
          }
        // Under mpirun, rank k > 0 runs in its own directory (io/ranks.h):
        // only rank 0 speaks and writes the run's result set.
        prm.enter_subsection("Output");
        const std::string shared = prm.get("Output directory");
        prm.set("Output directory", ranks::enter_run(shared));
        prm.leave_subsection();
        if (ranks::rank() > 0)
          options.quiet = true;
        ranks::share_cores();
        run(prm, options);
        prm.enter_subsection("Output");
        options.postprocessors->finish(prm.get("Output directory"));
        prm.leave_subsection();
        // The ranks serving rank 0's factorizations (a one-path run) stop.
        solvers::factorization_ranks::release();
        // A rank done early sleeps until the others are, instead of
        // spinning in MPI_Finalize.
        ranks::wait_for_all();
        // Its results are in rank 0's files now; nothing to resume. Rank 0
        // removes those of the ranks beyond this run's (a run resumed on
        // fewer ranks than it was begun with).
        std::error_code ec;
        if (ranks::rank() > 0)
          std::filesystem::remove_all(ranks::private_directory(shared, ranks::rank()), ec);
        else
          for (unsigned int k = std::max(1u, ranks::size());
               std::filesystem::is_directory(ranks::private_directory(shared, k), ec); ++k)
            std::filesystem::remove_all(ranks::private_directory(shared, k), ec);
      }
    } // namespace

    int
    run_application(int                                                       argc,
                    char **                                                   argv,
                    const ApplicationInfo &                                   info,
                    const std::function<void(ParameterHandler &)> &           declare,
                    const std::function<void(ParameterHandler &, const RunOptions &)> &run)
    {
      // MPI is initialised for HDF5/pvtu output and MUMPS, and for the ranks
      // of mpirun (io/ranks.h); the node's cores are divided among the
      // ranks' assembly threads.
      const auto mpi = ranks::init_mpi(argc, argv);
      // Errors below are reported by us, not by deal.II's abort-on-exception.
      deal_II_exceptions::disable_abort_on_exception();
      // SIGINT/SIGTERM end the run between steps, with its files complete.
      install_signal_handlers();

      // A run that ends in an error under mpirun ends every rank: the others
      // may wait in a gather the failed one never reaches (a signal or an
      // error on one rank only), where MPI_Finalize would wait for ever.
      auto ended = [](const int status) {
        if (ranks::size() > 1)
          {
            std::cerr.flush();
            MPI_Abort(MPI_COMM_WORLD, status);
          }
        return status;
      };
      const std::vector<std::string> args(argv + 1, argv + argc);
      RunOptions                     options;
      // The library's entries of every application, then its own.
      auto declare_all = [&declare](ParameterHandler &prm) {
        declare_application_parameters(prm, declare);
      };
      try
        {
          if (const auto status = read_command_line(args, info, declare_all, options))
            return *status;
          run_from_file(declare_all, run, options);
          return 0;
        }
      catch (InputError &e)
        {
          // An output directory this run only began leaves as it was.
          roll_back_unused_run_directories();
          std::cerr << "\n" << info.name << ": bad input in '" << options.parameter_file
                    << "' " << e.what() << "\n";
          return ended(1);
        }
      catch (Interrupted &e)
        {
          std::cerr << "\n"
                    << info.name << ": " << e.what()
                    << "; the files written so far are complete and summary.json (if the run "
                       "writes one) says \"interrupted\".\n";
          return ended(e.exit_status());
        }
      catch (RunFailure &e)
        {
          std::cerr << "\n" << info.name << ": the run could not proceed: " << e.what()
                    << "\nEverything written so far is kept.\n";
          return ended(2);
        }
      // Errors outside a run's attempt() (its set-up, say): a directory the
      // run wrote no result in is left as it was, as after bad input, so
      // that no summary.json says "running" of a run that is over.
      catch (std::runtime_error &e)
        {
          roll_back_unused_run_directories();
          std::cerr << "\n" << info.name << ": " << e.what() << "\n";
          return ended(1);
        }
      catch (ExceptionBase &e)
        {
          roll_back_unused_run_directories();
          std::ostringstream s;
          e.print_info(s);
          std::cerr << "\n" << info.name << ": error: " << s.str() << "\n";
          return ended(1);
        }
      catch (std::exception &e)
        {
          roll_back_unused_run_directories();
          std::cerr << "\n" << info.name << ": error: " << e.what() << "\n";
          return ended(1);
        }
    }
  } // namespace io
} // namespace cosmo

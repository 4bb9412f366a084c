#include <deal.II/base/utilities.h>

#include <cmath>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/resources.h>
#include <cosmo/io/parameters.h>

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace io
  {
    void
    ParameterSweep::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Parameter sweep");
      prm.declare_entry("Entry", "", Patterns::Anything(),
                        "The parameter-file entry to vary, as its path of subsections "
                        "and name separated by '/', e.g. 'Material 1/Growth factor' or "
                        "'Surface layer 1/Surface shear modulus'. Empty: a single run.");
      prm.declare_entry("Values", "", Patterns::List(Patterns::Double(), 0),
                        "The values of the swept quantity, comma-separated. Empty: use "
                        "'Range'.");
      prm.declare_entry("Range", "0, 1, 5", Patterns::List(Patterns::Double(), 3, 3),
                        "From, To, Number of values: equally spaced values, used when "
                        "'Values' is empty.");
      prm.declare_entry("Template", "", Patterns::Anything(),
                        "The text the entry is set to, with '{}' standing for the "
                        "value, e.g. '1 + {}*x' to sweep the magnitude of a growth law. "
                        "Empty: the value itself.");
      prm.declare_entry("Critical curve", "false", Patterns::Bool(),
                        "In a study of critical points (plate_rod, strip, and rod_cross_section "
                        "with 'Arclength continuation / Stop at first event'): from the second "
                        "value on, continue the critical point of the previous values "
                        "(extrapolated through up to three of them in the swept value, then "
                        "Newton on the augmented system; no path from the start) instead of an "
                        "independent run. A point where that fails, or where another mode has "
                        "become critical first, is run independently (said in the log; column "
                        "'continued' = 0); where the critical mode changes, the new mode is "
                        "continued back to the previous value and the codimension-2 point "
                        "estimated (columns codim2_value, codim2_t). Writes critical_curve.csv "
                        "(the columns of sweep.csv, which is written too).");
      prm.leave_subsection();
    }

    namespace
    {
      /// The text of the entry at `path` ("Section/.../Entry"); empty if there is none
      /// (apply() then names the entry in its error).
      std::string
      entry_text(ParameterHandler &prm, const std::string &path)
      {
        const auto   parts = Utilities::split_string_list(path, '/');
        unsigned int depth = 0;
        std::string  text;
        try
          {
            for (unsigned int i = 0; i + 1 < parts.size(); ++i, ++depth)
              prm.enter_subsection(parts[i]);
            if (!parts.empty())
              text = prm.get(parts.back());
          }
        catch (ExceptionBase &)
          {
          }
        for (; depth > 0; --depth)
          prm.leave_subsection();
        return text;
      }
    } // namespace

    void
    ParameterSweep::set_entry(ParameterHandler & prm,
                              const std::string &path,
                              const std::string &value,
                              const std::string &section,
                              const std::string &entry)
    {
      const auto parts = Utilities::split_string_list(path, '/');
      if (parts.empty() || parts.back().empty())
        throw InputError(section, entry, path,
                         "the path of an entry, subsections and name separated by '/'");
      unsigned int depth = 0;
      try
        {
          for (unsigned int i = 0; i + 1 < parts.size(); ++i, ++depth)
            prm.enter_subsection(parts[i]);
          prm.set(parts.back(), value);
        }
      catch (ExceptionBase &e)
        {
          for (; depth > 0; --depth)
            prm.leave_subsection();
          std::ostringstream info;
          e.print_info(info);
          throw InputError(section, entry, path,
                           "an existing entry that accepts '" + value +
                             "' (see --print-parameters); deal.II said: " + info.str());
        }
      for (; depth > 0; --depth)
        prm.leave_subsection();
    }

    void
    ParameterSweep::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Parameter sweep");
      entry_path    = Utilities::trim(prm.get("Entry"));
      template_text = prm.get("Template");
      curve         = prm.get_bool("Critical curve");
      const std::string values_text = prm.get("Values");
      values = Utilities::string_to_double(Utilities::split_string_list(values_text, ','));
      for (const double v : values)
        if (!std::isfinite(v))
          throw InputError("Parameter sweep", "Values", values_text,
                           "finite numbers separated by ',' (not nan or inf)");
      if (values.empty())
        {
          const auto range = get_range(prm, "Range", "Parameter sweep");
          // A value, its row of sweep.csv (~40 numbers) and its summary in memory.
          check_points_memory(range.n, 8 + 2 * (40 * 8 + 24), estimated_memory(0, 1),
                              "Parameter sweep", "Range", prm.get("Range"));
          for (unsigned int k = 0; k < range.n; ++k)
            values.push_back(range.value(k));
        }
      prm.leave_subsection();
      if (!enabled())
        return;
      if (!template_text.empty() && template_text.find("{}") == std::string::npos)
        throw InputError("Parameter sweep", "Template", template_text,
                         "a text containing '{}' where the value goes (or empty)");
      // Fail now, not after the first points have run: the entry must exist
      // and accept every value. The entry's own text is put back: the study
      // runs each value on a copy of the parameters (io/parameter_copy.h),
      // and the handler stays as the file gave it.
      const std::string original = entry_text(prm, entry_path);
      for (unsigned int k = 0; k < values.size(); ++k)
        apply(prm, k);
      set_entry(prm, entry_path, original, "Parameter sweep", "Entry");
    }

    std::string
    ParameterSweep::label() const
    {
      const auto parts = Utilities::split_string_list(entry_path, '/');
      return parts.empty() ? std::string("value") : parts.back();
    }

    std::string
    ParameterSweep::axis_label() const
    {
      std::string l = entry_path;
      if (!template_text.empty())
        l += " = " + template_text;
      // It goes into a CSV header (as the unit of the value column).
      std::replace(l.begin(), l.end(), ',', ';');
      return l;
    }

    std::string
    ParameterSweep::text(const unsigned int k) const
    {
      std::ostringstream v;
      v << std::setprecision(15) << values[k];
      if (template_text.empty())
        return v.str();
      std::string t = template_text;
      // A negative value inside an expression needs parentheses ('{}^2' with
      // -0.1 must not become '-0.1^2', which is -0.01); in a list
      // ('0, 0, 1, {}, 0, 0') or alone it must stay a plain number for the
      // entry's pattern.
      auto binds = [](const char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ||
               std::string("+-*/^").find(c) != std::string::npos;
      };
      for (auto pos = t.find("{}"); pos != std::string::npos; pos = t.find("{}", pos))
        {
          auto before = pos, after = pos + 2;
          while (before > 0 && t[before - 1] == ' ')
            --before;
          while (after < t.size() && t[after] == ' ')
            ++after;
          const bool in_expression =
            (before > 0 && binds(t[before - 1])) || (after < t.size() && binds(t[after]));
          const std::string s =
            (values[k] < 0 && in_expression) ? "(" + v.str() + ")" : v.str();
          t.replace(pos, 2, s);
          pos += s.size();
        }
      return t;
    }

    namespace
    {
      /**
       * Back to the top level of the handler: a point whose parse_parameters
       * threw (bad input at that value) left it inside a subsection, and the
       * next point's entries were then looked up there ("You can't ask for
       * entry <Growth factor> you have not yet declared"). 'Output' is a
       * top-level subsection of every application and of no subsection.
       */
      void
      leave_all_subsections(ParameterHandler &prm)
      {
        for (unsigned int depth = 0; depth < 16 && !prm.subsection_path_exists({"Output"}); ++depth)
          prm.leave_subsection();
      }
    } // namespace

    void
    ParameterSweep::apply(ParameterHandler &prm, const unsigned int k) const
    {
      leave_all_subsections(prm);
      set_entry(prm, entry_path, text(k), "Parameter sweep", "Entry");
    }

    void
    ParameterSweep::prepare_point(ParameterHandler & prm,
                                  const unsigned int k,
                                  const std::string &point_directory) const
    {
      apply(prm, k);
      set_entry(prm, "Output/Output directory", point_directory, "Output", "Output directory");
      set_entry(prm, "Parameter sweep/Entry", "", "Parameter sweep", "Entry");
    }

    std::string
    ParameterSweep::point_directory(const std::string &directory, const unsigned int k)
    {
      return directory + "/point-" + Utilities::int_to_string(k, 2);
    }
    void
    ParameterSweep::refuse_distributed_mesh(ParameterHandler &prm, const std::string &section) const
    {
      prm.enter_subsection(section);
      const bool distributed = prm.get_bool("Distributed");
      prm.leave_subsection();
      if (enabled() && distributed)
        throw InputError(section, "Distributed", "true",
                         "a parameter study spreads its values over the MPI ranks, each value "
                         "on one rank's whole mesh: set Distributed = false, or run the values "
                         "one by one on a distributed mesh");
    }
  } // namespace io
} // namespace cosmo

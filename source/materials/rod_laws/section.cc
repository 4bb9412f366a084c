// The rod law of part-1 sections (rod_laws/section.h): one section or a
// family over a growth parameter, read from rod_cross_section's output.
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/materials/rod_laws/section.h>
#include <cosmo/materials/section_stiffness.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace cosmo
{
  namespace materials
  {
    namespace
    {
      const std::array<std::string, 6> strain_names{{"nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"}};
      const std::array<std::string, 6> resultant_names{{"n1", "n2", "n3", "m1", "m2", "m3"}};

      std::string
      read_text(const std::string &file, const std::string &section, const std::string &entry)
      {
        std::ifstream in(file);
        if (!in)
          throw io::InputError(section, entry, file, "a readable rod_cross_section result (cannot open it)");
        std::stringstream buffer;
        buffer << in.rdbuf();
        return buffer.str();
      }

      /// The number of member `key` of `object` (NaN if absent).
      double
      number(const io::JSON *object, const std::string &key)
      {
        const io::JSON *v = object ? object->find(key) : nullptr;
        return v && v->is_number() ? v->as_number() : std::nan("");
      }

      /**
       * A natural state is stress-free: the strain its residual resultants
       * would cause, |n_k| / K_kk, is below 1e-6 (a part-1 natural shape
       * has them at Newton's tolerance, ~1e-12). Otherwise the section was
       * computed with prescribed strains and its strains are not natural.
       */
      void
      check_natural(const SectionResult &r, const std::string &file, const std::string &section,
                    const std::string &entry)
      {
        for (unsigned int k = 0; k < 6; ++k)
          if (!(std::isfinite(r.strains[k]) && std::abs(r.resultants[k]) <= 1e-6 * std::abs(r.stiffness[7 * k])))
            throw io::InputError(section, entry, file,
                                 "a rod_cross_section result at a natural shape ('Rod strains / Mode "
                                 "= natural shape': zero resultants); its " + resultant_names[k] + " = " +
                                   io::format_number(r.resultants[k]) + " against the stiffness " +
                                   io::format_number(r.stiffness[7 * k]));
      }

      std::vector<std::string>
      split_csv(const std::string &line)
      {
        std::vector<std::string> cells;
        std::stringstream        in(line);
        std::string              cell;
        while (std::getline(in, cell, ','))
          cells.push_back(cell);
        return cells;
      }

      /// A cell's name without its unit: "nu1 [1]" -> "nu1".
      std::string
      column_name(const std::string &cell)
      {
        const auto end = cell.find(" [");
        return cell.substr(0, end);
      }
    } // namespace

    RodLaw::SectionOutline
    read_outline(const std::string &file)
    {
      // loop,X1,X2,w1,w2,w3,von_Mises_stress (rod_cross_section's or a
      // strip's outline.csv), and part 1's stress linearization (42 more);
      // absent or unreadable: no outline (the body is then drawn as a tube).
      RodLaw::SectionOutline loops;
      std::ifstream          in(file);
      std::string            line;
      std::getline(in, line);
      const std::size_t n_cells = split_csv(line).size();
      if (n_cells != 7 && n_cells != 49)
        return {};
      while (std::getline(in, line))
        try
        {
          const auto cells = split_csv(line);
          if (cells.size() != n_cells)
            return {};
          const std::size_t l = std::stoul(cells[0]);
          if (l > loops.size())
            return {};
          if (l == loops.size())
            loops.emplace_back();
          std::vector<double> p(n_cells - 1);
          for (unsigned int k = 0; k + 1 < n_cells; ++k)
            p[k] = std::stod(cells[1 + k]);
          loops[l].push_back(p);
        }
        catch (std::exception &)
        {
          return {};
        }
      return loops;
    }

    std::string
    application_of_parameter_file(const std::string &file)
    {
      std::ifstream in(file);
      std::string   line;
      while (std::getline(in, line))
        {
          std::istringstream words(line);
          std::string        first, second;
          words >> first >> second;
          if (first == "subsection" && second == "Strip")
            return "strip";
        }
      return "rod_cross_section";
    }

    SectionResult
    read_section_summary(const std::string &file, const std::string &section, const std::string &entry)
    {
      SectionResult r;
      try
        {
          const io::JSON  summary = io::JSON::parse(read_text(file, section, entry));
          const io::JSON *status  = summary.find("status");
          if (!status || status->str() != "\"converged\"")
            throw io::InputError(section, entry, file,
                                 "a converged rod_cross_section summary.json (its status is " +
                                   (status ? status->str() : std::string("missing")) + ")");
          for (unsigned int k = 0; k < 6; ++k)
            {
              r.strains[k]    = number(summary.find("strains"), strain_names[k]);
              r.resultants[k] = number(summary.find("resultants"), resultant_names[k]);
            }
          r.stiffness = read_summary_stiffness(file, section, entry);
          // A strip (part 2) gives its resultants and stiffness per E w h
          // (doc/user-guide-strip.md): restore w h, so that strips of
          // different widths are comparable and the law is in units of E.
          const io::JSON *application = summary.find("application");
          if (application && application->str() == "\"strip\"")
            {
              const double wh = number(&summary, "width") * number(&summary, "thickness");
              if (!(wh > 0))
                throw io::InputError(section, entry, file,
                                     "a strip summary.json with a positive width and thickness");
              for (double &n : r.resultants)
                n *= wh;
              for (double &k : r.stiffness)
                k *= wh;
              r.strip = true;
            }
        }
      catch (io::InputError &)
        {
          throw;
        }
      catch (std::runtime_error &e)
        {
          throw io::InputError(section, entry, file, "a rod_cross_section summary.json (" + std::string(e.what()) + ")");
        }
      return r;
    }

    std::vector<SectionResult>
    read_section_sweep(const std::string &file, const std::string &section, const std::string &entry,
                       unsigned int &holes)
    {
      std::stringstream in(read_text(file, section, entry));
      std::string       line;
      std::getline(in, line);
      // The value's header may hold commas (its template): columns are
      // counted from 'converged', the third column of every row.
      const auto header = split_csv(line);
      std::map<std::string, long> column;
      long converged = -1;
      for (std::size_t c = 0; c < header.size(); ++c)
        if (column_name(header[c]) == "converged")
          converged = static_cast<long>(c);
      for (std::size_t c = converged > 0 ? converged : 0; c < header.size(); ++c)
        column[column_name(header[c])] = static_cast<long>(c) - converged + 2;
      const auto need = [&](const std::string &name) {
        if (converged < 0 || !column.count(name))
          throw io::InputError(section, entry, file,
                               "a rod_cross_section sweep.csv (a parameter sweep's table; no column '" + name + "')");
        return column.at(name);
      };
      std::vector<SectionResult> rows;
      holes = 0;
      while (std::getline(in, line))
        {
          if (line.empty())
            continue;
          const auto cells = split_csv(line);
          auto       get   = [&](const std::string &name) {
            const long c = need(name);
            try
              {
                return c < static_cast<long>(cells.size()) ? std::stod(cells[c]) : std::nan("");
              }
            catch (std::exception &)
              {
                return std::nan("");
              }
          };
          SectionResult r;
          r.parameter = cells.size() > 1 ? std::stod(cells[1]) : std::nan("");
          for (unsigned int k = 0; k < 6; ++k)
            {
              r.strains[k]    = get(strain_names[k]);
              r.resultants[k] = get(resultant_names[k]);
            }
          for (unsigned int a = 0; a < 6; ++a)
            for (unsigned int b = a; b < 6; ++b)
              r.stiffness[6 * a + b] = r.stiffness[6 * b + a] =
                get("K_" + strain_names[a] + "_" + strain_names[b]);
          const bool finite = std::all_of(r.stiffness.begin(), r.stiffness.end(), [](double v) { return std::isfinite(v); });
          if (get("converged") != 1 || !finite || !std::isfinite(r.parameter))
            ++holes;
          else
            rows.push_back(r);
        }
      return rows;
    }

    void
    SectionRodLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Section file", "", Patterns::Anything(),
                        "Law = section: a rod_cross_section result: its summary.json (one "
                        "section), the sweep.csv of a parameter sweep (a family of sections "
                        "over the swept value p), or a rod_cross_section parameter file, "
                        "which the run computes itself (its output in the run's directory "
                        "'section', reused while that file's parameters and the files they "
                        "name are unchanged); or likewise a strip's summary.json or parameter file (one with a "
                        "subsection 'Strip': a ribbon's law, its E w h units restored). The "
                        "section's natural strains replace 'Natural strains'; it must be at "
                        "a natural shape ('Rod strains / Mode = natural shape').");
      prm.declare_entry("Section parameter", "0", Patterns::Anything(),
                        "Law = section with a family: the swept value p(s, t) of the section "
                        "at the reference arclength s and load parameter t (a muparser "
                        "expression, e.g. 't*s/0.5': differential growth growing in time and "
                        "along the rod). Natural strains and stiffnesses are interpolated in "
                        "p (monotone cubic, C1); a p outside the family's range stops the "
                        "path with a message.");
    }

    void
    SectionRodLaw::parse_parameters(ParameterHandler &prm, const std::string &section)
    {
      section_name   = section;
      file           = prm.get("Section file");
      parameter_text = prm.get("Section parameter");
      members.clear();
      if (file.empty())
        throw io::InputError(section, "Section file", file,
                             "a rod_cross_section summary.json, sweep.csv or parameter file (Law = section)");
      parameter = std::make_shared<FunctionParser<2>>(1);
      try
        {
          parameter->initialize("s,t", parameter_text, {{"pi", M_PI}});
          parameter->value(Point<2>(0.1, 0.2));
        }
      catch (ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw io::InputError(section, "Section parameter", parameter_text,
                               "a muparser expression of s and t (and pi); the parser said: " + info.str());
        }
      const std::filesystem::path path(file);
      if (path.extension() != ".prm")
        read_result(file);
    }

    void
    SectionRodLaw::read_result(const std::string &path_text)
    {
      std::filesystem::path path(path_text);
      if (std::filesystem::is_directory(path))
        path /= std::filesystem::exists(path / "sweep.csv") ? "sweep.csv" : "summary.json";
      origin = path.string();
      holes  = 0;
      if (path.extension() == ".csv")
        members = read_section_sweep(origin, section_name, "Section file", holes);
      else
        members = {read_section_summary(origin, section_name, "Section file")};
      if (members.empty())
        throw io::InputError(section_name, "Section file", origin,
                             "a sweep with at least one converged section (" + std::to_string(holes) +
                               " did not converge)");
      std::sort(members.begin(), members.end(),
                [](const SectionResult &a, const SectionResult &b) { return a.parameter < b.parameter; });
      for (std::size_t i = 0; i < members.size(); ++i)
        {
          check_natural(members[i], origin, section_name, "Section file");
          if (i > 0 && !(members[i].parameter > members[i - 1].parameter))
            throw io::InputError(section_name, "Section file", origin,
                                 "a sweep with distinct values (" +
                                   io::format_number(members[i].parameter) + " twice)");
        }
      build_curves();
      check_positive_definite();
      outline.clear();
      if (members.size() == 1)
        outline = read_outline((path.parent_path() / "outline.csv").string());
    }

    void
    SectionRodLaw::build_curves()
    {
      std::vector<double> p;
      for (const auto &m : members)
        p.push_back(m.parameter);
      auto curve = [&](auto pick) {
        std::vector<double> y;
        for (const auto &m : members)
          y.push_back(pick(m));
        return base::MonotoneCubic(p, y);
      };
      for (unsigned int k = 0; k < 6; ++k)
        strain_curves[k] = curve([k](const SectionResult &m) { return m.strains[k]; });
      // The symmetric part (a summary's K is symmetric to round-off), upper triangle.
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = a; b < 6; ++b)
          stiffness_curves[6 * a + b] =
            curve([a, b](const SectionResult &m) { return 0.5 * (m.stiffness[6 * a + b] + m.stiffness[6 * b + a]); });
    }

    void
    SectionRodLaw::check_positive_definite() const
    {
      // Each member, and 16 points in each interval: the interpolated
      // entries stay between their neighbours', not the matrix in the cone.
      const auto [p0, p1] = range();
      for (std::size_t i = 0; i < members.size(); ++i)
        for (unsigned int j = 0; j < (i + 1 < members.size() ? 16u : 1u); ++j)
          {
            const double p = i + 1 < members.size() ?
                               members[i].parameter + j * (members[i + 1].parameter - members[i].parameter) / 16 :
                               members[i].parameter;
            if (indefinite_leading_block(stiffness_at(std::clamp(p, p0, p1))) != 0)
              throw io::InputError(section_name, "Section file", origin,
                                   "sections whose 6x6 stiffness is positive definite, and between them "
                                   "(not at p = " + io::format_number(p) +
                                   (j > 0 ? ": add sections between the neighbours" : "") + ")");
          }
    }

    std::pair<double, double>
    SectionRodLaw::range() const
    {
      return {members.front().parameter, members.back().parameter};
    }

    void
    SectionRodLaw::check_range(const double p) const
    {
      const auto [p0, p1] = range();
      // A family of one section is that section for every p.
      if (members.size() > 1 && !(p >= p0 - 1e-12 * (p1 - p0) && p <= p1 + 1e-12 * (p1 - p0)))
        throw LawRangeError("the section parameter p = " + io::format_number(p) +
                            " is outside the family's range [" + io::format_number(p0) + ", " +
                            io::format_number(p1) + "] (" + section_name + "/Section parameter = " +
                            parameter_text + ", sections of " + origin + ")");
    }

    std::array<double, 36>
    SectionRodLaw::stiffness_at(const double p) const
    {
      // The upper triangle's curves, mirrored: symmetric by construction.
      check_range(p);
      std::array<double, 36> K;
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = a; b < 6; ++b)
          K[6 * a + b] = K[6 * b + a] = stiffness_curves[6 * a + b].value(p);
      return K;
    }

    SectionResult
    SectionRodLaw::member_at(const double p) const
    {
      SectionResult r;
      r.parameter = p;
      r.stiffness = stiffness_at(p);
      for (unsigned int k = 0; k < 6; ++k)
        r.strains[k] = strain_curves[k].value(p);
      return r;
    }

    void
    SectionRodLaw::energy_derivatives(const std::array<double, 6> &e,
                                      const bool                   with_hessian,
                                      double &                     W,
                                      std::array<double, 6> &      dW,
                                      std::array<double, 36> &     ddW) const
    {
      energy_derivatives_at(members.front().parameter, e, with_hessian, W, dW, ddW);
    }

    void
    SectionRodLaw::energy_derivatives_at(const double                 p,
                                         const std::array<double, 6> &e,
                                         const bool                   with_hessian,
                                         double &                     W,
                                         std::array<double, 6> &      dW,
                                         std::array<double, 36> &     ddW) const
    {
      // dW = K(p) e, W = 1/2 e . K(p) e, ddW = K(p): only the stiffness is
      // interpolated here (the natural strains were, once, for the state).
      const std::array<double, 36> K = stiffness_at(p);
      W                              = 0;
      for (unsigned int i = 0; i < 6; ++i)
        {
          dW[i] = 0;
          for (unsigned int j = 0; j < 6; ++j)
            dW[i] += K[6 * i + j] * e[j];
          W += 0.5 * dW[i] * e[i];
        }
      if (with_hessian)
        ddW = K;
    }

    double
    SectionRodLaw::parameter_at(const double s, const double t) const
    {
      return parameter->value(Point<2>(s, t));
    }

    std::optional<std::array<double, 6>>
    SectionRodLaw::natural_strains_at(const double p) const
    {
      check_range(p);
      std::array<double, 6> xi;
      for (unsigned int k = 0; k < 6; ++k)
        xi[k] = strain_curves[k].value(p);
      return xi;
    }

    std::string
    SectionRodLaw::description() const
    {
      std::ostringstream m;
      if (members.size() == 1)
        m << "section: the " << (members[0].strip ? "part-2 strip" : "part-1 section") << " of " << origin;
      else
        m << "section: a family of " << members.size() << " part-1 sections over p in ["
          << members.front().parameter << ", " << members.back().parameter << "] from " << origin
          << (holes ? " (" + std::to_string(holes) + " unconverged left out)" : std::string()) << ", p(s, t) = "
          << parameter_text << ", monotone cubic in p";
      if (!computed_note.empty())
        m << "; " << computed_note;
      return m.str();
    }

    COSMO_REGISTER_PLUGIN(RodLaw,
                          SectionRodLaw,
                          "section",
                          "the quadratic law of a part-1 (rod_cross_section) section about its "
                          "natural strains, or of a family of sections interpolated in a growth "
                          "parameter p(s, t) along the rod: 'Section file', 'Section parameter'.")
  } // namespace materials
} // namespace cosmo

// Unit tests of the parameter sweep (io/parameter_sweep.h): values from a
// list or a range, the template substitution (a negative value is
// parenthesized inside an expression, not in a list or alone), and the
// checks that the swept entry exists and accepts every value; a study
// point's parameters as a copy (io/parameter_copy.h) that leaves the
// study's handler as it was; the JSON reader against the writer
// (io/output.h).
#include <deal.II/base/parameter_handler.h>

#include <cosmo/io/output.h>
#include <cosmo/io/parameter_copy.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/run_record.h>
#include <cosmo/solvers/arclength.h>

#include "test_tools.h"

#include <cmath>

using namespace dealii;
using cosmo_test::check;

namespace
{
  /// A handler with a sweep and two entries to sweep.
  void
  declare(ParameterHandler &prm)
  {
    cosmo::io::ParameterSweep::declare_parameters(prm);
    prm.enter_subsection("Material 1");
    prm.declare_entry("Growth factor", "1", Patterns::Anything());
    prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-1, 0.5));
    prm.leave_subsection();
    prm.declare_entry("Strains", "0, 0, 1, 0, 0, 0", Patterns::List(Patterns::Double(), 6, 6));
  }

  cosmo::io::ParameterSweep
  sweep(const std::string &text, ParameterHandler &prm)
  {
    declare(prm);
    prm.parse_input_from_string(text);
    cosmo::io::ParameterSweep s;
    s.parse_parameters(prm);
    return s;
  }

  bool
  rejected(const std::string &text, const std::string &message_part)
  {
    try
      {
        ParameterHandler prm;
        sweep(text, prm);
      }
    catch (cosmo::io::InputError &e)
      {
        std::cout << "        (" << e.what() << ")\n";
        return std::string(e.what()).find(message_part) != std::string::npos;
      }
    return false;
  }
} // namespace

int
main()
{
  {
    // A study's point k: a copy of the study's parameters, its value set in
    // the copy (prepare_point), the study's handler unchanged.
    ParameterHandler prm;
    auto declare_all = [](ParameterHandler &p) {
      declare(p);
      p.enter_subsection("Output");
      p.declare_entry("Output directory", "out", Patterns::Anything());
      p.leave_subsection();
    };
    cosmo::io::declare_application_parameters(prm, declare_all);
    const std::string text = "subsection Parameter sweep\n set Entry = Material 1/Growth factor\n"
                             " set Values = 0.5, 0.75\n set Template = 1 + {}*x\nend\n"
                             "subsection Material 1\n set Poisson's ratio = 0.25\nend\n"
                             "set Strains = 0, 0, 1.5, 0, 0.125, 0\nsubsection Output\n set Output directory = study\nend\n";
    prm.parse_input_from_string(text);
    cosmo::io::ParameterSweep s;
    s.parse_parameters(prm);
    const auto copy = cosmo::io::copy_parameters(prm, declare_all);
    bool same = true;
    copy->enter_subsection("Material 1");
    prm.enter_subsection("Material 1");
    same &= copy->get("Poisson's ratio") == prm.get("Poisson's ratio");
    same &= copy->get("Growth factor") == prm.get("Growth factor");
    copy->leave_subsection();
    prm.leave_subsection();
    same &= copy->get("Strains") == prm.get("Strains");
    copy->enter_subsection("Output");
    same &= copy->get("Output directory") == "study";
    copy->leave_subsection();
    check("copy: every value of the original", same);
    s.prepare_point(*copy, 1, "study/point-01");
    copy->enter_subsection("Material 1");
    prm.enter_subsection("Material 1");
    check("copy: the point's value set in the copy", copy->get("Growth factor") == "1 + 0.75*x");
    check("copy: the original's value unchanged", prm.get("Growth factor") == "1");
    copy->leave_subsection();
    prm.leave_subsection();
    copy->enter_subsection("Output");
    prm.enter_subsection("Output");
    check("copy: the original's output directory unchanged",
          prm.get("Output directory") == "study" && copy->get("Output directory") == "study/point-01");
    copy->leave_subsection();
    prm.leave_subsection();
    prm.enter_subsection("Parameter sweep");
    check("copy: the original's sweep unchanged", prm.get("Entry") == "Material 1/Growth factor");
    prm.leave_subsection();
    bool refused = false;
    try
      {
        cosmo::io::copy_parameters(prm, {});
      }
    catch (std::logic_error &)
      {
        refused = true;
      }
    check("copy: no declarations is refused", refused);
  }
  {
    ParameterHandler prm;
    const auto       s = sweep("subsection Parameter sweep\n set Entry = Material 1/Growth factor\n"
                         " set Template = 1 + {}*x\n set Range = -0.2, 0.2, 3\nend\n",
                         prm);
    check("range -0.2 .. 0.2 in 3 values: " + s.text(0) + " | " + s.text(1) + " | " + s.text(2),
          s.size() == 3 && s.text(0) == "1 + (-0.2)*x" && s.text(1) == "1 + 0*x" &&
            s.text(2) == "1 + 0.2*x");
    s.apply(prm, 0);
    prm.enter_subsection("Material 1");
    check("apply sets the entry: '" + prm.get("Growth factor") + "'",
          prm.get("Growth factor") == "1 + (-0.2)*x");
    prm.leave_subsection();
    check("axis label names entry and template: '" + s.axis_label() + "'",
          s.axis_label() == "Material 1/Growth factor = 1 + {}*x");
  }
  {
    ParameterHandler prm;
    const auto       s = sweep("subsection Parameter sweep\n set Entry = Strains\n"
                         " set Template = 0, 0, 1, {}, 0, 0\n set Values = -0.1, 0.1\nend\n",
                         prm);
    check("a negative value in a list stays a number: '" + s.text(0) + "'",
          s.text(0) == "0, 0, 1, -0.1, 0, 0");
  }
  {
    ParameterHandler prm;
    const auto       s = sweep("subsection Parameter sweep\n set Entry = Material 1/Growth factor\n"
                         " set Template = {}^2\n set Values = -0.5\nend\n",
                         prm);
    check("a negative value before an operator is parenthesized: '" + s.text(0) + "'",
          s.text(0) == "(-0.5)^2");
  }
  {
    ParameterHandler prm;
    const auto       s = sweep("", prm);
    check("no entry: no sweep", !s.enabled());
  }
  check("an entry that does not exist is rejected",
        rejected("subsection Parameter sweep\n set Entry = Material 1/Youngs modulus\n"
                 " set Values = 1\nend\n",
                 "entry 'Entry' = 'Material 1/Youngs modulus'"));
  check("a value outside the entry's pattern is rejected",
        rejected("subsection Parameter sweep\n set Entry = Material 1/Poisson's ratio\n"
                 " set Values = 0.2, 0.7\nend\n",
                 "accepts '0.7'"));
  check("a range with a fractional count is rejected",
        rejected("subsection Parameter sweep\n set Entry = Material 1/Poisson's ratio\n"
                 " set Range = 0, 0.4, 2.5\nend\n",
                 "whole number"));
  {
    // The reader reads what the writer writes: a tree with every kind of
    // value, numbers at full precision (the writer's format), escapes.
    using cosmo::io::JSON;
    JSON j           = JSON::object();
    j["name"]        = "a \"quoted\"\tname\n";
    j["flag"]        = true;
    j["nothing"]     = JSON();
    j["pi"]          = 3.141592653589793;
    j["tiny"]        = -1.2345678901234567e-300;
    // A subnormal number (a Rayleigh quotient's margin can be one) is written and read back.
    j["subnormal"]   = 1.2345e-310;
    j["stiffness"]   = JSON::array();
    for (int a = 0; a < 3; ++a)
      j["stiffness"].push_back(JSON::array({a + 0.1, 1. / 3, -2e10}));
    j["nested"]["deeper"]["n"] = 7;
    const JSON r               = JSON::parse(j.str());
    check("JSON round trip: the text of the read tree is the written text", r.str() == j.str());
    check("JSON round trip: numbers bit for bit",
          r.find("pi")->as_number() == 3.141592653589793 &&
            r.find("tiny")->as_number() == -1.2345678901234567e-300 &&
            r.find("subnormal")->as_number() == 1.2345e-310 &&
            r.find("stiffness")->at(2).at(1).as_number() == 1. / 3);
    check("JSON: a missing key is nullptr, null reads as NaN",
          r.find("absent") == nullptr && std::isnan(r.find("nothing")->as_number()));
    for (const std::string bad : {"{\"a\": [1, 2}", "{\"a\" 1}", "[1, 2] x", "", "{\"a\": tru}"})
      {
        bool thrown = false;
        try
          {
            JSON::parse(bad);
          }
        catch (std::runtime_error &e)
          {
            thrown = std::string(e.what()).find("not JSON at character") != std::string::npos;
            std::cout << "        ('" << bad << "': " << e.what() << ")\n";
          }
        check("JSON: '" + bad + "' is refused with the position", thrown);
      }
  }
  // The end-of-run path summary: per branch the states, the t range and
  // the stable count with the largest number of negative eigenvalues; the events.
  {
    std::vector<cosmo::solvers::PathRow> rows = {{0, 0., 0}, {0, 0.5, 0}, {0, 1., 2}, {1, 0.5, 0}, {1, 0.8, 0}};
    cosmo::solvers::BifurcationProblem::Event e;
    e.kind              = cosmo::solvers::BifurcationProblem::Event::Kind::branch_point;
    e.lambda            = 0.75;
    e.n_negative_before = 0;
    e.n_negative_after  = 2;
    const std::string text =
      cosmo::solvers::path_summary(rows, {e}, [](unsigned int) { return std::string(", mode n = 3"); });
    std::cout << text << "\n";
    cosmo_test::check("path summary: counts", text.find("2 branches, 5 states, 1 event") != std::string::npos);
    cosmo_test::check("path summary: branch 0 has 2 of 3 stable states, at most 2 negative",
                      text.find("2 of 3 (2)") != std::string::npos);
    cosmo_test::check("path summary: branch 1 from t = 0.5 to 0.8, stable",
                      text.find("0.5 .. 0.8") != std::string::npos && text.find("2 of 2 (0)") != std::string::npos);
    cosmo_test::check("path summary: the event with its extra words",
                      text.find("at t = 0.75 on branch 0, negative eigenvalues 0 -> 2, mode n = 3") != std::string::npos);
  }
  {
    // The step line's progress: "step k of ~N" with N = k / fraction,
    // rounded up; nothing about steps or an ETA outside (0.01, 1).
    cosmo::io::RunRecord record("test");
    const std::string quarter = record.progress(0.25, 10);
    std::cout << "progress(0.25, 10) = '" << quarter << "'\n";
    cosmo_test::check("progress: step 10 of ~40 and an ETA",
                      quarter.find("step 10 of ~40, ETA") != std::string::npos);
    cosmo_test::check("progress: ~N rounded up (3 / 0.7 -> 5)",
                      record.progress(0.7, 3).find("step 3 of ~5,") != std::string::npos);
    cosmo_test::check("progress: no step count without a fraction",
                      record.progress(std::numeric_limits<double>::quiet_NaN(), 7).find("step") == std::string::npos);
  }
  return cosmo_test::report();
}

// What the cases of test_plate_rod share: a problem made from a few settings,
// its first event, the closed forms' setting.
#ifndef cosmo_tests_plate_rod_common_h
#define cosmo_tests_plate_rod_common_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <cosmo/analysis/plate_rod_thresholds.h>
#include <cosmo/io/ranks.h>
#include "run.h"
#include "../test_tools.h"
#include <fstream>
#include <iomanip>
#include <map>
#include <random>
#include <sstream>
#include <tuple>

using namespace dealii;
using namespace cosmo;
using cosmo_test::check;
using cosmo_test::check_close;

namespace plate_rod_test
{
  constexpr double R = 1, E = 1, poisson = 0.3;

  inline double
  plate_D(const double h)
  {
    return E * h * h * h / (12 * (1 - poisson * poisson));
  }

  struct Setup
  {
    double       h = 0.01;
    std::string  model = "kirchhoff";
    std::string  domain = "sector";
    double       sector_angle = 45;
    unsigned int refinements = 3;
    double       EA = 1, GA = 1, EI1 = 1e-5, EI2 = 1e-5, GJ = 1e-5;
    double       plate_growth = 1, rod_growth = 1;
    double       t_max = 1, initial_step = 0.1, maximum_step = 0.2;
    bool         switch_branches = false;
    unsigned int branches = 1, steps = 40;
    std::string  extra;

    analysis::PlateRod
    closed_form() const
    {
      analysis::PlateRod p;
      p.radius = R, p.thickness = h, p.young = E, p.poisson = poisson;
      p.rod_EA = EA, p.rod_EI1 = EI1, p.rod_EI2 = EI2, p.rod_GJ = GJ;
      return p;
    }
  };

  inline std::unique_ptr<plate_rod::PlateRodRun>
  make(const Setup &s)
  {
    ParameterHandler prm;
    plate_rod::PlateRodProblem::declare_parameters(prm);
    std::ostringstream t;
    t << std::setprecision(17) << "subsection Plate\n set Radius = " << R
      << "\n set Thickness = " << s.h << "\nend\nsubsection Plate material\n set Young's modulus = "
      << E << "\n set Poisson's ratio = " << poisson
      << "\nend\nsubsection Plate growth\n set Kind = isotropic\n set Radial growth factor = "
      << s.plate_growth << "\nend\nsubsection Rim rod\n set Stiffnesses = " << s.GA << ", "
      << s.GA << ", " << s.EA << ", " << s.EI1 << ", " << s.EI2 << ", " << s.GJ
      << "\n set Growth factor = " << s.rod_growth << "\nend\nsubsection Model\n set Model = "
      << s.model << "\nend\nsubsection Mesh\n set Domain = " << s.domain
      << "\n set Sector angle = " << s.sector_angle << "\n set Global refinements = "
      << s.refinements << "\nend\nsubsection Nonlinear solver\n set Relative tolerance = 1e-10\nend\n"
      << "subsection Arclength continuation\n set Parameter range = 0, " << s.t_max
      << "\n set Initial step = " << s.initial_step << "\n set Maximum step = " << s.maximum_step
      << "\n set Maximum number of steps = " << s.steps
      << "\n set Switch branches = " << (s.switch_branches ? "true" : "false")
      << "\n set Maximum number of branches = " << s.branches << "\n set Switch amplitude = 1e-3\n set Event tolerance = 1e-6"
      << "\nend\n"
      << s.extra;
    prm.parse_input_from_string(t.str());
    auto p = std::make_unique<plate_rod::PlateRodRun>();
    p->parse_parameters(prm);
    p->get_problem().set_quiet(true);
    p->get_problem().setup_system();
    return p;
  }

  /// Follow the flat branch from t = 0; the first located event (t, mismatch) or NaNs.
  inline std::pair<double, double>
  first_event(plate_rod::PlateRodRun &p)
  {
    p.solve_flat_state(0.);
    p.follow_branches();
    if (p.event_records().empty())
      return {NAN, NAN};
    const double t = p.event_records().front().event.lambda;
    return {t, p.get_problem().mismatch(t)};
  }

  /// Mode number and whether out of plane (plate_rod::classify_mode on p's discretization).
  inline std::pair<unsigned int, bool>
  classify(const plate_rod::PlateRodRun &p, const Vector<double> &mode)
  {
    return plate_rod::classify_mode(p.get_problem().get_discretization(), mode);
  }

  /// Growth factor of the plate that puts the closed-form threshold at t = 0.5.
  inline double
  growth_for_threshold(const Setup &s)
  {
    return 1 + 2 * analysis::axisymmetric_critical_mismatch(s.closed_form());
  }

  inline const std::string stop_at_first_event = "subsection Growth path\n set Stop at first event = true\nend\n";

  /// The first event of the Kirchhoff and of the Cosserat model in the same setting, and
  /// Mindlin's relative difference -r/(1 + r) for the axisymmetric mode, r = N_K/(ks G h)
  /// (the rim restrains the director, as the Reissner-Mindlin edge condition does).
  struct ModelPair
  {
    std::unique_ptr<plate_rod::PlateRodRun> kirchhoff, cosserat;
    double                                       D_kirchhoff = 0, D_cosserat = 0, mindlin = 0;
  };

  inline ModelPair
  cosserat_and_kirchhoff(Setup s, const std::string &cosserat_extra = "",
                         const std::string &kirchhoff_extra = "")
  {
    ModelPair m;
    s.extra       = stop_at_first_event;
    s.model       = "kirchhoff";
    const std::string common = s.extra;
    s.extra += kirchhoff_extra;
    m.kirchhoff   = make(s);
    s.extra = common;
    m.D_kirchhoff = first_event(*m.kirchhoff).second;
    s.model       = "cosserat";
    s.extra += cosserat_extra;
    m.cosserat    = make(s);
    m.D_cosserat  = first_event(*m.cosserat).second;
    const double rho = s.EI1 / (R * plate_D(s.h));
    const double P   = analysis::axisymmetric_load_factor(poisson, rho) * plate_D(s.h) / (R * R);
    const double r   = P / (5. / 6 * E / (2 * (1 + poisson)) * s.h);
    m.mindlin        = -r / (1 + r);
    return m;
  }

  /// Each topic's cases, by name.
  void
  add_states_cases(cosmo_test::Cases &cases);
  void
  add_thresholds_cases(cosmo_test::Cases &cases);
  void
  add_lobes_cases(cosmo_test::Cases &cases);
  void
  add_shear_convergence_cases(cosmo_test::Cases &cases);
} // namespace plate_rod_test

#endif

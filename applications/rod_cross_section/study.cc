// The application's studies: one run, a parameter sweep (sweep.csv) or critical points.
#include <cosmo/config.h>
#include <cosmo/io/checkpoint.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/point_loop.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>

#include <cosmo/io/parameter_copy.h>

#include "cross_section_problem.h"

#include <sstream>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      /// sweep.csv's columns.
      io::CSVTable
      sweep_columns(const io::ParameterSweep &sweep)
      {
        io::CSVTable table;
        table.add_column("point");
        table.add_column("value", sweep.axis_label());
        table.add_column("converged");
        table.add_column("energy", "E L^2");
        for (const auto &s : kinematics::strain_names)
          table.add_column(s, s[0] == 'n' ? "1" : "1/L");
        for (unsigned int k = 0; k < 6; ++k)
          table.add_column(kinematics::resultant_names[k], k < 3 ? "E L^2" : "E L^3");
        for (unsigned int a = 0; a < 6; ++a)
          for (unsigned int b = a; b < 6; ++b)
            table.add_column("K_" + kinematics::strain_names[a] + "_" + kinematics::strain_names[b]);
        table.add_column("helix_radius", "L");
        table.add_column("helix_pitch", "L");
        table.add_column("n_negative_eigenvalues");
        return table;
      }

      /// Point k of a sweep (its parameters prepared in `prm`, its files in `directory`): its
      /// row and line.
      io::PointLoop::Point
      sweep_point(ParameterHandler &        prm,
                  const io::RunOptions &    options,
                  const io::ParameterSweep &sweep,
                  const unsigned int        k,
                  const std::string &       directory)
      {
        const io::RunOptions point_options = io::PointLoop::point_options(options, prm);
        io::PointLoop::Point p;
        p.row = {double(k), sweep.value(k)};
        std::ostringstream line;
        line << "point " << k + 1 << "/" << sweep.size() << ": " << sweep.label() << " = "
             << sweep.text(k);
        try
          {
            CrossSectionProblem problem;
            problem.parse_parameters(prm);
            problem.run(point_options, prm);
            io::PointLoop::finish_point(point_options, directory);
            const auto &s = problem.final_state();
            const auto  h = kinematics::helix_geometry(kinematics::RodStrains(s.strains));
            p.row.push_back(1);
            p.row.push_back(s.energy);
            p.row.insert(p.row.end(), s.strains.begin(), s.strains.end());
            p.row.insert(p.row.end(), s.resultants.begin(), s.resultants.end());
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int b = a; b < 6; ++b)
                p.row.push_back(s.stiffness(a, b));
            p.row.push_back(h.radius);
            p.row.push_back(h.pitch);
            p.row.push_back(s.n_negative);
            line << "  strains (";
            for (unsigned int i = 0; i < 6; ++i)
              line << (i ? ", " : "") << io::format_significant(s.strains[i], 6);
            line << ")  " << h.description();
          }
        catch (io::RunFailure &e)
          {
            p.outcome = io::PointLoop::Point::Outcome::failed;
            p.row.push_back(0);
            line << "  FAILED: " << e.what();
          }
        catch (io::InputError &e)
          {
            // A value can pass the entry's pattern and still be rejected
            // by the problem (det Fg <= 0 somewhere, ...): that point is
            // bad input, the others still run.
            p.outcome = io::PointLoop::Point::Outcome::rejected;
            p.row.push_back(0);
            line << "  REJECTED: " << e.what();
          }
        p.line = line.str();
        return p;
      }
    } // namespace

    void
    run_study(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      sweep.refuse_distributed_mesh(prm, "Finite element");
      if (!sweep.enabled())
        {
          CrossSectionProblem problem;
          problem.parse_parameters(prm);
          if (problem.distributed_mesh && assembly::ConstitutiveTable::enabled_in(prm))
            throw io::InputError("Finite element", "Distributed", "true",
                                 "a constitutive table spreads its points over the MPI ranks, "
                                 "each on one rank's whole mesh: set Distributed = false");
          // A distributed mesh: every rank runs the path on its part of the mesh.
          if (io::ranks::idle(assembly::ConstitutiveTable::enabled_in(prm) ||
                              problem.distributed_mesh))
            return;
          if (problem.distributed_mesh && io::ranks::size() > 1)
            io::collective_interrupts(MPI_COMM_WORLD);
          problem.run(options, prm);
          return;
        }
      // A study of the first critical point of each value's path (arclength
      // continuation stopping at its first event), or a critical curve.
      prm.enter_subsection("Arclength continuation");
      const bool first_event = prm.get_bool("Stop at first event");
      prm.leave_subsection();
      if (first_event || sweep.critical_curve())
        {
          solvers::CriticalPointStudy study;
          study.application     = "rod_cross_section";
          study.mode_columns    = {"mode_symmetry_X1", "mode_symmetry_X2"};
          study.describe_mode   = [](const std::vector<double> &c) {
            auto word = [](const double p) {
              return p > 0 ? std::string("symmetric") :
                     p < 0 ? std::string("antisymmetric") :
                     p == 0 ? std::string("mixed") : std::string("unclassified (mesh not symmetric)");
            };
            return word(c[0]) + " under the half-turn about X1, " + word(c[1]) +
                   " under the half-turn about X2";
          };
          study.further_columns = assembly::ReducedRodProblem::critical_point_column_names();
          study.make_run        = [](ParameterHandler &p) {
            return std::make_unique<solvers::CriticalPointRunOf<CrossSectionProblem>>(p);
          };
          study.declare_parameters = &CrossSectionProblem::declare_parameters;
          return solvers::run_critical_point_study(prm, options, sweep, study);
        }

      // Each value runs on a copy of the parameters: one now, before the
      // directory is opened, so that a copy that cannot be made ends here.
      (void)io::copy_parameters(prm, &CrossSectionProblem::declare_parameters);
      io::PointLoop::Description d;
      d.application     = "rod_cross_section";
      d.checkpoint_kind = "rod_cross_section sweep";
      // A checkpoint of other parameters is refused before anything is touched.
      d.parameters = io::checkpoint_parameters(prm);
      prm.enter_subsection("Output");
      d.directory = prm.get("Output directory");
      prm.leave_subsection();
      d.entry = sweep.entry();
      for (unsigned int k = 0; k < sweep.size(); ++k)
        d.values.push_back(sweep.text(k));
      io::PointLoop loop(d, sweep_columns(sweep), !options.resume_directory.empty());
      const auto log = io::open_run_directory(d.directory, prm, options.quiet, d.log_file,
                                              !options.resume_directory.empty());
      (*log)("rod_cross_section " + std::string(COSMO_VERSION) + ": " + options.parameter_file +
             ", sweep of '" + sweep.entry() + "' over " + std::to_string(sweep.size()) + " values");
      loop.run(*log, [&](const unsigned int k) {
        const std::string directory = io::ParameterSweep::point_directory(loop.shared_directory(), k);
        // Each value on its own copy of the parameters: the handler stays as given.
        const auto point = io::copy_parameters(prm, &CrossSectionProblem::declare_parameters);
        sweep.prepare_point(*point, k, directory);
        return sweep_point(*point, options, sweep, k, directory);
      });
    }
  } // namespace rod
} // namespace cosmo

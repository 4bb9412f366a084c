// The plate bounded by a rod (part 3): the problem's driver interface; its
// run is in run.cc, the assembly in assembly.cc, the discretization in
// discretization.cc and mesh.cc, the reports in postprocess.cc.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/assumed_shear.h>
#include <cosmo/assembly/local_variables.h>
#include <cosmo/config.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/resources.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/materials/energy_derivatives.h>

#include <cosmo/materials/growth_admissibility.h>

#include "plate_rod_problem.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {
    materials::RodNaturalState
    PlateRodParameters::rim_natural_state(const Point<2> &X, const kinematics::RimFrame &frame,
                                       const double t) const
    {
      materials::RodNaturalState n;
      n.reference_strains = kinematics::rim_reference_strains(X, frame);
      n.growth            = rod_growth_at(t);
      // The model's factor f on the shear stiffnesses GA1, GA2 (the Kirchhoff
      // penalty) as the weight sqrt(f) on the shear strains: K -> D K D, the
      // couplings by sqrt(f), which keeps K positive definite.
      for (const unsigned int k : {0u, 1u})
        n.weights[k] = std::sqrt(model->shear_scale());
      return n;
    }

    kinematics::PlateGrowthAtPoint
    PlateRodParameters::growth_at(const Point<2> &X, const double t) const
    {
      auto g              = kinematics::PlateGrowthAtPoint::of(plate_growth.value(X, t));
      g.natural_curvature = plate_growth.natural_curvature(X, t);
      return g;
    }

    double
    PlateRodParameters::thickness_at(const Point<2> &X) const
    {
      return thickness_profile ? thickness * thickness_profile->value(Point<3>(X[0], X[1], X.norm())) :
                                 thickness;
    }

    void
    PlateRodProblem::setup_system()
    {
      energy_assembly.clear();
      // A stiffness with its constraints eliminated: every diagonal entry is nonzero.
      system.set_nonzero_diagonal(true);
      discretization.reinit();
      discretization.reinit_system(system);
      solution.reinit(discretization.n_dofs());
    }

    double
    PlateRodProblem::energy(const Vector<double> &U)
    {
      Vector<double> R;
      AssertThrow(residual(U, R) == 0, ExcMessage("the energy cannot be evaluated at this state"));
      return energy_assembly.energy();
    }

    int
    PlateRodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
      if (energy_assembly.recall(U, load_parameter, R))
        return std::isfinite(energy_assembly.energy()) ? 0 : 1;
      io::PhaseTimer::Scope scope(timer, "assembly (residual)");
      return energy_assembly.assemble(U, load_parameter, &R, false);
    }

    bool
    PlateRodProblem::store_jacobian(const Vector<double> &U, const unsigned int slot)
    {
      AssertIndexRange(slot, stored_jacobians.size());
      if (distributed_mesh)
        return false;
      io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
      return system.assemble_copy(
        [&] { return energy_assembly.assemble(U, load_parameter, nullptr, true) == 0; }, stored_jacobians[slot]);
    }

    int
    PlateRodProblem::setup_jacobian(const Vector<double> &U)
    {
      // The factorization in place may be this very state's: the start's
      // stability check (run.cc) and the driver's tangent there ask for the
      // same one. The Jacobian depends on nothing but (U, t) within a run.
      // COSMO_NO_REUSE: factorize anyway, to measure against (benchmarks/).
      static const bool reuse = std::getenv("COSMO_NO_REUSE") == nullptr;
      if (reuse && factorization.here(U, load_parameter))
        return 0;
      {
        io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
        if (energy_assembly.assemble(U, load_parameter, nullptr, true) != 0)
          return 1;
      }
      io::PhaseTimer::Scope scope(timer, "factorization");
      try
        {
          system.factorize();
        }
      catch (std::exception &e)
        {
          // (on a distributed mesh only MUMPS's own failure is every rank's:
          // anything else ends this rank, and so all)
          if (distributed_mesh && dynamic_cast<const solvers::FactorizationFailure *>(&e) == nullptr)
            throw;
          factorization.clear();
          record.say(std::string("  factorization failed: ") + e.what());
          return 1;
        }
      factorization.set(U, load_parameter);
      return 0;
    }

    int
    PlateRodProblem::solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst)
    {
      io::PhaseTimer::Scope scope(timer, "solve");
      system.solve(rhs, dst, {});
      discretization.distribute(dst);
      return 0;
    }

    double
    PlateRodProblem::jacobian_abs_form(const Vector<double> &v) const
    {
      return system.absolute_quadratic_form(v);
    }

    void
    PlateRodProblem::residual_weights(Vector<double> &w) const
    {
      // Nodal forces against E h R, nodal moments against E h R^2.
      const double F = plate_law->young() * thickness * radius;
      w.reinit(n_unknowns());
      for (unsigned int i = 0; i < w.size(); ++i)
        w[i] = discretization.dof_component[i] < 3 ? 1 / F : 1 / (F * radius);
    }

    double
    PlateRodParameters::mismatch(const double t) const
    {
      // Uniform isotropic plate growth only: g_r = g_t independent of r.
      const auto g0 = plate_growth.factors(0, t);
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const auto g = plate_growth.factors(radius * i / 10., t);
          if (std::abs(g[0] - g0[0]) > 1e-14 || std::abs(g[1] - g0[0]) > 1e-14)
            return std::numeric_limits<double>::quiet_NaN();
        }
      return analysis::growth_mismatch(g0[0], rod_growth_at(t));
    }
  } // namespace plate_rod
} // namespace cosmo

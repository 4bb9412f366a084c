#include <cosmo/assembly/reduced_rod_problem.h>
#include <cosmo/io/parameters.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/solvers/newton.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cosmo
{
  namespace assembly
  {
    std::array<double, 6>
    ReducedRodProblem::strains_of(const Vector<double> &U) const
    {
      std::array<double, 6> e;
      for (unsigned int k = 0; k < n_strains; ++k)
        e[k] = U[n_field + n_gauge + k];
      return e;
    }

    int
    ReducedRodProblem::assemble(const Vector<double> &U,
                                Vector<double> *      R,
                                const bool            jacobian,
                                FieldIntegrals *      results)
    {
      const auto         e = strains_of(U);
      FieldIntegrals     integrals;
      FullMatrix<double> E(n_strains, n_strains);
      if (R)
        R->reinit(n_unknowns());
      if (jacobian)
        {
          system->clear();
          factorization.clear(); // the factorization no longer matches the matrix
        }
      int status = assemble_field(U, e, R, jacobian, E, integrals);
      const unsigned int nf = n_field;
      if (system && system->distributed())
        {
          // Each rank assembled its cells: decide together, then sum the parts.
          std::vector<double> flag = {double(status)};
          field_layout.max(flag);
          status = flag[0] != 0 ? 1 : 0;
          if (jacobian)
            add_distributed_gauge_entries();
          if (status != 0)
            return 1;
          sum_rank_parts(R, jacobian, E, integrals.energy, integrals.resultants,
                         integrals.min_elastic_J);
        }
      if (status != 0)
        return 1; // recoverable: Newton's line search or the driver cuts back

      // Gauge constraints with their multipliers, and the strain rows.
      if (R)
        {
          add_gauge_residuals(*R, U);
          const auto eP = prescribed_strains_at(load_parameter);
          const auto nP = resultants_at(load_parameter);
          for (unsigned int k = 0; k < n_strains; ++k)
            (*R)[nf + n_gauge + k] = strain_is_free[k] ? integrals.resultants[k] - nP[k] : e[k] - eP[k];
        }
      if (jacobian)
        {
          if (!system->distributed())
            set_gauge_entries();
          system->border_block = E;
        }
      if (results)
        *results = integrals;
      return 0;
    }

    void
    ReducedRodProblem::located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode)
    {
      record_event(e, strains_of(U), U, mode);
    }

    void
    ReducedRodProblem::save_progress(io::CheckpointWriter &w) const
    {
      w.put(load_parameter);
      w.put(total_newton_iterations);
      save_records(w);
    }

    void
    ReducedRodProblem::load_progress(io::CheckpointReader &r)
    {
      load_parameter          = r.get_double();
      total_newton_iterations = r.get_unsigned();
      load_records(r);
    }

    std::vector<double>
    ReducedRodProblem::critical_point_columns(const solvers::EventRecord &e) const
    {
      const auto strains = strains_of(Vector<double>(e.state.begin(), e.state.end()));
      return std::vector<double>(strains.begin(), strains.end());
    }

    std::vector<std::string>
    ReducedRodProblem::critical_point_column_names()
    {
      std::vector<std::string> names;
      for (const auto &s : kinematics::strain_names)
        names.push_back(s + "_critical");
      return names;
    }

    void
    ReducedRodProblem::follow_path(const solvers::ArclengthSettings &               arclength,
                                   const solvers::NewtonSettings &                  newton,
                                   Vector<double> &                                 U,
                                   const std::function<void(const std::string &)> &progress)
    {
      solvers::ArclengthContinuation driver(arclength, newton);
      driver.progress = progress;
      if (!critical_guess)
        {
          checkpoints.connect(driver, *this, timer);
          driver.run(*this, U, 0.);
          return;
        }
      const auto record = solvers::locate_continued_critical_point(driver, *this, *critical_guess, newton);
      U = Vector<double>(record.state.begin(), record.state.end());
      solvers::StepReport report;
      report.t          = record.event.lambda;
      report.n_negative = record.event.n_negative_after;
      report.final      = true;
      set_load_parameter(report.t);
      // The inertia and the condensed stiffness from the last factorization,
      // as plate_rod's continued points do: not factorizing again is what a
      // continued point saves.
      factorization.with_last = true;
      converged_step(U, report);
      factorization.with_last = false;
    }

    int
    ReducedRodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
      io::PhaseTimer::Scope scope(timer, "assembly (residual)");
      return assemble(U, &R, false);
    }


    int
    ReducedRodProblem::setup_jacobian(const Vector<double> &U)
    {
      // Newton's first Jacobian is often the one condensed_state() has just
      // factorized at the same state and load (the next point of a table,
      // the next step of a path from its converged start): the Jacobian
      // does not depend on the target strains (their rows are the
      // identity) nor on the held resultants (dead loads), so the
      // factorization in place is exactly it.
      // COSMO_NO_REUSE: refactorize anyway, to measure against (benchmarks/).
      static const bool reuse = std::getenv("COSMO_NO_REUSE") == nullptr;
      if (reuse && factorization.here(U, load_parameter))
        {
          ++total_newton_iterations;
          timer.add("factorization reused", 0.); // counted in summary.json timings
          return 0;
        }
      {
        io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
        if (assemble(U, nullptr, true) != 0)
          return 1;
      }
      io::PhaseTimer::Scope scope(timer, "factorization");
      try
        {
          system->factorize();
        }
      catch (std::exception &e)
        {
          // (on a distributed mesh only MUMPS's own failure is every rank's:
          // anything else ends this rank, and so all)
          if (system->distributed() &&
              dynamic_cast<const solvers::FactorizationFailure *>(&e) == nullptr)
            throw;
          factorization.clear();
          if (report)
            report(std::string("  factorization failed: ") + e.what());
          return 1;
        }
      factorization.set(U, load_parameter);
      ++total_newton_iterations;
      return 0;
    }

    bool
    ReducedRodProblem::store_jacobian(const Vector<double> &U, const unsigned int slot)
    {
      AssertIndexRange(slot, stored_jacobians.size());
      io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
      // (assembling clears the mark; the factorization stays the marked one's)
      const solvers::FactorizationMark mark = factorization;
      const bool stored = system->assemble_copy([&] { return assemble(U, nullptr, true) == 0; },
                                                stored_jacobians[slot]);
      factorization = mark;
      return stored;
    }

    void
    ReducedRodProblem::stored_jacobian_vmult(const unsigned int slot, const Vector<double> &x, Vector<double> &y) const
    {
      system->vmult(y, x, std::vector<bool>(strain_is_free.begin(), strain_is_free.end()), stored_jacobians[slot]);
    }

    int
    ReducedRodProblem::solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst)
    {
      io::PhaseTimer::Scope scope(timer, "solve");
      std::vector<bool>     free(strain_is_free.begin(), strain_is_free.end());
      system->solve(rhs, dst, free);
      return 0;
    }

    int
    ReducedRodProblem::n_negative_eigenvalues()
    {
      std::vector<bool> free(strain_is_free.begin(), strain_is_free.end());
      return system->n_negative_eigenvalues(free, n_gauge);
    }

    double
    ReducedRodProblem::jacobian_abs_form(const Vector<double> &v) const
    {
      return system ? system->absolute_quadratic_form(v) : -1.;
    }

    void
    ReducedRodProblem::mode_mask(Vector<double> &mask) const
    {
      // Mode shapes live in the field; multipliers and strains are not part of them.
      mask.reinit(n_unknowns());
      for (unsigned int i = 0; i < n_field; ++i)
        mask[i] = 1;
    }

    void
    ReducedRodProblem::stability_mask(Vector<double> &mask) const
    {
      // A free strain is an unknown of the energy like the field: the
      // critical mode of a twisted section moves it, and the Hessian's
      // coupling to it changes with the load. (Prescribed strains' rows fix
      // them; the multipliers are not unknowns of the energy.)
      mode_mask(mask);
      for (unsigned int k = 0; k < n_strains; ++k)
        if (strain_is_free[k])
          mask[n_field + n_gauge + k] = 1;
    }

    void
    ReducedRodProblem::residual_weights(Vector<double> &w) const
    {
      // Every row dimensionless (see NewtonSettings): nodal forces ~ F/D
      // (F a force per rod length, e.g. E D^2), constraints ~ D^3 (D^4 with
      // a lever arm), resultants ~ F and F D.
      double F = 1, D = 1;
      residual_scales(F, D);
      w.reinit(n_unknowns());
      for (unsigned int i = 0; i < n_field; ++i)
        w[i] = D / F;
      std::array<double, 6> g;
      gauge_weights(g);
      for (unsigned int k = 0; k < n_gauge; ++k)
        w[n_field + k] = g[k];
      for (unsigned int k = 0; k < n_strains; ++k)
        w[n_field + n_gauge + k] =
          strain_is_free[k] ? (k < 3 ? 1. / F : 1. / (F * D)) : (k < 3 ? 1. : D);
    }

    void
    ReducedRodProblem::gauge_weights(std::array<double, 6> &w) const
    {
      double F = 1, D = 1;
      residual_scales(F, D);
      for (unsigned int k = 0; k < n_gauge; ++k)
        w[k] = k < 3 ? 1. / std::pow(D, 3) : 1. / std::pow(D, 4);
    }

    ReducedRodState
    ReducedRodProblem::condensed_state(const Vector<double> &U)
    {
      ReducedRodState s;
      FieldIntegrals  a;
      ++n_condensed_states;
      // The arclength driver has just factorized at this very state (for the
      // tangent and the stability count): then only the integrals are
      // needed, from the cheap residual assembly.
      const bool reuse = factorization.at.size() == U.size() &&
                         (factorization.with_last || factorization.here(U, load_parameter));
      factorization.with_last = false;
      if (reuse)
        {
          io::PhaseTimer::Scope scope(timer, "assembly (residual)");
          AssertThrow(assemble(U, nullptr, false, &a) == 0,
                      ExcMessage("inadmissible state (det Fe <= 0) at a converged step"));
        }
      else
        {
          {
            io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
            AssertThrow(assemble(U, nullptr, true, &a) == 0,
                        ExcMessage("inadmissible state (det Fe <= 0) at a converged step"));
          }
          io::PhaseTimer::Scope scope(timer, "factorization");
          system->factorize();
          factorization.set(U, load_parameter);
        }
      s.t             = load_parameter;
      s.energy        = a.energy;
      s.min_elastic_J = a.min_elastic_J;
      s.strains       = strains_of(U);
      s.resultants    = a.resultants;
      for (unsigned int k = 0; k < n_gauge; ++k)
        s.multipliers[k] = U[n_field + k];
      s.stiffness  = system->schur_complement();
      s.n_negative = n_negative_eigenvalues();
      return s;
    }
  } // namespace assembly
} // namespace cosmo

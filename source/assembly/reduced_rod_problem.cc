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
    void
    ReducedRodProblem::declare_strain_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rod strains");
      prm.declare_entry("Mode", "natural shape",
                        Patterns::Selection("prescribed strains|natural shape"),
                        "prescribed strains: the six strains are ramped from the "
                        "reference (0,0,1,0,0,0) to 'Strains' (except 'Free strains'); "
                        "natural shape: all six strains are free, their resultants vanish "
                        "('Strains', 'Free strains' and 'Path' must then be left unset).");
      prm.declare_entry("Strains", "0, 0, 1, 0, 0, 0",
                        Patterns::List(Patterns::Double(), 6, 6),
                        "Target strains nu1, nu2, nu3, kappa1, kappa2, kappa3 in the "
                        "director frame (nu dimensionless, kappa per unit reference "
                        "length); reached at load parameter t = 1.");
      prm.declare_entry("Free strains", "",
                        Patterns::MultipleSelection("nu1|nu2|nu3|kappa1|kappa2|kappa3"),
                        "In 'prescribed strains' mode: strains left free (their "
                        "resultant vanishes, or reaches its entry of 'Resultants'), e.g. "
                        "'nu3' for twisting at zero axial force.");
      prm.declare_entry("Resultants", "0, 0, 0, 0, 0, 0",
                        Patterns::List(Patterns::Double(), 6, 6),
                        "Target resultants n1, n2, n3, m1, m2, m3 (force E L^2, moment E L^3) "
                        "of the free strains, ramped as t times the target (reached at t = 1): "
                        "resultant control, e.g. a tension n3 with nu3 free, a torque m3 with "
                        "kappa3 free. The entry of a prescribed strain must be 0 (a strain is "
                        "prescribed or its resultant is).");
      prm.declare_entry("Path", "", Patterns::Anything(),
                        "A path through strain space instead of the straight ramp to "
                        "'Strains': waypoints of six strains separated by ';', e.g. "
                        "'0,0,1,0.5,0,0; 0,0,1,0.5,0,1' (bend, then twist while bent). The "
                        "load parameter t runs through them at equal intervals from the "
                        "reference; the last waypoint is reached at t = 1. A free strain "
                        "must not change along the path.");
      prm.leave_subsection();
    }

    namespace
    {
      /// 'Mode = natural shape' (section 'Rod strains' entered): all six strains are unknowns
      /// there, so what prescribes or frees a strain has no effect, and a user who set it
      /// meant something else.
      void
      refuse_prescriptions_in_natural_shape(ParameterHandler &prm)
      {
        for (const auto &[entry, unset] :
             std::vector<std::pair<std::string, std::string>>{{"Strains", "0, 0, 1, 0, 0, 0"},
                                                              {"Free strains", ""},
                                                              {"Path", ""},
                                                              {"Resultants", "0, 0, 0, 0, 0, 0"}})
          {
            const std::string text = prm.get(entry);
            bool              is_unset = text == unset;
            if (!is_unset && (entry == "Strains" || entry == "Resultants"))
              try
                {
                  is_unset = Utilities::string_to_double(Utilities::split_string_list(text, ',')) ==
                             (entry == "Strains" ? std::vector<double>{0, 0, 1, 0, 0, 0} :
                                                   std::vector<double>(6, 0.));
                }
              catch (...)
                {}
            if (!is_unset)
              throw io::InputError("Rod strains", entry, text,
                                   "nothing in 'Mode = natural shape' (all six strains are free "
                                   "there and this entry is ignored): set 'Mode = prescribed "
                                   "strains' to use it, or remove it");
          }
      }

      /// A strain of a size no rod has (a shear or stretch of 100, a curvature of 100 turns per
      /// unit length) is a typing error, and would only make the nonlinear solver wander.
      void
      check_strain_sizes(const std::string &entry, const std::string &text, const std::array<double, 6> &v)
      {
        for (unsigned int k = 0; k < 6; ++k)
          if (std::abs(v[k]) > (k < 3 ? 100. : 200. * M_PI))
            {
              std::ostringstream m;
              m << "strains of a rod: |nu| <= 100 and |kappa| <= 200 pi per unit length ("
                << kinematics::strain_names[k] << " = " << v[k] << " is not)";
              throw io::InputError("Rod strains", entry, text, m.str());
            }
      }
    } // namespace

    void
    ReducedRodProblem::parse_strain_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rod strains");
      mode         = prm.get("Mode");
      if (mode == "natural shape")
        refuse_prescriptions_in_natural_shape(prm);
      const auto e = io::get_double_list(prm, "Strains", 6, "Rod strains");
      check_strain_sizes("Strains", prm.get("Strains"), {{e[0], e[1], e[2], e[3], e[4], e[5]}});
      std::copy(e.begin(), e.end(), target_strains.begin());
      {
        const auto n = io::get_double_list(prm, "Resultants", 6, "Rod strains");
        std::copy(n.begin(), n.end(), target_resultants.begin());
        for (unsigned int k = 0; k < 6; ++k)
          if (!std::isfinite(target_resultants[k]))
            throw io::InputError("Rod strains", "Resultants", prm.get("Resultants"),
                                 "six finite numbers");
      }
      const auto free_names = Utilities::split_string_list(prm.get("Free strains"), ',');
      strain_is_free.fill(mode == "natural shape");
      for (const auto &name : free_names)
        for (unsigned int k = 0; k < 6; ++k)
          if (kinematics::strain_names[k] == name)
            strain_is_free[k] = true;
      if (mode == "prescribed strains")
        {
          const auto ref = kinematics::RodStrains::reference().as_array();
          for (unsigned int k = 0; k < 6; ++k)
            if (strain_is_free[k] && target_strains[k] != ref[k])
              throw io::InputError("Rod strains", "Strains", prm.get("Strains"),
                                   kinematics::strain_names[k] +
                                     " is in 'Free strains' and set here to a value other "
                                     "than its reference: a strain is either prescribed or "
                                     "free (leave it at the reference value)");
          for (unsigned int k = 0; k < 6; ++k)
            if (!strain_is_free[k] && target_resultants[k] != 0)
              throw io::InputError("Rod strains", "Resultants", prm.get("Resultants"),
                                   kinematics::resultant_names[k] + " = " +
                                     io::format_number(target_resultants[k]) + " for the prescribed " +
                                     kinematics::strain_names[k] +
                                     ": a resultant can only be prescribed for a strain in 'Free "
                                     "strains' (a strain is prescribed or its resultant is)");
        }
      waypoints.clear();
      const std::string path_text = prm.get("Path");
      for (const auto &point : Utilities::split_string_list(path_text, ';'))
        {
          std::vector<double> v;
          try
            {
              v = Utilities::string_to_double(Utilities::split_string_list(point, ','));
            }
          catch (...)
            {}
          if (v.size() != 6)
            throw io::InputError("Rod strains", "Path", path_text,
                                 "waypoints of six numbers separated by ';' ('" + point +
                                   "' is not six numbers)");
          for (const double x : v)
            if (!std::isfinite(x))
              throw io::InputError("Rod strains", "Path", path_text,
                                   "waypoints of six finite numbers ('" + point +
                                     "' has nan or inf)");
          waypoints.push_back({{v[0], v[1], v[2], v[3], v[4], v[5]}});
          check_strain_sizes("Path", path_text, waypoints.back());
        }
      if (!waypoints.empty())
        {
          target_strains = waypoints.back();
          // A strip cannot be asked for a strain twice: free (its resultant
          // vanishes) and prescribed by the path.
          const auto ref = kinematics::RodStrains::reference().as_array();
          for (unsigned int k = 0; k < 6; ++k)
            if (strain_is_free[k])
              for (const auto &w : waypoints)
                if (w[k] != ref[k])
                  throw io::InputError("Rod strains", "Path", path_text,
                                       "the path prescribes " + kinematics::strain_names[k] +
                                         ", which 'Free strains' (or the natural-shape mode) "
                                         "leaves free: a strain is either prescribed or free");
        }
      prm.leave_subsection();
    }

    std::array<double, 6>
    ReducedRodProblem::strains_of(const Vector<double> &U) const
    {
      std::array<double, 6> e;
      for (unsigned int k = 0; k < n_strains; ++k)
        e[k] = U[n_field + n_gauge + k];
      return e;
    }

    std::array<double, 6>
    ReducedRodProblem::prescribed_strains_at(const double t) const
    {
      const auto            ref = kinematics::RodStrains::reference().as_array();
      std::array<double, 6> e;
      if (waypoints.empty())
        {
          for (unsigned int k = 0; k < n_strains; ++k)
            e[k] = ref[k] + t * (target_strains[k] - ref[k]);
          return e;
        }
      // Piecewise linear through reference, waypoint 1, ..., waypoint K.
      const unsigned int K   = waypoints.size();
      const double       x   = std::min(std::max(t, 0.), 1.) * K;
      const unsigned int seg = std::min(static_cast<unsigned int>(x), K - 1);
      const auto &       a   = seg == 0 ? ref : waypoints[seg - 1];
      const auto &       b   = waypoints[seg];
      for (unsigned int k = 0; k < n_strains; ++k)
        e[k] = a[k] + (x - seg) * (b[k] - a[k]);
      return e;
    }

    void
    ReducedRodProblem::setup_bordered_system(DynamicSparsityPattern &            field_pattern,
                                             const std::array<Vector<double>, 6> &rows,
                                             const std::string &                  linear_solver)
    {
      constraint_rows = rows;
      n_field         = rows[0].size();
      DynamicSparsityPattern dsp(n_field + n_gauge);
      for (unsigned int i = 0; i < n_field; ++i)
        for (auto it = field_pattern.begin(i); it != field_pattern.end(i); ++it)
          dsp.add(i, it->column());
      for (unsigned int k = 0; k < n_gauge; ++k)
        for (unsigned int i = 0; i < n_field; ++i)
          if (constraint_rows[k][i] != 0)
            {
              dsp.add(n_field + k, i);
              dsp.add(i, n_field + k);
            }
      system = std::make_unique<BorderedSystem>(
        solvers::SparseDirectSolver::kind_from_string(linear_solver));
      system->reinit(dsp, n_strains);
    }

    void
    ReducedRodProblem::setup_distributed_bordered_system(
      const IndexSet &                                                 owned_field,
      const IndexSet &                                                 relevant_field,
      const std::function<void(TrilinosWrappers::SparsityPattern &)> &add_field_entries,
      const std::array<Vector<double>, 6> &                            rows,
      MPI_Comm                                                         comm)
    {
      constraint_rows = rows;
      n_field         = rows[0].size();
      const bool last = Utilities::MPI::this_mpi_process(comm) + 1 == Utilities::MPI::n_mpi_processes(comm);
      IndexSet   owned(n_field + n_gauge), writable(n_field + n_gauge);
      owned.add_indices(owned_field);
      writable.add_indices(relevant_field);
      if (last)
        {
          owned.add_range(n_field, n_field + n_gauge);
          writable.add_range(n_field, n_field + n_gauge);
        }
      owned.compress();
      writable.compress();
      TrilinosWrappers::SparsityPattern sp;
      sp.reinit(owned, owned, writable, comm);
      add_field_entries(sp);
      // C: its columns on the rows of the DoFs' owners, its rows on the last rank.
      for (unsigned int k = 0; k < n_gauge; ++k)
        for (unsigned int i = 0; i < n_field; ++i)
          if (constraint_rows[k][i] != 0)
            {
              if (owned_field.is_element(i))
                sp.add(i, n_field + k);
              if (last)
                sp.add(n_field + k, i);
            }
      sp.compress();
      field_layout = solvers::ReplicatedVectorLayout(comm, owned_field);
      system       = std::make_unique<BorderedSystem>();
      system->reinit(sp, n_strains, solvers::ReplicatedVectorLayout(comm, owned));
      // (the strains' and gauge rows' residuals are computed from whole vectors on every rank)
    }

    namespace
    {
      /**
       * The gauge block C of a distributed system (A is zeroed: adding
       * sets), on the rows this rank owns, a row per call (entry by entry
       * took a second per assembly of 250 000 unknowns); the last rank adds
       * C's own rows. Compresses the matrix.
       */
      void
      add_distributed_gauge_entries(BorderedSystem &                       system,
                                    const solvers::ReplicatedVectorLayout &field_layout,
                                    const std::array<Vector<double>, 6> &  constraint_rows,
                                    const unsigned int                     nf)
      {
        constexpr unsigned int n_gauge = ReducedRodProblem::n_gauge;
        const bool             last    = field_layout.is_last_rank();
        std::vector<types::global_dof_index> columns;
        std::vector<double>                  values;
        for (types::global_dof_index i = 0; i < nf; ++i)
          if (field_layout.owns(i))
            {
              columns.clear();
              values.clear();
              for (unsigned int k = 0; k < n_gauge; ++k)
                if (constraint_rows[k][i] != 0)
                  {
                    columns.push_back(nf + k);
                    values.push_back(constraint_rows[k][i]);
                  }
              if (!columns.empty())
                system.distributed_matrix.add(i, columns.size(), columns.data(), values.data());
            }
        if (last)
          for (unsigned int k = 0; k < n_gauge; ++k)
            {
              columns.clear();
              values.clear();
              for (types::global_dof_index i = 0; i < nf; ++i)
                if (constraint_rows[k][i] != 0)
                  {
                    columns.push_back(i);
                    values.push_back(constraint_rows[k][i]);
                  }
              system.distributed_matrix.add(nf + k, columns.size(), columns.data(), values.data());
            }
        system.distributed_matrix.compress(VectorOperation::add);
      }

      /**
       * Sum the ranks' parts of a distributed assembly: the residual R (may
       * be null), the energy and resultants, and with the `jacobian` the
       * system's border columns and the block E; the smallest det Fe over
       * the ranks.
       */
      void
      sum_rank_parts(const solvers::ReplicatedVectorLayout &field_layout,
                     BorderedSystem &                       system,
                     Vector<double> *                       R,
                     const bool                             jacobian,
                     FullMatrix<double> &                   E,
                     double &                               energy,
                     std::array<double, 6> &                resultants,
                     double &                               min_elastic_J)
      {
        if (R)
          field_layout.sum_parts(*R);
        std::vector<double> sums = {energy};
        sums.insert(sums.end(), resultants.begin(), resultants.end());
        if (jacobian)
          {
            for (auto &b : system.border_columns)
              field_layout.sum_parts(b);
            sums.insert(sums.end(), E.begin(), E.end());
          }
        field_layout.sum(sums);
        energy = sums[0];
        for (unsigned int k = 0; k < 6; ++k)
          resultants[k] = sums[1 + k];
        if (jacobian)
          std::copy(sums.begin() + 7, sums.end(), E.begin());
        std::vector<double> smallest = {-min_elastic_J};
        field_layout.max(smallest);
        min_elastic_J = -smallest[0];
      }

      /// The gauge constraints with their multipliers U[nf + k]: C^T lambda
      /// into the field rows of R, C U into its gauge rows.
      void
      add_gauge_residuals(Vector<double> &                     R,
                          const Vector<double> &               U,
                          const std::array<Vector<double>, 6> &constraint_rows,
                          const unsigned int                   nf)
      {
        for (unsigned int k = 0; k < ReducedRodProblem::n_gauge; ++k)
          {
            const double lambda_k = U[nf + k];
            double       cu       = 0;
            for (unsigned int i = 0; i < nf; ++i)
              {
                const double cki = constraint_rows[k][i];
                if (cki != 0)
                  {
                    R[i] += lambda_k * cki;
                    cu += cki * U[i];
                  }
              }
            R[nf + k] = cu;
          }
      }
    } // namespace

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
          factorized_at.reinit(0); // the factorization no longer matches the matrix
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
            add_distributed_gauge_entries(*system, field_layout, constraint_rows, nf);
          if (status != 0)
            return 1;
          sum_rank_parts(field_layout, *system, R, jacobian, E, integrals.energy,
                         integrals.resultants, integrals.min_elastic_J);
        }
      if (status != 0)
        return 1; // recoverable: Newton's line search or the driver cuts back

      // Gauge constraints with their multipliers, and the strain rows.
      if (R)
        {
          add_gauge_residuals(*R, U, constraint_rows, nf);
          const auto eP = prescribed_strains_at(load_parameter);
          const auto nP = resultants_at(load_parameter);
          for (unsigned int k = 0; k < n_strains; ++k)
            (*R)[nf + n_gauge + k] = strain_is_free[k] ? integrals.resultants[k] - nP[k] : e[k] - eP[k];
        }
      if (jacobian)
        {
          if (!system->distributed())
            for (unsigned int k = 0; k < n_gauge; ++k)
              for (unsigned int i = 0; i < nf; ++i)
                if (constraint_rows[k][i] != 0)
                  {
                    system->matrix.set(nf + k, i, constraint_rows[k][i]);
                    system->matrix.set(i, nf + k, constraint_rows[k][i]);
                  }
          system->border_block = E;
        }
      if (results)
        *results = integrals;
      return 0;
    }

    void
    ReducedRodProblem::add_state_to_summary(
      io::JSON &                                            j,
      const ReducedRodState &                               s,
      const std::function<void(unsigned int, io::JSON &)> &event_extra) const
    {
      using io::JSON;
      j["energy"] = s.energy;
      for (unsigned int k = 0; k < 6; ++k)
        {
          j["strains"][kinematics::strain_names[k]]       = s.strains[k];
          j["resultants"][kinematics::resultant_names[k]] = s.resultants[k];
        }
      j["multipliers"] = JSON::array(std::vector<double>(s.multipliers.begin(), s.multipliers.end()));
      // Resultant control: what the free strains' resultants are held at (t nbar).
      if (std::any_of(target_resultants.begin(), target_resultants.end(), [](double n) { return n != 0; }))
        {
          const auto held = resultants_at(s.t);
          for (unsigned int k = 0; k < 6; ++k)
            if (strain_is_free[k])
              j["held_resultants"][kinematics::resultant_names[k]] = held[k];
        }
      JSON K           = JSON::array();
      for (unsigned int a = 0; a < s.stiffness.m(); ++a)
        {
          std::vector<double> row(6);
          for (unsigned int b = 0; b < 6; ++b)
            row[b] = s.stiffness(a, b);
          K.push_back(JSON::array(row));
        }
      j["stiffness"]                           = K;
      j["stiffness_order"]                     = "nu1, nu2, nu3, kappa1, kappa2, kappa3";
      j["stability"]["n_negative_eigenvalues"] = s.n_negative;
      JSON ev                                  = JSON::array();
      for (unsigned int k = 0; k < located_events.size(); ++k)
        {
          const auto &e          = located_events[k];
          JSON        x          = JSON::object();
          x["kind"]              = e.name();
          x["t"]                 = e.lambda; // the load parameter, as in steps.csv (all applications)
          x["branch"]            = e.branch;
          x["n_negative_before"] = e.n_negative_before;
          x["n_negative_after"]  = e.n_negative_after;
          x["eigenvalue"]        = e.eigenvalue;
          solvers::add_location_to_json(e, x);
          for (unsigned int c = 0; c < 6; ++c)
            x["strains"][kinematics::strain_names[c]] = strains_at_events[k][c];
          if (event_extra)
            event_extra(k, x);
          ev.push_back(x);
        }
      j["events"] = ev;
    }

    void
    ReducedRodProblem::located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode)
    {
      located_events.push_back(e);
      strains_at_events.push_back(strains_of(U));
      solvers::EventRecord r;
      r.event = e;
      r.state.assign(U.begin(), U.end());
      if (mode)
        r.mode.assign(mode->begin(), mode->end());
      records.push_back(std::move(r));
    }

    void
    ReducedRodProblem::save_progress(io::CheckpointWriter &w) const
    {
      w.put(load_parameter);
      w.put(total_newton_iterations);
      w.put(std::uint64_t(visited.size()));
      for (const auto &p : visited)
        {
          w.put(p.t);
          w.put(p.branch);
          w.put(p.energy);
          w.put(p.n_negative);
          w.put_vector(p.strains);
          w.put_vector(p.resultants);
        }
      w.put(std::uint64_t(records.size()));
      for (unsigned int k = 0; k < records.size(); ++k)
        {
          records[k].save(w);
          w.put_vector(strains_at_events[k]);
        }
    }

    void
    ReducedRodProblem::load_progress(io::CheckpointReader &r)
    {
      auto get6 = [&r](std::array<double, 6> &a) {
        const auto v = r.get_vector();
        if (v.size() != 6)
          throw std::runtime_error("the checkpoint is damaged (6 strains expected)");
        std::copy(v.begin(), v.end(), a.begin());
      };
      load_parameter          = r.get_double();
      total_newton_iterations = r.get_unsigned();
      visited.resize(r.get_size());
      for (auto &p : visited)
        {
          p.t          = r.get_double();
          p.branch     = r.get_unsigned();
          p.energy     = r.get_double();
          p.n_negative = r.get_int();
          get6(p.strains);
          get6(p.resultants);
        }
      records.resize(r.get_size());
      strains_at_events.resize(records.size());
      located_events.clear();
      for (unsigned int k = 0; k < records.size(); ++k)
        {
          records[k].load(r);
          get6(strains_at_events[k]);
          located_events.push_back(records[k].event);
        }
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
          connect_checkpoints(driver);
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
      report_with_last_factorization = true;
      converged_step(U, report);
      report_with_last_factorization = false;
    }

    int
    ReducedRodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
      io::PhaseTimer::Scope scope(timer, "assembly (residual)");
      return assemble(U, &R, false);
    }

    bool
    ReducedRodProblem::factorized_here(const Vector<double> &U) const
    {
      return factorized_load == load_parameter && solvers::same_point(U, factorized_at);
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
      if (reuse && factorized_here(U))
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
          factorized_at.reinit(0);
          if (report)
            report(std::string("  factorization failed: ") + e.what());
          return 1;
        }
      factorized_at   = U;
      factorized_load = load_parameter;
      ++total_newton_iterations;
      return 0;
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

    std::array<double, 6>
    ReducedRodProblem::resultants_at(const double t) const
    {
      std::array<double, 6> n;
      for (unsigned int k = 0; k < n_strains; ++k)
        n[k] = strain_is_free[k] ? t * target_resultants[k] : 0.;
      return n;
    }

    std::array<double, 6>
    ReducedRodProblem::prescribed_strain_rate(const double t) const
    {
      const auto            ref = kinematics::RodStrains::reference().as_array();
      std::array<double, 6> r{};
      if (waypoints.empty())
        {
          for (unsigned int k = 0; k < n_strains; ++k)
            r[k] = target_strains[k] - ref[k];
          return r;
        }
      if (t < 0 || t > 1)
        return r;
      const unsigned int K   = waypoints.size();
      const unsigned int seg = std::min(static_cast<unsigned int>(t * K), K - 1);
      const auto &       a   = seg == 0 ? ref : waypoints[seg - 1];
      for (unsigned int k = 0; k < n_strains; ++k)
        r[k] = K * (waypoints[seg][k] - a[k]);
      return r;
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
      const bool reuse = factorized_at.size() == U.size() && (report_with_last_factorization || factorized_here(U));
      report_with_last_factorization = false;
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
          factorized_at   = U;
          factorized_load = load_parameter;
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

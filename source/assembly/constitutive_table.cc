#include <deal.II/base/utilities.h>

#include <cosmo/assembly/constitutive_table.h>
#include <cosmo/io/resources.h>
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/solvers/newton.h>

#include <cmath>
#include <iomanip>
#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>
#include <tuple>

#include "constitutive_table_h5.h"

namespace cosmo
{
  namespace assembly
  {
    void
    ConstitutiveTable::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Constitutive table");
      prm.declare_entry("Enabled", "false", Patterns::Bool(),
                        "Instead of one path: energy, resultants and stiffness on a grid of "
                        "two strains (table.csv, table.h5 in the output directory); the "
                        "other strains are prescribed or free as in 'Rod strains'.");
      const std::string names = "nu1|nu2|nu3|kappa1|kappa2|kappa3";
      prm.declare_entry("First strain", "kappa1", Patterns::Selection(names), "The first axis.");
      prm.declare_entry("First range", "-1, 1, 5", Patterns::List(Patterns::Double(), 3, 3),
                        "From, To, Number of values of the first strain.");
      prm.declare_entry("Second strain", "kappa3", Patterns::Selection(names), "The second axis.");
      prm.declare_entry("Second range", "-1, 1, 5", Patterns::List(Patterns::Double(), 3, 3),
                        "From, To, Number of values of the second strain.");
      prm.leave_subsection();
    }

    void
    ConstitutiveTable::run_in(io::RunRecord &              record,
                              Vector<double> &             solution,
                              const std::array<double, 6> &base,
                              const std::array<double, 6> &start_strains,
                              const Resolver &             resolve,
                              const std::string &          directory,
                              const TableDescription &     description) const
    {
      Vector<double>     start;
      TableCheckpointing cp;
      cp.write      = [&record](const io::CheckpointWriter &w) { record.write_checkpoint(w); };
      cp.save_start = [&](io::CheckpointWriter &w) { w.put_vector(start); };
      cp.set_start = [&](const std::vector<double> &v) {
        start.reinit(v.size());
        std::copy(v.begin(), v.end(), start.begin());
        solution = start;
      };
      cp.read_in  = [&record](const std::string &d) { return record.read_checkpoint_in(d); };
      cp.resuming = record.resuming();
      run(base, start_strains, resolve, [&]() { start = solution; }, [&]() { solution = start; },
          directory, record.reporter(), description, cp);
    }

    bool
    ConstitutiveTable::enabled_in(ParameterHandler &prm)
    {
      prm.enter_subsection("Constitutive table");
      const bool enabled = prm.get_bool("Enabled");
      prm.leave_subsection();
      return enabled;
    }

    void
    ConstitutiveTable::check_axes(const std::array<bool, 6> &free_strains) const
    {
      if (is_enabled)
        for (const unsigned int k : {first, second})
          if (free_strains[k])
            throw io::InputError("Constitutive table", k == first ? "First strain" : "Second strain",
                                 kinematics::strain_names[k],
                                 "a prescribed strain: this one is free ('Rod strains / Mode' "
                                 "or 'Free strains'), so its value would be ignored");
    }

    void
    ConstitutiveTable::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Constitutive table");
      is_enabled = prm.get_bool("Enabled");
      auto index = [](const std::string &name) {
        for (unsigned int k = 0; k < 6; ++k)
          if (kinematics::strain_names[k] == name)
            return k;
        return 0u;
      };
      first  = index(prm.get("First strain"));
      second = index(prm.get("Second strain"));
      const auto r1 = io::get_range(prm, "First range", "Constitutive table");
      const auto r2 = io::get_range(prm, "Second range", "Constitutive table");
      from1 = r1.from, to1 = r1.to, n1 = r1.n;
      from2 = r2.from, to2 = r2.to, n2 = r2.n;
      // The sizes a rod's strains can have, as for 'Rod strains / Strains'
      // (reduced_rod_problem.cc): |nu| <= 100, |kappa| <= 200 pi.
      for (const auto &[entry, k, range] :
           {std::tuple{"First range", first, r1}, std::tuple{"Second range", second, r2}})
        if (!(std::max(std::abs(range.from), std::abs(range.to)) <= (k < 3 ? 100. : 200. * M_PI)))
          throw io::InputError("Constitutive table", entry, prm.get(entry),
                               std::string("strains of a rod: |nu| <= 100 and |kappa| <= 200 pi "
                                           "per unit length (this axis is ") +
                                 kinematics::strain_names[k] + ")");
      // Refused before anything is allocated (1e5 x 1e5 points ended in
      // std::bad_alloc); the estimate is printed when the table starts.
      if (is_enabled)
        io::check_points_memory(double(n1) * n2, bytes_per_point, io::estimated_memory(0, 1),
                                "Constitutive table", n1 >= n2 ? "First range" : "Second range",
                                prm.get(n1 >= n2 ? "First range" : "Second range") +
                                  "' (with '" + (n1 >= n2 ? "Second range" : "First range") +
                                  "' = '" + prm.get(n1 >= n2 ? "Second range" : "First range"));
      if (is_enabled && first == second)
        throw io::InputError("Constitutive table", "Second strain", prm.get("Second strain"),
                             "a strain other than the first one (a path asks for each strain once)");
      prm.leave_subsection();
    }

    namespace
    {
      double
      axis_value(const double a, const double b, const unsigned int n, const unsigned int i)
      {
        return n == 1 ? a : a + (b - a) * i / (n - 1);
      }

      /**
       * What a table's checkpoint holds after its point header (io/ranks.h):
       * the values of the rank's points so far (over the whole grid, NaN
       * where not done), the strains and state of its last converged point.
       */
      struct Saved
      {
        unsigned int          n_failed = 0;
        std::array<double, 6> last{};
        std::vector<double>   energy, resultants, stiffness, converged;
        std::vector<double>   start_state;
      };

      /**
       * One run of a constitutive table: the grid's points in serpentine
       * order, each continued from the last converged one, this rank's
       * block of them (io/ranks.h), and what its checkpoints keep.
       */
      class TableRun
      {
      public:
        TableRun(const ConstitutiveTable &                       t,
                 const std::array<double, 6> &                   base,
                 const std::array<double, 6> &                   start,
                 const ConstitutiveTable::Resolver &             resolve,
                 const std::function<void()> &                   save,
                 const std::function<void()> &                   restore,
                 const std::string &                             directory,
                 const std::function<void(const std::string &)> &progress,
                 const TableCheckpointing &                      checkpointing)
          : t(t)
          , base(base)
          , resolve(resolve)
          , save(save)
          , restore(restore)
          , directory(directory)
          , progress(progress)
          , checkpointing(checkpointing)
          , N(t.n1 * t.n2)
          , n_ranks(io::ranks::size())
          , energy(N, NAN)
          , resultants(6 * N, NAN)
          , stiffness(36 * N, NAN)
          , converged(N, 0)
          , last(start)
        {
          progress("constitutive table: " + std::to_string(N) + " points, their results estimated at " +
                   io::format_bytes(N * ConstitutiveTable::bytes_per_point) +
                   " beside the problem's memory");
          table.add_column(kinematics::strain_names[t.first]);
          table.add_column(kinematics::strain_names[t.second]);
          table.add_column("converged");
          table.add_column("energy");
          for (unsigned int k = 0; k < 6; ++k)
            table.add_column(kinematics::resultant_names[k]);
          for (unsigned int a = 0; a < 6; ++a)
            for (unsigned int b = a; b < 6; ++b)
              table.add_column("K_" + kinematics::strain_names[a] + "_" + kinematics::strain_names[b]);
          // Under mpirun each rank takes a contiguous block of the serpentine
          // (io/ranks.h) and continues from its own converged neighbour; rank
          // k > 0 reaches its first point from the start in substeps.
          std::tie(block_begin, block_end) = io::ranks::my_block(N);
          save();
          next = block_begin;
          far  = block_begin > 0;
        }

        /// Go on from this rank's checkpoint, or take the points an earlier
        /// run on another number of ranks did.
        void
        resume();
        /// This rank's points.
        void
        solve_block();
        /// The seams compared, table.csv and table.h5 of all ranks, the end.
        void
        finish(const TableDescription &description);

      private:
        const ConstitutiveTable &                t;
        const std::array<double, 6>              base;
        const ConstitutiveTable::Resolver &      resolve;
        const std::function<void()> &            save, &restore;
        const std::string                        directory;
        std::function<void(const std::string &)> progress;
        const TableCheckpointing &               checkpointing;

        const unsigned int N; // < 2^32: check_points_memory refused more
        const unsigned int n_ranks;
        unsigned int       block_begin = 0, block_end = 0;
        std::vector<double> energy, resultants, stiffness, converged;
        io::CSVTable          table;
        std::array<double, 6> last;
        unsigned int          n_failed = 0;
        /// Points are taken in serpentine order; this rank's are done up to `next`.
        unsigned int next = 0;
        /// Resumed on another number of ranks: the rows of the points any
        /// earlier rank did, and what each earlier rank held, by the first
        /// point it had not done (io::ranks::Resumed).
        std::map<unsigned int, std::vector<double>> earlier_rows;
        std::map<unsigned int, Saved>               earlier;
        /// The state of a point away from the last one solved here (a
        /// block's first point, or one after an earlier run's points):
        /// reached in substeps from the start, more of them than between
        /// neighbours.
        bool far = false;

        /// The strains of serpentine point q.
        std::array<double, 6>
        strains_of_point(unsigned int q) const;
        /// Its index in the grid (i n2 + j).
        unsigned int
        grid_index(unsigned int q) const;
        bool
        solve_point(const std::array<double, 6> &e, bool far, ReducedRodState &s) const;
        void
        write_checkpoint() const;
        Saved
        read_saved(io::CheckpointReader &r) const;
        void
        resume_from_other_ranks(io::ranks::Resumed &resumed);
        /// Point `next` done by an earlier run: taken as it is (true), else its start set.
        bool
        take_earlier();
        /// Point `next` solved here.
        void
        solve_next();
        /// Each rank but the last continues one point further, to the next block's first.
        std::vector<std::vector<double>>
        seam() const;
        void
        compare_seams(const std::vector<std::vector<double>> &seams,
                      const std::vector<std::vector<double>> &all_rows) const;
        void
        write_h5(const std::string &shared, const TableDescription &description) const;
      };

      unsigned int
      TableRun::grid_index(const unsigned int q) const
      {
        const unsigned int i = q / t.n2, jj = q % t.n2;
        return i * t.n2 + ((i % 2 == 0) ? jj : t.n2 - 1 - jj); // serpentine
      }

      std::array<double, 6>
      TableRun::strains_of_point(const unsigned int q) const
      {
        const unsigned int    p = grid_index(q);
        std::array<double, 6> e = base;
        e[t.first]              = axis_value(t.from1, t.to1, t.n1, p / t.n2);
        e[t.second]             = axis_value(t.from2, t.to2, t.n2, p % t.n2);
        return e;
      }

      void
      TableRun::write_checkpoint() const
      {
        if (!checkpointing.write)
          return;
        // The point header first, so that a run resumed on another number
        // of ranks finds each point in the checkpoint of the rank that did it.
        io::CheckpointWriter w;
        io::ranks::put_point_header(w, block_begin, next, table);
        w.put(n_failed);
        w.put_vector(last);
        w.put_vector(energy);
        w.put_vector(resultants);
        w.put_vector(stiffness);
        w.put_vector(converged);
        checkpointing.save_start(w);
        checkpointing.write(w);
      }

      Saved
      TableRun::read_saved(io::CheckpointReader &r) const
      {
        Saved v;
        v.n_failed   = r.get_unsigned();
        const auto l = r.get_vector();
        std::copy(l.begin(), l.end(), v.last.begin());
        v.energy      = r.get_vector();
        v.resultants  = r.get_vector();
        v.stiffness   = r.get_vector();
        v.converged   = r.get_vector();
        v.start_state = r.get_vector();
        if (v.energy.size() != N)
          throw std::runtime_error("the checkpoint's table has another size");
        return v;
      }

      void
      TableRun::resume()
      {
        if (checkpointing.resuming)
          {
            auto resumed = io::ranks::resume_points(directory, table, checkpointing.read_in);
            if (resumed.same_ranks)
              {
                // The same number of ranks goes on exactly where it was.
                Saved v = read_saved(resumed.reader);
                next    = resumed.own.next;
                if (next > block_end || next < block_begin)
                  throw std::runtime_error("the checkpoint's table has another size");
                for (const auto &row : resumed.own.rows)
                  table.add_row(row);
                n_failed   = v.n_failed;
                last       = v.last;
                energy     = std::move(v.energy);
                resultants = std::move(v.resultants);
                stiffness  = std::move(v.stiffness);
                converged  = std::move(v.converged);
                checkpointing.set_start(v.start_state);
                save();
                far = next == block_begin && block_begin > 0;
                progress("  going on after " + std::to_string(next - block_begin) + " of " +
                         std::to_string(block_end - block_begin) + " table points");
              }
            else
              resume_from_other_ranks(resumed);
          }
        if (n_ranks > 1)
          progress("  table points " + std::to_string(block_begin + 1) + " to " +
                   std::to_string(block_end) + " of " + std::to_string(N) + " on rank " +
                   std::to_string(io::ranks::rank()) + " of " + std::to_string(n_ranks));
      }

      void
      TableRun::resume_from_other_ranks(io::ranks::Resumed &resumed)
      {
        // Begun on another number of ranks: every rank's points so far, each
        // point of this rank's block taken from the one that did it; the
        // others solved here, from the state an earlier rank stopped at
        // where it stopped, else from this rank's last.
        earlier_rows = std::move(resumed.done);
        for (auto &[stopped_at, r] : resumed.after)
          earlier.emplace(stopped_at, read_saved(r));
        const auto taken =
          std::distance(earlier_rows.lower_bound(block_begin), earlier_rows.lower_bound(block_end));
        progress("  resumed on " + std::to_string(n_ranks) + " ranks a table begun on " +
                 std::to_string(resumed.ranks_then) + ": " + std::to_string(taken) +
                 " of this rank's " + std::to_string(block_end - block_begin) +
                 " points done before");
      }

      bool
      TableRun::solve_point(const std::array<double, 6> &e, const bool far, ReducedRodState &s) const
      {
        // The state at strains e from the last converged one (`last`), in
        // substeps if one step fails. A point away from the last one solved
        // here (`far`): its path is longer than one grid step, so more
        // substeps may be needed.
        const std::vector<unsigned int> attempts =
          far ? std::vector<unsigned int>{1u, 4u, 16u, 64u, 256u} : std::vector<unsigned int>{1u, 4u, 16u};
        for (const unsigned int substeps : attempts)
          {
            restore(); // from the last converged point
            try
              {
                for (unsigned int k = 1; k <= substeps; ++k)
                  {
                    std::array<double, 6> ek;
                    for (unsigned int c = 0; c < 6; ++c)
                      ek[c] = last[c] + (e[c] - last[c]) * k / substeps;
                    s = resolve(ek);
                  }
                return true;
              }
            catch (solvers::NewtonFailure &)
              {}
          }
        return false;
      }

      bool
      TableRun::take_earlier()
      {
        const unsigned int p = grid_index(next);
        if (const auto row = earlier_rows.find(next); row != earlier_rows.end())
          {
            // Solved by an earlier run: its row and values as they are, from
            // the rank that did it (the blocks are disjoint and in order, so
            // the first to stop after this point).
            const Saved &done = earlier.upper_bound(next)->second;
            table.add_row(row->second);
            converged[p] = done.converged[p];
            energy[p]    = done.energy[p];
            std::copy_n(done.resultants.begin() + 6 * p, 6, resultants.begin() + 6 * p);
            std::copy_n(done.stiffness.begin() + 36 * p, 36, stiffness.begin() + 36 * p);
            n_failed += converged[p] == 0;
            far = true;
            return true;
          }
        if (const auto stopped = earlier.find(next); stopped != earlier.end())
          {
            // An earlier rank stopped here: its state is this point's neighbour.
            checkpointing.set_start(stopped->second.start_state);
            save();
            last = stopped->second.last;
            far  = false;
          }
        return false;
      }

      void
      TableRun::solve_next()
      {
        const unsigned int          p = grid_index(next);
        const std::array<double, 6> e = strains_of_point(next);
        ReducedRodState             s;
        const bool                  ok  = solve_point(e, far, s);
        std::vector<double>         row = {e[t.first], e[t.second], ok ? 1. : 0.};
        if (ok)
          {
            far = false;
            save();
            last         = e;
            converged[p] = 1;
            energy[p]    = s.energy;
            for (unsigned int a = 0; a < 6; ++a)
              {
                resultants[6 * p + a] = s.resultants[a];
                for (unsigned int b = 0; b < 6; ++b)
                  stiffness[36 * p + 6 * a + b] = s.stiffness(a, b);
              }
            row.push_back(s.energy);
            row.insert(row.end(), s.resultants.begin(), s.resultants.end());
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int b = a; b < 6; ++b)
                row.push_back(s.stiffness(a, b));
          }
        else
          {
            ++n_failed;
            restore();
          }
        row.resize(table.n_columns(), NAN);
        table.add_row(row);
      }

      void
      TableRun::solve_block()
      {
        auto last_checkpoint = std::chrono::steady_clock::now();
        for (; next < block_end; ++next)
          {
            if (io::pending_signal() != 0)
              {
                // Interrupted: the rows so far as a complete (shorter) table,
                // and the checkpoint to go on from.
                table.write(directory + "/table.csv");
                write_checkpoint();
                io::check_interrupt();
              }
            if (take_earlier())
              continue;
            solve_next();
            // A checkpoint a second: what a kill can lose, against the cost of writing the table.
            if (std::chrono::steady_clock::now() - last_checkpoint > std::chrono::seconds(1))
              {
                ++next;
                table.write(directory + "/table.csv"); // a killed run leaves the rows so far
                write_checkpoint();
                --next;
                last_checkpoint = std::chrono::steady_clock::now();
              }
          }
      }

      std::vector<std::vector<double>>
      TableRun::seam() const
      {
        // The seams: a block's first point was reached from the start, not
        // from its serpentine neighbour, and where the table crosses an
        // instability the two paths can end on different branches. So each
        // rank but the last continues one point further, to the next
        // block's first, and rank 0 compares the two (a state from another
        // path agrees to Newton's stopping test, 1e-10; another branch does
        // not).
        std::vector<std::vector<double>> seam;
        if (io::ranks::rank() + 1 < n_ranks && block_end < N && block_end > block_begin)
          {
            ReducedRodState s;
            if (solve_point(strains_of_point(block_end), far, s))
              {
                std::vector<double> v = {double(block_end), s.energy};
                v.insert(v.end(), s.resultants.begin(), s.resultants.end());
                seam.push_back(v);
              }
          }
        return seam;
      }

      void
      TableRun::compare_seams(const std::vector<std::vector<double>> &seams,
                              const std::vector<std::vector<double>> &all_rows) const
      {
        // The energy against its largest value; a resultant a against
        // sqrt(2 max K_aa max Psi) (Psi ~ K e^2/2, so K e ~ sqrt(2 K Psi)):
        // a free strain's resultant is held at 0 and is round-off itself.
        // (Row: strains, converged, energy, 6 resultants, K_ab for b >= a.)
        auto max_of = [&](const unsigned int column) {
          double m = 0;
          for (const auto &row : all_rows)
            if (std::isfinite(row[column]))
              m = std::max(m, std::abs(row[column]));
          return m;
        };
        std::vector<double> scale(7, max_of(3));
        for (unsigned int a = 0, column = 10; a < 6; column += 6 - a, ++a)
          scale[1 + a] = std::sqrt(2 * max_of(column) * scale[0]);
        for (const auto &v : seams)
          {
            const auto &row = all_rows[static_cast<unsigned int>(v[0])];
            if (row[2] != 1)
              continue;
            double gap = 0;
            for (unsigned int c = 0; c < 7; ++c)
              if (scale[c] > 0)
                gap = std::max(gap, std::abs(row[3 + c] - v[1 + c]) / scale[c]);
            std::ostringstream m;
            m << std::setprecision(3) << "  seam before point " << v[0] + 1
              << ": the block's first state and its neighbour's continuation agree to " << gap
              << " (energy and resultants, of their scales)";
            if (gap > 1e-6)
              m << "\nWARNING: they differ by more than 1e-6: the blocks followed different "
                   "branches across an instability; run the table on one rank (or on ranks "
                   "whose blocks do not start past it) to follow the serpentine's";
            progress(m.str());
          }
      }

      void
      TableRun::write_h5(const std::string &shared, const TableDescription &description) const
      {
        // HDF5, written under a temporary name and renamed: complete or absent.
        const std::string         tmp = shared + "/table.h5.tmp", h5 = shared + "/table.h5";
        std::vector<unsigned int> mine;
        for (unsigned int q = block_begin; q < block_end; ++q)
          mine.push_back(grid_index(q));
        // The axes: the strains of the points, as table.csv has them.
        std::vector<double> axis1(t.n1), axis2(t.n2);
        for (unsigned int i = 0; i < t.n1; ++i)
          axis1[i] = axis_value(t.from1, t.to1, t.n1, i);
        for (unsigned int j = 0; j < t.n2; ++j)
          axis2[j] = axis_value(t.from2, t.to2, t.n2, j);
        internal::write_table_h5(tmp, description, t.first, t.second, axis1, axis2, mine, energy,
                                 resultants, stiffness, converged);
        if (io::ranks::rank() == 0)
          {
            std::filesystem::rename(tmp, h5);
            io::record_output_file(h5);
          }
      }

      void
      TableRun::finish(const TableDescription &description)
      {
        const auto seams = io::ranks::gather_rows(seam());
        // Rank 0 writes the rows of all ranks (in rank order: the serpentine's).
        const auto all_rows = io::ranks::gather_rows(table.row_values());
        if (io::ranks::rank() == 0 && !seams.empty())
          compare_seams(seams, all_rows);
        if (n_ranks > 1 && io::ranks::rank() == 0)
          {
            io::CSVTable whole = table;
            whole.clear_rows();
            for (const auto &row : all_rows)
              whole.add_row(row);
            whole.write(io::ranks::shared_directory() + "/table.csv");
          }
        else
          table.write(directory + "/table.csv");
        const unsigned int failed = io::ranks::sum(n_failed);
        const std::string  shared = n_ranks > 1 ? io::ranks::shared_directory() : directory;
        write_h5(shared, description);
        std::ostringstream m;
        m << "constitutive table: " << t.n1 << " x " << t.n2 << " points of ("
          << kinematics::strain_names[t.first] << ", " << kinematics::strain_names[t.second]
          << "), " << failed << " not converged";
        if (n_ranks > 1)
          m << ", on " << n_ranks << " MPI ranks";
        m << "; " << shared << "/table.csv, table.h5";
        progress(m.str());
        if (failed > 0)
          throw io::RunFailure(std::to_string(failed) + " table points did not converge");
      }
    } // namespace

    void
    ConstitutiveTable::run(const std::array<double, 6> &                   base,
                           const std::array<double, 6> &                   start,
                           const Resolver &                                 resolve,
                           const std::function<void()> &                    save,
                           const std::function<void()> &                    restore,
                           const std::string &                              directory,
                           const std::function<void(const std::string &)> &progress,
                           const TableDescription &                         description,
                           const TableCheckpointing &                       checkpointing) const
    {
      TableRun run(*this, base, start, resolve, save, restore, directory, progress, checkpointing);
      run.resume();
      run.solve_block();
      run.finish(description);
    }
  } // namespace assembly
} // namespace cosmo

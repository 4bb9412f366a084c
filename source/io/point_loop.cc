#include <cosmo/io/checkpoint.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/point_loop.h>
#include <cosmo/io/postprocessors.h>
#include <cosmo/io/run_directory.h>

#include <limits>

namespace cosmo
{
  namespace io
  {
    PointLoop::PointLoop(const Description &description,
                         const CSVTable &   columns,
                         const bool         resume,
                         const Hooks &      hooks)
      : description(description)
      , table(columns)
      , resume(resume)
      , hooks(hooks)
    {
      // (read before the directory is claimed: open_run_directory moves what it finds)
      if (resume)
        resumed = ranks::resume_points(description.directory, table, [&](const std::string &d) {
          return read_checkpoint(d, description.checkpoint_kind, description.parameters);
        });
    }

    RunOptions
    PointLoop::point_options(const RunOptions &options, ParameterHandler &prm)
    {
      RunOptions o = options;
      o.quiet      = true;
      o.resume_directory.clear();
      o.postprocessors = std::make_shared<Postprocessors>();
      o.postprocessors->parse_parameters(prm);
      return o;
    }

    void
    PointLoop::finish_point(const RunOptions &point_options, const std::string &point_directory)
    {
      if (point_options.postprocessors)
        point_options.postprocessors->finish(point_directory);
    }

    void
    PointLoop::write_checkpoint(const unsigned int first, const unsigned int next) const
    {
      CheckpointWriter w;
      ranks::put_point_header(w, first, next, table);
      w.put(n_failed);
      w.put(rejected);
      if (hooks.save_held)
        hooks.save_held(w);
      io::write_checkpoint(description.directory, description.checkpoint_kind,
                           description.parameters, w);
    }

    void
    PointLoop::read_payload(CheckpointReader &r, const bool keep_counters)
    {
      const unsigned int             failed   = r.get_unsigned();
      const std::vector<std::string> refusals = r.get_strings();
      if (keep_counters)
        {
          n_failed = failed;
          rejected = refusals;
        }
      if (hooks.load_held)
        hooks.load_held(r);
    }

    bool
    PointLoop::take_done(const unsigned int k, RunLog &log, std::vector<std::string> &point_lines)
    {
      const auto done = resumed.done.find(k);
      if (done == resumed.done.end())
        return false;
      const auto &       row = done->second;
      const unsigned int c   = description.converged_column;
      std::optional<Point> p;
      if (hooks.take_done)
        p = hooks.take_done(k, row);
      else if (row.size() > c && row[c] == 1)
        {
          p       = Point();
          p->line = "point " + std::to_string(k + 1) + "/" +
                    std::to_string(description.values.size()) + ": done before the resume";
        }
      if (!p)
        return false; // run again
      table.add_row(row);
      n_failed += p->outcome == Point::Outcome::failed;
      log(p->line);
      point_lines.push_back(p->line);
      // The last point of an earlier rank's block: go on from what that
      // rank held there, as it would have.
      if (const auto a = resumed.after.find(k + 1);
          hooks.load_held && a != resumed.after.end() && !resumed.done.count(k + 1))
        read_payload(a->second, false);
      return true;
    }

    void
    PointLoop::run(RunLog &log, const std::function<Point(unsigned int k)> &point)
    {
      const std::string &base = description.directory;
      const unsigned int n    = description.values.size();
      // Each rank a contiguous block of the points, after rank 0 has taken
      // the run's directory.
      const unsigned int n_ranks          = ranks::size();
      const auto [block_begin, block_end] = ranks::my_block(n);
      shared                              = n_ranks > 1 ? ranks::shared_directory() : base;
      ranks::barrier();

      unsigned int k0 = block_begin;
      if (resume && resumed.same_ranks)
        {
          k0 = resumed.own.next;
          for (const auto &row : resumed.own.rows)
            table.add_row(row);
          read_payload(resumed.reader, true);
          table.write(base + "/" + description.table_file);
          for (const auto &name : description.also_written)
            table.write(base + "/" + name);
          log("  resumed from the checkpoint: " + std::to_string(k0 - block_begin) + " of " +
              std::to_string(block_end - block_begin) + " values done");
        }
      else if (resume)
        log("  resumed on " + std::to_string(n_ranks) + " ranks a " + description.kind +
            " begun on " + std::to_string(resumed.ranks_then) +
            ": the values done before are taken as they are, the others run again");
      if (n_ranks > 1)
        log("  values " + std::to_string(block_begin + 1) + " to " + std::to_string(block_end) +
            " of " + std::to_string(n) + " on rank " + std::to_string(ranks::rank()) + " of " +
            std::to_string(n_ranks));
      std::vector<std::string> point_lines; // this rank's, for rank 0's log
      auto interrupted = [&]() {
        log("interrupted; continue with: " + description.application + " --resume " + base);
      };
      for (unsigned int k = k0; k < block_end; ++k)
        {
          if (pending_signal() != 0)
            interrupted();
          check_interrupt(); // between points: the table holds every point done so far
          if (take_done(k, log, point_lines))
            continue;
          Point p;
          try
            {
              p = point(k);
            }
          catch (Interrupted &)
            {
              interrupted();
              throw;
            }
          if (p.outcome == Point::Outcome::failed)
            ++n_failed;
          else if (p.outcome == Point::Outcome::rejected)
            rejected.push_back(p.rejection.empty() ? "'" + description.values[k] + "'" :
                                                     p.rejection);
          p.row.resize(table.n_columns(), std::numeric_limits<double>::quiet_NaN());
          log(p.line);
          point_lines.push_back(p.line);
          // Rewritten after every point: a killed study leaves a complete table.
          table.add_row(p.row);
          table.write(base + "/" + description.table_file);
          for (const auto &name : description.also_written)
            table.write(base + "/" + name);
          write_checkpoint(block_begin, k + 1);
        }
      gather(log, point_lines);
      // Not before: a rank stopped while the others still run resumes from it.
      remove_checkpoint(base);
      log("table: " + shared + "/" + description.table_file);
      report();
    }

    void
    PointLoop::report() const
    {
      const unsigned int n = description.values.size();
      if (!rejected.empty())
        {
          std::string what;
          for (const auto &v : rejected)
            what += (what.empty() ? "" : ", ") + v;
          throw InputError("Parameter sweep", description.rejected_entry, description.entry,
                           std::to_string(rejected.size()) + " of " + std::to_string(n) +
                             " values were rejected by the problem: " + what +
                             " (the other points ran; see " + description.directory + "/" +
                             description.log_file + ")");
        }
      if (n_failed > 0)
        throw RunFailure(std::to_string(n_failed) + " of " + std::to_string(n) + " " +
                         description.failed_words + " (see " + description.directory + "/" +
                         description.log_file + ")");
    }

    void
    PointLoop::gather(RunLog &log, const std::vector<std::string> &point_lines)
    {
      const unsigned int n_ranks = ranks::size();
      if (n_ranks == 1 && !(hooks.complete_rows && !resumed.done.empty()))
        return;
      // Rank 0 writes every rank's rows (in rank order: the values').
      auto       rows  = ranks::gather_rows(table.row_values());
      const auto lines = ranks::gather_lines(point_lines);
      n_failed         = ranks::sum(n_failed);
      rejected         = ranks::all_gather_lines(rejected);
      if (ranks::rank() > 0)
        {
          log("the values of this rank are in " + shared + "/" + description.table_file);
          return;
        }
      if (n_ranks > 1)
        {
          log("the " + std::to_string(n_ranks) + " ranks' values:");
          for (const auto &l : lines)
            log(l);
        }
      if (hooks.complete_rows)
        hooks.complete_rows(rows);
      table.clear_rows();
      for (const auto &r : rows)
        table.add_row(r);
      table.write(shared + "/" + description.table_file);
      for (const auto &name : description.also_written)
        table.write(shared + "/" + name);
    }
  } // namespace io
} // namespace cosmo

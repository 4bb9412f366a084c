#include <cosmo/io/checkpoint.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/point_loop.h>
#include <cosmo/io/run_directory.h>

#include <limits>

namespace cosmo
{
  namespace io
  {
    PointLoop::PointLoop(const Description &description, const CSVTable &columns, const bool resume)
      : description(description)
      , table(columns)
      , resume(resume)
    {
      // (read before the directory is claimed: open_run_directory moves what it finds)
      if (resume)
        resumed = ranks::resume_points(description.directory, table, [&](const std::string &d) {
          return read_checkpoint(d, description.checkpoint_kind, description.parameters);
        });
    }

    void
    PointLoop::write_checkpoint(const unsigned int first, const unsigned int next) const
    {
      CheckpointWriter w;
      ranks::put_point_header(w, first, next, table);
      w.put(n_failed);
      w.put(rejected);
      io::write_checkpoint(description.directory, description.checkpoint_kind,
                           description.parameters, w);
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
          n_failed = resumed.reader.get_unsigned();
          rejected = resumed.reader.get_strings();
          table.write(base + "/" + description.table_file);
          log("  resumed from the checkpoint: " + std::to_string(k0 - block_begin) + " of " +
              std::to_string(block_end - block_begin) + " values done");
        }
      else if (resume)
        log("  resumed on " + std::to_string(n_ranks) + " ranks a sweep begun on " +
            std::to_string(resumed.ranks_then) +
            ": the converged values done before are taken as they are, the others run again");
      std::vector<std::string> point_lines; // this rank's, for rank 0's log
      for (unsigned int k = k0; k < block_end; ++k)
        {
          auto interrupted = [&]() {
            log("interrupted; continue with: " + description.application + " --resume " + base);
          };
          if (pending_signal() != 0)
            interrupted();
          check_interrupt(); // between points: the table holds every point done so far
          const unsigned int c = description.converged_column;
          if (const auto done = resumed.done.find(k);
              done != resumed.done.end() && done->second.size() > c && done->second[c] == 1)
            {
              table.add_row(done->second);
              point_lines.push_back("point " + std::to_string(k + 1) + "/" + std::to_string(n) +
                                    ": done before the resume");
              log(point_lines.back());
              continue;
            }
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
            rejected.push_back(description.values[k]);
          p.row.resize(table.n_columns(), std::numeric_limits<double>::quiet_NaN());
          log(p.line);
          point_lines.push_back(p.line);
          // Rewritten after every point: a killed sweep leaves a complete table.
          table.add_row(p.row);
          table.write(base + "/" + description.table_file);
          write_checkpoint(block_begin, k + 1);
        }
      gather(log, point_lines);
      // Not before: a rank stopped while the others still run resumes from it.
      remove_checkpoint(base);
      log("sweep table: " + shared + "/" + description.table_file);
      if (!rejected.empty())
        {
          std::string values;
          for (const auto &v : rejected)
            values += (values.empty() ? "'" : ", '") + v + "'";
          throw InputError("Parameter sweep", "Entry", description.entry,
                           std::to_string(rejected.size()) + " of " + std::to_string(n) +
                             " values were rejected by the problem: " + values +
                             " (the other points ran; see " + base + "/" + description.log_file +
                             ")");
        }
      if (n_failed > 0)
        throw RunFailure(std::to_string(n_failed) + " of " + std::to_string(n) +
                         " sweep points failed (see " + base + "/" + description.log_file + ")");
    }

    void
    PointLoop::gather(RunLog &log, const std::vector<std::string> &point_lines)
    {
      const unsigned int n_ranks = ranks::size();
      if (n_ranks == 1)
        return;
      // Rank 0 writes every rank's rows (in rank order: the values').
      const auto rows  = ranks::gather_rows(table.row_values());
      const auto lines = ranks::gather_lines(point_lines);
      n_failed         = ranks::sum(n_failed);
      rejected         = ranks::all_gather_lines(rejected);
      if (ranks::rank() == 0)
        {
          log("the " + std::to_string(n_ranks) + " ranks' values:");
          for (const auto &l : lines)
            log(l);
          table.clear_rows();
          for (const auto &r : rows)
            table.add_row(r);
          table.write(shared + "/" + description.table_file);
        }
    }
  } // namespace io
} // namespace cosmo

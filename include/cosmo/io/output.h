#ifndef cosmo_io_output_h
#define cosmo_io_output_h

#include <cosmo/io/checkpoint.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

/**
 * The output contract of every application (doc/specification/architecture.md): one directory
 * with parameters.prm, summary.json, steps.csv, solution.pvd + VTU files and
 * log.txt. Every file except the log is written to a temporary name and
 * renamed, so a killed run never leaves a half-written file; the log is
 * flushed line by line.
 */
namespace cosmo
{
  namespace io
  {
    /// Write through `writer` to path.tmp, then rename to path.
    void
    write_file_atomically(const std::string &path,
                          const std::function<void(std::ostream &)> &writer);

    /// A table with a header row "name [unit]", rewritten whole after each row.
    class CSVTable
    {
    public:
      void
      add_column(const std::string &name, const std::string &unit = "");
      void
      add_row(const std::vector<double> &values);
      void
      write(const std::string &path) const;
      std::size_t
      n_columns() const
      {
        return columns.size();
      }
      /// The rows so far, in order (what the ranks of a run gather).
      const std::vector<std::vector<double>> &
      row_values() const
      {
        return rows;
      }
      /// The last row by column name (no units); empty before the first row.
      std::vector<std::pair<std::string, double>>
      last_row() const;
      /// The same columns, no rows.
      void
      clear_rows()
      {
        rows.clear();
      }
      /// The rows, for a checkpoint (the columns are declared again by the run).
      void
      save(CheckpointWriter &w) const;
      void
      load(CheckpointReader &r);

    private:
      std::vector<std::string>         columns; ///< "name [unit]"
      std::vector<std::string>         names;
      std::vector<std::vector<double>> rows;
    };

    /// A minimal JSON value tree: numbers, strings, bools, arrays, objects.
    class JSON
    {
    public:
      JSON(); // null
      JSON(double v);
      JSON(int v);
      JSON(unsigned int v);
      JSON(bool v);
      JSON(const char *v);
      JSON(const std::string &v);
      static JSON
      array();
      static JSON
      object();
      static JSON
      array(const std::vector<double> &v);

      /// Object member (created if absent).
      JSON &operator[](const std::string &key);
      /// Append to an array.
      void
      push_back(const JSON &v);

      void
      print(std::ostream &out, unsigned int indent = 0) const;
      std::string
      str() const;

      /**
       * Read a JSON text (what print() writes, and any standard JSON):
       * std::runtime_error naming the position and what was expected if it
       * is not JSON. Numbers are doubles; null reads as null (print()
       * writes NaN as null).
       */
      static JSON
      parse(const std::string &text);

      bool
      is_number() const
      {
        return type == Type::number;
      }
      bool
      is_array() const
      {
        return type == Type::array_t;
      }
      /// The number (NaN for null; std::runtime_error for anything else).
      double
      as_number() const;
      /// Items of an array, members of an object (0 otherwise).
      std::size_t
      size() const;
      /// Item k of an array (std::runtime_error if not an array or out of range).
      const JSON &
      at(std::size_t k) const;
      /// The member `key` of an object, or nullptr.
      const JSON *
      find(const std::string &key) const;

    private:
      enum class Type
      {
        null,
        number,
        string,
        boolean,
        array_t,
        object_t
      } type;
      double                                                    number  = 0;
      bool                                                      boolean = false;
      std::string                                               text;
      std::vector<JSON>                                         items;
      std::vector<std::pair<std::string, std::shared_ptr<JSON>>> members;
    };

    /// Terminal progress (unless quiet) and log.txt, flushed line by line.
    class RunLog
    {
    public:
      RunLog(const std::string &path, bool quiet, bool append = false);
      /// Print a line to the terminal (unless quiet) and to the log.
      void
      operator()(const std::string &line);
      /// Only to the log.
      void
      log_only(const std::string &line);

    private:
      std::ofstream file;
      bool          quiet;
    };

    /// A ParaView collection solution.pvd, rewritten atomically after each file.
    class PVDSeries
    {
    public:
      explicit PVDSeries(const std::string &pvd_path);
      void
      add(double time, const std::string &vtu_file_name);
      /// The entries, for a checkpoint; load() also rewrites the file.
      void
      save(CheckpointWriter &w) const;
      void
      load(CheckpointReader &r);

    private:
      void
      write() const;
      std::string                                 path;
      std::vector<std::pair<double, std::string>> entries;
    };

    /**
     * The ParaView collections of a continuation's states of one kind (stem
     * "plate": plate.pvd and plate-branch-K.pvd): `stem.pvd` lists every
     * state in path order (time = the step), `stem-branch-K.pvd` the states
     * of branch K with time = the load parameter t, so that an animation of
     * one branch runs in t (turning back at a fold) instead of jumping back
     * at every branch start.
     */
    class PathCollections
    {
    public:
      PathCollections(const std::string &directory, const std::string &stem);
      void
      add(unsigned int step, unsigned int branch, double t, const std::string &vtu_file_name);
      /// For a checkpoint; load() rewrites the files as they were.
      void
      save(CheckpointWriter &w) const;
      void
      load(CheckpointReader &r);

    private:
      std::string                         directory, stem;
      PVDSeries                           all;
      std::map<unsigned int, PVDSeries>   branches;
      PVDSeries &
      branch(unsigned int b);
    };

    /// Wall-clock time per phase (assembly, factorization, solve, output, ...).
    class PhaseTimer
    {
    public:
      class Scope
      {
      public:
        Scope(PhaseTimer &timer, const std::string &phase);
        ~Scope();

      private:
        PhaseTimer &                                   timer;
        std::string                                    phase;
        std::chrono::steady_clock::time_point          start;
      };

      void
      add(const std::string &phase, double seconds);
      double
      seconds(const std::string &phase) const;
      unsigned int
      calls(const std::string &phase) const;
      const std::vector<std::string> &
      phases() const
      {
        return order;
      }
      JSON
      to_json() const;

    private:
      std::map<std::string, std::pair<double, unsigned int>> data;
      std::vector<std::string>                               order;
    };

    /// Create the directory (and parents); clear error if impossible.
    void
    create_directory(const std::string &path);

    /// Shortest round-trip text of a double for tables.
    std::string
    format_number(double v);

    /// A double with `precision` significant digits, for progress lines and logs.
    std::string
    format_significant(double v, int precision = 6);
  } // namespace io
} // namespace cosmo

#endif

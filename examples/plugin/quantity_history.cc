// The example of doc/cookbook.md, "Add a postprocessor": the history of
// chosen quantities of a run (any columns of the application's steps.csv) at
// every converged state, and the located events, in quantity_history.csv,
// with the largest absolute value of each quantity along the path in
// quantity_history.json at the end. This file is the whole extension.
#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/postprocessors.h>

#include <cmath>
#include <iomanip>

namespace cosmo
{
  namespace io
  {
    class QuantityHistory : public Postprocessor
    {
    public:
      // Its entries, in subsection 'Postprocess / quantity history'.
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Quantities", "energy", Patterns::List(Patterns::Anything()),
                          "Columns of the application's steps.csv to record, separated by ','.");
      }
      void
      parse_parameters(ParameterHandler &prm) override
      {
        names = Utilities::split_string_list(prm.get("Quantities"), ',');
        if (names.empty())
          throw InputError("Postprocess / quantity history", "Quantities", "",
                           "name at least one column of steps.csv");
        largest.assign(names.size(), 0.);
      }
      void
      execute(const PostprocessedState &s) override
      {
        std::vector<double> row = {double(s.kind == PostprocessedState::Kind::located_event),
                                   double(s.branch), s.t};
        for (unsigned int k = 0; k < names.size(); ++k)
          {
            // (NaN at an event, and for a name the application does not have)
            const double v = s.quantity(names[k]);
            row.push_back(v);
            if (std::isfinite(v))
              largest[k] = std::max(largest[k], std::abs(v));
          }
        rows.push_back(row);
        write(s.output_directory);
      }
      // What it has gathered goes into the run's checkpoint, and comes back
      // on --resume: the resumed run's files are then the uninterrupted run's.
      void
      save(CheckpointWriter &w) const override
      {
        w.put_vector(largest);
        w.put(std::uint64_t(rows.size()));
        for (const auto &r : rows)
          w.put_vector(r);
      }
      void
      load(CheckpointReader &r, const std::string &output_directory) override
      {
        largest = r.get_vector();
        rows.resize(r.get_size());
        for (auto &row : rows)
          row = r.get_vector();
        write(output_directory);
      }
      void
      finish(const std::string &output_directory) override
      {
        JSON j = JSON::object();
        j["states"] = JSON(unsigned(rows.size()));
        for (unsigned int k = 0; k < names.size(); ++k)
          j["largest |" + names[k] + "|"] = JSON(largest[k]);
        write_file_atomically(output_directory + "/quantity_history.json",
                              [&](std::ostream &o) { j.print(o); });
      }

    private:
      std::vector<std::string>         names;
      std::vector<double>              largest;
      std::vector<std::vector<double>> rows;

      void
      write(const std::string &directory) const
      {
        write_file_atomically(directory + "/quantity_history.csv", [&](std::ostream &o) {
          o << "event,branch,t";
          for (const auto &n : names)
            o << "," << n;
          o << "\n" << std::setprecision(17);
          for (const auto &r : rows)
            for (unsigned int k = 0; k < r.size(); ++k)
              o << r[k] << (k + 1 < r.size() ? "," : "\n");
        });
      }
    };

    COSMO_REGISTER_PLUGIN(Postprocessor,
                          QuantityHistory,
                          "quantity history",
                          "quantity_history.csv: chosen columns of steps.csv at every state "
                          "(doc/cookbook.md).")
  } // namespace io
} // namespace cosmo

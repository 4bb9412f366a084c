// The postprocessor 'steps table': steps.csv, one row per converged state.
#include <cosmo/io/output.h>
#include <cosmo/io/postprocessors.h>

namespace cosmo
{
  namespace io
  {
    /**
     * steps.csv: the application's quantities of every converged state
     * (io::StateSource: its columns "name [unit]" and values), rewritten
     * whole and atomically after each row, so that a killed run leaves a
     * complete table; a resumed run rewrites it as it was at the checkpoint.
     */
    class StepsTable : public Postprocessor
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      execute(const PostprocessedState &s) override
      {
        if (s.kind != PostprocessedState::Kind::converged_state || s.source == nullptr)
          return;
        if (columns.empty())
          declare_columns(s.source->quantity_columns());
        table.add_row(s.source->quantity_values());
        table.write(s.output_directory + "/steps.csv");
      }
      void
      save(CheckpointWriter &w) const override
      {
        std::vector<std::string> names, units;
        for (const auto &c : columns)
          names.push_back(c.first), units.push_back(c.second);
        w.put(names);
        w.put(units);
        table.save(w);
      }
      void
      load(CheckpointReader &r, const std::string &output_directory) override
      {
        const auto names = r.get_strings(), units = r.get_strings();
        if (names.size() != units.size())
          throw std::runtime_error("the checkpoint's steps table is not one");
        std::vector<std::pair<std::string, std::string>> c;
        for (unsigned int k = 0; k < names.size(); ++k)
          c.emplace_back(names[k], units[k]);
        declare_columns(c);
        table.load(r);
        if (!columns.empty())
          table.write(output_directory + "/steps.csv");
      }

    private:
      void
      declare_columns(const std::vector<std::pair<std::string, std::string>> &c)
      {
        columns = c;
        table   = CSVTable();
        for (const auto &x : columns)
          table.add_column(x.first, x.second);
      }
      std::vector<std::pair<std::string, std::string>> columns;
      CSVTable                                         table;
    };

    COSMO_REGISTER_PLUGIN(Postprocessor,
                          StepsTable,
                          "steps table",
                          "steps.csv: the application's quantities (load, energy, strains, "
                          "resultants, stability, ...) at every converged state, one row each.")
  } // namespace io
} // namespace cosmo

// The postprocessor 'unknowns': the norms of the unknowns at every state.
#include <cosmo/io/output.h>
#include <cosmo/io/postprocessors.h>

#include <iomanip>
#include <vector>

namespace cosmo
{
  namespace io
  {
    /**
     * unknowns.csv: kind (0 converged state, 1 located event), step, branch,
     * t, the negative eigenvalues and the l2 and max norms of the unknowns,
     * one row per state, rewritten whole (atomically) after each: a cheap
     * record of a path that needs no VTU. Its rows are in the run's
     * checkpoint: a resumed run's file is the uninterrupted run's.
     */
    class UnknownsNorms : public Postprocessor
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}
      void
      execute(const PostprocessedState &s) override
      {
        if (s.unknowns == nullptr)
          return;
        rows.push_back({double(s.kind == PostprocessedState::Kind::located_event), double(s.step),
                        double(s.branch), s.t, double(s.n_negative), s.unknowns->l2_norm(),
                        s.unknowns->linfty_norm()});
        write(s.output_directory);
      }
      /// The rows so far go into the run's checkpoint, and back on --resume.
      void
      save(CheckpointWriter &w) const override
      {
        w.put(std::uint64_t(rows.size()));
        for (const auto &r : rows)
          w.put_vector(r);
      }
      void
      load(CheckpointReader &r, const std::string &output_directory) override
      {
        rows.resize(r.get_size());
        for (auto &row : rows)
          row = r.get_vector();
        write(output_directory);
      }

    private:
      std::vector<std::vector<double>> rows;

      void
      write(const std::string &directory) const
      {
        write_file_atomically(directory + "/unknowns.csv", [&](std::ostream &o) {
          o << "event,step,branch,t,n_negative,l2_norm,max_norm\n" << std::setprecision(17);
          for (const auto &r : rows)
            for (unsigned int k = 0; k < r.size(); ++k)
              o << r[k] << (k + 1 < r.size() ? "," : "\n");
        });
      }
    };

    COSMO_REGISTER_PLUGIN(Postprocessor,
                          UnknownsNorms,
                          "unknowns",
                          "unknowns.csv: the l2 and max norms of the unknowns at every converged "
                          "state and located event.")
  } // namespace io
} // namespace cosmo

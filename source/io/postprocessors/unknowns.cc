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
     * record of a path that needs no VTU.
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
        write_file_atomically(s.output_directory + "/unknowns.csv", [&](std::ostream &o) {
          o << "event,step,branch,t,n_negative,l2_norm,max_norm\n" << std::setprecision(17);
          for (const auto &r : rows)
            for (unsigned int k = 0; k < r.size(); ++k)
              o << r[k] << (k + 1 < r.size() ? "," : "\n");
        });
      }

    private:
      std::vector<std::vector<double>> rows;
    };

    COSMO_REGISTER_PLUGIN(Postprocessor,
                          UnknownsNorms,
                          "unknowns",
                          "unknowns.csv: the l2 and max norms of the unknowns at every converged "
                          "state and located event.")
  } // namespace io
} // namespace cosmo

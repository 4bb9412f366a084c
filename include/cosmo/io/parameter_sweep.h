#ifndef cosmo_io_parameter_sweep_h
#define cosmo_io_parameter_sweep_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

/**
 * A one-parameter study declared in the .prm: the same run repeated with one
 * entry of the parameter file set to each value of a list.
 *
 *   subsection Parameter sweep
 *     set Entry    = Material 1/Growth factor   # path of the entry to vary
 *     set Values   = 0, 0.1, 0.2, 0.3           # or: From, To, Number of values
 *     set Template = 1 + {}*x                   # {} stands for the value
 *   end
 *
 * The template makes any entry sweepable, numbers and expressions alike
 * (a growth magnitude inside a growth law, a fibre angle, a modulus). Every
 * application declares it; the application decides what to tabulate.
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    class ParameterSweep
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads the sweep and checks that the entry exists and accepts every value.
      void
      parse_parameters(ParameterHandler &prm);

      bool
      enabled() const
      {
        return !entry_path.empty();
      }

      /**
       * io::InputError if this sweep is enabled and `section / Distributed`
       * is true: a study spreads its values over the MPI ranks, each value
       * on one rank's whole mesh, which a mesh divided over the ranks is not.
       */
      void
      refuse_distributed_mesh(ParameterHandler &prm, const std::string &section) const;
      unsigned int
      size() const
      {
        return values.size();
      }
      double
      value(const unsigned int k) const
      {
        return values[k];
      }
      /// The swept entry, as "Section/Subsection/Entry".
      const std::string &
      entry() const
      {
        return entry_path;
      }
      /// A short column name for the swept value, e.g. "Growth factor".
      std::string
      label() const;

      /// What the value is, e.g. "Material 1/Growth factor = 1 + {}*x".
      std::string
      axis_label() const;

      /// The text the entry is set to at point k (the template with the value).
      std::string
      text(unsigned int k) const;

      /// Set the swept entry of `prm` to point k (InputError if it is refused).
      void
      apply(ParameterHandler &prm, unsigned int k) const;

      /**
       * The parameters of point k alone, with output to `point_directory`:
       * the swept entry set to its value, `Output directory` to that
       * directory and `Parameter sweep/Entry` cleared, so that the point's
       * parameters.prm reproduces that point alone.
       */
      void
      prepare_point(ParameterHandler & prm,
                    unsigned int       k,
                    const std::string &point_directory) const;

      /// Where point k of a study in `directory` writes: `directory`/point-kk.
      static std::string
      point_directory(const std::string &directory, unsigned int k);

      /// Set any entry given by its path "Section/.../Entry" (InputError if refused).
      static void
      set_entry(ParameterHandler &prm, const std::string &path, const std::string &value,
                const std::string &section, const std::string &entry);

      /// 'Critical curve': continue the critical point from value to value.
      bool
      critical_curve() const
      {
        return curve;
      }

    private:
      bool                curve = false;
      std::string         entry_path;
      std::string         template_text;
      std::vector<double> values;
    };
  } // namespace io
} // namespace cosmo

#endif

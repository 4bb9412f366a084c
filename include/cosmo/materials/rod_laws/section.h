#ifndef cosmo_materials_rod_laws_section_h
#define cosmo_materials_rod_laws_section_h

#include <deal.II/base/function_parser.h>

#include <cosmo/base/monotone_cubic.h>
#include <cosmo/materials/rod_law.h>

#include <memory>
#include <string>
#include <vector>

/**
 * The rod law of part-1 sections (or of a part-2 strip at its natural
 * shape), registered as 'section' (doc/theory-rod.md 4.2): the quadratic energy
 *
 *   psi(e) = 1/2 e . K(p) e
 *
 * about the natural strains (nu0(p), kappa0(p)) of a grown cross-section,
 * both computed by rod_cross_section. One section (its summary.json), or a
 * family of them over a growth parameter p (the sweep.csv of a parameter
 * sweep, p its swept value), with p = p(s, t) an expression along the rod
 * and in the load parameter: a rod whose differential growth varies along
 * its length and in time. Between the family's members every natural
 * strain and every stiffness is interpolated by a monotone piecewise cubic
 * (base::MonotoneCubic): C1 in p, exact at the members and for data linear
 * in p, and without overshoot, so that a stiffness stays between its
 * neighbours' values. A p outside the family's range is refused
 * (LawRangeError naming p, where and the range).
 */
namespace cosmo
{
  namespace materials
  {
    /// What part 1 (or part 2) says of one grown section at its natural shape,
    /// forces in units of E L^2 and moments E L^3 (a strip's E w h restored).
    struct SectionResult
    {
      double                 parameter = 0; ///< the swept value (0 for one section)
      std::array<double, 6>  strains{};     ///< natural nu1, nu2, nu3, kappa1, kappa2, kappa3
      std::array<double, 6>  resultants{};  ///< n, m there (zero at a natural shape)
      std::array<double, 36> stiffness{};   ///< 6 x 6, row-major
      bool                   strip = false; ///< a part-2 strip's result
    };

    /**
     * The result in a rod_cross_section summary.json: io::InputError naming
     * `entry` of `section` unless it is one, converged, with a 6x6
     * "stiffness" of finite numbers.
     */
    SectionResult
    read_section_summary(const std::string &file, const std::string &section, const std::string &entry);

    /// The loops of a rod_cross_section outline.csv (empty if absent or malformed).
    RodLaw::SectionOutline
    read_outline(const std::string &file);

    /// "strip" for a parameter file with a subsection 'Strip' (part 2), else
    /// "rod_cross_section" (part 1): the application a 'Section file' names.
    std::string
    application_of_parameter_file(const std::string &file);

    /// The converged rows of a rod_cross_section sweep.csv (the others are
    /// holes: counted in `holes`), in the order of the file.
    std::vector<SectionResult>
    read_section_sweep(const std::string &file, const std::string &section, const std::string &entry,
                       unsigned int &holes);

    class SectionRodLaw : public RodLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      /// 'Section file' and 'Section parameter'; a .prm file is only remembered
      /// (computed_input()): the application computes it and calls read_computed().
      void
      parse_parameters(ParameterHandler &prm, const std::string &section) override;

      /// 'Section file' is a rod_cross_section parameter file the run computes itself.
      ComputedInput
      computed_input() const override
      {
        if (members.empty() && !file.empty())
          return {application_of_parameter_file(file), file, "Section file", "section"};
        return {};
      }
      void
      read_computed(const std::string &directory, const std::string &note) override
      {
        read_result(directory);
        computed_note = note;
      }
      /// Read the members from a result: a summary.json, a sweep.csv, or a
      /// directory holding one of them (a sweep's first).
      void
      read_result(const std::string &path);

      /// The member with the smallest p (scales, the natural stiffness).
      void
      energy_derivatives(const std::array<double, 6> &e,
                         bool                         with_hessian,
                         double &                     W,
                         std::array<double, 6> &      dW,
                         std::array<double, 36> &     ddW) const override;
      void
      energy_derivatives_at(double                       p,
                            const std::array<double, 6> &e,
                            bool                         with_hessian,
                            double &                     W,
                            std::array<double, 6> &      dW,
                            std::array<double, 36> &     ddW) const override;
      double
      parameter_at(double s, double t) const override;
      bool
      parameter_depends_on_load() const override
      {
        return members.size() > 1 && expression_names(parameter_text, "t");
      }
      std::optional<std::array<double, 6>>
      natural_strains_at(double p) const override;
      bool
      gives_natural_strains() const override
      {
        return true;
      }
      std::string
      description() const override;
      /// One section's outline.csv (part 1, or a strip's), beside its summary.json (none for a family).
      SectionOutline
      section_outline() const override
      {
        return outline;
      }

      /// The natural strains and stiffness at p (LawRangeError outside the range).
      SectionResult
      member_at(double p) const;
      /// The stiffness alone at p (LawRangeError outside the range): what the energy needs.
      std::array<double, 36>
      stiffness_at(double p) const;
      /// The family's range [p_min, p_max] (one value for one section).
      std::pair<double, double>
      range() const;

      /// How the sections came (computed by this run, reused): for the log.
      std::string computed_note;

    private:
      std::string                        file, section_name, origin;
      std::string                        parameter_text = "0";
      std::shared_ptr<FunctionParser<2>> parameter;
      std::vector<SectionResult>         members;
      unsigned int                       holes = 0;
      SectionOutline                     outline;
      /// Per natural strain and per stiffness entry (upper triangle), over p.
      std::array<base::MonotoneCubic, 6>  strain_curves;
      std::array<base::MonotoneCubic, 36> stiffness_curves; ///< upper triangle (a <= b) used

      void
      build_curves();
      /// LawRangeError unless p lies in the family's range (any p for one section).
      void
      check_range(double p) const;
      /// io::InputError unless K(p) is positive definite between the members.
      void
      check_positive_definite() const;
    };
  } // namespace materials
} // namespace cosmo

#endif

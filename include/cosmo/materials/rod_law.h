#ifndef cosmo_materials_rod_law_h
#define cosmo_materials_rod_law_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/base/plugins.h>
#include <cosmo/materials/plate_law.h>

#include <array>
#include <cctype>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>
#include <type_traits>

/**
 * A special Cosserat rod's law and its axial growth
 * (doc/specification/plate-rod.md): with reference strains (nu0, kappa0) and
 * growth g, the stress-free rod has strains g nu0 and kappa0 (a ring of
 * radius R grows to radius g R: the curvature per reference length stays
 * 1/R), and the energy per reference length is
 *
 *   g psi(e),  e = (nu/g - nu0, (kappa - kappa0)/g)
 *
 * in the elastic strains e (shear 1, 2, extension, bending 1, 2, twist),
 * zero in the natural state. psi is the law, a registered RodLaw; the growth
 * map is the rod's kinematics (grown_rod_energy()), the same for every law.
 */
namespace cosmo
{
  namespace materials
  {
    using namespace dealii;

    /**
     * A rod law: psi(e), the energy per unit length of the stress-free rod
     * in the six elastic strains e. Implementations register themselves by
     * name (COSMO_REGISTER_PLUGIN), one file each in
     * source/materials/rod_laws/; the names are the values of 'Rim rod /
     * Law' (doc/cookbook.md, "Add a rod law"). The law gives its value,
     * gradient (the resultants) and Hessian (the tangent stiffness) at a
     * state; grown_rod_energy() evaluates it on Sacado numbers through its
     * second-order Taylor expansion there.
     */
    /**
     * A law asked for a state it does not cover (a table's strain outside
     * its grid, a family's parameter outside its range): the message names
     * the quantity, its value and the range. Not an error of the run by
     * itself (a Newton iterate may stray): the state is refused, and the
     * message says why a path that cannot go on stopped.
     */
    class LawRangeError : public std::runtime_error
    {
    public:
      using std::runtime_error::runtime_error;
    };

    class RodLaw
    {
    public:
      virtual ~RodLaw() = default;
      /// Reads its entries in `section` (entered; named in its errors).
      virtual void
      parse_parameters(ParameterHandler &prm, const std::string &section) = 0;
      /// psi(e), its gradient dW and, with_hessian, its Hessian ddW (6 x 6,
      /// row-major, symmetric, every entry written).
      virtual void
      energy_derivatives(const std::array<double, 6> &e,
                         bool                         with_hessian,
                         double &                     W,
                         std::array<double, 6> &      dW,
                         std::array<double, 36> &     ddW) const = 0;
      /// A line for the log: what the law is and where its numbers come from.
      virtual std::string
      description() const = 0;

      /**
       * A law that varies along the rod (a family of sections over a growth
       * parameter p): p at the reference arclength s and load parameter t.
       * 0 for a law that does not vary.
       */
      virtual double
      parameter_at(const double /*s*/, const double /*t*/) const
      {
        return 0;
      }
      /// Whether parameter_at() depends on t (its expression names t).
      virtual bool
      parameter_depends_on_load() const
      {
        return false;
      }
      /**
       * The natural strains (nu, kappa) the law itself gives at parameter p
       * (a part-1 section's natural shape), or nothing: then the rod's own
       * 'Natural strains'. LawRangeError outside the law's range.
       */
      virtual std::optional<std::array<double, 6>>
      natural_strains_at(const double /*p*/) const
      {
        return std::nullopt;
      }
      /// Does natural_strains_at() give them (whatever p)?
      virtual bool
      gives_natural_strains() const
      {
        return false;
      }
      /**
       * A law computed from another application's parameter file by the
       * rod run itself (a part-1 section, a part-2 table): that
       * application's name, the file, the law's entry that names it (for
       * errors) and the directory of the run's output to compute it in;
       * empty if the law is read as given.
       */
      struct ComputedInput
      {
        std::string application, parameter_file, entry, directory;
      };
      virtual ComputedInput
      computed_input() const
      {
        return {};
      }
      /// Read the law from the directory the computation of computed_input() wrote.
      virtual void
      read_computed(const std::string & /*directory*/, const std::string & /*note*/)
      {}

      /**
       * The cross-section the law was computed from, to draw the rod as its
       * section swept along the centreline: closed loops (the boundary, and
       * a hole's) of points, each (X1, X2, w1, w2, w3, stress): the reference
       * point, its placement w in the director frame at the natural state
       * and the section's von Mises stress there; then, where the section
       * was linearized (6 + 6 + 36 values), the Cauchy stress's components
       * (11, 22, 33, 12, 13, 23) there and their derivatives in the six
       * strains (strain-major), so that the stress follows the rod's strains.
       * Empty if the law has no section (a part-1 or strip outline.csv
       * beside the law's result).
       */
      using SectionOutline = std::vector<std::vector<std::vector<double>>>;
      virtual SectionOutline
      section_outline() const
      {
        return {};
      }

      /// energy_derivatives() of the member at parameter p (LawRangeError outside its range).
      virtual void
      energy_derivatives_at(const double                 /*p*/,
                            const std::array<double, 6> &e,
                            const bool                   with_hessian,
                            double &                     W,
                            std::array<double, 6> &      dW,
                            std::array<double, 36> &     ddW) const
      {
        energy_derivatives(e, with_hessian, W, dW, ddW);
      }

      /// The tangent stiffness in the natural state (e = 0), 6 x 6 row-major:
      /// the small-strain stiffnesses of the closed forms and the checks.
      std::array<double, 36>
      natural_stiffness() const;
    };

    /**
     * The largest normalized coupling max over a != b of |K_ab| / sqrt(|K_aa
     * K_bb|) of a 6 x 6 stiffness (row-major): 0 for a diagonal one. The
     * closed forms take the diagonal alone; this says how far the law is
     * from them.
     */
    double
    largest_coupling(const std::array<double, 36> &K);

    /**
     * Where a rod's strains are measured from at a point: the reference
     * strains (nu0, kappa0), the axial growth g and a weight on each
     * elastic strain (psi(w e): the stiffness K -> D K D with D = diag(w),
     * the Kirchhoff penalty on the shears). For a quadratic law that is
     * the stiffness times w^2; a nonlinear law is evaluated at the weighted
     * strain, which is a penalty of the same stiffness at small strain only.
     */
    /// Whether a muparser expression names `variable` (an identifier of its own, not part of one).
    inline bool
    expression_names(const std::string &text, const std::string &variable)
    {
      auto is_name = [](const char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
      for (std::size_t at = text.find(variable); at != std::string::npos; at = text.find(variable, at + 1))
        if ((at == 0 || !is_name(text[at - 1])) &&
            (at + variable.size() == text.size() || !is_name(text[at + variable.size()])))
          return true;
      return false;
    }

    struct RodNaturalState
    {
      std::array<double, 6> reference_strains{{0, 0, 1, 0, 0, 0}};
      double                growth = 1;
      std::array<double, 6> weights{{1, 1, 1, 1, 1, 1}};
      /// The law's parameter here (RodLaw::parameter_at; 0 for a law that does not vary).
      double parameter = 0;
    };

    /// The weighted elastic strains w_k e_k, e = (nu/g - nu0, (kappa - kappa0)/g).
    template <typename Number>
    std::array<Number, 6>
    elastic_rod_strains(const std::array<Number, 6> &strains, const RodNaturalState &n)
    {
      std::array<Number, 6> e;
      for (unsigned int k = 0; k < 6; ++k)
        e[k] = n.weights[k] * (k < 3 ? Number(strains[k] / n.growth - n.reference_strains[k]) :
                                       Number((strains[k] - n.reference_strains[k]) / n.growth));
      return e;
    }

    /**
     * g psi(e) of the strains (nu, kappa), on Sacado numbers through the
     * law's second-order Taylor expansion at their value (value, gradient
     * and Hessian there are the law's; exact for a quadratic law).
     */
    template <typename Number>
    Number
    grown_rod_energy(const RodLaw &law, const std::array<Number, 6> &strains, const RodNaturalState &n)
    {
      const auto             e = elastic_rod_strains(strains, n);
      std::array<double, 6>  e0, dW{};
      std::array<double, 36> ddW{};
      for (unsigned int k = 0; k < 6; ++k)
        e0[k] = value_of(e[k]);
      double W = 0;
      if constexpr (std::is_same_v<Number, double>)
        {
          law.energy_derivatives_at(n.parameter, e0, false, W, dW, ddW);
          return n.growth * W;
        }
      else
        {
          law.energy_derivatives_at(n.parameter, e0, true, W, dW, ddW);
          std::array<Number, 6> de;
          Number                w(W); // no derivatives
          for (unsigned int k = 0; k < 6; ++k)
            {
              de[k] = e[k] - e0[k];
              if (dW[k] != 0)
                w += dW[k] * de[k];
            }
          for (unsigned int k = 0; k < 6; ++k)
            for (unsigned int l = k; l < 6; ++l)
              if (const double h = ddW[6 * k + l]; h != 0)
                w += (k == l ? 0.5 * h : h) * de[k] * de[l];
          return n.growth * w;
        }
    }

    /**
     * The resultants (n, m) = d(g psi)/d(nu, kappa) = w_k dpsi/de_k (the
     * growth's 1/g and g cancel). The output writes these.
     */
    std::array<double, 6>
    grown_rod_resultants(const RodLaw &law, const std::array<double, 6> &strains, const RodNaturalState &n);

    /// The entry 'Law' (the registered rod laws) and every law's entries, in
    /// the entered section.
    void
    declare_rod_law_parameters(ParameterHandler &prm);
    /// The law selected in the entered section `section`'s 'Law', its entries read.
    std::unique_ptr<RodLaw>
    create_rod_law(ParameterHandler &prm, const std::string &section);
  } // namespace materials

  namespace plugins
  {
    // One registry of rod laws per process (instantiated in source/materials/rod_law.cc).
    extern template class Registry<materials::RodLaw>;
  } // namespace plugins
} // namespace cosmo

#endif

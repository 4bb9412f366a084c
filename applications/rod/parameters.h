#ifndef cosmo_applications_rod_parameters_h
#define cosmo_applications_rod_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <cosmo/materials/rod_law.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/continuation.h>
#include <cosmo/solvers/newton.h>

#include <array>
#include <memory>
#include <string>

/**
 * The parameters of the rod application, typed and parsed once
 * (doc/user-guide-rod.md): the rod's length, mesh and shape, its law and
 * natural state, its ends and loads, the solvers and the output.
 * Expressions are muparser expressions of the reference arclength s and the
 * load parameter t (and pi), components separated by ';'.
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    /// An expression of (s, t) with n components: evaluate at Point<2>(s, t).
    using Expression = std::shared_ptr<FunctionParser<2>>;

    /// One end of an open rod (section 'End A' or 'End B').
    struct RodEnd
    {
      enum class Support
      {
        clamped, ///< position and rotation prescribed
        pinned,  ///< position prescribed, rotation free
        rotation, ///< rotation prescribed, position free ('rotation only')
        free     ///< nothing prescribed
      };
      Support    support = Support::free;
      Expression displacement; ///< from the reference position, of t (3)
      Expression rotation;     ///< rotation vector applied to the reference frame, of t (3)
      Expression force;        ///< dead force on the end, of t (3)
      bool       force_depends_on_load = true; ///< its expression names t
    };

    struct RodParameters
    {
      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads and checks every entry (io::InputError naming the entry).
      void
      parse_parameters(ParameterHandler &prm);

      /// io::InputError unless the supports hold the rigid motions of an open rod.
      void
      check_supports(ParameterHandler &prm) const;
      /// Values of an expression at (s, t).
      static Vector<double>
      evaluate(const Expression &f, double s, double t);
      /// The natural state (strains, growth) at s and t.
      materials::RodNaturalState
      natural_state(double s, double t) const;
      /// sqrt of the 'Stiffness factors' at s and t (LawRangeError unless positive).
      std::array<double, 6>
      stiffness_weights(double s, double t) const;
      /// The law's stiffness at the natural state, for scales.
      double
      largest_force_stiffness() const;
      double
      largest_moment_stiffness() const;

      double       length     = 1;
      unsigned int n_elements = 40;
      bool         ring       = false;
      std::string  shape      = "straight"; ///< straight | natural | ring
      Expression   natural_strains;          ///< 6 components of (s, t)
      Expression   imperfection;             ///< 6 components of (s, t), added to any law's natural strains
      Expression   growth;                   ///< the natural stretch g(s, t)
      Expression   stiffness_factors;        ///< 6 factors f_k(s, t) on the law's stiffness
      Expression   distributed_force;        ///< per reference length, of (s, t)
      /// Whether the natural strains, imperfection, growth, stiffness factors or distributed force name t.
      bool         element_data_depend_on_load = true;
      Expression   seam_twist;               ///< a ring's added twist in turns, of t
      std::shared_ptr<const materials::RodLaw> law;
      std::array<RodEnd, 2>                    ends;
      double       rotation_limit = 0.75 * M_PI; ///< largest relative rotation of an element
      double       contact_radius = 0;           ///< self-contact's radius a (0: none)
      double       contact_stiffness = 100;      ///< k a^6 / B, dimensionless (doc/theory-rod.md 9)
      double       start          = 0;           ///< the load parameter at the path's start

      solvers::NewtonSettings    newton_settings;
      solvers::ArclengthSettings arclength_settings;
      solvers::ContinuationSettings continuation_settings;
      std::string                output_directory;
      double                     tube_radius = 0.02; ///< of the tube drawn as the body, per length (0: none)
      bool                       section_body = false; ///< the body drawn as the law's swept section
      /// Link, twist and writhe of a ring or a rod clamped at both ends: the
      /// writhe costs O(N^2), so 'auto' computes them up to 2000 elements.
      bool                       topology = true;
    };
  } // namespace rod
} // namespace cosmo

#endif

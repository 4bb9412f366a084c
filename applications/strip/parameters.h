#ifndef cosmo_applications_strip_parameters_h
#define cosmo_applications_strip_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <cosmo/materials/plate_law.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/continuation.h>
#include <cosmo/solvers/newton.h>

#include <array>
#include <memory>
#include <string>

/**
 * The parameters of part 2, typed and parsed once (doc/user-guide-strip.md):
 * the strip's width, thickness and mesh, its plate law, the solvers and the
 * output. The rod strains are the reduced-rod base's
 * (assembly/reduced_rod_problem.h); StripProblem is a problem on both.
 */
namespace cosmo
{
  namespace strip
  {
    using namespace dealii;

    struct StripParameters
    {
      /// Every entry of the application (the strains', the sweep's and the table's too).
      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads and checks the entries of this struct (io::InputError naming the entry).
      void
      parse_parameters(ParameterHandler &prm);

      double                        strip_width = 1, thickness = 0.01;
      unsigned int                  n_cells = 40, degree = 2;
      std::string                   mesh_kind = "graded";
      bool                          reduced_shear = true;
      /// 'Natural curvature': k11, k22, k12 of the stress-free plate as
      /// expressions of (eta, t); null when the entry is zero (a flat plate).
      std::shared_ptr<FunctionParser<2>> natural_curvature;
      /// Parses and checks 'Natural curvature' (io::InputError naming it).
      void
      parse_natural_curvature(const std::string &text);
      /// The natural curvature (k11, k22, k12) at eta for the load t.
      std::array<double, 3>
      natural_curvature_at(double eta, double t) const;
      /// The plate law of the strip ('Plate material / Law').
      std::shared_ptr<const materials::PlateLaw> plate_law;
      solvers::NewtonSettings       newton_settings;
      solvers::ContinuationSettings continuation_settings;
      solvers::ArclengthSettings    arclength_settings;
      std::string                   linear_solver_name = "MUMPS";
      std::string                   output_directory;
    };
  } // namespace strip
} // namespace cosmo

#endif

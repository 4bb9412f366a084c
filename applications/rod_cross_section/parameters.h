#ifndef cosmo_applications_rod_cross_section_parameters_h
#define cosmo_applications_rod_cross_section_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <cosmo/geometry/cross_section.h>
#include <cosmo/materials/material.h>
#include <cosmo/materials/surface_layer.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/continuation.h>
#include <cosmo/solvers/newton.h>

#include <string>

/**
 * The parameters of part 1, typed and parsed once
 * (doc/user-guide-rod-cross-section.md): the section's shape, its materials
 * and surface layers, the finite element, the solvers and the output. The
 * rod strains are the reduced-rod base's (assembly/reduced_rod_problem.h);
 * CrossSectionProblem is a problem on both.
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    struct CrossSectionParameters
    {
      /// Every entry of the application (the strains', the sweep's and the table's too).
      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads and checks the entries of this struct (io::InputError naming the entry).
      void
      parse_parameters(ParameterHandler &prm);

      geometry::CrossSectionGeometry geometry;
      materials::MaterialLibrary     materials;
      materials::SurfaceLayerLibrary surface_layers;
      unsigned int                   degree = 2;
      solvers::NewtonSettings        newton_settings;
      solvers::ContinuationSettings  continuation_settings;
      solvers::ArclengthSettings     arclength_settings;
      std::string                    linear_solver_name;
      unsigned int                   coarse_start_levels = 0;
      std::string                    parameters_text; // the run's parameters, for a coarser copy
      std::string                    output_directory;
      double                         rod_piece_length = 0; // 0: automatic
      unsigned int                   rod_piece_slices = 24;
      bool                           stiffness_every_step = true;
      /// 'Finite element / Distributed': the mesh divided over the ranks.
      bool                           distributed_mesh = false;
    };
  } // namespace rod
} // namespace cosmo

#endif

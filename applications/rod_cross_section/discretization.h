#ifndef cosmo_applications_rod_cross_section_discretization_h
#define cosmo_applications_rod_cross_section_discretization_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <cosmo/analysis/section_properties.h>
#include <cosmo/geometry/cross_section.h>
#include <cosmo/geometry/mesh_of_ranks.h>

#include "parameters.h"

#include <array>
#include <limits>
#include <memory>
#include <vector>

/**
 * The discretization of part 1's cross-section: what depends on the mesh
 * and the finite element only, apart from the problem that assembles,
 * solves and writes on it (cross_section_problem.h).
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    /**
     * The section's mesh (with 'Finite element / Distributed' divided over
     * the ranks: each assembles its own cells, the bordered system's A is
     * distributed by rows, the drivers' vectors are whole on every rank;
     * doc/parallel-runs.md), FE_Q(p)^3 with its mapping and DoFs, the
     * discrete section's properties, the boundary faces of the surface
     * layers and the growth at the quadrature points, on the parameters it
     * was made from (the problem's own, held by reference). The assembly,
     * the VTU writers and the mode classification read it.
     */
    class SectionDiscretization
    {
    public:
      /// A boundary face carrying a surface layer.
      struct SurfaceFace
      {
        typename DoFHandler<2>::active_cell_iterator cell;
        unsigned int                                 face;
        unsigned int                                 layer;
      };

      explicit SectionDiscretization(const CrossSectionParameters &parameters);
      ~SectionDiscretization();

      /// The mesh of the section's shape, refused if it would not fit in memory.
      void
      create_mesh();
      /// The material ids of the mesh's cells, in the order first met.
      std::vector<types::material_id>
      material_ids() const;
      /// On the mesh (its regions resolved): the element, mapping and DoFs,
      /// the section's properties and the faces of every surface layer.
      void
      distribute_dofs();

      /// io::InputError unless every bulk and surface law is admissible on every
      /// level of the mesh along the ramp (materials/growth_admissibility.h).
      void
      check_growth() const;
      /// Growth at the quadrature points at load t; false where det Fg
      /// or a surface factor is not positive.
      bool
      update_growth_cache(double t);

      /**
       * The parity of a mode's field under the half-turn of the rod about the
       * section's axis X_axis (axis 0 or 1; geometry::reflection_parity):
       * +1 symmetric, -1 antisymmetric, NaN where the mesh is not its own
       * mirror image about that axis.
       */
      double
      mode_parity(const Vector<double> &mode, unsigned int axis) const;
      /// The linear Saint-Venant properties of the reference section
      /// (analysis/section_properties.h): centres, principal axes, GJ, shear factors.
      analysis::LinearSectionProperties
      linear_section_properties() const;

      const geometry::MeshOfRanks<2> &
      get_mesh() const
      {
        return triangulation;
      }
      const FESystem<2> &
      get_fe() const
      {
        return *fe;
      }
      const MappingQ<2> &
      get_mapping() const
      {
        return *mapping;
      }
      const DoFHandler<2> &
      get_dof_handler() const
      {
        return dof_handler;
      }
      /// The displacement's DoFs, the first unknowns of the problem.
      unsigned int
      n_u() const
      {
        return dof_handler.n_dofs();
      }
      /// Area, moments and diameter of the discrete section.
      const geometry::SectionProperties &
      properties() const
      {
        return section_properties;
      }
      const std::vector<SurfaceFace> &
      get_surface_faces() const
      {
        return surface_faces;
      }
      /// Per layer, its reference arc length.
      const std::vector<double> &
      get_surface_length() const
      {
        return surface_length;
      }
      /// Fg per cell and quadrature point (update_growth_cache()).
      const std::vector<Tensor<2, 3>> &
      bulk_growth() const
      {
        return growth_at_qp;
      }
      /// (gT, g3) per surface face and quadrature point (update_growth_cache()).
      const std::vector<std::array<double, 2>> &
      surface_growth() const
      {
        return surface_growth_at_qp;
      }

    private:
      const CrossSectionParameters &parameters;

      geometry::MeshOfRanks<2>           triangulation;
      std::unique_ptr<FESystem<2>>       fe;
      std::unique_ptr<MappingQ<2>>       mapping;
      DoFHandler<2>                      dof_handler;
      geometry::SectionProperties        section_properties;
      std::vector<Tensor<2, 3>>          growth_at_qp; // per cell and quadrature point
      double                             growth_cached_for = std::numeric_limits<double>::quiet_NaN();
      std::vector<SurfaceFace>           surface_faces;
      std::vector<std::array<double, 2>> surface_growth_at_qp; // (gT, g3) per face and point
      std::vector<double>                surface_length;       // per layer, reference arc length

      /// The faces of every surface layer (after the mesh and DoFs exist).
      void
      setup_surface_faces();
    };
  } // namespace rod
} // namespace cosmo

#endif

#ifndef cosmo_geometry_mesh_of_ranks_h
#define cosmo_geometry_mesh_of_ranks_h

#include <deal.II/distributed/tria.h>
#include <deal.II/grid/tria.h>

#include <memory>

/**
 * The mesh of an application that runs on one process or on a mesh divided
 * over the MPI ranks ('Distributed', doc/parallel-runs.md "Distributed
 * meshes"): a serial Triangulation, or a parallel::distributed::Triangulation
 * over MPI_COMM_WORLD, made when first asked for. Both are filled by the
 * same GridGenerator calls and refinements, so that the two meshes are the
 * same cells.
 */
namespace cosmo
{
  namespace geometry
  {
    using namespace dealii;

    template <int dim>
    class MeshOfRanks
    {
    public:
      /// Use the distributed mesh (true) or the serial one (false) from now on.
      void
      set_distributed(const bool d)
      {
        distributed = d;
        if (d && !of_ranks)
          of_ranks = std::make_unique<parallel::distributed::Triangulation<dim>>(MPI_COMM_WORLD);
      }

      bool
      is_distributed() const
      {
        return distributed;
      }

      /// The mesh in use.
      Triangulation<dim> &
      get()
      {
        return distributed ? *of_ranks : serial;
      }
      const Triangulation<dim> &
      get() const
      {
        return distributed ? *of_ranks : serial;
      }

    private:
      bool                                                       distributed = false;
      Triangulation<dim>                                         serial;
      std::unique_ptr<parallel::distributed::Triangulation<dim>> of_ranks;
    };
  } // namespace geometry
} // namespace cosmo

#endif

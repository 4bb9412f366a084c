#ifndef cosmo_applications_plate_rod_discretization_h
#define cosmo_applications_plate_rod_discretization_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>
#include <cosmo/geometry/mesh_of_ranks.h>
#include <cosmo/solvers/replicated_vector.h>

#include "parameters.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

/**
 * The discretization of part 3, made from the parameters alone: the disc or
 * the sector (mesh.cc), the curved rim's mapping, FE_Q(p)^6 with its DoFs
 * and their constraints (mirror edges, gauges, the rim rotation off the rim),
 * and what follows per DoF. The problem (plate_rod_problem.h) assembles on
 * it; the diagnostics and the output (diagnostics.h) read it. It depends on
 * neither the state nor the load, so a new set of parameters needs only
 * reinit().
 */
namespace cosmo
{
  namespace plate_rod
  {
    using namespace dealii;

    /// Rim boundary id; the mirror edges of a sector are 1 (theta = 0) and 2 (theta = pi/n).
    constexpr types::boundary_id rim_id = 0, mirror_first = 1, mirror_second = 2;

    class PlateRodDiscretization
    {
    public:
      /// On `parameters`, which outlive it (the problem is its parameters).
      explicit PlateRodDiscretization(const PlateRodParameters &parameters);
      ~PlateRodDiscretization();

      /// The mesh, the FE and its DoFs, the constraints, the per-DoF tables
      /// and the reflection from the parameters as they are now; then the
      /// plate's fields checked on the mesh (check_plate_fields).
      void
      reinit();
      /// The Hessian's sparsity on these DoFs and constraints into `system`
      /// (serial, or its rows distributed as `layout`'s).
      void
      reinit_system(assembly::BorderedSystem &system) const;

      unsigned int
      n_dofs() const
      {
        return dof_handler.n_dofs();
      }
      /// 1 on the full disc, n on a sector pi/n: the admitted mode numbers are its multiples.
      unsigned int
      sector_step() const
      {
        return parameters.domain == "sector" ? parameters.sector_n : 1;
      }
      /// The constraints' slaves of v set from their masters; every rank takes
      /// them from their owners (each set only those it knows).
      void
      distribute(Vector<double> &v) const;
      /// 1 on the DoFs the constraints leave free, 0 on those they set.
      void
      free_dof_mask(Vector<double> &mask) const;
      /// max |u_s - sum_m w_m u_m| over the constraints (0 to round-off on every state).
      double
      constraint_violation(const Vector<double> &U) const;
      /// Full disc: (v + S v)/2 with S the reflection y -> -y (sector: false).
      bool
      project_to_fixed_point_space(Vector<double> &v) const;
      /// The run's discretization in one line of the log.
      std::string
      describe() const;

      const PlateRodParameters &parameters;
      // With 'Mesh / Distributed' the mesh is divided over the ranks: each
      // knows its own cells and their neighbours, and the drivers' vectors
      // are whole on every rank, kept equal by `layout`.
      geometry::MeshOfRanks<2>        triangulation;
      std::unique_ptr<MappingQ<2>>    mapping;
      std::unique_ptr<FESystem<2>>    fe;
      DoFHandler<2>                   dof_handler;
      AffineConstraints<double>       constraints;
      solvers::ReplicatedVectorLayout layout;
      std::vector<unsigned char>      dof_component;   ///< field component of each DoF
      std::vector<unsigned char>      dof_constrained; ///< 1 where the constraints set the DoF

    private:
      /// Full disc: the DoF each DoF maps to under y -> -y, and the sign.
      std::vector<std::pair<types::global_dof_index, double>> reflection;

      void
      make_mesh();
      void
      make_constraints();
      void
      make_reflection();
      /// io::InputError unless the thickness profile and the natural curvature are finite at
      /// every quadrature point of the mesh and the thickness positive there.
      void
      check_plate_fields() const;
    };
  } // namespace plate_rod
} // namespace cosmo

#endif

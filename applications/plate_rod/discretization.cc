// The discretization of part 3: its DoFs and the tables per DoF, the
// Hessian's sparsity, the constraints' use, the full disc's reflection and
// the check of the plate's fields on the mesh; the mesh and the constraints
// themselves are made in mesh.cc.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/parameters.h>
#include <cosmo/io/resources.h>
#include <cosmo/materials/growth_admissibility.h>

#include "discretization.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {
    PlateRodDiscretization::PlateRodDiscretization(const PlateRodParameters &parameters)
      : parameters(parameters)
    {}

    PlateRodDiscretization::~PlateRodDiscretization()
    {
      dof_handler.clear();
    }

    void
    PlateRodDiscretization::reinit()
    {
      make_mesh();
      fe = std::make_unique<FESystem<2>>(FE_Q<2>(parameters.degree), 6);
      dof_handler.reinit(triangulation.get());
      dof_handler.distribute_dofs(*fe);
      make_constraints();
      // On a distributed mesh each rank owns a contiguous range of the DoFs.
      layout = parameters.distributed_mesh ?
                 solvers::ReplicatedVectorLayout(MPI_COMM_WORLD, dof_handler.locally_owned_dofs()) :
                 solvers::ReplicatedVectorLayout();
      // Per DoF, its field and whether it is constrained, taken from its owner's cells.
      dof_component.assign(dof_handler.n_dofs(), 0);
      dof_constrained.assign(dof_handler.n_dofs(), 0);
      std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(idx);
            for (unsigned int i = 0; i < idx.size(); ++i)
              {
                dof_component[idx[i]]   = fe->system_to_component_index(i).first;
                dof_constrained[idx[i]] = constraints.is_constrained(idx[i]) ? 1 : 0;
              }
          }
      layout.take_from_owners(dof_component);
      layout.take_from_owners(dof_constrained);
      make_reflection();
      check_plate_fields();
    }

    void
    PlateRodDiscretization::reinit_system(assembly::BorderedSystem &system) const
    {
      if (parameters.distributed_mesh)
        {
          // Each rank's rows: those of its own DoFs, entries from its cells
          // sent to their owners at compress().
          const IndexSet owned = dof_handler.locally_owned_dofs();
          IndexSet       relevant;
          DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
          TrilinosWrappers::SparsityPattern sp;
          sp.reinit(owned, owned, relevant, MPI_COMM_WORLD);
          DoFTools::make_sparsity_pattern(dof_handler, sp, constraints, false,
                                          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD));
          sp.compress();
          system.reinit(sp, 0, layout);
        }
      else
        {
          DynamicSparsityPattern dsp(dof_handler.n_dofs());
          DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
          system.reinit(dsp, 0);
        }
    }

    void
    PlateRodDiscretization::distribute(Vector<double> &v) const
    {
      constraints.distribute(v);
      layout.take_from_owners(v);
    }

    void
    PlateRodDiscretization::free_dof_mask(Vector<double> &mask) const
    {
      mask.reinit(n_dofs());
      mask = 1.;
      for (unsigned int i = 0; i < mask.size(); ++i)
        if (dof_constrained[i])
          mask[i] = 0;
    }

    double
    PlateRodDiscretization::constraint_violation(const Vector<double> &U) const
    {
      double v = 0;
      for (const auto &line : constraints.get_lines())
        {
          double r = U[line.index] - line.inhomogeneity;
          for (const auto &entry : line.entries)
            r -= entry.second * U[entry.first];
          v = std::max(v, std::abs(r));
        }
      return parameters.distributed_mesh ? Utilities::MPI::max(v, MPI_COMM_WORLD) : v;
    }

    void
    PlateRodDiscretization::make_reflection()
    {
      // The full disc's reflection y -> -y: u1, u3 even, u2 odd; the rotation
      // vector is axial, theta -> -diag(1, -1, 1) theta: theta1 and alpha
      // (about E3) odd, theta2 even. DoFs are paired by their support points.
      reflection.clear();
      if (parameters.domain == "sector")
        return;
      // (empty where the mesh is not mirror-symmetric: no reflection)
      const auto   mirror  = geometry::mirror_dofs(*mapping, dof_handler, 1, parameters.radius);
      const double sign[6] = {1, -1, 1, -1, 1, -1};
      for (types::global_dof_index i = 0; i < mirror.size(); ++i)
        reflection.emplace_back(mirror[i], sign[dof_component[i]]);
    }

    bool
    PlateRodDiscretization::project_to_fixed_point_space(Vector<double> &v) const
    {
      if (reflection.empty() || v.size() != reflection.size())
        return false;
      const Vector<double> w = v;
      for (unsigned int i = 0; i < v.size(); ++i)
        v[i] = 0.5 * (w[i] + reflection[i].second * w[reflection[i].first]);
      return true;
    }

    std::string
    PlateRodDiscretization::describe() const
    {
      const PlateRodParameters &p = parameters;
      std::ostringstream        info;
      info << "  " << p.model->name() << " model, R = " << p.radius << ", h = " << p.thickness
           << " (h/R = " << p.thickness / p.radius << "), "
           << (p.domain == "sector" ? "sector pi/" + std::to_string(p.sector_n) :
                                      std::string("full disc"))
           << ", " << triangulation.get().n_global_active_cells() << " cells, Q" << p.degree
           << ", " << dof_handler.n_dofs() << " DoFs ("
           << std::count(dof_constrained.begin(), dof_constrained.end(), 1)
           << " constrained), estimated peak memory "
           << io::format_bytes(io::estimated_memory(dof_handler.n_dofs(), p.degree));
      if (p.distributed_mesh)
        info << ", the mesh distributed over " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
             << (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ? " rank" : " ranks");
      return info.str();
    }

    void
    PlateRodDiscretization::check_plate_fields() const
    {
      const PlateRodParameters &p = parameters;
      // Where the energy is evaluated: the Gauss points of every cell (the assumed shear's tying
      // points lie between them or on the cell's edges, within the cell).
      const QGauss<2>       quadrature(p.degree + 1);
      FEValues<2>           fev(*mapping, *fe, quadrature, update_quadrature_points);
      std::vector<Point<2>> points;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fev.reinit(cell);
            for (const auto &X : fev.get_quadrature_points())
              {
                points.push_back(X);
                const double h = p.thickness_at(X);
                if (!(h > 0) || !std::isfinite(h))
                  throw io::InputError("Plate", "Thickness profile", p.thickness_profile_text,
                                       "the thickness must be positive and finite at the "
                                       "quadrature points of the plate (it is " +
                                         std::to_string(h) + " at x = " + std::to_string(X[0]) +
                                         ", y = " + std::to_string(X[1]) + ")");
              }
          }
      p.plate_growth.check_natural_curvature(points);

      // The plate's and the rim's growth: one check, at every vertex and
      // quadrature point of the mesh (materials/growth_admissibility.h).
      const MPI_Comm comm = p.distributed_mesh ? MPI_COMM_WORLD : MPI_COMM_SELF;
      p.plate_growth.check_admissible(
        materials::growth_points(*mapping, triangulation.get(), quadrature,
                                 [](const auto &) { return true; }),
        comm);
      materials::check_growth_admissible(
        materials::boundary_growth_points(*mapping, triangulation.get(), QGauss<1>(p.degree + 1),
                                          [](const auto &face) {
                                            return face->boundary_id() == rim_id;
                                          }),
        [&p](const Point<2> &, const double t) { return std::vector<double>{p.rod_growth_at(t)}; },
        {"Rim rod", "Growth factor", io::format_number(p.rim_growth->final_factor()),
         "the rim's growth factor"},
        comm);
    }
  } // namespace plate_rod
} // namespace cosmo

// CrossSectionProblem's set-up: mesh, DoFs, gauge rows, surface faces, growth at the points.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/io/resources.h>
#include <cosmo/materials/growth_admissibility.h>

#include "cross_section_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      constexpr unsigned int n_strains = assembly::ReducedRodProblem::n_strains;
      constexpr unsigned int n_gauge   = assembly::ReducedRodProblem::n_gauge;

      /// The material ids of the mesh's cells, in the order first met.
      std::vector<types::material_id>
      material_ids(const Triangulation<2> &triangulation)
      {
        std::vector<types::material_id> ids;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (std::find(ids.begin(), ids.end(), cell->material_id()) == ids.end())
            ids.push_back(cell->material_id());
        return ids;
      }

      /// The six gauge constraints C U = 0, as integrals of the shape functions
      /// (not sums of nodal values, which would weight nodes by the mesh), over
      /// this rank's cells.
      std::array<Vector<double>, 6>
      gauge_constraint_rows(const Mapping<2> &       mapping,
                            const FiniteElement<2> & fe,
                            const DoFHandler<2> &    dof_handler,
                            const unsigned int       degree)
      {
        std::array<Vector<double>, 6> rows;
        for (auto &c : rows)
          c.reinit(dof_handler.n_dofs());
        const QGauss<2> quadrature(degree + 1);
        FEValues<2>     fev(mapping, fe, quadrature,
                            update_values | update_quadrature_points | update_JxW_values);
        std::vector<types::global_dof_index> idx(fe.n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              fev.reinit(cell);
              cell->get_dof_indices(idx);
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const Point<2> X  = fev.quadrature_point(q);
                  const double   dA = fev.JxW(q);
                  for (unsigned int i = 0; i < idx.size(); ++i)
                    {
                      const unsigned int c = fe.system_to_component_index(i).first;
                      const double       N = fev.shape_value(i, q) * dA;
                      rows[c][idx[i]] += N; // int u = 0
                      if (c == 1)
                        rows[3][idx[i]] += X[0] * N; // int X1 u2 - X2 u1 = 0
                      if (c == 0)
                        rows[3][idx[i]] -= X[1] * N;
                      if (c == 2)
                        {
                          rows[4][idx[i]] += X[0] * N; // int X1 u3 = 0
                          rows[5][idx[i]] += X[1] * N; // int X2 u3 = 0
                        }
                    }
                }
            }
        return rows;
      }

      /// The field's couplings on a distributed mesh: every pair of DoFs of one
      /// of this rank's cells.
      void
      add_owned_cell_couplings(const DoFHandler<2> &dof_handler, TrilinosWrappers::SparsityPattern &sp)
      {
        std::vector<types::global_dof_index> idx(dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(idx);
              for (const auto i : idx)
                sp.add_entries(i, idx.begin(), idx.end());
            }
      }

      /// The field's couplings on a whole mesh: every pair of DoFs of a cell.
      /// (Filled in place: a DynamicSparsityPattern copies only when empty.)
      void
      add_cell_couplings(const DoFHandler<2> &dof_handler, DynamicSparsityPattern &dsp)
      {
        std::vector<types::global_dof_index> idx(dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(idx);
            for (const auto i : idx)
              dsp.add_entries(i, idx.begin(), idx.end());
          }
      }
    } // namespace

    void
    CrossSectionProblem::setup_system()
    {
      this->triangulation.set_distributed(distributed_mesh);
      Triangulation<2> &triangulation = this->triangulation.get();
      {
        // 3 displacement fields of degree p: about 3 p^2 unknowns per cell.
        const boost::signals2::scoped_connection guard(io::guard_refinement(
          triangulation, 3. * degree * degree, degree, "Cross-section", "Global refinements",
          std::to_string(geometry.refinements)));
        geometry.create_triangulation(triangulation);
      }
      materials.resolve_regions(geometry.region_ids());
      materials.check_regions(material_ids(triangulation));
      fe      = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 3);
      mapping = std::make_unique<MappingQ<2>>(degree);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(*fe);
      section_properties = geometry::CrossSectionGeometry::properties(triangulation, degree);
      setup_surface_faces();

      // The six gauge constraints C U = 0.
      std::array<Vector<double>, 6> rows = gauge_constraint_rows(*mapping, *fe, dof_handler, degree);

      if (distributed_mesh)
        {
          // Each rank integrated its own cells: the rows summed by their owners.
          const solvers::ReplicatedVectorLayout owners(MPI_COMM_WORLD, dof_handler.locally_owned_dofs());
          for (auto &c : rows)
            owners.sum_parts(c);
          IndexSet relevant;
          DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
          setup_distributed_bordered_system(
            dof_handler.locally_owned_dofs(), relevant,
            [this](TrilinosWrappers::SparsityPattern &sp) {
              add_owned_cell_couplings(dof_handler, sp);
            },
            rows, MPI_COMM_WORLD);
        }
      else
        {
          DynamicSparsityPattern dsp(n_u());
          add_cell_couplings(dof_handler, dsp);
          setup_bordered_system(dsp, rows, linear_solver_name);
        }
      report = [this](const std::string &line) { say(line); };

      // Bad input, refused now rather than met as a nonlinear failure on the
      // path, or missed (materials/growth_admissibility.h).
      check_growth();

      solution.reinit(n_unknowns());
      const auto ref = kinematics::RodStrains::reference().as_array();
      for (unsigned int k = 0; k < n_strains; ++k)
        solution[n_u() + n_gauge + k] = ref[k];
      growth_cached_for = std::numeric_limits<double>::quiet_NaN();
    }

    void
    CrossSectionProblem::check_growth() const
    {
      const MPI_Comm  comm = distributed_mesh ? MPI_COMM_WORLD : MPI_COMM_SELF;
      const QGauss<2> quadrature(degree + 1);
      std::vector<types::material_id> ids = material_ids(triangulation.get());
      // (every rank checks every material: the check is collective)
      if (distributed_mesh)
        ids = Utilities::MPI::compute_set_union(ids, comm);
      for (const auto id : ids)
        {
          const auto &material = materials.material(id);
          materials::check_growth_admissible(
            materials::growth_points(*mapping, triangulation.get(), quadrature,
                                     [id](const auto &cell) { return cell->material_id() == id; }),
            [&material](const Point<2> &X, const double t) {
              return std::vector<double>{determinant(material.growth.value(X, t))};
            },
            {material.section, "Growth factor", material.growth.factor_expression()},
            comm);
        }
      const QGauss<1> face_quadrature(degree + 1);
      for (const auto &layer : surface_layers.layers())
        {
          geometry::BoundarySelection selection;
          selection.parse(layer.boundary_parts, layer.section, "Boundary parts", geometry);
          materials::check_growth_admissible(
            materials::boundary_growth_points(*mapping, triangulation.get(), face_quadrature,
                                              [&selection](const auto &face) {
                                                return selection.contains(face);
                                              }),
            [&layer](const Point<2> &X, const double t) {
              const auto g = layer.growth(X, t);
              return std::vector<double>{g[0], g[1]};
            },
            {layer.section, "Growth factor", layer.growth_text, "each surface factor (gT, g3)"},
            comm);
        }
    }

    bool
    CrossSectionProblem::update_growth_cache()
    {
      if (growth_cached_for == load_parameter)
        return true;
      // Outside [0, 1] (a trial load of Newton on an augmented system) the
      // ramp may leave det Fg > 0: an inadmissible state there (on [0, 1]
      // check_growth() has refused it at setup).
      const auto refuse = [&]() {
        growth_cached_for = std::numeric_limits<double>::quiet_NaN();
        return false;
      };
      const QGauss<2> quadrature(degree + 1);
      FEValues<2>     fev(*mapping, *fe, quadrature, update_quadrature_points);
      growth_at_qp.resize(triangulation.get().n_active_cells() * quadrature.size());
      // (on a distributed mesh: this rank's cells; assemble() decides together)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fev.reinit(cell);
          const auto &material = materials.material(cell->material_id());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, 3> Fg =
                material.growth.value(fev.quadrature_point(q), load_parameter);
              const double J = determinant(Fg);
              if (!(J > 0) || !std::isfinite(J))
                return refuse();
              growth_at_qp[cell->active_cell_index() * quadrature.size() + q] = Fg;
            }
        }

      const QGauss<1> face_quadrature(degree + 1);
      FEFaceValues<2> ffv(*mapping, *fe, face_quadrature, update_quadrature_points);
      const unsigned int nqf = face_quadrature.size();
      surface_growth_at_qp.resize(surface_faces.size() * nqf);
      for (unsigned int f = 0; f < surface_faces.size(); ++f)
        {
          const auto &sf    = surface_faces[f];
          const auto &layer = surface_layers.layers()[sf.layer];
          ffv.reinit(sf.cell, sf.face);
          for (unsigned int q = 0; q < nqf; ++q)
            {
              const Point<2> &X = ffv.quadrature_point(q);
              const auto      g = layer.growth(X, load_parameter);
              if (!(g[0] > 0 && g[1] > 0) || !std::isfinite(g[0]) || !std::isfinite(g[1]))
                return refuse();
              surface_growth_at_qp[f * nqf + q] = g;
            }
        }
      growth_cached_for = load_parameter;
      return true;
    }

    void
    CrossSectionProblem::setup_surface_faces()
    {
      surface_faces.clear();
      surface_length.assign(surface_layers.layers().size(), 0.);
      const QGauss<1> face_quadrature(degree + 1);
      FEFaceValues<2> ffv(*mapping, *fe, face_quadrature, update_JxW_values);
      for (unsigned int l = 0; l < surface_layers.layers().size(); ++l)
        {
          const auto &layer = surface_layers.layers()[l];
          geometry::BoundarySelection selection;
          selection.parse(layer.boundary_parts, layer.section, "Boundary parts", geometry);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() && selection.contains(cell->face(f)))
                {
                  surface_faces.push_back({cell, f, l});
                  ffv.reinit(cell, f);
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    surface_length[l] += ffv.JxW(q);
                }
        }
      // (a distributed mesh: each rank's faces, their lengths summed)
      if (distributed_mesh)
        solvers::sum_on_all_ranks(surface_length, MPI_COMM_WORLD);
      for (unsigned int l = 0; l < surface_layers.layers().size(); ++l)
        {
          const auto &layer = surface_layers.layers()[l];
          if (surface_length[l] == 0)
            throw io::InputError(layer.section, "Boundary parts", layer.boundary_parts,
                                 "selects no boundary face of this section");
        }
    }
  } // namespace rod
} // namespace cosmo

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/vector_tools_interpolate.h>

#include <cosmo/solvers/run_start.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/io/checkpoint.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/config.h>
#include <cosmo/io/resources.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/point_loop.h>
#include <cosmo/io/ranks.h>
#include <cosmo/kinematics/section.h>

#include <cosmo/materials/growth_admissibility.h>

#include "cross_section_problem.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      constexpr unsigned int n_strains = assembly::ReducedRodProblem::n_strains;
      constexpr unsigned int n_gauge   = assembly::ReducedRodProblem::n_gauge;
    } // namespace

    CrossSectionProblem::CrossSectionProblem() = default;
    CrossSectionProblem::~CrossSectionProblem()
    {
      dof_handler.clear();
    }

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
      {
        std::vector<types::material_id> ids;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (std::find(ids.begin(), ids.end(), cell->material_id()) == ids.end())
            ids.push_back(cell->material_id());
        materials.check_regions(ids);
      }
      fe      = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 3);
      mapping = std::make_unique<MappingQ<2>>(degree);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(*fe);
      section_properties = geometry::CrossSectionGeometry::properties(triangulation, degree);
      setup_surface_faces();

      // The six gauge constraints C U = 0, as integrals of the shape functions
      // (not sums of nodal values, which would weight nodes by the mesh).
      std::array<Vector<double>, 6> rows;
      for (auto &c : rows)
        c.reinit(n_u());
      {
        const QGauss<2> quadrature(degree + 1);
        FEValues<2>     fev(*mapping, *fe, quadrature,
                            update_values | update_quadrature_points | update_JxW_values);
        std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
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
                    const unsigned int c = fe->system_to_component_index(i).first;
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
      }

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
              std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
              for (const auto &cell : dof_handler.active_cell_iterators())
                if (cell->is_locally_owned())
                  {
                    cell->get_dof_indices(idx);
                    for (const auto i : idx)
                      sp.add_entries(i, idx.begin(), idx.end());
                  }
            },
            rows, MPI_COMM_WORLD);
        }
      else
        {
          DynamicSparsityPattern dsp(n_u());
          std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
          for (const auto &cell : dof_handler.active_cell_iterators())
            {
              cell->get_dof_indices(idx);
              for (const auto i : idx)
                dsp.add_entries(i, idx.begin(), idx.end());
            }
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
      std::vector<types::material_id> ids;
      for (const auto &cell : triangulation.get().active_cell_iterators())
        if (std::find(ids.begin(), ids.end(), cell->material_id()) == ids.end())
          ids.push_back(cell->material_id());
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

    namespace
    {
      // Sparse rows of dFbar/dU_i and dFbar/de_k: at most 5 of the 9 entries.
      struct SparseRow
      {
        unsigned int n = 0;
        unsigned int a[5];
        double       v[5];
        void
        add(unsigned int aa, double vv)
        {
          if (vv != 0.)
            {
              a[n] = aa;
              v[n] = vv;
              ++n;
            }
        }
        double
        dot(const std::array<double, 9> &x) const
        {
          double r = 0;
          for (unsigned int z = 0; z < n; ++z)
            r += x[a[z]] * v[z];
          return r;
        }
      };

      // out = C s for the 9x9 material tangent C.
      void
      apply_tangent(const std::array<double, 81> &C, const SparseRow &s, std::array<double, 9> &out)
      {
        for (unsigned int a = 0; a < 9; ++a)
          {
            double v = 0;
            for (unsigned int z = 0; z < s.n; ++z)
              v += C[9 * a + s.a[z]] * s.v[z];
            out[a] = v;
          }
      }

      /// Per-thread work space of the assembly (WorkStream scratch).
      struct AssemblyScratch
      {
        AssemblyScratch(const Mapping<2> &mapping, const FiniteElement<2> &fe, const Quadrature<2> &q)
          : fev(mapping, fe, q,
                update_values | update_gradients | update_quadrature_points | update_JxW_values)
          , U_local(fe.n_dofs_per_cell())
          , B(fe.n_dofs_per_cell())
          , CB(fe.n_dofs_per_cell())
        {}
        AssemblyScratch(const AssemblyScratch &o)
          : AssemblyScratch(o.fev.get_mapping(), o.fev.get_fe(), o.fev.get_quadrature())
        {}
        FEValues<2>                                  fev;
        std::vector<double>                          U_local;
        std::vector<SparseRow>                       B;
        std::vector<std::array<double, 9>>           CB;
        std::array<SparseRow, n_strains>             D;
        std::array<std::array<double, 9>, n_strains> CD;
        materials::EnergyDerivatives                 d;
      };

      /// The component of each DoF of a cell.
      std::vector<unsigned int>
      dof_components(const FiniteElement<2> &fe)
      {
        std::vector<unsigned int> comp(fe.n_dofs_per_cell());
        for (unsigned int i = 0; i < comp.size(); ++i)
          comp[i] = fe.system_to_component_index(i).first;
        return comp;
      }

      /// The strains and what the derivatives of Fbar need of them: [kappa]x and e_m x e_c.
      struct HelicalStrainTerms
      {
        explicit HelicalStrainTerms(const std::array<double, 6> &e)
          : nu({e[0], e[1], e[2]})
          , kappa({e[3], e[4], e[5]})
          , Kx(kinematics::skew(kappa))
        {
          for (unsigned int m = 0; m < 3; ++m)
            for (unsigned int c = 0; c < 3; ++c)
              e_x_e[m][c] = kinematics::axial_column_mixed_derivative(m, c);
        }
        Tensor<1, 3> nu, kappa;
        Tensor<2, 3> Kx;
        Tensor<1, 3> e_x_e[3][3];
      };
    } // namespace

    int
    CrossSectionProblem::assemble_field(const Vector<double> &       U,
                                        const std::array<double, 6> &e,
                                        Vector<double> *             R,
                                        const bool                   jacobian,
                                        FullMatrix<double> &         E,
                                        FieldIntegrals &             results)
    {
      if (!update_growth_cache())
        return 1; // growth inadmissible at this trial load
      if (!assemble_bulk(U, e, R, jacobian, E, results))
        return 1; // recoverable: Newton's line search or the driver cuts back
      if (!surface_faces.empty())
        assemble_surface_layers(U, e, R, jacobian, E, results);
      return 0;
    }

    bool
    CrossSectionProblem::assemble_bulk(const Vector<double> &       U,
                                       const std::array<double, 6> &e,
                                       Vector<double> *             R,
                                       const bool                   jacobian,
                                       FullMatrix<double> &         E,
                                       FieldIntegrals &             results)
    {
      const HelicalStrainTerms h(e);

      const QGauss<2>    quadrature(degree + 1);
      const unsigned int nq  = quadrature.size();
      const unsigned int              dpc  = fe->n_dofs_per_cell();
      const std::vector<unsigned int> comp = dof_components(*fe);

      // Cells are independent: the worker runs on all cores, the copier adds
      // the contributions in cell order (so sums are reproducible).
      auto worker = [&](const typename DoFHandler<2>::active_cell_iterator &cell,
                        AssemblyScratch &                                  scratch,
                        assembly::CellContribution &                       out) {
        auto &fev = scratch.fev;
        fev.reinit(cell);
        for (unsigned int i = 0; i < dpc; ++i)
          scratch.U_local[i] = U[out.dof_indices[i]];
        const auto &material = materials.material(cell->material_id());
        auto &B = scratch.B;
        auto &D = scratch.D;
        auto &d = scratch.d;
        for (unsigned int q = 0; q < nq; ++q)
          {
            const double   dA = fev.JxW(q);
            const Point<2> X  = fev.quadrature_point(q);
            Tensor<1, 3>   u;
            Tensor<2, 3>   grad_u; // columns 0, 1: du/dX1, du/dX2
            for (unsigned int i = 0; i < dpc; ++i)
              {
                const double N = fev.shape_value(i, q);
                const auto   g = fev.shape_grad(i, q);
                u[comp[i]] += scratch.U_local[i] * N;
                grad_u[comp[i]][0] += scratch.U_local[i] * g[0];
                grad_u[comp[i]][1] += scratch.U_local[i] * g[1];
              }
            const Tensor<1, 3> w = kinematics::section_placement(X, u);
            const Tensor<2, 3> F = kinematics::section_deformation_gradient(grad_u, w, h.nu, h.kappa);

            const Tensor<2, 3> &Fg = growth_at_qp[cell->active_cell_index() * nq + q];
            material.evaluate(F, Fg, jacobian, d);
            if (!d.admissible)
              {
                out.admissible = false;
                return;
              }
            out.scalars[0] += d.energy * dA;
            out.minimum = std::min(out.minimum, determinant(F) / determinant(Fg));
            const auto &P = d.P;

            for (unsigned int i = 0; i < dpc; ++i)
              {
                const double       N = fev.shape_value(i, q);
                const auto         g = fev.shape_grad(i, q);
                const unsigned int c = comp[i];
                B[i].n               = 0;
                B[i].add(3 * c, g[0]);
                B[i].add(3 * c + 1, g[1]);
                for (unsigned int r = 0; r < 3; ++r)
                  B[i].add(3 * r + 2, h.Kx[r][c] * N);
                out.residual[i] += B[i].dot(P) * dA;
              }
            // dFbar/d(strain k): only the third column depends on the strains.
            for (unsigned int k = 0; k < n_strains; ++k)
              {
                D[k].n                = 0;
                const Tensor<1, 3> db = kinematics::axial_column_strain_derivative(k, w);
                for (unsigned int r = 0; r < 3; ++r)
                  if (k >= 3 || r == k)
                    D[k].add(3 * r + 2, db[r]);
                out.scalars[1 + k] += D[k].dot(P) * dA;
              }

            if (!jacobian)
              continue;
            for (unsigned int i = 0; i < dpc; ++i)
              apply_tangent(d.C, B[i], scratch.CB[i]);
            for (unsigned int k = 0; k < n_strains; ++k)
              apply_tangent(d.C, D[k], scratch.CD[k]);

            for (unsigned int i = 0; i < dpc; ++i)
              {
                const auto &CBi = scratch.CB[i];
                for (unsigned int j = 0; j <= i; ++j)
                  out.hessian(i, j) += B[j].dot(CBi) * dA;
                const double       N = fev.shape_value(i, q);
                const unsigned int c = comp[i];
                for (unsigned int k = 0; k < n_strains; ++k)
                  {
                    double bik = D[k].dot(CBi);
                    if (k >= 3) // P : d2 Fbar / dU_i dkappa_k, column 3 = e_k x e_c N
                      {
                        const Tensor<1, 3> &ex = h.e_x_e[k - 3][c];
                        for (unsigned int r = 0; r < 3; ++r)
                          bik += P[3 * r + 2] * ex[r] * N;
                      }
                    out.border(i, k) += bik * dA;
                  }
              }
            for (unsigned int k = 0; k < n_strains; ++k)
              for (unsigned int l = 0; l < n_strains; ++l)
                out.border_block(k, l) += D[l].dot(scratch.CD[k]) * dA;
          }
        if (jacobian)
          for (unsigned int i = 0; i < dpc; ++i)
            for (unsigned int j = 0; j < i; ++j)
              out.hessian(j, i) = out.hessian(i, j);
      };

      // The cell's scalars: its energy, then the six resultants dE/de.
      const auto totals = assembly::EnergyAssembler<2>::assemble(
        dof_handler, worker, AssemblyScratch(*mapping, *fe, quadrature),
        assembly::CellContribution(dpc, n_strains, 1 + n_strains), field_target(R, jacobian, E));
      if (!totals.admissible)
        return false;
      results.energy        = totals.scalars[0];
      results.min_elastic_J = totals.minimum;
      for (unsigned int k = 0; k < n_strains; ++k)
        results.resultants[k] = totals.scalars[1 + k];
      return true;
    }

    void
    CrossSectionProblem::assemble_surface_layers(const Vector<double> &       U,
                                                 const std::array<double, 6> &e,
                                                 Vector<double> *             R,
                                                 const bool                   jacobian,
                                                 FullMatrix<double> &         E,
                                                 FieldIntegrals &             results)
    {
      // Few faces: serial, in face order.
      const HelicalStrainTerms h(e);

      const unsigned int              dpc  = fe->n_dofs_per_cell();
      const std::vector<unsigned int> comp = dof_components(*fe);

      const QGauss<1>    face_quadrature(degree + 1);
      const unsigned int nqf = face_quadrature.size();
      FEFaceValues<2>    ffv(*mapping, *fe, face_quadrature,
                          update_values | update_gradients | update_quadrature_points |
                            update_JxW_values | update_normal_vectors);
      assembly::CellContribution         out(dpc, n_strains);
      std::vector<double>                U_local(dpc);
      std::vector<std::array<double, 6>> dF(dpc), CdF(dpc);
      std::array<std::array<double, 6>, n_strains> D, CD;
      materials::SurfaceEnergyDerivatives          d;
      auto dot6 = [](const std::array<double, 6> &a, const std::array<double, 6> &b) {
        double r = 0;
        for (unsigned int z = 0; z < 6; ++z)
          r += a[z] * b[z];
        return r;
      };
      auto apply6 = [](const std::array<double, 36> &C, const std::array<double, 6> &a,
                       std::array<double, 6> &b) {
        for (unsigned int x = 0; x < 6; ++x)
          {
            double v = 0;
            for (unsigned int z = 0; z < 6; ++z)
              v += C[6 * x + z] * a[z];
            b[x] = v;
          }
      };
      for (unsigned int f = 0; f < surface_faces.size(); ++f)
        {
          const auto &sf    = surface_faces[f];
          const auto &layer = surface_layers.layers()[sf.layer];
          ffv.reinit(sf.cell, sf.face);
          out.reset(jacobian);
          sf.cell->get_dof_indices(out.dof_indices);
          for (unsigned int i = 0; i < dpc; ++i)
            U_local[i] = U[out.dof_indices[i]];
          for (unsigned int q = 0; q < nqf; ++q)
            {
              const double        dS = ffv.JxW(q);
              const Point<2>      X  = ffv.quadrature_point(q);
              const Tensor<1, 2> &Nn = ffv.normal_vector(q);
              // Unit tangent of the boundary curve (counterclockwise on the
              // outer boundary; the energy is even in T).
              const Tensor<1, 2> T = kinematics::boundary_tangent(Nn);
              Tensor<1, 3>       u, du_dS;
              for (unsigned int i = 0; i < dpc; ++i)
                {
                  const auto g = ffv.shape_grad(i, q);
                  u[comp[i]] += U_local[i] * ffv.shape_value(i, q);
                  du_dS[comp[i]] += U_local[i] * (g * T);
                }
              const Tensor<1, 3> w  = kinematics::section_placement(X, u);
              const auto Fs = kinematics::surface_deformation_gradient(w, du_dS, T, h.nu, h.kappa);
              layer.evaluate(Fs, surface_growth_at_qp[f * nqf + q], load_parameter,
                             jacobian, d);
              results.energy += d.energy * dS;

              for (unsigned int i = 0; i < dpc; ++i)
                {
                  const unsigned int c = comp[i];
                  const double       N = ffv.shape_value(i, q);
                  dF[i].fill(0.);
                  dF[i][2 * c] = ffv.shape_grad(i, q) * T;
                  for (unsigned int r = 0; r < 3; ++r)
                    dF[i][2 * r + 1] += h.Kx[r][c] * N;
                  out.residual[i] += dot6(dF[i], d.P) * dS;
                }
              for (unsigned int k = 0; k < n_strains; ++k)
                {
                  D[k].fill(0.);
                  const Tensor<1, 3> db = kinematics::axial_column_strain_derivative(k, w);
                  for (unsigned int r = 0; r < 3; ++r)
                    D[k][2 * r + 1] = db[r];
                  results.resultants[k] += dot6(D[k], d.P) * dS;
                }
              if (!jacobian)
                continue;
              for (unsigned int i = 0; i < dpc; ++i)
                apply6(d.C, dF[i], CdF[i]);
              for (unsigned int k = 0; k < n_strains; ++k)
                apply6(d.C, D[k], CD[k]);
              for (unsigned int i = 0; i < dpc; ++i)
                {
                  for (unsigned int j = 0; j < dpc; ++j)
                    out.hessian(i, j) += dot6(dF[j], CdF[i]) * dS;
                  const double       N = ffv.shape_value(i, q);
                  const unsigned int c = comp[i];
                  for (unsigned int k = 0; k < n_strains; ++k)
                    {
                      double bik = dot6(D[k], CdF[i]);
                      if (k >= 3) // Ps : d2 Fs / dU_i dkappa_k (second column)
                        {
                          const Tensor<1, 3> &ex = h.e_x_e[k - 3][c];
                          for (unsigned int r = 0; r < 3; ++r)
                            bik += d.P[2 * r + 1] * ex[r] * N;
                        }
                      out.border(i, k) += bik * dS;
                    }
                }
              for (unsigned int k = 0; k < n_strains; ++k)
                for (unsigned int l = 0; l < n_strains; ++l)
                  E(k, l) += dot6(D[l], CD[k]) * dS;
            }
          // (the 6x6 block of the surface went into E point by point)
          auto target         = field_target(R, jacobian, E);
          target.border_block = nullptr;
          assembly::add_cell_contribution(out, target);
        }
    }

    void
    CrossSectionProblem::residual_scales(double &force, double &length) const
    {
      length = section_properties.diameter;
      force  = materials.max_young() * length * length;
    }

    double
    CrossSectionProblem::mode_parity(const Vector<double> &mode, const unsigned int axis) const
    {
      // The half-turn about X_axis maps the section point X to its mirror
      // image about that axis (the other coordinate changes sign) and the
      // placement w by diag(+1 on X_axis, -1 on the others): a proper
      // rotation, a symmetry also of a twisted or stretched rod (a
      // reflection would reverse the twist).
      std::vector<double> signs = {-1., -1., -1.};
      signs[axis]               = 1.;
      return geometry::reflection_parity(
        dof_handler,
        geometry::mirror_dofs(*mapping, dof_handler, 1 - axis, section_properties.diameter), mode,
        signs);
    }

    std::vector<double>
    CrossSectionProblem::classify_critical_mode(const Vector<double> &mode) const
    {
      std::vector<double> c;
      for (unsigned int axis = 0; axis < 2; ++axis)
        {
          const double p = mode_parity(mode, axis);
          c.push_back(p > 0.5 ? 1. : p < -0.5 ? -1. : std::isfinite(p) ? 0. : NAN);
        }
      return c;
    }

    CrossSectionState
    CrossSectionProblem::current_state()
    {
      return condensed_state(solution);
    }

    CrossSectionState
    CrossSectionProblem::resolve(const std::array<double, 6> &strains)
    {
      set_target_strains(strains); // (also clears 'Path' waypoints, which would win at t = 1)
      set_load_parameter(1.);
      solvers::newton_solve(*this, solution, newton_settings);
      last_state = current_state();
      return last_state;
    }

    bool
    CrossSectionProblem::first_step_guess(const double t, Vector<double> &U)
    {
      // (not on a distributed mesh: the interpolation between two meshes needs their cells on
      // the same ranks, which p4est's partitions of two refinements do not give)
      if (coarse_start_levels == 0 || geometry.refinements == 0 || parameters_text.empty() ||
          distributed_mesh)
        return false;
      io::PhaseTimer::Scope scope(timer, "coarse-mesh start");
      // A copy of this problem on the section refined once less, from the run's own parameters.
      ParameterHandler prm;
      declare_parameters(prm);
      // (skipping the library's own entries, Postprocess and Additional shared libraries)
      prm.parse_input_from_string(parameters_text, "", /*skip_undefined=*/true);
      CrossSectionProblem coarse;
      coarse.parse_parameters(prm);
      coarse.quiet                = true;
      coarse.parameters_text      = parameters_text;
      coarse.geometry.refinements = geometry.refinements - 1;
      coarse.coarse_start_levels  = coarse_start_levels - 1;
      try
        {
          coarse.setup_system();
        }
      catch (const io::InputError &e)
        {
          // E.g. a shape that needs a refinement more than the coarser mesh has.
          say("  coarse-mesh start: no coarser mesh of this section (" + std::string(e.what()) +
              "); the first step starts from the reference state");
          return false;
        }
      // The interpolation follows the cells' hierarchy: the coarse cells must be the same
      // (interpolate_to_different_mesh asserts it, to the last bit). A section meshed anew per
      // refinement is not nested; nor is one shifted to its centroid, whose discrete centroid
      // moves with the refinement.
      const bool nested = GridTools::have_same_coarse_mesh(coarse.triangulation.get(), triangulation.get());
      if (!nested)
        {
          say("  coarse-mesh start: the section refined once less has other coarse cells (a "
              "shape meshed anew per refinement, or shifted to its centroid); the first step "
              "starts from the reference state");
          return false;
        }
      Vector<double> Uc = coarse.solution;
      coarse.first_step_guess(t, Uc);
      coarse.set_load_parameter(t);
      solvers::NewtonResult r;
      try
        {
          r = solvers::newton_solve(coarse, Uc, newton_settings);
        }
      catch (const solvers::NewtonFailure &e)
        {
          say("  coarse-mesh start: Newton failed on " + std::to_string(coarse.n_unknowns()) +
              " unknowns (" + e.what() + "); starting from the reference state, also after a "
              "cut-back");
          coarse_start_levels = 0; // a cut-back would only repeat the failing coarse solves
          return false;
        }
      Vector<double> field_coarse(coarse.n_u()), field(n_u());
      for (unsigned int i = 0; i < coarse.n_u(); ++i)
        field_coarse[i] = Uc[i];
      VectorTools::interpolate_to_different_mesh(coarse.dof_handler, field_coarse, dof_handler, field);
      for (unsigned int i = 0; i < n_u(); ++i)
        U[i] = field[i];
      for (unsigned int k = 0; k < n_gauge + n_strains; ++k)
        U[n_u() + k] = Uc[coarse.n_u() + k];
      coarse_start_report = coarse.coarse_start_report + (coarse.coarse_start_report.empty() ? "" : ", ") +
                            std::to_string(r.iterations) + " on " +
                            std::to_string(coarse.n_unknowns());
      say("  first step started on coarser meshes (Newton iterations on unknowns: " +
          coarse_start_report + ")");
      return true;
    }

    CrossSectionState
    CrossSectionProblem::solve()
    {
      if (arclength_settings.enabled)
        {
          follow_path(arclength_settings, newton_settings, solution,
                      [this](const std::string &s) { say(s); });
          return last_state;
        }
      solvers::NaturalParameterContinuation driver(continuation_settings, newton_settings);
      driver.progress = [this](const std::string &s) { say(s); };
      connect_checkpoints(driver);
      driver.run(*this, solution);
      return last_state;
    }


    analysis::LinearSectionProperties
    CrossSectionProblem::linear_section_properties() const
    {
      // The small-strain moduli of each region's law, from its tangent at F = I
      // (isotropic: C_1212 = mu, C_1122 = lambda), so that any registered law works.
      std::map<types::material_id, analysis::RegionModuli> moduli;
      for (const auto &cell : triangulation.get().active_cell_iterators())
        if (moduli.count(cell->material_id()) == 0)
          {
            materials::EnergyDerivatives d;
            Tensor<2, 3>                 I;
            for (unsigned int i = 0; i < 3; ++i)
              I[i][i] = 1;
            materials.material(cell->material_id()).evaluate(I, I, true, d);
            const double mu = d.C[9 * 1 + 1], lambda = d.C[9 * 0 + 4];
            moduli[cell->material_id()] = {mu * (3 * lambda + 2 * mu) / (lambda + mu), mu,
                                           materials.material(cell->material_id()).density};
          }
      return analysis::linear_section_properties(triangulation.get(), *mapping, degree,
                                                 [&moduli](const types::material_id id) {
                                                   return moduli.at(id);
                                                 });
    }


    void
    CrossSectionProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      write_output   = true;
      solvers::start_run(record, *this, options, prm, output_directory, distributed_mesh);
      pvd = std::make_unique<io::PVDSeries>(output_directory + "/solution.pvd");
      pvd_rod = std::make_unique<io::PVDSeries>(output_directory + "/rod.pvd");
      if (!surface_faces.empty() || !surface_layers.layers().empty())
        pvd_surface = std::make_unique<io::PVDSeries>(output_directory + "/surface.pvd");
      {
        io::PhaseTimer::Scope scope(timer, "setup");
        setup_system();
      }
      std::ostringstream info;
      info << "  section: " << geometry.shape << ", " << triangulation.get().n_global_active_cells()
           << " cells, Q" << degree << ", " << n_u() << " field DoFs + 6 multipliers + 6 strains; area "
           << section_properties.area << "; estimated peak memory "
           << io::format_bytes(io::estimated_memory(n_unknowns(), degree));
      if (distributed_mesh)
        info << "; the mesh distributed over " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
             << (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ? " rank" : " ranks");
      say(info.str());
      if (!geometry.meshing_summary.empty())
        say("  " + geometry.meshing_summary);
      if (geometry.applied_shift.norm() > 0)
        say("  mesh shifted by (" + io::format_significant(geometry.applied_shift[0]) + ", " +
            io::format_significant(geometry.applied_shift[1]) + ") to put its centroid at the origin");
      for (const auto &m : materials.descriptions())
        say("  " + m);
      if (distributed_mesh)
        say("  linear section properties (reference): not computed on a distributed mesh "
            "(their warping problem is solved on one process: run the section with "
            "Distributed = false, on a coarser mesh if need be)");
      else
        {
          {
            io::PhaseTimer::Scope scope(timer, "section properties");
            reference_properties = linear_section_properties();
          }
          say_reference_properties();
        }
      for (unsigned int l = 0; l < surface_layers.layers().size(); ++l)
        say("  " + surface_layers.layers()[l].description() + " (arc length " +
            io::format_significant(surface_length[l]) + ")");

      steps_table = io::CSVTable();
      for (const auto &c : {"step", "branch", "t", "newton_iterations", "residual", "cutbacks"})
        steps_table.add_column(c);
      steps_table.add_column("energy", "E L^2");
      for (const auto &s : kinematics::strain_names)
        steps_table.add_column(s, s[0] == 'n' ? "1" : "1/L");
      for (unsigned int k = 0; k < 6; ++k)
        steps_table.add_column(kinematics::resultant_names[k], k < 3 ? "E L^2" : "E L^3");
      for (unsigned int k = 1; k <= 6; ++k)
        steps_table.add_column("multiplier" + std::to_string(k));
      for (const auto &s : kinematics::strain_names)
        steps_table.add_column("K_" + s + "_" + s);
      steps_table.add_column("n_negative_eigenvalues");
      steps_table.add_column("min_elastic_J");

      if (table.enabled())
        {
          // The path to t = 1 (the base state, redone on --resume: it is
          // short), then the table, whose checkpoints hold its points.
          record.attempt([&]() {
            solve();
            run_table(prm);
          });
          write_summary();
          return;
        }
      // Checkpoints after every converged step; --resume goes on from the last.
      write_checkpoint = [this](const io::CheckpointWriter &w) { record.write_checkpoint(w); };
      if (record.has_checkpoint())
        resume_from = &record.checkpoint();
      record.attempt([&]() { solve(); });
      if (!record.failed())
        say_result();
      write_summary();
    }

    void
    CrossSectionProblem::run_table(const ParameterHandler &prm)
    {
      io::PhaseTimer::Scope scope(timer, "constitutive table");
      say("constitutive table around the state at t = 1:");
      const bool keep_output = write_output;
      write_output           = false; // no per-point files
      set_load_parameter(1.);
      assembly::TableDescription d;
      d.application     = "rod_cross_section";
      d.version         = COSMO_VERSION;
      d.parameters      = io::checkpoint_parameters(prm);
      d.free_strains    = strain_is_free;
      d.held_resultants = resultants_at(1.);
      table.run_in(record, solution, target_strains, strains_of(solution),
                   [this](const std::array<double, 6> &e) { return resolve(e); }, output_directory, d);
      write_output = keep_output;
    }

    namespace
    {
      /// sweep.csv's columns.
      io::CSVTable
      sweep_columns(const io::ParameterSweep &sweep)
      {
        io::CSVTable table;
        table.add_column("point");
        table.add_column("value", sweep.axis_label());
        table.add_column("converged");
        table.add_column("energy", "E L^2");
        for (const auto &s : kinematics::strain_names)
          table.add_column(s, s[0] == 'n' ? "1" : "1/L");
        for (unsigned int k = 0; k < 6; ++k)
          table.add_column(kinematics::resultant_names[k], k < 3 ? "E L^2" : "E L^3");
        for (unsigned int a = 0; a < 6; ++a)
          for (unsigned int b = a; b < 6; ++b)
            table.add_column("K_" + kinematics::strain_names[a] + "_" + kinematics::strain_names[b]);
        table.add_column("helix_radius", "L");
        table.add_column("helix_pitch", "L");
        table.add_column("n_negative_eigenvalues");
        return table;
      }

      /// Point k of a sweep (its parameters prepared in `prm`, its files in `directory`): its
      /// row and line.
      io::PointLoop::Point
      sweep_point(ParameterHandler &        prm,
                  const io::RunOptions &    options,
                  const io::ParameterSweep &sweep,
                  const unsigned int        k,
                  const std::string &       directory)
      {
        const io::RunOptions point_options = io::PointLoop::point_options(options, prm);
        io::PointLoop::Point p;
        p.row = {double(k), sweep.value(k)};
        std::ostringstream line;
        line << "point " << k + 1 << "/" << sweep.size() << ": " << sweep.label() << " = "
             << sweep.text(k);
        try
          {
            CrossSectionProblem problem;
            problem.parse_parameters(prm);
            problem.run(point_options, prm);
            io::PointLoop::finish_point(point_options, directory);
            const auto &s = problem.final_state();
            const auto  h = kinematics::helix_geometry(kinematics::RodStrains(s.strains));
            p.row.push_back(1);
            p.row.push_back(s.energy);
            p.row.insert(p.row.end(), s.strains.begin(), s.strains.end());
            p.row.insert(p.row.end(), s.resultants.begin(), s.resultants.end());
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int b = a; b < 6; ++b)
                p.row.push_back(s.stiffness(a, b));
            p.row.push_back(h.radius);
            p.row.push_back(h.pitch);
            p.row.push_back(s.n_negative);
            line << "  strains (";
            for (unsigned int i = 0; i < 6; ++i)
              line << (i ? ", " : "") << io::format_significant(s.strains[i], 6);
            line << ")  " << h.description();
          }
        catch (io::RunFailure &e)
          {
            p.outcome = io::PointLoop::Point::Outcome::failed;
            p.row.push_back(0);
            line << "  FAILED: " << e.what();
          }
        catch (io::InputError &e)
          {
            // A value can pass the entry's pattern and still be rejected
            // by the problem (det Fg <= 0 somewhere, ...): that point is
            // bad input, the others still run.
            p.outcome = io::PointLoop::Point::Outcome::rejected;
            p.row.push_back(0);
            line << "  REJECTED: " << e.what();
          }
        p.line = line.str();
        return p;
      }
    } // namespace

    void
    run_study(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      sweep.refuse_distributed_mesh(prm, "Finite element");
      if (!sweep.enabled())
        {
          CrossSectionProblem problem;
          problem.parse_parameters(prm);
          if (problem.mesh_is_distributed() && assembly::ConstitutiveTable::enabled_in(prm))
            throw io::InputError("Finite element", "Distributed", "true",
                                 "a constitutive table spreads its points over the MPI ranks, "
                                 "each on one rank's whole mesh: set Distributed = false");
          // A distributed mesh: every rank runs the path on its part of the mesh.
          if (io::ranks::idle(assembly::ConstitutiveTable::enabled_in(prm) ||
                              problem.mesh_is_distributed()))
            return;
          if (problem.mesh_is_distributed() && io::ranks::size() > 1)
            io::collective_interrupts(MPI_COMM_WORLD);
          problem.run(options, prm);
          return;
        }
      // A study of the first critical point of each value's path (arclength
      // continuation stopping at its first event), or a critical curve.
      prm.enter_subsection("Arclength continuation");
      const bool first_event = prm.get_bool("Stop at first event");
      prm.leave_subsection();
      if (first_event || sweep.critical_curve())
        {
          solvers::CriticalPointStudy study;
          study.application     = "rod_cross_section";
          study.mode_columns    = {"mode_symmetry_X1", "mode_symmetry_X2"};
          study.describe_mode   = [](const std::vector<double> &c) {
            auto word = [](const double p) {
              return p > 0 ? std::string("symmetric") :
                     p < 0 ? std::string("antisymmetric") :
                     p == 0 ? std::string("mixed") : std::string("unclassified (mesh not symmetric)");
            };
            return word(c[0]) + " under the half-turn about X1, " + word(c[1]) +
                   " under the half-turn about X2";
          };
          study.further_columns = assembly::ReducedRodProblem::critical_point_column_names();
          study.make_run        = [](ParameterHandler &p) {
            return std::make_unique<solvers::CriticalPointRunOf<CrossSectionProblem>>(p);
          };
          return solvers::run_critical_point_study(prm, options, sweep, study);
        }

      io::PointLoop::Description d;
      d.application     = "rod_cross_section";
      d.checkpoint_kind = "rod_cross_section sweep";
      // A checkpoint of other parameters is refused before anything is touched.
      d.parameters = io::checkpoint_parameters(prm);
      prm.enter_subsection("Output");
      d.directory = prm.get("Output directory");
      prm.leave_subsection();
      d.entry = sweep.entry();
      for (unsigned int k = 0; k < sweep.size(); ++k)
        d.values.push_back(sweep.text(k));
      io::PointLoop loop(d, sweep_columns(sweep), !options.resume_directory.empty());
      const auto log = io::open_run_directory(d.directory, prm, options.quiet, d.log_file,
                                              !options.resume_directory.empty());
      (*log)("rod_cross_section " + std::string(COSMO_VERSION) + ": " + options.parameter_file +
             ", sweep of '" + sweep.entry() + "' over " + std::to_string(sweep.size()) + " values");
      loop.run(*log, [&](const unsigned int k) {
        const std::string directory = io::ParameterSweep::point_directory(loop.shared_directory(), k);
        sweep.prepare_point(prm, k, directory);
        return sweep_point(prm, options, sweep, k, directory);
      });
    }
  } // namespace rod
} // namespace cosmo

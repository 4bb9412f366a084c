#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/config.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/kinematics/section.h>

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

      std::string
      fixed(const double v, const int precision = 6)
      {
        std::ostringstream s;
        s << std::setprecision(precision) << v;
        return s.str();
      }
    } // namespace

    CrossSectionProblem::CrossSectionProblem() = default;
    CrossSectionProblem::~CrossSectionProblem()
    {
      dof_handler.clear();
    }

    void
    CrossSectionProblem::declare_parameters(ParameterHandler &prm)
    {
      geometry::CrossSectionGeometry::declare_parameters(prm);
      materials::MaterialLibrary::declare_parameters(prm);
      materials::SurfaceLayerLibrary::declare_parameters(prm);

      prm.enter_subsection("Finite element");
      prm.declare_entry("Polynomial degree", "2", Patterns::Integer(1, 4),
                        "Degree p of the FE_Q(p)^3 displacement of the cross-section "
                        "(and of the isoparametric mapping). p >= 2 for nearly "
                        "incompressible materials.");
      prm.leave_subsection();

      assembly::ReducedRodProblem::declare_strain_parameters(prm);

      solvers::NewtonSettings::declare_parameters(prm);
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Linear solver", solvers::SparseDirectSolver::kind_names() ==
                                             "UMFPACK" ? "UMFPACK" : "MUMPS",
                        Patterns::Selection(solvers::SparseDirectSolver::kind_names()),
                        "Sparse direct solver of the Newton systems: MUMPS (LDL^T, "
                        "gives the stability indicator) or UMFPACK (LU).");
      prm.leave_subsection();
      solvers::ContinuationSettings::declare_parameters(prm);
      solvers::ArclengthSettings::declare_parameters(prm);

      prm.enter_subsection("Output");
      prm.declare_entry("Output directory", "output/rod_cross_section", Patterns::Anything(),
                        "Directory for parameters.prm, summary.json, steps.csv, the VTU "
                        "series and log.txt (created if needed).");
      prm.declare_entry("VTU output", "every step", Patterns::Selection("every step|final|none"),
                        "When to write the deformed section (solution-NNNN.vtu, "
                        "solution.pvd) and the 3D rod piece (rod-NNNN.vtu, rod.pvd).");
      prm.declare_entry("Rod piece length", "0", Patterns::Double(0),
                        "Length (reference arc length) of the 3D piece of rod swept along "
                        "the helix; 0: one helical turn, at most 10 section diameters.");
      prm.declare_entry("Rod piece slices", "24", Patterns::Integer(1, 1000),
                        "Number of slices of the 3D rod piece along its length.");
      prm.declare_entry("Stiffness at every step", "true", Patterns::Bool(),
                        "Compute the 6x6 stiffness (one more factorization) at every "
                        "step, not only at the final one.");
      prm.leave_subsection();

      io::ParameterSweep::declare_parameters(prm);
    }

    void
    CrossSectionProblem::parse_parameters(ParameterHandler &prm)
    {
      geometry.parse_parameters(prm);
      materials.parse_parameters(prm);
      surface_layers.parse_parameters(prm);

      prm.enter_subsection("Finite element");
      degree = prm.get_integer("Polynomial degree");
      prm.leave_subsection();

      parse_strain_parameters(prm);

      newton_settings.parse_parameters(prm);
      prm.enter_subsection("Nonlinear solver");
      linear_solver_name = prm.get("Linear solver");
      prm.leave_subsection();
      continuation_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);

      prm.enter_subsection("Output");
      output_directory     = prm.get("Output directory");
      vtu_frequency        = prm.get("VTU output");
      rod_piece_length     = prm.get_double("Rod piece length");
      rod_piece_slices     = prm.get_integer("Rod piece slices");
      stiffness_every_step = prm.get_bool("Stiffness at every step");
      prm.leave_subsection();
    }

    void
    CrossSectionProblem::setup_system()
    {
      geometry.create_triangulation(triangulation);
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

      DynamicSparsityPattern dsp(n_u());
      {
        std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            cell->get_dof_indices(idx);
            for (const auto i : idx)
              dsp.add_entries(i, idx.begin(), idx.end());
          }
      }
      setup_bordered_system(dsp, rows, linear_solver_name);
      report = [this](const std::string &line) { say(line); };

      // Growth is ramped as 1 + t (g - 1), a convex combination: det Fg > 0
      // along the whole path iff it holds at t = 1. Check it now, as bad
      // input, rather than as a nonlinear failure somewhere on the path.
      const double t_saved = load_parameter;
      load_parameter       = 1.;
      growth_cached_for    = std::numeric_limits<double>::quiet_NaN();
      update_growth_cache(true);
      load_parameter    = t_saved;
      growth_cached_for = std::numeric_limits<double>::quiet_NaN();

      solution.reinit(n_unknowns());
      const auto ref = kinematics::RodStrains::reference().as_array();
      for (unsigned int k = 0; k < n_strains; ++k)
        solution[n_u() + n_gauge + k] = ref[k];
      growth_cached_for = std::numeric_limits<double>::quiet_NaN();
    }

    bool
    CrossSectionProblem::update_growth_cache(const bool throw_if_inadmissible)
    {
      if (growth_cached_for == load_parameter)
        return true;
      // Outside [0, 1] (a trial load of Newton on an augmented system) the
      // ramp may leave det Fg > 0: an inadmissible state there, bad input
      // only if it happens at t = 1 (checked at setup).
      const auto refuse = [&](const std::string &section, const std::string &entry,
                              const std::string &value, const std::string &why) {
        growth_cached_for = std::numeric_limits<double>::quiet_NaN();
        if (throw_if_inadmissible)
          throw io::InputError(section, entry, value, why);
        return false;
      };
      const QGauss<2> quadrature(degree + 1);
      FEValues<2>     fev(*mapping, *fe, quadrature, update_quadrature_points);
      growth_at_qp.resize(triangulation.n_active_cells() * quadrature.size());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          const auto &material = materials.material(cell->material_id());
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Tensor<2, 3> Fg =
                material.growth.value(fev.quadrature_point(q), load_parameter);
              if (!(determinant(Fg) > 0))
                return refuse(
                  material.section, "Growth factor", material.growth.factor_expression(),
                  "det Fg = " + std::to_string(determinant(Fg)) + " <= 0 at (" +
                    std::to_string(fev.quadrature_point(q)[0]) + ", " +
                    std::to_string(fev.quadrature_point(q)[1]) +
                    ") of the section: growth must keep det Fg > 0");
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
              if (!(g[0] > 0 && g[1] > 0))
                return refuse(
                  layer.section, "Growth factor", layer.growth_text,
                  "surface growth (gT, g3) = (" + std::to_string(g[0]) + ", " +
                    std::to_string(g[1]) + ") at boundary point (" + std::to_string(X[0]) +
                    ", " + std::to_string(X[1]) + "): both factors must stay positive");
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
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() && selection.contains(cell->face(f)))
                {
                  surface_faces.push_back({cell, f, l});
                  ffv.reinit(cell, f);
                  for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                    surface_length[l] += ffv.JxW(q);
                }
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

      /// One cell's contributions (WorkStream copy data).
      struct CellContribution
      {
        explicit CellContribution(const unsigned int dpc)
          : idx(dpc)
          , r(dpc)
          , K(dpc, dpc)
          , B(dpc, n_strains)
          , E(n_strains, n_strains)
        {}
        std::vector<types::global_dof_index> idx;
        Vector<double>                       r;
        FullMatrix<double>                   K, B, E;
        std::array<double, 6>                resultants{};
        double                               energy     = 0;
        double                               min_J      = 0;
        bool                                 admissible = true;
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
      const Tensor<1, 3> nu({e[0], e[1], e[2]});
      const Tensor<1, 3> kappa({e[3], e[4], e[5]});
      const Tensor<2, 3> Kx = kinematics::skew(kappa);
      Tensor<1, 3>       e_x_e[3][3];
      for (unsigned int m = 0; m < 3; ++m)
        for (unsigned int c = 0; c < 3; ++c)
          e_x_e[m][c] = kinematics::axial_column_mixed_derivative(m, c);

      const QGauss<2>    quadrature(degree + 1);
      const unsigned int nq  = quadrature.size();
      const unsigned int dpc = fe->n_dofs_per_cell();
      std::vector<unsigned int> comp(dpc);
      for (unsigned int i = 0; i < dpc; ++i)
        comp[i] = fe->system_to_component_index(i).first;

      // Cells are independent: the worker runs on all cores, the copier adds
      // the contributions in cell order (so sums are reproducible).
      auto worker = [&](const typename DoFHandler<2>::active_cell_iterator &cell,
                        AssemblyScratch &                                  scratch,
                        CellContribution &                                 out) {
        auto &fev = scratch.fev;
        fev.reinit(cell);
        cell->get_dof_indices(out.idx);
        for (unsigned int i = 0; i < dpc; ++i)
          scratch.U_local[i] = U[out.idx[i]];
        const auto &material = materials.material(cell->material_id());
        out.r                = 0;
        out.resultants.fill(0.);
        out.energy     = 0;
        out.min_J      = std::numeric_limits<double>::max();
        out.admissible = true;
        if (jacobian)
          {
            out.K = 0;
            out.B = 0;
            out.E = 0;
          }
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
            const Tensor<2, 3> F = kinematics::section_deformation_gradient(grad_u, w, nu, kappa);

            const Tensor<2, 3> &Fg = growth_at_qp[cell->active_cell_index() * nq + q];
            material.evaluate(F, Fg, jacobian, d);
            if (!d.admissible)
              {
                out.admissible = false;
                return;
              }
            out.energy += d.energy * dA;
            out.min_J = std::min(out.min_J, determinant(F) / determinant(Fg));
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
                  B[i].add(3 * r + 2, Kx[r][c] * N);
                out.r[i] += B[i].dot(P) * dA;
              }
            // dFbar/d(strain k): only the third column depends on the strains.
            for (unsigned int k = 0; k < n_strains; ++k)
              {
                D[k].n                = 0;
                const Tensor<1, 3> db = kinematics::axial_column_strain_derivative(k, w);
                for (unsigned int r = 0; r < 3; ++r)
                  if (k >= 3 || r == k)
                    D[k].add(3 * r + 2, db[r]);
                out.resultants[k] += D[k].dot(P) * dA;
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
                  out.K(i, j) += B[j].dot(CBi) * dA;
                const double       N = fev.shape_value(i, q);
                const unsigned int c = comp[i];
                for (unsigned int k = 0; k < n_strains; ++k)
                  {
                    double bik = D[k].dot(CBi);
                    if (k >= 3) // P : d2 Fbar / dU_i dkappa_k, column 3 = e_k x e_c N
                      {
                        const Tensor<1, 3> &ex = e_x_e[k - 3][c];
                        for (unsigned int r = 0; r < 3; ++r)
                          bik += P[3 * r + 2] * ex[r] * N;
                      }
                    out.B(i, k) += bik * dA;
                  }
              }
            for (unsigned int k = 0; k < n_strains; ++k)
              for (unsigned int l = 0; l < n_strains; ++l)
                out.E(k, l) += D[l].dot(scratch.CD[k]) * dA;
          }
        if (jacobian)
          for (unsigned int i = 0; i < dpc; ++i)
            for (unsigned int j = 0; j < i; ++j)
              out.K(j, i) = out.K(i, j);
      };

      std::array<double, 6> resultants{};
      double                energy = 0, minJ = std::numeric_limits<double>::max();
      bool                  admissible = true;
      auto copier = [&](const CellContribution &c) {
        if (!c.admissible)
          admissible = false;
        if (!admissible)
          return;
        energy += c.energy;
        minJ = std::min(minJ, c.min_J);
        for (unsigned int k = 0; k < n_strains; ++k)
          resultants[k] += c.resultants[k];
        add_local_contribution(c.idx, c.r, c.K, c.B, &c.E, R, jacobian, E);
      };
      WorkStream::run(dof_handler.begin_active(), dof_handler.end(), worker, copier,
                      AssemblyScratch(*mapping, *fe, quadrature), CellContribution(dpc));
      if (!admissible)
        return 1; // recoverable: Newton's line search or the driver cuts back

      // Surface layers on boundary faces. Few faces: serial, in face order.
      if (!surface_faces.empty())
        {
          const QGauss<1>    face_quadrature(degree + 1);
          const unsigned int nqf = face_quadrature.size();
          FEFaceValues<2>    ffv(*mapping, *fe, face_quadrature,
                              update_values | update_gradients | update_quadrature_points |
                                update_JxW_values | update_normal_vectors);
          CellContribution                   out(dpc);
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
              sf.cell->get_dof_indices(out.idx);
              for (unsigned int i = 0; i < dpc; ++i)
                U_local[i] = U[out.idx[i]];
              out.r = 0;
              if (jacobian)
                {
                  out.K = 0;
                  out.B = 0;
                  out.E = 0;
                }
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
                  const auto Fs = kinematics::surface_deformation_gradient(w, du_dS, T, nu, kappa);
                  layer.evaluate(Fs, surface_growth_at_qp[f * nqf + q], load_parameter,
                                 jacobian, d);
                  energy += d.energy * dS;

                  for (unsigned int i = 0; i < dpc; ++i)
                    {
                      const unsigned int c = comp[i];
                      const double       N = ffv.shape_value(i, q);
                      dF[i].fill(0.);
                      dF[i][2 * c] = ffv.shape_grad(i, q) * T;
                      for (unsigned int r = 0; r < 3; ++r)
                        dF[i][2 * r + 1] += Kx[r][c] * N;
                      out.r[i] += dot6(dF[i], d.P) * dS;
                    }
                  for (unsigned int k = 0; k < n_strains; ++k)
                    {
                      D[k].fill(0.);
                      const Tensor<1, 3> db = kinematics::axial_column_strain_derivative(k, w);
                      for (unsigned int r = 0; r < 3; ++r)
                        D[k][2 * r + 1] = db[r];
                      resultants[k] += dot6(D[k], d.P) * dS;
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
                        out.K(i, j) += dot6(dF[j], CdF[i]) * dS;
                      const double       N = ffv.shape_value(i, q);
                      const unsigned int c = comp[i];
                      for (unsigned int k = 0; k < n_strains; ++k)
                        {
                          double bik = dot6(D[k], CdF[i]);
                          if (k >= 3) // Ps : d2 Fs / dU_i dkappa_k (second column)
                            {
                              const Tensor<1, 3> &ex = e_x_e[k - 3][c];
                              for (unsigned int r = 0; r < 3; ++r)
                                bik += d.P[2 * r + 1] * ex[r] * N;
                            }
                          out.B(i, k) += bik * dS;
                        }
                    }
                  for (unsigned int k = 0; k < n_strains; ++k)
                    for (unsigned int l = 0; l < n_strains; ++l)
                      E(k, l) += dot6(D[l], CD[k]) * dS;
                }
              // The 6x6 block of the surface went into E point by point.
              add_local_contribution(out.idx, out.r, out.K, out.B, nullptr, R, jacobian, E);
            }
        }

      results.energy        = energy;
      results.min_elastic_J = minJ;
      results.resultants    = resultants;
      return 0;
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
      driver.run(*this, solution);
      return last_state;
    }


    void
    CrossSectionProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution = U;
      const bool with_stiffness = stiffness_every_step || report.final;
      if (with_stiffness)
        last_state = current_state();
      else
        {
          FieldIntegrals a;
          assemble(solution, nullptr, false, &a);
          last_state.t             = load_parameter;
          last_state.energy        = a.energy;
          last_state.min_elastic_J = a.min_elastic_J;
          last_state.resultants    = a.resultants;
          last_state.strains       = strains_of(solution);
          for (unsigned int k = 0; k < n_gauge; ++k)
            last_state.multipliers[k] = solution[n_u() + k];
          last_state.n_negative = -1;
        }
      const CrossSectionState &s = last_state;
      record_state(report, s);

      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  t = " << std::setw(8)
           << fixed(report.t, 5) << "  Newton " << std::setw(2) << report.newton_iterations
           << "  |R| " << std::scientific << std::setprecision(1) << report.residual_norm
           << std::defaultfloat << "  Psi = " << fixed(s.energy, 8) << "  neg.eig. "
           << s.n_negative;
      if (std::any_of(strain_is_free.begin(), strain_is_free.end(), [](bool b) { return b; }))
        {
          line << "  strains (";
          for (unsigned int k = 0; k < 6; ++k)
            line << (k ? ", " : "") << fixed(s.strains[k], 6);
          line << ")";
        }
      say(line.str());

      if (!write_output)
        return;
      io::PhaseTimer::Scope scope(timer, "output");
      std::vector<double> row = {double(report.step), double(report.branch), report.t,
                                 double(report.newton_iterations), report.residual_norm,
                                 double(report.cutbacks), s.energy};
      row.insert(row.end(), s.strains.begin(), s.strains.end());
      row.insert(row.end(), s.resultants.begin(), s.resultants.end());
      row.insert(row.end(), s.multipliers.begin(), s.multipliers.end());
      for (unsigned int k = 0; k < 6; ++k)
        row.push_back(with_stiffness ? s.stiffness(k, k) : NAN);
      row.push_back(s.n_negative);
      row.push_back(s.min_elastic_J);
      steps_table.add_row(row);
      steps_table.write(output_directory + "/steps.csv");
      if (vtu_frequency == "every step" || (vtu_frequency == "final" && report.final))
        write_vtu(report.step, report.t);
    }

    namespace
    {
      /// Stresses and growth at output points of the deformed section.
      class SectionPostprocessor : public DataPostprocessor<2>
      {
      public:
        SectionPostprocessor(const materials::MaterialLibrary &materials,
                             const std::array<double, 6> &     strains,
                             const double                      t)
          : materials(materials)
          , nu({strains[0], strains[1], strains[2]})
          , kappa({strains[3], strains[4], strains[5]})
          , t(t)
        {}

        std::vector<std::string>
        get_names() const override
        {
          return {"position", "position", "position", "traction_E3", "traction_E3",
                  "traction_E3", "von_Mises_stress", "mean_stress", "growth_J",
                  "elastic_J", "energy_density", "region"};
        }
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          std::vector<DataComponentInterpretation::DataComponentInterpretation> v(
            12, DataComponentInterpretation::component_is_scalar);
          for (unsigned int k = 0; k < 6; ++k)
            v[k] = DataComponentInterpretation::component_is_part_of_vector;
          return v;
        }
        UpdateFlags
        get_needed_update_flags() const override
        {
          return update_values | update_gradients | update_quadrature_points;
        }
        void
        evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &in,
                              std::vector<Vector<double>> &             out) const override
        {
          const auto  cell     = in.template get_cell<2>();
          const auto &material = materials.material(cell->material_id());
          for (unsigned int p = 0; p < out.size(); ++p)
            {
              const Point<2> &X = in.evaluation_points[p];
              const Tensor<1, 3> w = kinematics::section_placement(
                X, Tensor<1, 3>({in.solution_values[p][0], in.solution_values[p][1],
                                 in.solution_values[p][2]}));
              Tensor<2, 3> grad_u;
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int j = 0; j < 2; ++j)
                  grad_u[i][j] = in.solution_gradients[p][i][j];
              const Tensor<2, 3> F = kinematics::section_deformation_gradient(grad_u, w, nu, kappa);
              const Tensor<2, 3>           Fg = material.growth.value(X, t);
              materials::EnergyDerivatives d;
              material.evaluate(F, Fg, false, d);
              Tensor<2, 3> P;
              for (unsigned int a = 0; a < 9; ++a)
                P[a / 3][a % 3] = d.P[a];
              const double       J     = determinant(F);
              const Tensor<2, 3> sigma = (J > 0 ? 1. / J : 0.) * P * transpose(F);
              const double       mean  = trace(sigma) / 3;
              Tensor<2, 3>       dev   = sigma;
              for (unsigned int i = 0; i < 3; ++i)
                dev[i][i] -= mean;
              for (unsigned int i = 0; i < 3; ++i)
                out[p][i] = w[i];
              for (unsigned int i = 0; i < 3; ++i)
                out[p][3 + i] = P[i][2];
              out[p][6]  = std::sqrt(1.5 * scalar_product(dev, dev));
              out[p][7]  = mean;
              out[p][8]  = determinant(Fg);
              out[p][9]  = J / determinant(Fg);
              out[p][10] = d.energy;
              out[p][11] = cell->material_id();
            }
        }

      private:
        const materials::MaterialLibrary &materials;
        const Tensor<1, 3>                nu, kappa;
        const double                      t;
      };
    } // namespace

    void
    CrossSectionProblem::write_vtu(const unsigned int step, const double t)
    {
      const std::string name = "solution-" + Utilities::int_to_string(step, 4) + ".vtu";
      {
        Vector<double> u(solution.begin(), solution.begin() + n_u());
        SectionPostprocessor post(materials, strains_of(solution), t);
        DataOut<2>           data_out;
        data_out.attach_dof_handler(dof_handler);
        std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
          3, DataComponentInterpretation::component_is_part_of_vector);
        data_out.add_data_vector(u, std::vector<std::string>(3, "displacement"),
                                 DataOut<2>::type_dof_data, interp);
        data_out.add_data_vector(u, post);
        data_out.build_patches(*mapping, degree, DataOut<2>::curved_inner_cells);

        // deal.II groups vector components of 2D output in pairs, but the
        // section's fields (displacement, position, traction) are 3-vectors:
        // lift the patches into 3D space (points (X1, X2, 0)), where VTU
        // vectors have three components and ParaView can warp the section
        // by the displacement.
        const std::vector<std::string> names = {
          "displacement", "displacement", "displacement", "position", "position", "position",
          "traction_E3", "traction_E3", "traction_E3", "von_Mises_stress", "mean_stress",
          "growth_J", "elastic_J", "energy_density", "region"};
        const unsigned int n_data = names.size();
        std::vector<DataOutBase::Patch<2, 3>> patches;
        for (const auto &p2 : data_out.get_patches())
          {
            DataOutBase::Patch<2, 3> p3;
            p3.n_subdivisions       = p2.n_subdivisions;
            p3.reference_cell       = p2.reference_cell;
            p3.patch_index          = p2.patch_index;
            p3.points_are_available = true;
            for (unsigned int v = 0; v < 4; ++v)
              p3.vertices[v] = Point<3>(p2.vertices[v][0], p2.vertices[v][1], 0);
            const unsigned int n_points = p2.data.n_cols();
            const unsigned int np       = p2.n_subdivisions + 1;
            p3.data.reinit(n_data + 3, n_points);
            for (unsigned int k = 0; k < n_points; ++k)
              {
                for (unsigned int r = 0; r < n_data; ++r)
                  p3.data(r, k) = p2.data(r, k);
                Point<2> x;
                if (p2.points_are_available)
                  x = Point<2>(p2.data(n_data, k), p2.data(n_data + 1, k));
                else
                  {
                    const double xi = double(k % np) / p2.n_subdivisions,
                                 eta = double(k / np) / p2.n_subdivisions;
                    x = (1 - xi) * (1 - eta) * p2.vertices[0] + xi * (1 - eta) * p2.vertices[1] +
                        (1 - xi) * eta * p2.vertices[2] + xi * eta * p2.vertices[3];
                  }
                p3.data(n_data, k)     = x[0];
                p3.data(n_data + 1, k) = x[1];
                p3.data(n_data + 2, k) = 0;
              }
            patches.push_back(std::move(p3));
          }
        std::vector<std::tuple<unsigned int, unsigned int, std::string,
                               DataComponentInterpretation::DataComponentInterpretation>>
          vectors = {{0, 2, "displacement", DataComponentInterpretation::component_is_part_of_vector},
                     {3, 5, "position", DataComponentInterpretation::component_is_part_of_vector},
                     {6, 8, "traction_E3", DataComponentInterpretation::component_is_part_of_vector}};
        DataOutBase::VtkFlags flags;
        flags.write_higher_order_cells = false;
        io::write_file_atomically(output_directory + "/" + name, [&](std::ostream &out) {
          DataOutBase::write_vtu(patches, names, vectors, flags, out);
        });
      }
      pvd->add(t, name);
      const std::string rod_name = "rod-" + Utilities::int_to_string(step, 4) + ".vtu";
      write_rod_piece(output_directory + "/" + rod_name);
      pvd_rod->add(t, rod_name);
      if (!surface_faces.empty())
        {
          const std::string surface_name = "surface-" + Utilities::int_to_string(step, 4) + ".vtu";
          write_surface_layers(output_directory + "/" + surface_name, t);
          pvd_surface->add(t, surface_name);
        }
    }

    void
    CrossSectionProblem::write_surface_layers(const std::string &file, const double t) const
    {
      // The layers as polylines on the reference boundary (points (X1, X2, 0),
      // with the displacement to warp by), with their growth and stress.
      const auto         e = strains_of(solution);
      const Tensor<1, 3> nu({e[0], e[1], e[2]}), kappa({e[3], e[4], e[5]});
      const unsigned int p = degree;
      std::vector<Point<1>> unit_points;
      for (unsigned int i = 0; i <= p; ++i)
        unit_points.emplace_back(double(i) / p);
      const Quadrature<1> points(unit_points);
      FEFaceValues<2>     ffv(*mapping, *fe, points,
                          update_values | update_gradients | update_quadrature_points |
                            update_normal_vectors);
      Vector<double>                   u(solution.begin(), solution.begin() + n_u());
      std::vector<Vector<double>>      u_values(p + 1, Vector<double>(3));
      std::vector<std::vector<Tensor<1, 2>>> u_grads(p + 1, std::vector<Tensor<1, 2>>(3));
      const std::vector<std::string> names = {"displacement", "displacement", "displacement",
                                              "growth_T", "growth_3", "stress_TT", "stress_33",
                                              "stress_T3", "layer"};
      std::vector<DataOutBase::Patch<1, 3>> patches;
      for (const auto &sf : surface_faces)
        {
          const auto &layer = surface_layers.layers()[sf.layer];
          ffv.reinit(sf.cell, sf.face);
          ffv.get_function_values(u, u_values);
          ffv.get_function_gradients(u, u_grads);
          DataOutBase::Patch<1, 3> patch;
          patch.n_subdivisions       = p;
          patch.reference_cell       = ReferenceCells::Line;
          patch.points_are_available = true;
          patch.data.reinit(names.size() + 3, p + 1);
          for (unsigned int k = 0; k <= p; ++k)
            {
              const Point<2> &   X  = ffv.quadrature_point(k);
              const Tensor<1, 2> &N = ffv.normal_vector(k);
              const Tensor<1, 2> T = kinematics::boundary_tangent(N);
              Tensor<1, 3>       du_dS;
              for (unsigned int c = 0; c < 3; ++c)
                du_dS[c] = u_grads[k][c] * T;
              const Tensor<1, 3> w  = kinematics::section_placement(
                X, Tensor<1, 3>({u_values[k][0], u_values[k][1], u_values[k][2]}));
              const auto         g  = layer.growth(X, t);
              const auto         S  = layer.stress(
                kinematics::surface_deformation_gradient(w, du_dS, T, nu, kappa), g, t);
              const std::vector<double> v = {u_values[k][0], u_values[k][1], u_values[k][2],
                                             g[0], g[1], S[0], S[1], S[2], double(sf.layer + 1)};
              for (unsigned int r = 0; r < v.size(); ++r)
                patch.data(r, k) = v[r];
              patch.data(names.size(), k)     = X[0];
              patch.data(names.size() + 1, k) = X[1];
              patch.data(names.size() + 2, k) = 0;
            }
          patch.vertices[0] = Point<3>(patch.data(names.size(), 0), patch.data(names.size() + 1, 0), 0);
          patch.vertices[1] = Point<3>(patch.data(names.size(), p), patch.data(names.size() + 1, p), 0);
          patch.patch_index = patches.size();
          patches.push_back(std::move(patch));
        }
      std::vector<std::tuple<unsigned int, unsigned int, std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>
        vectors = {{0, 2, "displacement", DataComponentInterpretation::component_is_part_of_vector}};
      DataOutBase::VtkFlags flags;
      flags.write_higher_order_cells = false;
      io::write_file_atomically(file, [&](std::ostream &out) {
        DataOutBase::write_vtu(patches, names, vectors, flags, out);
      });
    }

    void
    CrossSectionProblem::write_rod_piece(const std::string &file) const
    {
      // A short piece of the rod in 3D: the deformed section swept along the
      // helix, x(X1, X2, X3) = r(X3) + R(X3) w(X1, X2).
      const auto                e = strains_of(solution);
      const kinematics::RodStrains strains(e);
      const double              D = section_properties.diameter;
      double                    L = rod_piece_length;
      if (L == 0)
        {
          const double k = strains.kappa.norm();
          L              = (k > 0) ? std::min(2 * M_PI / k, 10 * D) : 3 * D;
        }
      const unsigned int p  = degree;
      const unsigned int np = p + 1;
      std::vector<Point<2>> unit_points;
      for (unsigned int j = 0; j < np; ++j)
        for (unsigned int i = 0; i < np; ++i)
          unit_points.emplace_back(double(i) / p, double(j) / p);
      const Quadrature<2> points(unit_points);
      FEValues<2>         fev(*mapping, *fe, points, update_values | update_quadrature_points);
      Vector<double>              u(solution.begin(), solution.begin() + n_u());
      std::vector<Vector<double>> u_values(unit_points.size(), Vector<double>(3));

      std::vector<DataOutBase::Patch<3, 3>> patches;
      const unsigned int                    n_slices = rod_piece_slices;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(u, u_values);
          for (unsigned int s = 0; s < n_slices; ++s)
            {
              DataOutBase::Patch<3, 3> patch;
              patch.n_subdivisions       = p;
              patch.reference_cell       = ReferenceCells::Hexahedron;
              patch.points_are_available = true;
              const unsigned int n_points = np * np * np;
              patch.data.reinit(2 + 3, n_points);
              for (unsigned int k = 0; k < np; ++k)
                {
                  const double X3 = L * (s + double(k) / p) / n_slices;
                  const Tensor<2, 3> R = kinematics::helix_rotation(strains.kappa, X3);
                  const Tensor<1, 3> r = kinematics::helix_position(strains.nu, strains.kappa, X3);
                  for (unsigned int ij = 0; ij < np * np; ++ij)
                    {
                      const Point<2> &X = fev.quadrature_point(ij);
                      const Tensor<1, 3> w({X[0] + u_values[ij][0], X[1] + u_values[ij][1],
                                            u_values[ij][2]});
                      const Tensor<1, 3> x = r + R * w;
                      const unsigned int pt = k * np * np + ij;
                      patch.data(0, pt) = X3;
                      patch.data(1, pt) = cell->material_id();
                      for (unsigned int c = 0; c < 3; ++c)
                        patch.data(2 + c, pt) = x[c];
                    }
                }
              // Corner vertices (used by some writers for bounding boxes).
              for (unsigned int v = 0; v < 8; ++v)
                {
                  const unsigned int i = (v & 1) ? p : 0, j = (v & 2) ? p : 0,
                                     k = (v & 4) ? p : 0;
                  const unsigned int pt = k * np * np + j * np + i;
                  patch.vertices[v] =
                    Point<3>(patch.data(2, pt), patch.data(3, pt), patch.data(4, pt));
                }
              patch.patch_index = patches.size();
              patches.push_back(std::move(patch));
            }
        }
      DataOutBase::VtkFlags flags;
      flags.write_higher_order_cells = false;
      io::write_file_atomically(file, [&](std::ostream &out) {
        DataOutBase::write_vtu(patches, {"arc_length", "region"}, {}, flags, out);
      });
    }

    void
    CrossSectionProblem::write_summary() const
    {
      using io::JSON;
      JSON j                  = record.summary();
      j["mode"]               = mode;
      JSON free               = JSON::array();
      for (unsigned int k = 0; k < 6; ++k)
        if (strain_is_free[k])
          free.push_back(kinematics::strain_names[k]);
      j["free_strains"]       = free;
      j["load_parameter"]     = last_state.t;
      JSON &mesh              = j["mesh"];
      mesh["shape"]           = geometry.shape;
      mesh["cells"]           = triangulation.n_active_cells();
      mesh["field_dofs"]      = n_u();
      mesh["degree"]          = degree;
      mesh["area"]            = section_properties.area;
      mesh["I11"]             = section_properties.I11;
      mesh["I22"]             = section_properties.I22;
      mesh["diameter"]        = section_properties.diameter;
      mesh["centroid_shift"]  = JSON::array({geometry.applied_shift[0], geometry.applied_shift[1]});
      JSON mats               = JSON::array();
      for (const auto &s : materials.descriptions())
        mats.push_back(s);
      j["materials"]          = mats;
      JSON layers             = JSON::array();
      for (const auto &s : surface_layers.descriptions())
        layers.push_back(s);
      j["surface_layers"]     = layers;
      add_state_to_summary(j, last_state);
      j["min_elastic_J"]              = last_state.min_elastic_J;
      const auto h = kinematics::helix_geometry(kinematics::RodStrains(last_state.strains));
      JSON &helix  = j["helix"];
      helix["description"] = h.description();
      helix["radius"]      = h.radius;
      helix["pitch"]       = h.pitch; // inf -> null for a straight rod
      helix["handedness"]  = h.handedness;
      helix["axis"]        = JSON::array({h.axis[0], h.axis[1], h.axis[2]});
      helix["curvature"]   = h.curvature;
      helix["torsion"]     = h.torsion;
      j["newton_iterations"] = total_newton_iterations;
      record.finish(j, timer);
    }

    void
    CrossSectionProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      write_output   = true;
      record.open(output_directory, prm, options);
      pvd = std::make_unique<io::PVDSeries>(output_directory + "/solution.pvd");
      pvd_rod = std::make_unique<io::PVDSeries>(output_directory + "/rod.pvd");
      if (!surface_faces.empty() || !surface_layers.layers().empty())
        pvd_surface = std::make_unique<io::PVDSeries>(output_directory + "/surface.pvd");
      {
        io::PhaseTimer::Scope scope(timer, "setup");
        setup_system();
      }
      std::ostringstream info;
      info << "  section: " << geometry.shape << ", " << triangulation.n_active_cells()
           << " cells, Q" << degree << ", " << n_u() << " field DoFs + 6 multipliers + 6 strains; area "
           << section_properties.area;
      say(info.str());
      if (!geometry.meshing_summary.empty())
        say("  " + geometry.meshing_summary);
      if (geometry.applied_shift.norm() > 0)
        say("  mesh shifted by (" + fixed(geometry.applied_shift[0]) + ", " +
            fixed(geometry.applied_shift[1]) + ") to put its centroid at the origin");
      for (const auto &m : materials.descriptions())
        say("  " + m);
      for (unsigned int l = 0; l < surface_layers.layers().size(); ++l)
        say("  " + surface_layers.layers()[l].description() + " (arc length " +
            fixed(surface_length[l]) + ")");

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

      record.attempt([&]() { solve(); });
      if (!record.failed())
        say_result();
      write_summary();
    }

    void
    CrossSectionProblem::say_result() const
    {
      const auto &s = last_state;
      say("");
      say("Result at t = " + fixed(s.t) + ":");
      std::ostringstream out;
      out << "  energy per unit length  " << fixed(s.energy, 10) << "\n  strains    ";
      for (unsigned int k = 0; k < 6; ++k)
        out << " " << kinematics::strain_names[k] << " = " << fixed(s.strains[k], 10);
      out << "\n  resultants ";
      for (unsigned int k = 0; k < 6; ++k)
        out << " " << kinematics::resultant_names[k] << " = " << fixed(s.resultants[k], 6);
      out << "\n  multipliers";
      for (unsigned int k = 0; k < 6; ++k)
        out << " " << fixed(s.multipliers[k], 3);
      out << "\n  stiffness (nu1, nu2, nu3, kappa1, kappa2, kappa3):\n";
      for (unsigned int a = 0; a < 6; ++a)
        {
          out << "   ";
          for (unsigned int b = 0; b < 6; ++b)
            out << std::setw(14) << fixed(s.stiffness(a, b), 6);
          out << "\n";
        }
      out << "  natural/current centreline: "
          << kinematics::helix_geometry(kinematics::RodStrains(s.strains)).description() << "\n";
      out << "  timings [s]:";
      for (const auto &p : timer.phases())
        out << "  " << p << " " << fixed(timer.seconds(p), 3);
      say(out.str());
    }

    void
    run_study(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      if (!sweep.enabled())
        {
          CrossSectionProblem problem;
          problem.parse_parameters(prm);
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

      prm.enter_subsection("Output");
      const std::string base = prm.get("Output directory");
      prm.leave_subsection();
      const auto log_file = io::open_run_directory(base, prm, options.quiet, "sweep-log.txt");
      auto &     log      = *log_file;
      log("rod_cross_section " + std::string(COSMO_VERSION) + ": " + options.parameter_file +
          ", sweep of '" + sweep.entry() + "' over " + std::to_string(sweep.size()) + " values");

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

      unsigned int             n_failed = 0;
      std::vector<std::string> rejected;
      for (unsigned int k = 0; k < sweep.size(); ++k)
        {
          sweep.prepare_point(prm, k, io::ParameterSweep::point_directory(base, k));
          io::RunOptions point_options = options;
          point_options.quiet          = true; // the point's log.txt has the details
          std::vector<double> row = {double(k), sweep.value(k)};
          std::ostringstream  line;
          line << "point " << k + 1 << "/" << sweep.size() << ": " << sweep.label() << " = "
               << sweep.text(k);
          try
            {
              CrossSectionProblem problem;
              problem.parse_parameters(prm);
              problem.run(point_options, prm);
              const auto &s = problem.final_state();
              const auto  h = kinematics::helix_geometry(kinematics::RodStrains(s.strains));
              row.push_back(1);
              row.push_back(s.energy);
              row.insert(row.end(), s.strains.begin(), s.strains.end());
              row.insert(row.end(), s.resultants.begin(), s.resultants.end());
              for (unsigned int a = 0; a < 6; ++a)
                for (unsigned int b = a; b < 6; ++b)
                  row.push_back(s.stiffness(a, b));
              row.push_back(h.radius);
              row.push_back(h.pitch);
              row.push_back(s.n_negative);
              line << "  strains (";
              for (unsigned int i = 0; i < 6; ++i)
                line << (i ? ", " : "") << fixed(s.strains[i], 6);
              line << ")  " << h.description();
            }
          catch (io::RunFailure &e)
            {
              ++n_failed;
              row.push_back(0);
              row.resize(table.n_columns(), std::numeric_limits<double>::quiet_NaN());
              line << "  FAILED: " << e.what();
            }
          catch (io::InputError &e)
            {
              // A value can pass the entry's pattern and still be rejected
              // by the problem (det Fg <= 0 somewhere, ...): that point is
              // bad input, the others still run.
              rejected.push_back(sweep.text(k));
              row.push_back(0);
              row.resize(table.n_columns(), std::numeric_limits<double>::quiet_NaN());
              line << "  REJECTED: " << e.what();
            }
          log(line.str());
          // Rewritten after every point: a killed sweep leaves a complete table.
          table.add_row(row);
          table.write(base + "/sweep.csv");
        }
      log("sweep table: " + base + "/sweep.csv");
      if (!rejected.empty())
        {
          std::string values;
          for (const auto &v : rejected)
            values += (values.empty() ? "'" : ", '") + v + "'";
          throw io::InputError("Parameter sweep", "Entry", sweep.entry(),
                               std::to_string(rejected.size()) + " of " +
                                 std::to_string(sweep.size()) +
                                 " values were rejected by the problem: " + values +
                                 " (the other points ran; see " + base + "/sweep-log.txt)");
        }
      if (n_failed > 0)
        throw io::RunFailure(std::to_string(n_failed) + " of " + std::to_string(sweep.size()) +
                             " sweep points failed (see " + base + "/sweep-log.txt)");
    }
  } // namespace rod
} // namespace cosmo

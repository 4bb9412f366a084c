// The plate and rim energies are differentiated here (Sacado, 15 and 12
// local variables): the heavy translation unit of part 3.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/solvers/run_start.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/assumed_shear.h>
#include <cosmo/assembly/local_variables.h>
#include <cosmo/config.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/resources.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/run_directory.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/materials/energy_derivatives.h>

#include <cosmo/materials/growth_admissibility.h>

#include "plate_rod_problem.h"

#include <chrono>
#include <fstream>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {
    namespace
    {
      constexpr int n_plate = kinematics::plate_local_variables;
      constexpr int n_rim   = kinematics::rim_local_variables;

      using assembly::Drive;

      Drive
      plate_drive(const unsigned int c, const double N, const Tensor<1, 2> &g)
      {
        Drive d;
        if (c < 3)
          d = {3, {c, 3 + c, 6 + c}, {N, g[0], g[1]}};
        else if (c < 5)
          d = {3, {9 + c - 3, 11 + c - 3, 13 + c - 3}, {N, g[0], g[1]}};
        return d; // alpha: not a plate variable
      }

      Drive
      rim_drive(const unsigned int c, const double N, const double dS)
      {
        if (c < 3)
          return {2, {c, 3 + c, 0}, {N, dS, 0}};
        if (c < 5)
          return {2, {6 + c - 3, 8 + c - 3, 0}, {N, dS, 0}};
        return {2, {10, 11, 0}, {N, dS, 0}};
      }



    } // namespace

    namespace
    {
      // COSMO_PLATE_NESTED_AD=1: nested AD of the plate energy even where the
      // model has a chain rule (to measure against, benchmarks/README.md).
      const bool nested_ad_only = std::getenv("COSMO_PLATE_NESTED_AD") != nullptr;
    } // namespace

    /// Per-thread work space of the cell loop (WorkStream scratch).
    struct PlateRodProblem::Scratch
    {
      Scratch(const Mapping<2> &     mapping,
              const FiniteElement<2> &fe,
              const Quadrature<2> &   full,
              const Quadrature<2> &   reduced,
              const Quadrature<1> &   face,
              const Quadrature<2> &   tying)
        : fev_full(mapping, fe, full,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values | update_inverse_jacobians)
        , fev_reduced(mapping, fe, reduced,
                      update_values | update_gradients | update_quadrature_points |
                        update_JxW_values)
        , fev_face(mapping, fe, face,
                   update_values | update_gradients | update_quadrature_points |
                     update_JxW_values | update_normal_vectors)
        , fev_tying(mapping, fe, tying, update_values | update_gradients | update_jacobians)
        , U_local(fe.n_dofs_per_cell())
      {}
      Scratch(const Scratch &o)
        : Scratch(o.fev_full.get_mapping(), o.fev_full.get_fe(), o.fev_full.get_quadrature(),
                  o.fev_reduced.get_quadrature(), o.fev_face.get_quadrature(),
                  o.fev_tying.get_quadrature())
      {}
      FEValues<2>         fev_full, fev_reduced;
      FEFaceValues<2>     fev_face;
      FEValues<2>         fev_tying;
      std::vector<double> U_local;
      std::vector<Drive>  drives;
      /// Assumed shear: per tying point its drives, the covariant strain and its derivatives
      /// in the local variables; V(i, k) = d e_k / d U_i; the energy's derivatives in the e_k.
      std::vector<std::vector<Drive>>                                    tying_drives; ///< per location
      std::vector<std::array<double, kinematics::plate_local_variables>> tying_z; ///< per location
      std::vector<double>                                                tying_strain;
      std::vector<std::array<double, kinematics::plate_local_variables>> tying_gradient;
      std::vector<std::array<double, kinematics::plate_local_variables *
                                       kinematics::plate_local_variables>>
                         tying_hessian;
      FullMatrix<double> V, M, VM;
      std::vector<double> mu;

      /// The assumed shear's work space for the cell fev_full is on, zeroed.
      void
      prepare_tying(const unsigned int n_locations,
                    const unsigned int n_tying,
                    const unsigned int dpc,
                    const bool         jacobian)
      {
        fev_tying.reinit(fev_full.get_cell());
        tying_drives.resize(n_locations);
        tying_z.resize(n_locations);
        tying_strain.resize(n_tying);
        tying_gradient.resize(n_tying);
        tying_hessian.resize(n_tying);
        V.reinit(dpc, n_tying);
        mu.assign(n_tying, 0.);
        if (jacobian)
          {
            M.reinit(n_tying, n_tying);
            VM.reinit(dpc, n_tying);
          }
      }
    };

    /// What every cell of one assembly shares: the load, the laws at it, the
    /// assumed shear's tying points and weights.
    struct PlateRodProblem::CellLoopData
    {
      CellLoopData(const PlateRodProblem &p, const Quadrature<2> &full, const bool jacobian)
        : dpc(p.fe->n_dofs_per_cell())
        , comp(dpc)
        , assumed_shear(p.degree, p.shear_integration != ShearIntegration::interior_tying)
        , tying_weights(assumed_shear.interpolation(full))
        , n_tying(assumed_shear.n_tying_points())
        , n_locations(assumed_shear.tying_points().size())
        , strains_at(n_locations)
        , t(p.load_parameter)
        , g_rod(p.rod_growth_at(t))
        , rod(p.rod_law())
        , rim_natural_curvature({{t * p.rod_natural_curvature[0], t * p.rod_natural_curvature[1],
                                  t * p.rod_natural_curvature[2]}})
        , shear_scale(p.model->shear_scale())
        , jacobian(jacobian)
      {
        for (unsigned int i = 0; i < dpc; ++i)
          comp[i] = p.fe->system_to_component_index(i).first;
        // The tied strains at each location (e_0 and e_1 share some), once per assembly.
        for (unsigned int k = 0; k < n_tying; ++k)
          strains_at[assumed_shear.location_of(k)].push_back(k);
      }
      const unsigned int        dpc;
      std::vector<unsigned int> comp;
      /// The assumed shear's tying points and their weights at the full quadrature.
      const assembly::AssumedShear           assumed_shear;
      const FullMatrix<double>               tying_weights;
      const unsigned int                     n_tying, n_locations;
      std::vector<std::vector<unsigned int>> strains_at;
      const double                           t, g_rod;
      const materials::QuadraticRodLaw       rod;
      const std::array<double, 3>            rim_natural_curvature;
      const double                           shear_scale;
      const bool                             jacobian;
    };

    PlateRodProblem::PlateRodProblem() = default;
    PlateRodProblem::~PlateRodProblem()
    {
      dof_handler.clear();
    }

    namespace
    {
      /// The sector 0 <= theta <= pi/n of radius R: the quarter disc (3 cells; the half
      /// disc for n = 1) refined, then stretched in angle onto [0, pi/n] (circles stay circles).
      void
      stretched_sector(Triangulation<2> &tria, const unsigned int n, const double R,
                       const std::function<void()> &refine)
      {
        if (n == 1)
          {
            // The half disc y >= 0 (half_hyper_ball is x >= 0): no degenerate apex cell.
            GridGenerator::half_hyper_ball(tria, Point<2>(), R);
            GridTools::rotate(M_PI / 2, tria);
          }
        else
          GridGenerator::quarter_hyper_ball(tria, Point<2>(), R);
        refine();
        if (n > 2)
          {
            const double s = 2. / n;
            GridTools::transform(
              [s](const Point<2> &p) {
                const double r = p.norm(), a = std::atan2(p[1], p[0]);
                return Point<2>(r * std::cos(s * a), r * std::sin(s * a));
              },
              tria);
          }
      }

      /**
       * The sector pi/n as two mirror images of the (refined) mesh of the
       * sector pi/(2n), joined along theta = pi/(2n): the same discretization
       * on both halves, so that the states of the sector pi/n symmetric about
       * that line are exactly those of the sector pi/(2n) (a comparison of the
       * two symmetry reductions to round-off, not to the discretization error).
       */
      void
      mirrored_sector(Triangulation<2> &tria, const unsigned int n, const double R,
                      const std::function<void(Triangulation<2> &)> &refine)
      {
        Triangulation<2> half, flat;
        stretched_sector(half, 2 * n, R, [&]() { refine(half); });
        GridGenerator::flatten_triangulation(half, flat);
        const double          phi = M_PI / (2 * n);
        const Tensor<1, 2>    e({std::cos(phi), std::sin(phi)});
        std::vector<Point<2>> vertices = flat.get_vertices();
        const unsigned int    nv       = vertices.size();
        for (unsigned int v = 0; v < nv; ++v)
          vertices.push_back(Point<2>(2 * (vertices[v] * e) * e - vertices[v]));
        std::vector<CellData<2>> cells;
        for (const auto &cell : flat.active_cell_iterators())
          {
            CellData<2> c(4), m(4);
            for (unsigned int v = 0; v < 4; ++v)
              c.vertices[v] = cell->vertex_index(v);
            // The image of a cell has the opposite orientation: swap 0 <-> 1, 2 <-> 3.
            const unsigned int order[4] = {1, 0, 3, 2};
            for (unsigned int v = 0; v < 4; ++v)
              m.vertices[v] = c.vertices[order[v]] + nv;
            cells.push_back(c);
            cells.push_back(m);
          }
        SubCellData                subcells;
        std::vector<unsigned int>  unused;
        GridTools::delete_duplicated_vertices(vertices, cells, subcells, unused, 1e-10 * R);
        GridTools::consistently_order_cells(cells);
        tria.create_triangulation(vertices, cells, subcells);
      }
    } // namespace

    void
    PlateRodProblem::make_mesh()
    {
      this->triangulation.set_distributed(distributed_mesh);
      // The same coarse mesh and refinements on one process and on a distributed mesh.
      Triangulation<2> &triangulation = this->triangulation.get();
      triangulation.clear();
      // 6 fields of degree p: about 6 p^2 unknowns per cell; refused before refining what
      // cannot fit (io/resources.h).
      auto refine = [this](Triangulation<2> &tria) {
        const boost::signals2::scoped_connection guard(
          io::guard_refinement(tria, 6. * degree * degree, degree, "Mesh", "Global refinements",
                               std::to_string(refinements)));
        tria.refine_global(refinements);
      };
      if (domain == "sector" && sector_mesh == "mirrored")
        mirrored_sector(triangulation, sector_n, radius, refine);
      else if (domain == "sector")
        stretched_sector(triangulation, sector_n, radius, [&]() { refine(triangulation); });
      else
        {
          GridGenerator::hyper_ball(triangulation, Point<2>(), radius);
          refine(triangulation);
        }
      // Straight cells inside, the rim on the exact circle (MappingQ(p) bends
      // the cells next to it).
      triangulation.reset_all_manifolds();
      triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto   face = cell->face(f);
              const double r0 = face->vertex(0).norm(), r1 = face->vertex(1).norm();
              if (std::abs(r0 - radius) < 1e-8 * radius && std::abs(r1 - radius) < 1e-8 * radius)
                {
                  face->set_boundary_id(rim_id);
                  face->set_manifold_id(0);
                }
              else
                face->set_boundary_id(std::abs(face->center()[1]) < 1e-10 * radius ?
                                        mirror_first :
                                        mirror_second);
            }
      triangulation.set_manifold(0, SphericalManifold<2>(Point<2>()));
      mapping = std::make_unique<MappingQ<2>>(degree);
    }

    namespace
    {
      /// The sector's mirror edges (boundary mirror_first: m = E2; mirror_second: the edge
      /// at pi/n): m.u = 0 and theta parallel to m (m.d = 0), and the rim's alpha = 0 there.
      void
      add_mirror_constraints(const DoFHandler<2> &       dof_handler,
                             const FiniteElement<2> &    fe,
                             const unsigned int          sector_n,
                             AffineConstraints<double> &constraints)
      {
        // Mirror planes with normal m: m.u = 0 and theta parallel to m (m.d = 0).
        const double phi = M_PI / sector_n, c = std::cos(phi), s = std::sin(phi);
        std::vector<types::global_dof_index> fd(fe.n_dofs_per_face());
        auto constrain = [&constraints](const types::global_dof_index slave,
                                        const types::global_dof_index master,
                                        const double                  w) {
          if (constraints.is_constrained(slave))
            return;
          constraints.add_line(slave);
          if (master != numbers::invalid_dof_index && w != 0)
            constraints.add_entry(slave, master, w);
        };
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary() &&
                (cell->face(f)->boundary_id() == mirror_first ||
                 cell->face(f)->boundary_id() == mirror_second))
              {
                cell->face(f)->get_dof_indices(fd);
                std::map<unsigned int, std::array<types::global_dof_index, 6>> nodes;
                for (unsigned int i = 0; i < fd.size(); ++i)
                  {
                    const auto ci                     = fe.face_system_to_component_index(i);
                    nodes[ci.second][ci.first]        = fd[i];
                  }
                const bool first = cell->face(f)->boundary_id() == mirror_first;
                for (const auto &[node, d] : nodes)
                  {
                    (void)node;
                    constrain(d[5], numbers::invalid_dof_index, 0); // the rim end: alpha = 0
                    if (first)
                      {
                        // m = E2: u2 = 0, theta1 = 0.
                        constrain(d[1], numbers::invalid_dof_index, 0);
                        constrain(d[3], numbers::invalid_dof_index, 0);
                      }
                    else if (std::abs(c) >= std::abs(s))
                      {
                        // m = (-s, c): u2 = (s/c) u1;  c theta1 + s theta2 = 0.
                        constrain(d[1], d[0], s / c);
                        constrain(d[3], d[4], -s / c);
                      }
                    else
                      {
                        constrain(d[0], d[1], c / s);
                        constrain(d[4], d[3], -c / s);
                      }
                  }
              }
      }

      /// The rim's in-plane rotation alpha lives on the rim: zero elsewhere. (A cell with a DoF
      /// on the rim has its rim face there, so every rank that knows such a DoF sees it is on
      /// the rim.)
      void
      constrain_alpha_off_rim(const DoFHandler<2> &       dof_handler,
                              const FiniteElement<2> &    fe,
                              AffineConstraints<double> &constraints)
      {
        std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
        std::set<types::global_dof_index>    all_alpha, rim_alpha;
        std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int k = 0; k < cell_dofs.size(); ++k)
                if (fe.system_to_component_index(k).first == 5)
                  all_alpha.insert(cell_dofs[k]);
              for (const unsigned int f : cell->face_indices())
                if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
                  {
                    cell->face(f)->get_dof_indices(face_dofs);
                    for (unsigned int k = 0; k < face_dofs.size(); ++k)
                      if (fe.face_system_to_component_index(k).first == 5)
                        rim_alpha.insert(face_dofs[k]);
                  }
            }
        for (const auto i : all_alpha)
          if (!rim_alpha.count(i) && !constraints.is_constrained(i))
            constraints.add_line(i);
      }
    } // namespace

    void
    PlateRodProblem::make_constraints()
    {
      constraints.clear();
      const bool sector = domain == "sector";
      // In-plane only: u3, theta1, theta2 = 0 everywhere, first (the mirror
      // conditions below then find those DoFs constrained already).
      // On a distributed mesh each rank makes the constraints of the DoFs of
      // the cells it knows (its own and their neighbours): every constraint
      // here ties DoFs of one node, so the ranks that know a DoF agree on it.
      std::vector<types::global_dof_index> cell_dofs(fe->n_dofs_per_cell());
      if (in_plane_only)
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial())
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int k = 0; k < cell_dofs.size(); ++k)
                {
                  const unsigned int c = fe->system_to_component_index(k).first;
                  if (c >= 2 && c <= 4 && !constraints.is_constrained(cell_dofs[k]))
                    constraints.add_line(cell_dofs[k]);
                }
            }
      // The apex: no translation, director E3 (the gauge of the full disc; on a sector with
      // n >= 2 the mirrors imply all but u3 = 0, the one gauge left there).
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).norm() < 1e-10 * radius)
            for (unsigned int c = 0; c < 5; ++c)
              {
                const auto i = cell->vertex_dof_index(v, c);
                if (!constraints.is_constrained(i))
                  constraints.add_line(i);
              }
      if (!sector)
        {
          // Rotation about E3: u2 = 0 at the rim point (R, 0) (modes cos(n theta) keep it).
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (!cell->is_artificial())
            for (const unsigned int v : cell->vertex_indices())
              if ((cell->vertex(v) - Point<2>(radius, 0)).norm() < 1e-8 * radius)
                {
                  const auto i = cell->vertex_dof_index(v, 1);
                  if (!constraints.is_constrained(i))
                    constraints.add_line(i);
                }
        }
      else
        {
          add_mirror_constraints(dof_handler, *fe, sector_n, constraints);
        }
      constrain_alpha_off_rim(dof_handler, *fe, constraints);
      constraints.close();
    }

    void
    PlateRodProblem::setup_system()
    {
      residuals.clear();
      // A stiffness with its constraints eliminated: every diagonal entry is nonzero.
      system.set_nonzero_diagonal(true);
      make_mesh();
      fe = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 6);
      dof_handler.reinit(triangulation.get());
      dof_handler.distribute_dofs(*fe);
      make_constraints();
      if (distributed_mesh)
        {
          // Each rank's rows: those of its own DoFs, entries from its cells
          // sent to their owners at compress().
          const IndexSet owned    = dof_handler.locally_owned_dofs();
          IndexSet       relevant;
          DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
          TrilinosWrappers::SparsityPattern sp;
          sp.reinit(owned, owned, relevant, MPI_COMM_WORLD);
          DoFTools::make_sparsity_pattern(dof_handler, sp, constraints, false,
                                          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD));
          sp.compress();
          layout = solvers::ReplicatedVectorLayout(MPI_COMM_WORLD, owned);
          system.reinit(sp, 0, layout);
        }
      else
        {
          DynamicSparsityPattern dsp(dof_handler.n_dofs());
          DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
          system.reinit(dsp, 0);
          layout = solvers::ReplicatedVectorLayout();
        }
      solution.reinit(dof_handler.n_dofs());
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
    PlateRodProblem::make_reflection()
    {
      // The full disc's reflection y -> -y: u1, u3 even, u2 odd; the rotation
      // vector is axial, theta -> -diag(1, -1, 1) theta: theta1 and alpha
      // (about E3) odd, theta2 even. DoFs are paired by their support points.
      reflection.clear();
      if (domain == "sector")
        return;
      // (empty where the mesh is not mirror-symmetric: no reflection)
      const auto   mirror = geometry::mirror_dofs(*mapping, dof_handler, 1, radius);
      const double sign[6] = {1, -1, 1, -1, 1, -1};
      for (types::global_dof_index i = 0; i < mirror.size(); ++i)
        reflection.emplace_back(mirror[i], sign[dof_component[i]]);
    }

    bool
    PlateRodProblem::project_to_fixed_point_space(Vector<double> &v) const
    {
      if (reflection.empty() || v.size() != reflection.size())
        return false;
      const Vector<double> w = v;
      for (unsigned int i = 0; i < v.size(); ++i)
        v[i] = 0.5 * (w[i] + reflection[i].second * w[reflection[i].first]);
      return true;
    }

    kinematics::PlateGrowthAtPoint
    PlateRodProblem::growth_at(const Point<2> &X, const double t) const
    {
      auto g              = kinematics::PlateGrowthAtPoint::of(plate_growth.value(X, t));
      g.natural_curvature = plate_growth.natural_curvature(X, t);
      return g;
    }

    double
    PlateRodProblem::thickness_at(const Point<2> &X) const
    {
      return thickness_profile ? thickness * thickness_profile->value(Point<3>(X[0], X[1], X.norm())) :
                                 thickness;
    }

    void
    PlateRodProblem::check_plate_fields() const
    {
      // Where the energy is evaluated: the Gauss points of every cell (the assumed shear's tying
      // points lie between them or on the cell's edges, within the cell).
      const QGauss<2>       quadrature(degree + 1);
      FEValues<2>           fev(*mapping, *fe, quadrature, update_quadrature_points);
      std::vector<Point<2>> points;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fev.reinit(cell);
          for (const auto &X : fev.get_quadrature_points())
            {
              points.push_back(X);
              const double h = thickness_at(X);
              if (!(h > 0) || !std::isfinite(h))
                throw io::InputError("Plate", "Thickness profile", thickness_profile_text,
                                     "the thickness must be positive and finite at the "
                                     "quadrature points of the plate (it is " +
                                       std::to_string(h) + " at x = " + std::to_string(X[0]) +
                                       ", y = " + std::to_string(X[1]) + ")");
            }
        }
      plate_growth.check_natural_curvature(points);

      // The plate's and the rim's growth: one check, at every vertex and
      // quadrature point of the mesh (materials/growth_admissibility.h).
      const MPI_Comm comm = distributed_mesh ? MPI_COMM_WORLD : MPI_COMM_SELF;
      plate_growth.check_admissible(
        materials::growth_points(*mapping, triangulation.get(), quadrature,
                                 [](const auto &) { return true; }),
        comm);
      materials::check_growth_admissible(
        materials::boundary_growth_points(*mapping, triangulation.get(), QGauss<1>(degree + 1),
                                          [](const auto &face) {
                                            return face->boundary_id() == rim_id;
                                          }),
        [this](const Point<2> &, const double t) {
          return std::vector<double>{rod_growth_at(t)};
        },
        {"Rim rod", "Growth factor", io::format_number(rod_growth), "the rim's growth factor"},
        comm);
    }

    materials::QuadraticRodLaw
    PlateRodProblem::rod_law() const
    {
      materials::QuadraticRodLaw law;
      law.stiffness = rod_stiffness;
      for (unsigned int i = 0; i < 6; ++i)
        for (unsigned int j = i + 1; j < 6; ++j)
          law.set_coupling(i, j, rod_coupling[i][j]);
      // The model's factor on the shear stiffnesses GA1, GA2 (the Kirchhoff
      // penalty; their couplings by its square root, which keeps K positive).
      for (const unsigned int k : {0u, 1u})
        law.scale_strain(k, model->shear_scale());
      return law;
    }

    // The transverse shear of one cell with assumed covariant strains (fev_full reinit on it):
    // the energy E = sum_q W_q(e(q)) JxW_q, e(q) = sum_k N_qk e_k, depends on the DoFs through
    // the tying points' strains e_k only, so its gradient is sum_k mu_k de_k/dU and its Hessian
    // V M V^T + sum_k mu_k d2e_k/dU2, with mu_k = dE/de_k, M_kl = d2E/de_k de_l, V = de/dU.
    double
    PlateRodProblem::assumed_shear_of_cell(const CellLoopData &        d,
                                           Scratch &                   sc,
                                           assembly::CellContribution &c) const
    {
      const unsigned int dpc = d.dpc, n_tying = d.n_tying, n_locations = d.n_locations;
      const auto &       comp          = d.comp;
      const auto &       assumed_shear = d.assumed_shear;
      const auto &       tying_weights = d.tying_weights;
      const auto &       strains_at    = d.strains_at;
      const double       t = d.t, shear_scale = d.shear_scale;
      const bool         jacobian = d.jacobian;
      sc.prepare_tying(n_locations, n_tying, dpc, jacobian);
      // The fields at each location (e_0 and e_1 share some), then each tied strain.
      for (unsigned int l = 0; l < n_locations; ++l)
        {
          auto &drives = sc.tying_drives[l];
          drives.resize(dpc);
          for (unsigned int i = 0; i < dpc; ++i)
            drives[i] = plate_drive(comp[i], sc.fev_tying.shape_value(i, l),
                                    sc.fev_tying.shape_grad(i, l));
          sc.tying_z[l].fill(0.);
          assembly::gather_local_variables<n_plate>(drives, sc.U_local, sc.tying_z[l]);
        }
      // Location by location: the strains tied at one location follow each other, so that
      // the model's shear derivatives can reuse its director there.
      for (unsigned int location = 0; location < n_locations; ++location)
        for (const unsigned int k : strains_at[location])
        {
          const auto &       drives   = sc.tying_drives[location];
          const auto &       z        = sc.tying_z[location];
          const Tensor<2, 2> J        = sc.fev_tying.jacobian(location);
          const unsigned int comp_k   = assumed_shear.component(k);
          // The model's own chain rule if it has one; else nested AD: the
          // shear depends on du/dX and theta, local variables 3 to 10.
          if (nested_ad_only ||
              !model->covariant_shear_strain_derivatives(z, J, comp_k, jacobian, sc.tying_strain[k],
                                                         sc.tying_gradient[k], sc.tying_hessian[k]))
            {
              materials::internal::differentiate_subset<8>(
                z, 3,
                [&](const auto &x) {
                  using Number = std::decay_t<decltype(x[0])>;
                  std::array<Number, n_plate> y;
                  for (unsigned int m = 0; m < n_plate; ++m)
                    y[m] = m >= 3 && m < 11 ? x[m - 3] : Number(z[m]);
                  return kinematics::covariant_shear_strain(y, *model, J, comp_k);
                },
                jacobian, sc.tying_strain[k], sc.tying_gradient[k], sc.tying_hessian[k]);
            }
          for (unsigned int i = 0; i < dpc; ++i)
            {
              double v = 0;
              for (unsigned int p = 0; p < drives[i].n; ++p)
                v += drives[i].w[p] * sc.tying_gradient[k][drives[i].var[p]];
              sc.V(i, k) = v;
            }
        }
      double energy = 0;
      const FEValues<2> &fev = sc.fev_full;
      for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
        {
          std::array<double, 2> e{{0., 0.}};
          for (unsigned int k = 0; k < n_tying; ++k)
            e[assumed_shear.component(k)] += tying_weights(q, k) * sc.tying_strain[k];
          const auto         gr   = growth_at(fev.quadrature_point(q), t);
          const Tensor<2, 2> Kinv = fev.inverse_jacobian(q);
          const auto         law  = plate_law_at(fev.quadrature_point(q));
          double                W = 0;
          std::array<double, 2> dW;
          std::array<double, 4> ddW;
          materials::internal::differentiate<2>(
            e,
            [&](const auto &x) {
              return kinematics::assumed_shear_energy(x, Kinv, gr, law, shear_scale);
            },
            jacobian, W, dW, ddW);
          energy += W * fev.JxW(q);
          for (unsigned int k = 0; k < n_tying; ++k)
            {
              const double a = fev.JxW(q) * tying_weights(q, k);
              sc.mu[k] += a * dW[assumed_shear.component(k)];
              if (jacobian)
                for (unsigned int l = 0; l < n_tying; ++l)
                  sc.M(k, l) += a * tying_weights(q, l) *
                                ddW[2 * assumed_shear.component(k) + assumed_shear.component(l)];
            }
        }
      // sum_k mu_k (de_k/dU, d2e_k/dU2) through the drives, one pass per location (the
      // strains tied there summed), then V M V^T.
      std::array<double, n_plate>           g;
      std::array<double, n_plate * n_plate> H; // (read by add_point only with the Jacobian)
      for (unsigned int l = 0; l < n_locations; ++l)
        {
          g.fill(0.);
          if (jacobian)
            H.fill(0.);
          for (const unsigned int k : strains_at[l])
            {
              for (unsigned int m = 0; m < n_plate; ++m)
                g[m] += sc.mu[k] * sc.tying_gradient[k][m];
              if (jacobian)
                for (unsigned int m = 0; m < n_plate * n_plate; ++m)
                  H[m] += sc.mu[k] * sc.tying_hessian[k][m];
            }
          assembly::add_point<n_plate>(sc.tying_drives[l], g, H, 1., jacobian, c.residual, c.hessian);
        }
      if (jacobian)
        {
          sc.V.mmult(sc.VM, sc.M);
          sc.VM.mTmult(c.hessian, sc.V, true);
        }
      return energy;
    }

    void
    PlateRodProblem::plate_of_cell(const CellLoopData &                         d,
                                   const DoFHandler<2>::active_cell_iterator &cell,
                                   Scratch &                                    sc,
                                   assembly::CellContribution &                 c) const
    {
      const unsigned int dpc  = d.dpc;
      const auto &       comp = d.comp;
      const double       t = d.t, shear_scale = d.shear_scale;
      const bool         jacobian = d.jacobian;
      sc.drives.resize(dpc);
      std::array<double, n_plate>           z, g;
      std::array<double, n_plate * n_plate> H;
      const bool stabilized_shear = shear_integration == ShearIntegration::stabilized;
      for (const bool membrane_bending : {true, false})
        {
          if (!membrane_bending && (shear_integration == ShearIntegration::assumed_strain ||
                                    shear_integration == ShearIntegration::interior_tying))
            {
              c.scalars[0] += assumed_shear_of_cell(d, sc, c);
              continue;
            }
          FEValues<2> &fev =
            membrane_bending || stabilized_shear ? sc.fev_full : sc.fev_reduced;
          const double cell_shear_scale =
            !membrane_bending && stabilized_shear ?
              kinematics::stabilized_shear_scale(thickness_at(cell->center()), shear_scale,
                                                 shear_stabilization,
                                                 cell->diameter()) :
              shear_scale;
          fev.reinit(cell);
          for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
            {
              z.fill(0.);
              for (unsigned int i = 0; i < dpc; ++i)
                sc.drives[i] = plate_drive(comp[i], fev.shape_value(i, q), fev.shape_grad(i, q));
              assembly::gather_local_variables<n_plate>(sc.drives, sc.U_local, z);
              const auto gr  = growth_at(fev.quadrature_point(q), t);
              const auto law = plate_law_at(fev.quadrature_point(q));
              double     W   = 0;
              // The plate energy depends on the gradients of u, on theta and (membrane and
              // bending only) on its gradients: 12 resp. 8 of the 15 local variables are
              // differentiated (the cost of nested AD grows like the square).
              auto energy_of = [&](const auto &x) {
                using Number = std::decay_t<decltype(x[0])>;
                std::array<Number, n_plate> y;
                for (unsigned int k = 0; k < n_plate; ++k)
                  y[k] = k >= 3 && k < 3 + x.size() ? x[k - 3] : Number(z[k]);
                return kinematics::plate_energy(y, gr, law, *model, membrane_bending,
                                                cell_shear_scale);
              };
              // The model's own chain rule if it has one (the Cosserat kinematics).
              if (nested_ad_only ||
                  !model->plate_energy_derivatives(z, gr, law, membrane_bending, cell_shear_scale,
                                                   jacobian, W, g, H))
                {
                  if (membrane_bending)
                    materials::internal::differentiate_subset<12>(z, 3, energy_of, jacobian, W, g, H);
                  else
                    materials::internal::differentiate_subset<8>(z, 3, energy_of, jacobian, W, g, H);
                }
              c.scalars[0] += W * fev.JxW(q);
              assembly::add_point<n_plate>(sc.drives, g, H, fev.JxW(q), jacobian, c.residual,
                                           c.hessian);
            }
        }
    }

    void
    PlateRodProblem::rim_of_cell(const CellLoopData &                         d,
                                 const DoFHandler<2>::active_cell_iterator &cell,
                                 Scratch &                                    sc,
                                 assembly::CellContribution &                 c) const
    {
      const unsigned int dpc      = d.dpc;
      const auto &       comp     = d.comp;
      const auto &       rod      = d.rod;
      const double       g_rod    = d.g_rod;
      const auto &       rim_natural_curvature = d.rim_natural_curvature;
      const bool         jacobian = d.jacobian;
      // The rim rod on the cell's rim faces.
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
          {
            sc.fev_face.reinit(cell, f);
            std::array<double, n_rim>         zr, gr;
            std::array<double, n_rim * n_rim> Hr;
            for (unsigned int q = 0; q < sc.fev_face.n_quadrature_points; ++q)
              {
                const Point<2> X     = sc.fev_face.quadrature_point(q);
                const auto     frame = kinematics::circular_rim_frame(X, sc.fev_face.normal_vector(q));
                const Tensor<1, 2> t2({frame.tangent[0], frame.tangent[1]});
                zr.fill(0.);
                for (unsigned int i = 0; i < dpc; ++i)
                  sc.drives[i] = rim_drive(comp[i], sc.fev_face.shape_value(i, q),
                                           sc.fev_face.shape_grad(i, q) * t2);
                assembly::gather_local_variables<n_rim>(sc.drives, sc.U_local, zr);
                auto law              = rod;
                law.reference_strains = kinematics::rim_reference_strains(X, frame);
                double W              = 0;
                materials::internal::differentiate<n_rim>(
                  zr,
                  [&](const auto &x) {
                    return kinematics::rim_rod_energy(x, frame, law, g_rod, *model,
                                                      rim_natural_curvature);
                  },
                  jacobian, W, gr, Hr);
                c.scalars[1] += W * sc.fev_face.JxW(q);
                assembly::add_point<n_rim>(sc.drives, gr, Hr, sc.fev_face.JxW(q), jacobian,
                                           c.residual, c.hessian);
              }
          }
    }

    int
    PlateRodProblem::assemble(const Vector<double> &U,
                              Vector<double> *      R,
                              const bool            jacobian,
                              double *              energies)
    {
      const QGauss<2>    full(degree + 1), reduced(degree);
      const QGauss<1>    face(degree);
      const CellLoopData data(*this, full, jacobian);
      // The cell's scalars: the plate's energy and the rim's.
      auto worker = [&](const typename DoFHandler<2>::active_cell_iterator &cell,
                        Scratch &                                           sc,
                        assembly::CellContribution &                        c) {
        for (unsigned int i = 0; i < data.dpc; ++i)
          sc.U_local[i] = U[c.dof_indices[i]];
        plate_of_cell(data, cell, sc, c);
        rim_of_cell(data, cell, sc, c);
      };

      // A Jacobian assembly computes the residual at its state as well (the
      // local gradients are at hand): it is kept for the drivers' next request.
      Vector<double> jacobian_residual;
      if (!R)
        R = &jacobian_residual;
      R->reinit(n_unknowns());
      if (jacobian)
        system.clear();
      assembly::AssemblyTarget target;
      target.residual    = R;
      target.jacobian    = jacobian;
      target.system      = &system;
      target.constraints = &constraints;
      const auto totals  = assembly::EnergyAssembler<2>::assemble(
        dof_handler, worker, Scratch(*mapping, *fe, full, reduced, face, data.assumed_shear.tying_points()),
        assembly::CellContribution(data.dpc, 0, 2), target);
      double plate_energy = totals.scalars[0], rod_energy = totals.scalars[1];
      if (distributed_mesh)
        {
          // Every rank holds the whole residual and energies, the same bits on each.
          if (jacobian)
            system.distributed_matrix.compress(VectorOperation::add);
          layout.sum_parts(*R);
          std::vector<double> e = {plate_energy, rod_energy};
          layout.sum(e);
          plate_energy = e[0];
          rod_energy   = e[1];
        }
      // Every assembly evaluates the energy: keep it with its state, so that the
      // output of a converged step need not assemble once more.
      assembled_at       = U;
      assembled_load     = load_parameter;
      assembled_energy   = {{plate_energy, rod_energy}};
      residuals.store(U, load_parameter, *R, {plate_energy, rod_energy});
      if (energies)
        {
          energies[0] = plate_energy;
          energies[1] = rod_energy;
        }
      return std::isfinite(plate_energy + rod_energy) ? 0 : 1;
    }

    double
    PlateRodProblem::energy(const Vector<double> &U)
    {
      Vector<double> R;
      AssertThrow(residual(U, R) == 0, ExcMessage("the energy cannot be evaluated at this state"));
      return assembled_energy[0] + assembled_energy[1];
    }

    int
    PlateRodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
      if (const auto *e = residuals.find(U, load_parameter))
        {
          R                = e->R;
          assembled_at     = U;
          assembled_load   = load_parameter;
          assembled_energy = {{e->scalars[0], e->scalars[1]}};
          return std::isfinite(assembled_energy[0] + assembled_energy[1]) ? 0 : 1;
        }
      io::PhaseTimer::Scope scope(timer, "assembly (residual)");
      return assemble(U, &R, false);
    }

    int
    PlateRodProblem::setup_jacobian(const Vector<double> &U)
    {
      {
        io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
        if (assemble(U, nullptr, true) != 0)
          return 1;
      }
      io::PhaseTimer::Scope scope(timer, "factorization");
      try
        {
          system.factorize();
        }
      catch (std::exception &e)
        {
          // (on a distributed mesh only MUMPS's own failure is every rank's:
          // anything else ends this rank, and so all)
          if (distributed_mesh && dynamic_cast<const solvers::FactorizationFailure *>(&e) == nullptr)
            throw;
          factorized_at.reinit(0);
          say(std::string("  factorization failed: ") + e.what());
          return 1;
        }
      factorized_at   = U;
      factorized_load = load_parameter;
      return 0;
    }

    int
    PlateRodProblem::solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst)
    {
      io::PhaseTimer::Scope scope(timer, "solve");
      system.solve(rhs, dst, {});
      constraints.distribute(dst);
      // (each rank set the slaves it knows: everyone takes them from their owners)
      layout.take_from_owners(dst);
      return 0;
    }

    double
    PlateRodProblem::jacobian_abs_form(const Vector<double> &v) const
    {
      return system.absolute_quadratic_form(v);
    }

    void
    PlateRodProblem::mode_mask(Vector<double> &mask) const
    {
      // A constrained DoF's value follows from its masters: it carries no
      // independent part of a mode. Above all the border of the critical-point
      // system must vanish there: the solve returns J^-1 on the constrained
      // space only for right-hand sides with no slave entries, and a border
      // with them made the bordered test function g unsymmetric, its
      // derivative -v.dJ v wrong by ~3 % and Newton linear (rate 0.026,
      // measured on the sector) instead of quadratic.
      mask.reinit(n_unknowns());
      mask = 1.;
      for (unsigned int i = 0; i < mask.size(); ++i)
        if (dof_constrained[i])
          mask[i] = 0;
    }

    void
    PlateRodProblem::complete_mode(Vector<double> &v) const
    {
      // Every constraint here is homogeneous (mirror planes, in-plane only,
      // gauges): distribute() sets the slaves from their masters and adds nothing.
      constraints.distribute(v);
      layout.take_from_owners(v);
    }

    double
    PlateRodProblem::constraint_violation(const Vector<double> &U) const
    {
      double v = 0;
      for (const auto &line : constraints.get_lines())
        {
          double r = U[line.index] - line.inhomogeneity;
          for (const auto &entry : line.entries)
            r -= entry.second * U[entry.first];
          v = std::max(v, std::abs(r));
        }
      return distributed_mesh ? Utilities::MPI::max(v, MPI_COMM_WORLD) : v;
    }

    void
    PlateRodProblem::residual_weights(Vector<double> &w) const
    {
      // Nodal forces against E h R, nodal moments against E h R^2.
      const double F = plate_law.young * thickness * radius;
      w.reinit(n_unknowns());
      for (unsigned int i = 0; i < w.size(); ++i)
        w[i] = dof_component[i] < 3 ? 1 / F : 1 / (F * radius);
    }

    double
    PlateRodProblem::mismatch(const double t) const
    {
      // Uniform isotropic plate growth only: g_r = g_t independent of r.
      const auto g0 = plate_growth.factors(0, t);
      for (unsigned int i = 0; i <= 10; ++i)
        {
          const auto g = plate_growth.factors(radius * i / 10., t);
          if (std::abs(g[0] - g0[0]) > 1e-14 || std::abs(g[1] - g0[0]) > 1e-14)
            return std::numeric_limits<double>::quiet_NaN();
        }
      return analysis::growth_mismatch(g0[0], rod_growth_at(t));
    }

    void
    PlateRodProblem::solve_flat_state(const double t)
    {
      set_load_parameter(t);
      solvers::newton_solve(*this, solution, newton_settings);
    }

    std::vector<solvers::EventRecord>
    PlateRodProblem::follow_branches()
    {
      solvers::ArclengthContinuation driver(arclength_settings, newton_settings);
      driver.progress = [this](const std::string &s) { say(s); };
      if (write_output)
        {
          if (record.has_checkpoint())
            {
              driver.load(record.checkpoint());
              load_progress(record.checkpoint());
            }
          // After every converged step: the driver's state and what is written so far.
          driver.checkpoint = [this, &driver]() {
            io::PhaseTimer::Scope scope(timer, "checkpoint");
            io::CheckpointWriter  w;
            driver.save(w);
            save_progress(w);
            record.write_checkpoint(w);
          };
        }
      return driver.run(*this, solution, load_parameter);
    }

    void
    PlateRodProblem::locate_from_guess()
    {
      solvers::ArclengthContinuation driver(arclength_settings, newton_settings);
      driver.progress = [this](const std::string &s) { say(s); };
      const auto record = solvers::locate_continued_critical_point(driver, *this, *critical_guess,
                                                                  newton_settings);
      solution = Vector<double>(record.state.begin(), record.state.end());
      // The report below takes the inertia and smallest eigenvalue from the
      // last factorization, of the last Newton iterate: it differs from the
      // located state by the last update (critical_point.h), on which neither
      // depends beyond the located precision; not factorizing again is what
      // the continued point saves.
      report_with_last_factorization = true;
      solvers::StepReport report;
      report.t          = record.event.lambda;
      report.n_negative = record.event.n_negative_after;
      set_load_parameter(report.t);
      converged_step(solution, report);
    }

    void
    PlateRodProblem::say_discretization() const
    {
      std::ostringstream info;
      info << "  " << model->name() << " model, R = " << radius << ", h = " << thickness
           << " (h/R = " << thickness / radius << "), "
           << (domain == "sector" ? "sector pi/" + std::to_string(sector_n) : std::string("full disc"))
           << ", " << triangulation.get().n_global_active_cells() << " cells, Q" << degree << ", "
           << dof_handler.n_dofs() << " DoFs ("
           << std::count(dof_constrained.begin(), dof_constrained.end(), 1)
           << " constrained), estimated peak memory "
           << io::format_bytes(io::estimated_memory(dof_handler.n_dofs(), degree));
      if (distributed_mesh)
        info << ", the mesh distributed over " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
             << (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 ? " rank" : " ranks");
      say(info.str());
      if (!stiffness_file.empty())
        {
          std::ostringstream m;
          m << "  rim stiffness from " << stiffness_file << ", the full 6x6: diagonal";
          for (const double k : rod_stiffness)
            m << " " << k;
          m << ", largest coupling K_ab / sqrt(K_aa K_bb) = " << stiffness_coupling;
          if (stiffness_coupling > 0)
            m << " (the closed forms below use the diagonal only)";
          say(m.str());
        }

    }

    void
    PlateRodProblem::add_steps_columns()
    {
      for (const auto &c : {"step", "branch", "t", "mismatch", "plate_growth_rim", "rod_growth",
                            "newton_iterations"})
        steps_table.add_column(c);
      steps_table.add_column("energy");
      steps_table.add_column("plate_energy");
      steps_table.add_column("rod_energy");
      steps_table.add_column("dome_height");
      steps_table.add_column("w_range");
      steps_table.add_column("max_inplane_displacement");
      steps_table.add_column("rim_radial_strain");
      // The mode numbers the domain admits: 0, n, ..., 8 n on a sector pi/n.
      for (unsigned int k = 0; k < n_modes; ++k)
        steps_table.add_column("rim_w_" + std::to_string(k * sector_step()));
      for (unsigned int k = 0; k < n_modes; ++k)
        steps_table.add_column("rim_ur_" + std::to_string(k * sector_step()));
      steps_table.add_column("n_negative_eigenvalues");
      steps_table.add_column("smallest_eigenvalue");
    }

    void
    PlateRodProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      write_output = true;
      solvers::start_run(record, *this, options, prm, output_directory, distributed_mesh);
      plate_series = std::make_unique<io::PathCollections>(output_directory, "plate");
      rim_series   = std::make_unique<io::PathCollections>(output_directory, "rim");
      setup_system();
      say_discretization();

      // The closed forms (Kirchhoff, small strain, uniform isotropic growth).
      double             first_closed = NAN;
      std::string        closed_text;
      const io::JSON     closed = closed_forms(first_closed, closed_text);
      if (!closed_text.empty())
        say(closed_text);

      add_steps_columns();

      record.attempt([&]() {
        if (critical_guess)
          return locate_from_guess();
        if (record.has_checkpoint())
          {
            follow_branches();
            return;
          }
        set_load_parameter(path_start);
        try
          {
            solve_flat_state(path_start);
          }
        catch (solvers::NewtonFailure &e)
          {
            throw io::RunFailure(std::string("the flat state at the start did not converge: ") +
                                 e.what());
          }
        if (setup_jacobian(solution) == 0 && n_negative_eigenvalues() > 0)
          throw io::InputError(
            "Growth path", "Start", std::to_string(path_start),
            "the flat state there is already unstable (" +
              std::to_string(n_negative_eigenvalues()) +
              " negative eigenvalues) and no initial guess of a buckled state can be given: "
              "start the path below the first critical growth (t = 0 always is)");
        follow_branches();
      });
      finish_run(closed);
    }

    void
    run_plate_rod(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
      sweep.refuse_distributed_mesh(prm, "Mesh");
      if (sweep.enabled())
        {
          solvers::CriticalPointStudy study;
          study.application        = "plate_rod";
          study.arclength_sections = false; // its own 'Growth path / Stop at first event'
          study.mode_columns    = {"mode_number", "mode_out_of_plane"};
          study.further_columns = {"mismatch_critical", "closed_form_mismatch"};
          study.describe_mode   = [](const std::vector<double> &c) {
            std::ostringstream m;
            m << "n = " << c[0] << (c[1] == 1 ? " out of plane" : c[1] == 0 ? " planar" : "");
            return m.str();
          };
          study.make_run = [](ParameterHandler &p) {
            return std::make_unique<solvers::CriticalPointRunOf<PlateRodProblem>>(p);
          };
          return solvers::run_critical_point_study(prm, options, sweep, study);
        }
      PlateRodProblem problem;
      problem.parse_parameters(prm);
      // A distributed mesh: every rank runs the path on its part of the mesh.
      if (io::ranks::idle(problem.mesh_is_distributed()))
        return;
      if (problem.mesh_is_distributed() && io::ranks::size() > 1)
        io::collective_interrupts(MPI_COMM_WORLD);
      problem.run(options, prm);
    }
  } // namespace plate_rod
} // namespace cosmo

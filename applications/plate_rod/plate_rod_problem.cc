// The plate and rim energies are differentiated here (Sacado, 15 and 12
// local variables): the heavy translation unit of part 3.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/config.h>
#include <cosmo/geometry/mirror_dofs.h>
#include <cosmo/io/parameter_sweep.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/materials/energy_derivatives.h>

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

      /// Rim boundary id; the mirror edges of a sector are 1 (theta = 0) and 2 (theta = pi/n).
      constexpr types::boundary_id rim_id = 0, mirror_first = 1, mirror_second = 2;

      /// Which local variables a shape function drives and with what weight.
      struct Drive
      {
        unsigned int n = 0;
        unsigned int var[3];
        double       w[3];
      };

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

      struct Scratch
      {
        Scratch(const Mapping<2> &     mapping,
                const FiniteElement<2> &fe,
                const Quadrature<2> &   full,
                const Quadrature<2> &   reduced,
                const Quadrature<1> &   face)
          : fev_full(mapping, fe, full,
                     update_values | update_gradients | update_quadrature_points | update_JxW_values)
          , fev_reduced(mapping, fe, reduced,
                        update_values | update_gradients | update_quadrature_points |
                          update_JxW_values)
          , fev_face(mapping, fe, face,
                     update_values | update_gradients | update_quadrature_points |
                       update_JxW_values | update_normal_vectors)
          , U_local(fe.n_dofs_per_cell())
        {}
        Scratch(const Scratch &o)
          : Scratch(o.fev_full.get_mapping(), o.fev_full.get_fe(), o.fev_full.get_quadrature(),
                    o.fev_reduced.get_quadrature(), o.fev_face.get_quadrature())
        {}
        FEValues<2>         fev_full, fev_reduced;
        FEFaceValues<2>     fev_face;
        std::vector<double> U_local;
        std::vector<Drive>  drives;
      };

      struct Copy
      {
        explicit Copy(const unsigned int dpc)
          : idx(dpc)
          , r(dpc)
          , K(dpc, dpc)
        {}
        std::vector<types::global_dof_index> idx;
        Vector<double>                       r;
        FullMatrix<double>                   K;
        double                               plate_energy = 0, rod_energy = 0;
      };

      /// Add the contribution of one quadrature point: W, gradient g and Hessian H of the
      /// energy density in the local variables, the shape functions' drives.
      template <int N>
      void
      add_point(const std::vector<Drive> &      drives,
                const std::array<double, N> &   g,
                const std::array<double, N * N> &H,
                const double                     dA,
                const bool                       jacobian,
                Copy &                           c)
      {
        const unsigned int n = drives.size();
        for (unsigned int i = 0; i < n; ++i)
          {
            const Drive &a = drives[i];
            double       s = 0;
            for (unsigned int p = 0; p < a.n; ++p)
              s += g[a.var[p]] * a.w[p];
            c.r[i] += s * dA;
          }
        if (!jacobian)
          return;
        // K += B H B^T dA with B the (sparse) drives: first B H, then the
        // upper triangle of (B H) B^T, mirrored (H is symmetric).
        thread_local std::vector<std::array<double, N>> BH;
        BH.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            const Drive &a = drives[i];
            for (int b = 0; b < N; ++b)
              {
                double s = 0;
                for (unsigned int p = 0; p < a.n; ++p)
                  s += a.w[p] * H[N * a.var[p] + b];
                BH[i][b] = s * dA;
              }
          }
        for (unsigned int i = 0; i < n; ++i)
          {
            if (drives[i].n == 0)
              continue;
            for (unsigned int j = i; j < n; ++j)
              {
                const Drive &b = drives[j];
                double       k = 0;
                for (unsigned int q = 0; q < b.n; ++q)
                  k += BH[i][b.var[q]] * b.w[q];
                c.K(i, j) += k;
                if (j != i)
                  c.K(j, i) += k;
              }
          }
      }
    } // namespace

    PlateRodProblem::PlateRodProblem() = default;
    PlateRodProblem::~PlateRodProblem()
    {
      dof_handler.clear();
    }

    void
    PlateRodProblem::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate");
      prm.declare_entry("Radius", "1", Patterns::Double(0), "Radius R of the disc.");
      prm.declare_entry("Thickness", "0.01", Patterns::Double(0),
                        "Thickness h of the plate (h < R).");
      prm.leave_subsection();
      materials::NaghdiPlateLaw::declare_parameters(prm);
      materials::PlateGrowth::declare_parameters(prm);
      prm.enter_subsection("Rim rod");
      prm.declare_entry("Stiffnesses", "0.1, 0.1, 0.1, 1e-6, 1e-6, 1e-6",
                        Patterns::List(Patterns::Double(0), 6, 6),
                        "GA1, GA2, EA, EI1, EI2, GJ of the rim's cross-section (d1 radial, d2 "
                        "the plate normal, d3 the tangent): shear along d1, d2, extension, "
                        "bending about d1 (out of plane), about d2 (in plane), torsion. E.g. the "
                        "diagonal of a rod_cross_section stiffness.");
      prm.declare_entry("Stiffness file", "", Patterns::Anything(),
                        "If set: a rod_cross_section summary.json whose 6x6 'stiffness' gives "
                        "the rim's stiffnesses (its diagonal; the section's X1 is the rim's "
                        "radial axis d1, X2 the plate normal d2); replaces 'Stiffnesses'. The "
                        "largest dropped off-diagonal coupling is logged.");
      prm.declare_entry("Growth factor", "1", Patterns::Double(0),
                        "Axial growth g of the rim at t = 1 (ramped as 1 + t (g - 1)); the "
                        "stress-free rim is a ring of radius g R.");
      prm.leave_subsection();
      prm.enter_subsection("Model");
      using Models = plugins::Registry<kinematics::PlateModel>;
      prm.declare_entry("Model", "cosserat", Patterns::Selection(Models::names()),
                        "The plate model (the registered models, "
                        "source/kinematics/plate_models/). " + Models::documentation());
      Models::declare_parameters(prm);
      prm.declare_entry("Shear integration", "automatic",
                        Patterns::Selection("automatic|stabilized|reduced"),
                        "Transverse shear of the plate. stabilized: full Gauss integration with "
                        "the shear stiffness times t^2/(t^2 + alpha h_K^2) (h_K the cell "
                        "diameter; t^2 divided by the penalty in the kirchhoff model): "
                        "locking-free and free of spurious modes; reduced: p Gauss points "
                        "(Q2 then has a spurious transverse mode with little shear energy, "
                        "which membrane compression destabilizes on fine meshes: measured at "
                        "h_K ~ 3 h; the kirchhoff penalty keeps it far away); automatic: "
                        "reduced for kirchhoff, stabilized otherwise.");
      prm.declare_entry("Shear stabilization", "0.03", Patterns::Double(0),
                        "alpha of the stabilized shear integration (0.03: the smallest "
                        "threshold errors on coarse meshes, doc/theory-plate-rod.md).");
      prm.leave_subsection();
      prm.enter_subsection("Mesh");
      prm.declare_entry("Domain", "full disc", Patterns::Selection("full disc|sector"),
                        "full disc, or the sector 0 <= theta <= Sector angle with mirror "
                        "conditions on both radial edges (keeps the modes cos(k n theta)).");
      prm.declare_entry("Sector angle", "90", Patterns::Double(0, 360),
                        "Sector angle in degrees: 180/n for an integer n >= 1.");
      prm.declare_entry("Global refinements", "3", Patterns::Integer(0, 8),
                        "Refinements of the coarse disc (5 cells) or sector (3 cells).");
      prm.declare_entry("Polynomial degree", "2", Patterns::Integer(2, 4),
                        "Degree p of FE_Q(p) for all fields and of the mapping of the rim; "
                        "shear terms and the rod are integrated with p Gauss points.");
      prm.leave_subsection();
      prm.enter_subsection("Growth path");
      prm.declare_entry("Start", "0", Patterns::Double(0, 1),
                        "Load parameter t where the path starts (growth is ramped from "
                        "t = 0, none, to t = 1, the factors given); the flat state there "
                        "must be stable.");
      prm.declare_entry("Stop at first event", "false", Patterns::Bool(),
                        "Stop where the first change of stability is located (critical "
                        "growth only: studies, quick checks); the same as 'Arclength "
                        "continuation / Stop at first event'.");
      prm.leave_subsection();
      io::ParameterSweep::declare_parameters(prm);
      solvers::NewtonSettings::declare_parameters(prm);
      solvers::ArclengthSettings::declare_parameters(prm);
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory", "output/plate_rod", Patterns::Anything(),
                        "Directory for parameters.prm, summary.json, steps.csv, plate.pvd, "
                        "rim.pvd with their VTU files, event VTUs and log.txt.");
      prm.leave_subsection();
    }

    void
    PlateRodProblem::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Plate");
      radius    = prm.get_double("Radius");
      thickness = prm.get_double("Thickness");
      if (!(radius > 0))
        throw io::InputError("Plate", "Radius", prm.get("Radius"), "must be positive");
      if (!(thickness > 0) || !(thickness < radius))
        throw io::InputError("Plate", "Thickness", prm.get("Thickness"),
                             "must be positive and smaller than the radius " +
                               prm.get("Radius"));
      prm.leave_subsection();
      plate_law.parse_parameters(prm);
      plate_law.thickness = thickness;
      plate_growth.parse_parameters(prm);

      prm.enter_subsection("Rim rod");
      const auto k = io::get_double_list(prm, "Stiffnesses", 6, "Rim rod");
      std::copy(k.begin(), k.end(), rod_stiffness.begin());
      stiffness_file = prm.get("Stiffness file");
      if (!stiffness_file.empty())
        {
          // The part-1 summary.json: "stiffness": [[6 numbers], ... 6 rows].
          std::ifstream in(stiffness_file);
          if (!in)
            throw io::InputError("Rim rod", "Stiffness file", stiffness_file,
                                 "a readable rod_cross_section summary.json (cannot open it)");
          std::stringstream buffer;
          buffer << in.rdbuf();
          std::vector<double> K; // the finite numbers of "stiffness", row by row
          std::size_t         rows = 0, non_square = 0;
          try
            {
              const io::JSON  summary = io::JSON::parse(buffer.str());
              const io::JSON *k       = summary.find("stiffness");
              if (k && k->is_array())
                for (rows = 0; rows < k->size(); ++rows)
                  {
                    non_square += k->at(rows).size() != 6;
                    for (std::size_t b = 0; b < k->at(rows).size(); ++b)
                      if (std::isfinite(k->at(rows).at(b).as_number()))
                        K.push_back(k->at(rows).at(b).as_number());
                  }
            }
          catch (std::runtime_error &e)
            {
              throw io::InputError("Rim rod", "Stiffness file", stiffness_file,
                                   "a rod_cross_section summary.json (" + std::string(e.what()) +
                                     ")");
            }
          if (K.size() != 36 || rows != 6 || non_square > 0)
            throw io::InputError("Rim rod", "Stiffness file", stiffness_file,
                                 "a rod_cross_section summary.json with a 6x6 \"stiffness\" of "
                                 "finite numbers (found " + std::to_string(K.size()) +
                                 " numbers in " + std::to_string(rows) + " rows)");
          double coupling = 0;
          for (unsigned int a = 0; a < 6; ++a)
            {
              rod_stiffness[a] = K[7 * a];
              for (unsigned int b = 0; b < 6; ++b)
                if (a != b)
                  coupling = std::max(coupling, std::abs(K[6 * a + b]) /
                                                  std::sqrt(std::abs(K[7 * a] * K[7 * b])));
            }
          stiffness_coupling = coupling;
        }
      rod_growth = prm.get_double("Growth factor");
      if (!(rod_growth > 0))
        throw io::InputError("Rim rod", "Growth factor", prm.get("Growth factor"),
                             "must be positive");
      // The rim against the plate: beyond 1e8 times the plate's own stiffness
      // the coupled Hessian loses every digit of the plate's contribution in
      // double precision (the rigid limit is reached to 1e-8 long before).
      const double Eh = plate_law.young * thickness;
      const double D  = Eh * thickness * thickness / (12 * (1 - plate_law.poisson * plate_law.poisson));
      const char * names[6] = {"GA1", "GA2", "EA", "EI1", "EI2", "GJ"};
      for (unsigned int i = 0; i < 6; ++i)
        {
          const double scale = i < 3 ? Eh * radius : D * radius;
          if (!(rod_stiffness[i] > 0))
            throw io::InputError("Rim rod", "Stiffnesses", prm.get("Stiffnesses"),
                                 std::string("every stiffness must be positive (") + names[i] +
                                   " is not)");
          if (rod_stiffness[i] > 1e8 * scale)
            {
              std::ostringstream m;
              m << names[i] << " = " << rod_stiffness[i] << " is " << rod_stiffness[i] / scale
                << " times the plate's " << (i < 3 ? "E h R" : "D R")
                << ": stiffer than representable next to the plate in double precision (at "
                   "most 1e8 times); a rim 1e6 times stiffer is already rigid to 1e-6";
              throw io::InputError("Rim rod", "Stiffnesses", prm.get("Stiffnesses"), m.str());
            }
        }
      prm.leave_subsection();

      prm.enter_subsection("Model");
      const std::string m = prm.get("Model");
      model = plugins::Registry<kinematics::PlateModel>::create(m);
      model->parse_parameters(prm);
      stabilized_shear = prm.get("Shear integration") == "stabilized" ||
                         (prm.get("Shear integration") == "automatic" &&
                          !model->automatic_reduced_shear());
      shear_stabilization = prm.get_double("Shear stabilization");
      prm.leave_subsection();

      prm.enter_subsection("Mesh");
      domain = prm.get("Domain");
      {
        const double angle = prm.get_double("Sector angle");
        const double n     = 180. / angle;
        if (!(angle > 0) || std::abs(n - std::round(n)) > 1e-6 * n || std::round(n) < 1)
          throw io::InputError("Mesh", "Sector angle", prm.get("Sector angle"),
                               "the sector must be pi/n: 180/n degrees for an integer n >= 1 "
                               "(180, 90, 60, 45, 36, 30, ...)");
        sector_n = static_cast<unsigned int>(std::round(n));
      }
      refinements = prm.get_integer("Global refinements");
      if (domain == "full disc" && refinements == 0)
        throw io::InputError("Mesh", "Global refinements", "0",
                             "at least 1 for the full disc (its coarse mesh has no vertex at the "
                             "centre for the gauge conditions)");
      degree      = prm.get_integer("Polynomial degree");
      prm.leave_subsection();

      prm.enter_subsection("Growth path");
      path_start          = prm.get_double("Start");
      stop_at_first_event = prm.get_bool("Stop at first event");
      prm.leave_subsection();
      newton_settings.parse_parameters(prm);
      arclength_settings.parse_parameters(prm);
      arclength_settings.enabled = true; // the plate is always followed by arclength
      // 'Growth path / Stop at first event' is the library's entry under the
      // plate's name: either stops the first branch at its first event.
      arclength_settings.stop_at_first_event =
        arclength_settings.stop_at_first_event || stop_at_first_event;
      prm.enter_subsection("Output");
      output_directory = prm.get("Output directory");
      prm.leave_subsection();

      // Growth must stay positive along the path.
      prm.enter_subsection("Plate growth");
      const std::string radial_text = prm.get("Radial growth factor"),
                        circumferential_text = prm.get("Circumferential growth factor");
      prm.leave_subsection();
      for (const double t : {0., 1.})
        for (unsigned int i = 0; i <= 20; ++i)
          {
            const auto g = plate_growth.factors(radius * i / 20., t);
            if (!(g[0] > 0) || !(g[1] > 0))
              throw io::InputError("Plate growth",
                                   g[0] > 0 ? "Circumferential growth factor" : "Radial growth factor",
                                   g[0] > 0 ? circumferential_text : radial_text,
                                   "growth factors must be positive for 0 <= r <= R (not at r = " +
                                     std::to_string(radius * i / 20.) + ")");
          }
    }

    void
    PlateRodProblem::make_mesh()
    {
      triangulation.clear();
      const bool sector = domain == "sector";
      if (sector && sector_n == 1)
        {
          // The half disc y >= 0 (half_hyper_ball is x >= 0): no degenerate apex cell.
          GridGenerator::half_hyper_ball(triangulation, Point<2>(), radius);
          GridTools::rotate(M_PI / 2, triangulation);
        }
      else if (sector)
        GridGenerator::quarter_hyper_ball(triangulation, Point<2>(), radius);
      else
        GridGenerator::hyper_ball(triangulation, Point<2>(), radius);
      triangulation.refine_global(refinements);
      if (sector && sector_n > 2)
        {
          // Stretch the quarter disc in angle onto [0, pi/n]: circles stay circles.
          const double s = 2. / sector_n;
          GridTools::transform(
            [s](const Point<2> &p) {
              const double r = p.norm(), a = std::atan2(p[1], p[0]);
              return Point<2>(r * std::cos(s * a), r * std::sin(s * a));
            },
            triangulation);
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

    void
    PlateRodProblem::make_constraints()
    {
      constraints.clear();
      const bool sector = domain == "sector";
      // The apex: no translation, director E3 (the gauge of the full disc; on a sector with
      // n >= 2 the mirrors imply all but u3 = 0, the one gauge left there).
      for (const auto &cell : dof_handler.active_cell_iterators())
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
          // Mirror planes with normal m: m.u = 0 and theta parallel to m (m.d = 0).
          const double phi = M_PI / sector_n, c = std::cos(phi), s = std::sin(phi);
          std::vector<types::global_dof_index> fd(fe->n_dofs_per_face());
          auto constrain = [this](const types::global_dof_index slave,
                                  const types::global_dof_index master,
                                  const double                  w) {
            if (constraints.is_constrained(slave))
              return;
            constraints.add_line(slave);
            if (master != numbers::invalid_dof_index && w != 0)
              constraints.add_entry(slave, master, w);
          };
          for (const auto &cell : dof_handler.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  (cell->face(f)->boundary_id() == mirror_first ||
                   cell->face(f)->boundary_id() == mirror_second))
                {
                  cell->face(f)->get_dof_indices(fd);
                  std::map<unsigned int, std::array<types::global_dof_index, 6>> nodes;
                  for (unsigned int i = 0; i < fd.size(); ++i)
                    {
                      const auto ci                     = fe->face_system_to_component_index(i);
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
      // alpha lives on the rim: zero elsewhere.
      ComponentMask alpha(6, false);
      alpha.set(5, true);
      const IndexSet all_alpha = DoFTools::extract_dofs(dof_handler, alpha);
      const IndexSet rim_alpha = DoFTools::extract_boundary_dofs(dof_handler, alpha, {rim_id});
      for (const auto i : all_alpha)
        if (!rim_alpha.is_element(i) && !constraints.is_constrained(i))
          constraints.add_line(i);
      constraints.close();
    }

    void
    PlateRodProblem::setup_system()
    {
      make_mesh();
      fe = std::make_unique<FESystem<2>>(FE_Q<2>(degree), 6);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(*fe);
      make_constraints();
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      sparsity.copy_from(dsp);
      matrix.reinit(sparsity);
      solution.reinit(dof_handler.n_dofs());
      dof_component.assign(dof_handler.n_dofs(), 0);
      std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(idx);
          for (unsigned int i = 0; i < idx.size(); ++i)
            dof_component[idx[i]] = fe->system_to_component_index(i).first;
        }
      make_reflection();
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
      return kinematics::PlateGrowthAtPoint::of(plate_growth.value(X, t));
    }

    materials::QuadraticRodLaw
    PlateRodProblem::rod_law() const
    {
      materials::QuadraticRodLaw law;
      law.stiffness = rod_stiffness;
      // The model's factor on the shear stiffnesses GA1, GA2 (the Kirchhoff penalty).
      for (const unsigned int k : {0u, 1u})
        law.stiffness[k] *= model->shear_scale();
      return law;
    }

    int
    PlateRodProblem::assemble(const Vector<double> &U,
                              Vector<double> *      R,
                              const bool            jacobian,
                              double *              energies)
    {
      const unsigned int        dpc = fe->n_dofs_per_cell();
      std::vector<unsigned int> comp(dpc);
      for (unsigned int i = 0; i < dpc; ++i)
        comp[i] = fe->system_to_component_index(i).first;
      const QGauss<2> full(degree + 1), reduced(degree);
      const QGauss<1> face(degree);
      const double    t            = load_parameter;
      const double    g_rod        = rod_growth_at(t);
      const auto      rod          = rod_law();
      const double    shear_scale  = model->shear_scale();

      auto worker = [&](const typename DoFHandler<2>::active_cell_iterator &cell,
                        Scratch &                                           sc,
                        Copy &                                              c) {
        cell->get_dof_indices(c.idx);
        for (unsigned int i = 0; i < dpc; ++i)
          sc.U_local[i] = U[c.idx[i]];
        c.r            = 0;
        c.plate_energy = 0;
        c.rod_energy   = 0;
        if (jacobian)
          c.K = 0;
        sc.drives.resize(dpc);
        std::array<double, n_plate>           z, g;
        std::array<double, n_plate * n_plate> H;
        for (const bool membrane_bending : {true, false})
          {
            FEValues<2> &fev =
              membrane_bending || stabilized_shear ? sc.fev_full : sc.fev_reduced;
            const double cell_shear_scale =
              !membrane_bending && stabilized_shear ?
                kinematics::stabilized_shear_scale(thickness, shear_scale, shear_stabilization,
                                                   cell->diameter()) :
                shear_scale;
            fev.reinit(cell);
            for (unsigned int q = 0; q < fev.n_quadrature_points; ++q)
              {
                z.fill(0.);
                for (unsigned int i = 0; i < dpc; ++i)
                  {
                    sc.drives[i] = plate_drive(comp[i], fev.shape_value(i, q), fev.shape_grad(i, q));
                    for (unsigned int p = 0; p < sc.drives[i].n; ++p)
                      z[sc.drives[i].var[p]] += sc.U_local[i] * sc.drives[i].w[p];
                  }
                const auto gr = growth_at(fev.quadrature_point(q), t);
                double     W  = 0;
                // The plate energy depends on the gradients of u, on theta and (membrane and
                // bending only) on its gradients: 12 resp. 8 of the 15 local variables are
                // differentiated (the cost of nested AD grows like the square).
                auto energy_of = [&](const auto &x) {
                  using Number = std::decay_t<decltype(x[0])>;
                  std::array<Number, n_plate> y;
                  for (unsigned int k = 0; k < n_plate; ++k)
                    y[k] = k >= 3 && k < 3 + x.size() ? x[k - 3] : Number(z[k]);
                  return kinematics::plate_energy(y, gr, plate_law, *model, membrane_bending,
                                                  cell_shear_scale);
                };
                if (membrane_bending)
                  materials::internal::differentiate_subset<12>(z, 3, energy_of, jacobian, W, g, H);
                else
                  materials::internal::differentiate_subset<8>(z, 3, energy_of, jacobian, W, g, H);
                c.plate_energy += W * fev.JxW(q);
                add_point<n_plate>(sc.drives, g, H, fev.JxW(q), jacobian, c);
              }
          }
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
                    {
                      sc.drives[i] = rim_drive(comp[i], sc.fev_face.shape_value(i, q),
                                               sc.fev_face.shape_grad(i, q) * t2);
                      for (unsigned int p = 0; p < sc.drives[i].n; ++p)
                        zr[sc.drives[i].var[p]] += sc.U_local[i] * sc.drives[i].w[p];
                    }
                  auto law              = rod;
                  law.reference_strains = kinematics::rim_reference_strains(X, frame);
                  double W              = 0;
                  materials::internal::differentiate<n_rim>(
                    zr,
                    [&](const auto &x) { return kinematics::rim_rod_energy(x, frame, law, g_rod, *model); },
                    jacobian, W, gr, Hr);
                  c.rod_energy += W * sc.fev_face.JxW(q);
                  add_point<n_rim>(sc.drives, gr, Hr, sc.fev_face.JxW(q), jacobian, c);
                }
            }
      };

      if (R)
        {
          R->reinit(n_unknowns());
        }
      if (jacobian)
        matrix = 0;
      double plate_energy = 0, rod_energy = 0;
      auto   copier = [&](const Copy &c) {
        plate_energy += c.plate_energy;
        rod_energy += c.rod_energy;
        if (R && jacobian)
          constraints.distribute_local_to_global(c.K, c.r, c.idx, matrix, *R);
        else if (R)
          constraints.distribute_local_to_global(c.r, c.idx, *R);
        else if (jacobian)
          constraints.distribute_local_to_global(c.K, c.idx, matrix);
      };
      WorkStream::run(dof_handler.begin_active(), dof_handler.end(), worker, copier,
                      Scratch(*mapping, *fe, full, reduced, face), Copy(dpc));
      // Every assembly evaluates the energy: keep it with its state, so that the
      // output of a converged step need not assemble once more.
      assembled_at       = U;
      assembled_load     = load_parameter;
      assembled_energy   = {{plate_energy, rod_energy}};
      if (energies)
        {
          energies[0] = plate_energy;
          energies[1] = rod_energy;
        }
      return std::isfinite(plate_energy + rod_energy) ? 0 : 1;
    }

    int
    PlateRodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
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
          solver.factorize(matrix);
        }
      catch (std::exception &e)
        {
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
      dst = rhs;
      solver.solve(dst);
      constraints.distribute(dst);
      return 0;
    }

    double
    PlateRodProblem::jacobian_abs_form(const Vector<double> &v) const
    {
      return solvers::absolute_quadratic_form(matrix, v);
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
        if (constraints.is_constrained(i))
          mask[i] = 0;
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

    PlateRodState
    PlateRodProblem::analyse(const Vector<double> &U, const unsigned int n_modes) const
    {
      PlateRodState s;
      s.t = load_parameter;
      s.rim_w_amplitude.assign(n_modes, 0.);
      s.rim_ur_amplitude.assign(n_modes, 0.);
      const bool sector = domain == "sector";
      // Fourier coefficients of w and u_r on the rim in the polar angle, for
      // the mode numbers m = k step the domain admits (step = n on a sector
      // pi/n: the mirror-symmetric extension has only those).
      const unsigned int  step = sector_step();
      std::vector<double> aw(n_modes), bw(n_modes), ar(n_modes), br(n_modes);
      const QGauss<1>     face(degree + 1);
      FEFaceValues<2>     fev(*mapping, *fe, face, update_values | update_quadrature_points | update_JxW_values);
      std::vector<Vector<double>> values(face.size(), Vector<double>(6));
      double              ur_mean = 0, length = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
            {
              fev.reinit(cell, f);
              fev.get_function_values(U, values);
              for (unsigned int q = 0; q < face.size(); ++q)
                {
                  const Point<2> X  = fev.quadrature_point(q);
                  const double   r  = X.norm(), a = std::atan2(X[1], X[0]);
                  const double   da = fev.JxW(q) / r;
                  const double   w  = values[q][2];
                  const double   ur = (values[q][0] * X[0] + values[q][1] * X[1]) / r;
                  ur_mean += ur * fev.JxW(q);
                  length += fev.JxW(q);
                  for (unsigned int k = 0; k < n_modes; ++k)
                    {
                      const double m = double(k * step);
                      aw[k] += w * std::cos(m * a) * da;
                      bw[k] += w * std::sin(m * a) * da;
                      ar[k] += ur * std::cos(m * a) * da;
                      br[k] += ur * std::sin(m * a) * da;
                    }
                }
            }
      const double span = sector ? M_PI / sector_n : 2 * M_PI;
      for (unsigned int k = 0; k < n_modes; ++k)
        {
          const double f = (k == 0 ? 1. : 2.) / span;
          s.rim_w_amplitude[k]  = f * (sector ? std::abs(aw[k]) : std::hypot(aw[k], bw[k]));
          s.rim_ur_amplitude[k] = f * (sector ? std::abs(ar[k]) : std::hypot(ar[k], br[k]));
        }
      s.rim_radial_strain = ur_mean / length / radius;
      // The apex carries w = 0 (gauge): the dome height is minus the rim's mean w.
      s.w_centre = -aw[0] / span;
      double wmin = 0, wmax = 0;
      for (unsigned int i = 0; i < U.size(); ++i)
        if (dof_component[i] == 2)
          wmin = std::min(wmin, U[i]), wmax = std::max(wmax, U[i]);
      s.max_abs_w = wmax - wmin;
      // The in-plane displacement at every node: u1 and u2 of the same support point.
      std::vector<types::global_dof_index> idx(fe->n_dofs_per_cell());
      const unsigned int                   nodes = fe->base_element(0).n_dofs_per_cell();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(idx);
          for (unsigned int k = 0; k < nodes; ++k)
            s.max_abs_inplane =
              std::max(s.max_abs_inplane, std::hypot(U[idx[fe->component_to_system_index(0, k)]],
                                                     U[idx[fe->component_to_system_index(1, k)]]));
        }
      return s;
    }

    std::pair<unsigned int, bool>
    PlateRodProblem::classify_mode(const Vector<double> &mode) const
    {
      // Mode numbers up to what the rim resolves: one per rim face over the full circle
      // (beyond, the Fourier amplitudes of the sampled rim alias).
      unsigned int rim_faces = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
            ++rim_faces;
      const unsigned int full_circle = rim_faces * (domain == "sector" ? 2 * sector_n : 1);
      const auto         s = analyse(mode, std::max(2u, full_circle / sector_step() + 1));
      // Half the range of w (a mode's w is measured from the apex) against the largest
      // in-plane displacement.
      const bool   out = 0.5 * s.max_abs_w > s.max_abs_inplane;
      const auto & a   = out ? s.rim_w_amplitude : s.rim_ur_amplitude;
      unsigned int k   = 0;
      for (unsigned int j = 1; j < a.size(); ++j)
        if (a[j] > a[k])
          k = j;
      return {k * sector_step(), out};
    }

    analysis::PlateRod
    PlateRodProblem::closed_form_setting() const
    {
      analysis::PlateRod p;
      p.radius    = radius;
      p.thickness = thickness;
      p.young     = plate_law.young;
      p.poisson   = plate_law.poisson;
      p.rod_EA    = rod_stiffness[2];
      p.rod_EI1   = rod_stiffness[3];
      p.rod_EI2   = rod_stiffness[4];
      p.rod_GJ    = rod_stiffness[5];
      return p;
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
    PlateRodProblem::converged_step(const Vector<double> &U, const solvers::StepReport &report)
    {
      solution = U;
      load_parameter = report.t;
      PlateRodState s = analyse(U);
      s.n_negative    = report.n_negative;
      s.branch        = report.branch;
      auto same_state = [&](const Vector<double> &V, const double load) {
        return V.size() == U.size() && load == load_parameter &&
               std::equal(U.begin(), U.end(), V.begin());
      };
      // The driver has just factorized at this state, unless it located an event since.
      if (!report_with_last_factorization && !same_state(factorized_at, factorized_load))
        setup_jacobian(U);
      report_with_last_factorization = false;
      if (!same_state(assembled_at, assembled_load))
        {
          Vector<double> R;
          assemble(U, &R, false);
        }
      s.plate_energy = assembled_energy[0];
      s.rod_energy   = assembled_energy[1];
      {
        io::PhaseTimer::Scope scope(timer, "stability (smallest eigenvalue)");
        Vector<double>        mask, mode;
        mode_mask(mask);
        s.smallest_eigenvalue = solvers::smallest_eigenvalue(*this, mask, mode, 30);
      }
      states.push_back(s);
      std::ostringstream line;
      line << "step " << std::setw(3) << report.step << "  branch " << report.branch
           << "  t = " << std::setprecision(8) << std::setw(10) << report.t << "  Delta = "
           << std::setprecision(5) << mismatch(report.t) << "  Newton " << report.newton_iterations
           << "  dome " << std::setprecision(4) << s.w_centre << "  neg.eig. " << s.n_negative
           << "  min|eig| " << std::setprecision(3) << s.smallest_eigenvalue;
      say(line.str());
      if (!write_output)
        return;
      io::PhaseTimer::Scope scope(timer, "output");
      std::vector<double> row = {double(report.step), double(report.branch), report.t,
                                 mismatch(report.t), plate_growth.factors(radius, report.t)[1],
                                 rod_growth_at(report.t), double(report.newton_iterations),
                                 s.plate_energy + s.rod_energy, s.plate_energy, s.rod_energy,
                                 s.w_centre, s.max_abs_w, s.max_abs_inplane, s.rim_radial_strain};
      row.insert(row.end(), s.rim_w_amplitude.begin(), s.rim_w_amplitude.end());
      row.insert(row.end(), s.rim_ur_amplitude.begin(), s.rim_ur_amplitude.end());
      row.push_back(s.n_negative);
      row.push_back(s.smallest_eigenvalue);
      steps_table.add_row(row);
      steps_table.write(output_directory + "/steps.csv");
      const std::string tag = Utilities::int_to_string(output_index++, 4);
      write_plate(output_directory + "/plate-" + tag + ".vtu", U);
      write_rim(output_directory + "/rim-" + tag + ".vtu", U);
      plate_series->add(report.step, "plate-" + tag + ".vtu");
      rim_series->add(report.step, "rim-" + tag + ".vtu");
    }

    void
    PlateRodProblem::located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode)
    {
      solvers::EventRecord r;
      r.event = e;
      r.state.assign(U.begin(), U.end());
      if (mode)
        r.mode.assign(mode->begin(), mode->end());
      located_events.push_back(r);
      if (write_output)
        write_event(e, U, mode);
    }

    void
    PlateRodProblem::write_event(const Event &, const Vector<double> &U, const Vector<double> *mode)
    {
      const std::string tag = Utilities::int_to_string(located_events.size(), 2);
      write_plate(output_directory + "/event-" + tag + ".vtu", U);
      if (mode)
        {
          // The mode added to the state, scaled to a tenth of the radius.
          Vector<double> V = U;
          double         m = 0;
          for (unsigned int i = 0; i < mode->size(); ++i)
            if (dof_component[i] < 3)
              m = std::max(m, std::abs((*mode)[i]));
          if (m > 0)
            V.add(0.1 * radius / m, *mode);
          write_plate(output_directory + "/event-" + tag + "-mode.vtu", V);
        }
    }

    void
    PlateRodProblem::write_plate(const std::string &file, const Vector<double> &U) const
    {
      // The deformed mid-surface phi = X + u in 3D with the displacement, the
      // director, the growth factors and the membrane forces and bending
      // moments (polar components, plate law of the chosen model) as fields.
      std::vector<Point<2>> unit;
      for (unsigned int j = 0; j <= degree; ++j)
        for (unsigned int i = 0; i <= degree; ++i)
          unit.emplace_back(double(i) / degree, double(j) / degree);
      const Quadrature<2> nodes(unit);
      FEValues<2>         fev(*mapping, *fe, nodes,
                      update_values | update_gradients | update_quadrature_points);
      std::vector<Vector<double>>              values(nodes.size(), Vector<double>(6));
      std::vector<std::vector<Tensor<1, 2>>>   grads(nodes.size(), std::vector<Tensor<1, 2>>(6));
      std::vector<DataOutBase::Patch<2, 3>>    patches;
      const unsigned int                       np = degree + 1;
      const unsigned int                       n_data = 3 + 3 + 2 + 3 + 3;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fev.reinit(cell);
          fev.get_function_values(U, values);
          fev.get_function_gradients(U, grads);
          DataOutBase::Patch<2, 3> patch;
          patch.n_subdivisions       = degree;
          patch.reference_cell       = ReferenceCells::Quadrilateral;
          patch.points_are_available = true;
          patch.data.reinit(n_data + 3, np * np);
          for (unsigned int k = 0; k < nodes.size(); ++k)
            {
              const Point<2>               X = fev.quadrature_point(k);
              std::array<double, n_plate> z{};
              for (unsigned int c = 0; c < 3; ++c)
                {
                  z[c]     = values[k][c];
                  z[3 + c] = grads[k][c][0];
                  z[6 + c] = grads[k][c][1];
                }
              for (unsigned int c = 0; c < 2; ++c)
                {
                  z[9 + c]  = values[k][3 + c];
                  z[11 + c] = grads[k][3 + c][0];
                  z[13 + c] = grads[k][3 + c][1];
                }
              const auto gr = growth_at(X, load_parameter);
              const auto st = model->plate_strains(z, gr);
              const Tensor<1, 3> d = model->director(z);
              const double r = X.norm(), ca = r > 0 ? X[0] / r : 1, sa = r > 0 ? X[1] / r : 0;
              // Polar components of a symmetric (11, 22, 12) tensor.
              auto polar = [&](const std::array<double, 3> &a) {
                const double rr = ca * ca * a[0] + sa * sa * a[1] + 2 * ca * sa * a[2];
                const double tt = sa * sa * a[0] + ca * ca * a[1] - 2 * ca * sa * a[2];
                const double rt = -ca * sa * a[0] + ca * sa * a[1] + (ca * ca - sa * sa) * a[2];
                return std::array<double, 3>{{rr, tt, rt}};
              };
              const auto N  = polar(plate_law.membrane_force(st.membrane));
              const auto M  = polar(plate_law.bending_moment(st.bending));
              const auto gf = plate_growth.factors(r, load_parameter);
              unsigned int col = 0;
              for (unsigned int c = 0; c < 3; ++c)
                patch.data(col++, k) = values[k][c];
              for (unsigned int c = 0; c < 3; ++c)
                patch.data(col++, k) = d[c];
              patch.data(col++, k) = gf[0];
              patch.data(col++, k) = gf[1];
              for (unsigned int c = 0; c < 3; ++c)
                patch.data(col++, k) = N[c];
              for (unsigned int c = 0; c < 3; ++c)
                patch.data(col++, k) = M[c];
              patch.data(n_data + 0, k) = X[0] + values[k][0];
              patch.data(n_data + 1, k) = X[1] + values[k][1];
              patch.data(n_data + 2, k) = values[k][2];
            }
          for (unsigned int v = 0; v < 4; ++v)
            {
              const unsigned int pt = ((v & 2) ? degree * np : 0) + ((v & 1) ? degree : 0);
              patch.vertices[v] =
                Point<3>(patch.data(n_data, pt), patch.data(n_data + 1, pt), patch.data(n_data + 2, pt));
            }
          patch.patch_index = patches.size();
          patches.push_back(std::move(patch));
        }
      const std::vector<std::string> names = {"displacement", "displacement", "displacement",
                                              "director",     "director",     "director",
                                              "growth_radial", "growth_circumferential",
                                              "N_rr",         "N_tt",         "N_rt",
                                              "M_rr",         "M_tt",         "M_rt"};
      std::vector<std::tuple<unsigned int, unsigned int, std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>
        vectors = {{0, 2, "displacement", DataComponentInterpretation::component_is_part_of_vector},
                   {3, 5, "director", DataComponentInterpretation::component_is_part_of_vector}};
      DataOutBase::VtkFlags flags;
      io::write_file_atomically(file, [&](std::ostream &o) {
        DataOutBase::write_vtu(patches, names, vectors, flags, o);
      });
    }

    void
    PlateRodProblem::write_rim(const std::string &file, const Vector<double> &U) const
    {
      // The rim rod as a polyline through phi(X(S)) with its frame d1, d2, d3
      // and its strains and resultants (n = dpsi/dnu, m = dpsi/dkappa).
      std::vector<Point<1>> unit;
      for (unsigned int i = 0; i <= degree; ++i)
        unit.emplace_back(double(i) / degree);
      const Quadrature<1> nodes(unit);
      FEFaceValues<2>     fev(*mapping, *fe, nodes,
                          update_values | update_gradients | update_quadrature_points |
                            update_normal_vectors);
      std::vector<Vector<double>>            values(nodes.size(), Vector<double>(6));
      std::vector<std::vector<Tensor<1, 2>>> grads(nodes.size(), std::vector<Tensor<1, 2>>(6));
      std::vector<DataOutBase::Patch<1, 3>>  patches;
      const auto                             rod   = rod_law();
      const double                           g_rod = rod_growth_at(load_parameter);
      const unsigned int                     n_data = 9 + 6 + 6;
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
            {
              fev.reinit(cell, f);
              fev.get_function_values(U, values);
              fev.get_function_gradients(U, grads);
              DataOutBase::Patch<1, 3> patch;
              patch.n_subdivisions       = degree;
              patch.reference_cell       = ReferenceCells::Line;
              patch.points_are_available = true;
              patch.data.reinit(n_data + 3, nodes.size());
              for (unsigned int k = 0; k < nodes.size(); ++k)
                {
                  const Point<2> X     = fev.quadrature_point(k);
                  const auto     frame = kinematics::circular_rim_frame(X, fev.normal_vector(k));
                  const Tensor<1, 2> t2({frame.tangent[0], frame.tangent[1]});
                  std::array<double, n_rim> z{};
                  for (unsigned int c = 0; c < 3; ++c)
                    {
                      z[c]     = values[k][c];
                      z[3 + c] = grads[k][c] * t2;
                    }
                  z[6]  = values[k][3];
                  z[7]  = values[k][4];
                  z[8]  = grads[k][3] * t2;
                  z[9]  = grads[k][4] * t2;
                  z[10] = values[k][5];
                  z[11] = grads[k][5] * t2;
                  auto law              = rod;
                  law.reference_strains = kinematics::rim_reference_strains(X, frame);
                  const auto e          = model->rim_strains(
                    z, frame, {{law.reference_strains[3], law.reference_strains[4], law.reference_strains[5]}});
                  // Frame: Lambda = exp(theta) exp(alpha E3) Lambda0.
                  Tensor<1, 3, double> th, al;
                  th[0] = z[6], th[1] = z[7], al[2] = z[10];
                  const Tensor<2, 3> L =
                    kinematics::rotation_exp(th) * kinematics::rotation_exp(al) * frame.Lambda0;
                  unsigned int col = 0;
                  for (unsigned int j = 0; j < 3; ++j)
                    for (unsigned int i = 0; i < 3; ++i)
                      patch.data(col++, k) = L[i][j];
                  const auto resultants = law.resultants(e, g_rod);
                  for (unsigned int j = 0; j < 6; ++j)
                    patch.data(col++, k) = e[j];
                  for (unsigned int j = 0; j < 6; ++j)
                    patch.data(col++, k) = resultants[j];
                  patch.data(n_data + 0, k) = X[0] + values[k][0];
                  patch.data(n_data + 1, k) = X[1] + values[k][1];
                  patch.data(n_data + 2, k) = values[k][2];
                }
              for (unsigned int v = 0; v < 2; ++v)
                {
                  const unsigned int k = v == 0 ? 0 : degree;
                  patch.vertices[v] = Point<3>(patch.data(n_data, k), patch.data(n_data + 1, k),
                                               patch.data(n_data + 2, k));
                }
              patch.patch_index = patches.size();
              patches.push_back(std::move(patch));
            }
      std::vector<std::string> names = {"d1", "d1", "d1", "d2", "d2", "d2", "d3", "d3", "d3",
                                        "nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3",
                                        "n1", "n2", "n3", "m1", "m2", "m3"};
      std::vector<std::tuple<unsigned int, unsigned int, std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>
        vectors = {{0, 2, "d1", DataComponentInterpretation::component_is_part_of_vector},
                   {3, 5, "d2", DataComponentInterpretation::component_is_part_of_vector},
                   {6, 8, "d3", DataComponentInterpretation::component_is_part_of_vector}};
      DataOutBase::VtkFlags flags;
      io::write_file_atomically(file, [&](std::ostream &o) {
        DataOutBase::write_vtu(patches, names, vectors, flags, o);
      });
    }

    io::JSON
    PlateRodProblem::closed_forms(double &first_mismatch, std::string &text) const
    {
      io::JSON     closed = io::JSON::object();
      const double Delta1 = mismatch(1.);
      first_mismatch      = NAN;
      if (!std::isfinite(Delta1) || Delta1 == 0)
        return closed;
      const auto p = closed_form_setting();
      // t at which the mismatch reaches Delta (linear ramps).
      const double a = plate_growth.factors(0, 1.)[0] - 1, b = rod_growth - 1;
      auto         t_of = [&](const double D) { return analysis::load_parameter_at_mismatch(D, a, b); };
      auto         entry = [&](const unsigned int n, const double D) {
        io::JSON x    = io::JSON::object();
        x["n"]        = n;
        x["mismatch"] = D;
        x["t"]        = t_of(D);
        return x;
      };
      std::ostringstream c;
      c << std::setprecision(6);
      if (Delta1 > 0)
        {
          const double D                     = analysis::axisymmetric_critical_mismatch(p);
          closed["axisymmetric"]["mismatch"] = D;
          closed["axisymmetric"]["t"]        = t_of(D);
          first_mismatch                     = D;
          c << "  closed form (Kirchhoff, small strain): axisymmetric buckling at Delta = " << D
            << ", t = " << t_of(D);
        }
      else
        {
          // The lobed families, over the mode numbers the domain admits (a sector pi/n keeps
          // the multiples of n).
          const unsigned int step = domain == "sector" ? sector_n : 1;
          const unsigned int n0   = step >= 2 ? step : 2;
          double             best_out = -1e300, best_planar = -1e300;
          unsigned int       n_out = 0, n_planar = 0;
          c << "  closed forms (Kirchhoff, small strain), out-of-plane lobes:";
          for (unsigned int n = n0; n <= std::max(12u, n0 + 4 * step); n += step)
            {
              const double D = analysis::out_of_plane_critical_mismatch(p, n);
              closed["out_of_plane"].push_back(entry(n, D));
              if (n <= n0 + 3 * step)
                c << " n = " << n << ": Delta = " << D << " (t = " << t_of(D) << ")";
              if (D > best_out)
                best_out = D, n_out = n;
            }
          for (unsigned int n = n0; n <= 200; n += step)
            {
              const double D = analysis::planar_critical_mismatch(p, n);
              if (D > best_planar)
                best_planar = D, n_planar = n;
            }
          closed["first_out_of_plane"] = entry(n_out, best_out);
          closed["first_planar"]       = entry(n_planar, best_planar);
          first_mismatch               = std::max(best_out, best_planar);
          c << "\n  first out-of-plane mode n = " << n_out << " at Delta = " << best_out
            << "; first planar mode n = " << n_planar << " at Delta = " << best_planar << " (t = "
            << t_of(best_planar) << ")";
        }
      closed["first"]["mismatch"] = first_mismatch;
      closed["first"]["t"]        = t_of(first_mismatch);
      text                        = c.str();
      return closed;
    }

    void
    PlateRodProblem::run(const io::RunOptions &options, const ParameterHandler &prm)
    {
      write_output = true;
      record.open(output_directory, prm, options);
      plate_series = std::make_unique<io::PVDSeries>(output_directory + "/plate.pvd");
      rim_series   = std::make_unique<io::PVDSeries>(output_directory + "/rim.pvd");
      setup_system();
      std::ostringstream info;
      info << "  " << model->name() << " model, R = " << radius << ", h = " << thickness
           << " (h/R = " << thickness / radius << "), "
           << (domain == "sector" ? "sector pi/" + std::to_string(sector_n) : std::string("full disc"))
           << ", " << triangulation.n_active_cells() << " cells, Q" << degree << ", "
           << dof_handler.n_dofs() << " DoFs (" << constraints.n_constraints() << " constrained)";
      say(info.str());
      if (!stiffness_file.empty())
        {
          std::ostringstream m;
          m << "  rim stiffnesses from " << stiffness_file << ":";
          for (const double k : rod_stiffness)
            m << " " << k;
          m << " (largest dropped coupling K_ab / sqrt(K_aa K_bb) = " << stiffness_coupling << ")";
          say(m.str());
        }

      // The closed forms (Kirchhoff, small strain, uniform isotropic growth).
      double             first_closed = NAN;
      std::string        closed_text;
      const io::JSON     closed = closed_forms(first_closed, closed_text);
      if (!closed_text.empty())
        say(closed_text);

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

      record.attempt([&]() {
        if (critical_guess)
          return locate_from_guess();
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

      io::JSON j       = record.summary();
      j["model"]       = model->name();
      j["domain"]      = domain == "sector" ? "sector" : "full disc";
      if (domain == "sector")
        j["sector_n"] = sector_n;
      j["radius"]    = radius;
      j["thickness"] = thickness;
      j["dofs"]      = dof_handler.n_dofs();
      j["cells"]     = triangulation.n_active_cells();
      j["closed_form"] = closed;
      io::JSON ev      = io::JSON::array();
      for (unsigned int k = 0; k < located_events.size(); ++k)
        {
          const auto &e = located_events[k].event;
          io::JSON    x = io::JSON::object();
          x["kind"]              = e.name();
          x["t"]                 = e.lambda;
          x["mismatch"]          = mismatch(e.lambda);
          x["branch"]            = e.branch;
          x["n_negative_before"] = e.n_negative_before;
          x["n_negative_after"]  = e.n_negative_after;
          const std::string tag  = Utilities::int_to_string(k + 1, 2);
          x["state_vtu"]         = "event-" + tag + ".vtu";
          if (!located_events[k].mode.empty())
            {
              Vector<double> mode(located_events[k].mode.begin(), located_events[k].mode.end());
              const auto     c = classify_mode(mode);
              x["mode_number"]  = c.first;
              x["mode_type"]    = c.second ? "out of plane" : "planar";
              x["mode_type_out_of_plane"] = c.second ? 1 : 0;
              x["mode_vtu"]     = "event-" + tag + "-mode.vtu";
              x["eigenvalue"]   = e.eigenvalue;
            }
          solvers::add_location_to_json(e, x);
          ev.push_back(x);
        }
      j["events"] = ev;
      record.finish(j, timer);
    }

    std::vector<double>
    PlateRodProblem::classify_critical_mode(const Vector<double> &mode) const
    {
      const auto c = classify_mode(mode);
      return {double(c.first), double(c.second)};
    }

    std::vector<double>
    PlateRodProblem::critical_point_columns(const solvers::EventRecord &e) const
    {
      double      closed = NAN;
      std::string text;
      closed_forms(closed, text);
      return {mismatch(e.event.lambda), closed};
    }

    void
    run_plate_rod(ParameterHandler &prm, const io::RunOptions &options)
    {
      io::ParameterSweep sweep;
      sweep.parse_parameters(prm);
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
      problem.run(options, prm);
    }
  } // namespace plate_rod
} // namespace cosmo

// The VTU files of part 1: the section (stresses, growth), the surface layers, the rod piece.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <cosmo/io/output.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/kinematics/helix.h>
#include <cosmo/kinematics/section.h>

#include "cross_section_problem.h"
#include "section_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      /// Stresses and growth at output points of the deformed section.
      class SectionPostprocessor : public DataPostprocessor<2>
      {
      public:
        SectionPostprocessor(const materials::MaterialLibrary &materials,
                             const std::array<double, 6> &     strains,
                             const double                      t,
                             const bool                        with_stress_tensor = false)
          : materials(materials)
          , nu({strains[0], strains[1], strains[2]})
          , kappa({strains[3], strains[4], strains[5]})
          , t(t)
          , with_stress_tensor(with_stress_tensor)
        {}

        std::vector<std::string>
        get_names() const override
        {
          std::vector<std::string> names = {"position", "position", "position", "traction_E3", "traction_E3",
                                            "traction_E3", "von_Mises_stress", "mean_stress", "growth_J",
                                            "elastic_J", "energy_density", "region"};
          if (with_stress_tensor)
            for (const char *c : stress_components)
              names.push_back(std::string("sigma_") + c);
          return names;
        }
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
        get_data_component_interpretation() const override
        {
          std::vector<DataComponentInterpretation::DataComponentInterpretation> v(
            get_names().size(), DataComponentInterpretation::component_is_scalar);
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
              if (with_stress_tensor)
                for (unsigned int k = 0; k < 6; ++k)
                  out[p][12 + k] = sigma[stress_index[k][0]][stress_index[k][1]];
            }
        }

        /// The Cauchy stress's six components, in the order of outline.csv's columns.
        static constexpr const char *stress_components[6] = {"11", "22", "33", "12", "13", "23"};
        static constexpr unsigned int stress_index[6][2]  = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};

      private:
        const materials::MaterialLibrary &materials;
        const Tensor<1, 3>                nu, kappa;
        const double                      t;
        const bool                        with_stress_tensor;
      };
    } // namespace

    std::vector<std::pair<std::string, std::string>>
    CrossSectionProblem::write_fields(const std::string &tag) const
    {
      io::PhaseTimer::Scope  scope(timer, "output");
      const SectionVTUWriter writer(discretization, *this, solution, strains_of(solution), load_parameter);
      std::vector<std::pair<std::string, std::string>> files = {
        {"solution", writer.write_section(tag)}, {"rod", writer.write_rod_piece("rod-" + tag)}};
      if (!distributed_mesh)
        writer.write_outline(field_sensitivities());
      // (a distributed mesh: every rank writes its piece, with or without faces of its own)
      if (!surface_layers.layers().empty() &&
          (!discretization.get_surface_faces().empty() || distributed_mesh))
        files.emplace_back("surface", writer.write_surface_layers("surface-" + tag));
      return files;
    }

    std::vector<Vector<double>>
    CrossSectionProblem::field_sensitivities() const
    {
      // du/de_k = -A^-1 E_Ue e_k, from the factorization and border columns
      // of this very state (condensed_state()'s, for its stiffness); none if
      // the factorization in place is another state's.
      if (!system || system->distributed() || !factorization.here(solution, load_parameter))
        return {};
      std::vector<Vector<double>> du = system->border_columns;
      system->solver().solve(du);
      for (auto &v : du)
        v *= -1.;
      return du;
    }

    SectionVTUWriter::SectionVTUWriter(const SectionDiscretization & discretization,
                                       const CrossSectionParameters &parameters,
                                       const Vector<double> &        solution,
                                       const std::array<double, 6> & strains,
                                       const double                  t)
      : discretization(discretization)
      , parameters(parameters)
      , solution(solution)
      , strains(strains)
      , t(t)
    {}

    std::string
    SectionVTUWriter::write_section(const std::string &tag) const
    {
      const std::string name = "solution-" + tag;
      {
        Vector<double> u(solution.begin(), solution.begin() + discretization.n_u());
        SectionPostprocessor post(parameters.materials, strains, t);
        DataOut<2>           data_out;
        data_out.attach_dof_handler(discretization.get_dof_handler());
        std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
          3, DataComponentInterpretation::component_is_part_of_vector);
        data_out.add_data_vector(u, std::vector<std::string>(3, "displacement"),
                                 DataOut<2>::type_dof_data, interp);
        data_out.add_data_vector(u, post);
        data_out.build_patches(discretization.get_mapping(), parameters.degree,
                               DataOut<2>::curved_inner_cells);

        // deal.II groups vector components of 2D output in pairs, but the
        // section's fields (displacement, position, traction) are 3-vectors:
        // lift the patches into 3D space (points (X1, X2, 0)), where VTU
        // vectors have three components and ParaView can warp the section
        // by the displacement.
        io::VTUPatches<2> vtu({{"displacement", 3}, {"position", 3}, {"traction_E3", 3},
                               {"von_Mises_stress", 1}, {"mean_stress", 1}, {"growth_J", 1},
                               {"elastic_J", 1}, {"energy_density", 1}},
                              {"region"});
        // The columns of DataOut's patches: the displacement, then the
        // postprocessor's; its last one, the region, becomes integer cell data.
        const unsigned int n_data = vtu.n_columns();
        for (const auto &p2 : data_out.get_patches())
          {
            AssertThrow(p2.data.n_rows() >= n_data, ExcInternalError()); // fields as declared above
            vtu.begin_patch(p2.n_subdivisions);
            vtu.set_cell_value(0, static_cast<int>(std::lround(p2.data(n_data, 0))));
            const unsigned int n_points = p2.data.n_cols();
            const unsigned int np       = p2.n_subdivisions + 1;
            for (unsigned int k = 0; k < n_points; ++k)
              {
                for (unsigned int r = 0; r < n_data; ++r)
                  vtu.set_value(r, k, p2.data(r, k));
                Point<2> x;
                if (p2.points_are_available)
                  x = Point<2>(p2.data(n_data + 1, k), p2.data(n_data + 2, k));
                else
                  {
                    const double xi = double(k % np) / p2.n_subdivisions,
                                 eta = double(k / np) / p2.n_subdivisions;
                    x = (1 - xi) * (1 - eta) * p2.vertices[0] + xi * (1 - eta) * p2.vertices[1] +
                        (1 - xi) * eta * p2.vertices[2] + xi * eta * p2.vertices[3];
                  }
                vtu.set_position(k, Point<3>(x[0], x[1], 0));
              }
            vtu.end_patch();
          }
        vtu.set_time(t);
        return vtu.write_output(parameters.output_directory, name, parameters.distributed_mesh);
      }
    }

    std::string
    SectionVTUWriter::write_surface_layers(const std::string &name) const
    {
      // The layers as polylines on the reference boundary (points (X1, X2, 0),
      // with the displacement to warp by), with their growth and stress.
      const auto &       e = strains;
      const Tensor<1, 3> nu({e[0], e[1], e[2]}), kappa({e[3], e[4], e[5]});
      const unsigned int p = parameters.degree;
      std::vector<Point<1>> unit_points;
      for (unsigned int i = 0; i <= p; ++i)
        unit_points.emplace_back(double(i) / p);
      const Quadrature<1> points(unit_points);
      FEFaceValues<2>     ffv(discretization.get_mapping(), discretization.get_fe(), points,
                          update_values | update_gradients | update_quadrature_points |
                            update_normal_vectors);
      Vector<double> u(solution.begin(), solution.begin() + discretization.n_u());
      std::vector<Vector<double>>      u_values(p + 1, Vector<double>(3));
      std::vector<std::vector<Tensor<1, 2>>> u_grads(p + 1, std::vector<Tensor<1, 2>>(3));
      io::VTUPatches<1> vtu({{"displacement", 3}, {"growth_T", 1}, {"growth_3", 1},
                             {"stress_TT", 1}, {"stress_33", 1}, {"stress_T3", 1}, {"layer", 1}});
      for (const auto &sf : discretization.get_surface_faces())
        {
          const auto &layer = parameters.surface_layers.layers()[sf.layer];
          ffv.reinit(sf.cell, sf.face);
          ffv.get_function_values(u, u_values);
          ffv.get_function_gradients(u, u_grads);
          vtu.begin_patch(p);
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
              vtu.set_values(k, {u_values[k][0], u_values[k][1], u_values[k][2], g[0], g[1], S[0],
                                 S[1], S[2], double(sf.layer + 1)});
              vtu.set_position(k, Point<3>(X[0], X[1], 0));
            }
          vtu.end_patch();
        }
      vtu.set_time(t);
      return vtu.write_output(parameters.output_directory, name, parameters.distributed_mesh);
    }

    std::string
    SectionVTUWriter::write_rod_piece(const std::string &name) const
    {
      // A short piece of the rod in 3D: the deformed section swept along the
      // helix, x(X1, X2, X3) = r(X3) + R(X3) w(X1, X2).
      const kinematics::RodStrains rod(strains);
      const double                 D = discretization.properties().diameter;
      double                       L = parameters.rod_piece_length;
      if (L == 0)
        {
          const double k = rod.kappa.norm();
          L              = (k > 0) ? std::min(2 * M_PI / k, 10 * D) : 3 * D;
        }
      const unsigned int p  = parameters.degree;
      const unsigned int np = p + 1;
      std::vector<Point<2>> unit_points;
      for (unsigned int j = 0; j < np; ++j)
        for (unsigned int i = 0; i < np; ++i)
          unit_points.emplace_back(double(i) / p, double(j) / p);
      const Quadrature<2> points(unit_points);
      FEValues<2>         fev(discretization.get_mapping(), discretization.get_fe(), points,
                      update_values | update_quadrature_points);
      Vector<double>              u(solution.begin(), solution.begin() + discretization.n_u());
      std::vector<Vector<double>> u_values(unit_points.size(), Vector<double>(3));

      io::VTUPatches<3>  vtu({{"arc_length", 1}, {"displacement", 3}}, {"region"});
      const unsigned int n_slices = parameters.rod_piece_slices;
      for (const auto &cell : discretization.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fev.reinit(cell);
          fev.get_function_values(u, u_values);
          for (unsigned int s = 0; s < n_slices; ++s)
            {
              vtu.begin_patch(p);
              vtu.set_cell_value(0, cell->material_id());
              for (unsigned int k = 0; k < np; ++k)
                {
                  const double                     X3 = L * (s + double(k) / p) / n_slices;
                  const kinematics::HelixPlacement helix(rod, X3);
                  for (unsigned int ij = 0; ij < np * np; ++ij)
                    {
                      const Tensor<1, 3> w = kinematics::section_placement(
                        fev.quadrature_point(ij),
                        Tensor<1, 3>({u_values[ij][0], u_values[ij][1], u_values[ij][2]}));
                      const unsigned int pt = k * np * np + ij;
                      // Reference points (X1, X2, X3) of the straight rod; Warp
                      // By Vector by the displacement gives the rod on its helix.
                      const Point<2>     X  = fev.quadrature_point(ij);
                      const Tensor<1, 3> x  = helix.place(w);
                      vtu.set_values(pt, {X3, x[0] - X[0], x[1] - X[1], x[2] - X3});
                      vtu.set_position(pt, Point<3>(X[0], X[1], X3));
                    }
                }
              vtu.end_patch();
            }
        }
      vtu.set_time(t);
      return vtu.write_output(parameters.output_directory, name, parameters.distributed_mesh);
    }

    namespace
    {
      /**
       * A boundary face's points, each (X1, X2, w1, w2, w3, von Mises
       * stress), then, if linearized, the Cauchy stress's six components and
       * their derivatives in the six rod strains (outline.csv's columns).
       */
      using OutlineSegment = std::vector<std::vector<double>>;

      /// The segments chained end to end into closed loops (a hole is a loop
      /// of its own); the shared end points once.
      std::vector<OutlineSegment>
      chain_into_loops(std::vector<OutlineSegment> segments, const double tolerance)
      {
        auto same = [tolerance](const std::vector<double> &a, const std::vector<double> &b) {
          return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance;
        };
        std::vector<OutlineSegment> loops;
        std::vector<bool>           used(segments.size(), false);
        for (std::size_t first = 0; first < segments.size(); ++first)
          if (!used[first])
            {
              used[first]         = true;
              OutlineSegment loop = segments[first];
              for (bool extended = true; extended && !same(loop.back(), loop.front());)
                {
                  extended = false;
                  for (std::size_t k = 0; k < segments.size() && !extended; ++k)
                    if (!used[k] && (same(segments[k].front(), loop.back()) ||
                                     same(segments[k].back(), loop.back())))
                      {
                        OutlineSegment next = segments[k];
                        if (!same(next.front(), loop.back()))
                          std::reverse(next.begin(), next.end());
                        loop.insert(loop.end(), next.begin() + 1, next.end());
                        used[k] = extended = true;
                      }
                }
              if (same(loop.back(), loop.front()))
                loop.pop_back();
              loops.push_back(loop);
            }
        return loops;
      }

      /**
       * The postprocessor on the boundary faces of the field u: per face
       * its points, each the reference point (X1, X2), curved by the
       * section's mapping, then the postprocessor's columns.
       */
      std::vector<OutlineSegment>
      boundary_columns(const SectionDiscretization &discretization,
                       const Vector<double> &       u,
                       const SectionPostprocessor & post,
                       const unsigned int           degree)
      {
        DataOutFaces<2> out;
        out.attach_dof_handler(discretization.get_dof_handler());
        out.add_data_vector(u, post);
        out.build_patches(discretization.get_mapping(), degree);
        const unsigned int          n_data = post.get_names().size();
        std::vector<OutlineSegment> faces;
        for (const auto &patch : out.get_patches())
          {
            OutlineSegment face;
            for (unsigned int k = 0; k < patch.data.n_cols(); ++k)
              {
                const double xi = double(k) / patch.n_subdivisions;
                Point<2>     X  = (1 - xi) * patch.vertices[0] + xi * patch.vertices[1];
                if (patch.points_are_available)
                  X = Point<2>(patch.data(n_data, k), patch.data(n_data + 1, k));
                std::vector<double> row = {X[0], X[1]};
                for (unsigned int c = 0; c < n_data; ++c)
                  row.push_back(patch.data(c, k));
                face.push_back(row);
              }
            faces.push_back(face);
          }
        return faces;
      }
    } // namespace

    void
    SectionVTUWriter::write_outline(const std::vector<Vector<double>> &field_sensitivities) const
    {
      // The postprocessor of solution-NNNN.vtu on the boundary faces: the
      // placement w (its first three columns) and the von Mises stress (its
      // seventh) at the faces' points; with the field's sensitivities, also
      // the stress tensor (columns 12-17) and its derivatives in the strains.
      const unsigned int n_u        = discretization.n_u();
      const bool         linearized = field_sensitivities.size() == 6;
      Vector<double>     u(solution.begin(), solution.begin() + n_u);
      const auto         at = [&](const Vector<double> &v, const std::array<double, 6> &e) {
        return boundary_columns(discretization, v, SectionPostprocessor(parameters.materials, e, t, linearized),
                                parameters.degree);
      };
      const auto                  base = at(u, strains);
      std::vector<OutlineSegment> segments;
      for (const auto &face : base)
        {
          OutlineSegment segment;
          for (const auto &row : face)
            {
              std::vector<double> p = {row[0], row[1], row[2], row[3], row[4], row[8]};
              if (linearized)
                p.insert(p.end(), row.begin() + 14, row.begin() + 20);
              segment.push_back(p);
            }
          segments.push_back(segment);
        }
      if (linearized)
        add_stress_derivatives(field_sensitivities, at, segments);
      write_outline_csv(chain_into_loops(segments, 1e-9 * discretization.properties().diameter), linearized);
    }

    void
    SectionVTUWriter::add_stress_derivatives(
      const std::vector<Vector<double>> &                                                     field_sensitivities,
      const std::function<OutlineRows(const Vector<double> &, const std::array<double, 6> &)> &at,
      OutlineRows &                                                                           segments) const
    {
      // d sigma/d e_k along the section's linearized response: the strain
      // e_k moved with the field's du/de_k = -A^-1 E_Ue e_k, by central
      // differences of step 1e-5 (1e-5/D for a curvature): sigma is smooth
      // in both, so the difference's error is ~1e-10 of sigma, far below
      // what the drawing of a stress needs (validation.rod_section_stress).
      const unsigned int n_u = discretization.n_u();
      const double       D   = discretization.properties().diameter;
      for (unsigned int k = 0; k < 6; ++k)
        {
          const double                     h = 1e-5 * (k < 3 ? 1. : 1. / D);
          std::array<OutlineRows, 2> sides;
          for (unsigned int side = 0; side < 2; ++side)
            {
              const double   sign = side == 0 ? 1. : -1.;
              auto           e    = strains;
              Vector<double> v(solution.begin(), solution.begin() + n_u);
              e[k] += sign * h;
              for (unsigned int i = 0; i < n_u; ++i)
                v[i] += sign * h * field_sensitivities[k][i];
              sides[side] = at(v, e);
            }
          for (std::size_t f = 0; f < segments.size(); ++f)
            for (std::size_t q = 0; q < segments[f].size(); ++q)
              for (unsigned int c = 0; c < 6; ++c)
                segments[f][q].push_back((sides[0][f][q][14 + c] - sides[1][f][q][14 + c]) / (2 * h));
        }
    }

    void
    SectionVTUWriter::write_outline_csv(const OutlineRows &loops, const bool linearized) const
    {
      std::ostringstream csv;
      csv << "loop,X1,X2,w1,w2,w3,von_Mises_stress";
      if (linearized)
        {
          for (const char *c : SectionPostprocessor::stress_components)
            csv << ",sigma_" << c;
          for (const auto &strain : kinematics::strain_names)
            for (const char *c : SectionPostprocessor::stress_components)
              csv << ",dsigma_" << c << "/d" << strain;
        }
      csv << '\n' << std::setprecision(17);
      for (std::size_t l = 0; l < loops.size(); ++l)
        for (const auto &p : loops[l])
          {
            csv << l;
            for (const double v : p)
              csv << ',' << v;
            csv << '\n';
          }
      io::write_file_atomically(parameters.output_directory + "/outline.csv",
                                [&csv](std::ostream &o) { o << csv.str(); });
    }
  } // namespace rod
} // namespace cosmo

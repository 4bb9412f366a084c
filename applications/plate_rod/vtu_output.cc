// The VTU output of part 3: the plate (its displacement, director, growth,
// membrane forces and bending moments) and the rim rod (its frame, strains
// and resultants), a sector drawn with its images.
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>

#include <cosmo/config.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/vtu_patches.h>
#include <cosmo/solvers/newton.h>

#include "diagnostics.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace plate_rod
  {
    namespace
    {
      /**
       * A sector's images in the output (Output / Sector as full disc): the
       * rotations by 2 pi k / n, each also after the reflection y -> -y (the
       * sector 0 <= theta <= pi/n has mirror conditions on both edges); the
       * identity alone if `images` is false. `image(turn, reflect)` writes
       * one, with turn(x, y) = Rot(phi) diag(1, reflect) (x, y).
       */
      template <typename Image>
      void
      for_each_sector_image(const bool images, const unsigned int n, const Image &image)
      {
        for (unsigned int rot = 0; rot < (images ? n : 1u); ++rot)
          for (const double reflect : {1., -1.})
            {
              if (reflect < 0 && !images)
                continue;
              const double phi = 2 * M_PI * rot / n, c = std::cos(phi), s = std::sin(phi);
              image(
                [=](const double x, const double y) {
                  return std::array<double, 2>{{c * x - s * reflect * y, s * x + c * reflect * y}};
                },
                reflect);
            }
      }
    } // namespace

    std::string
    write_plate(const PlateRodDiscretization &discretization, const std::string &name,
                const Vector<double> &U, const double t)
    {
      const PlateRodParameters &p = discretization.parameters;
      const unsigned int        degree = p.degree;
      // The mid-surface at its reference points with the displacement, the
      // director, the growth factors and the membrane forces and bending
      // moments (polar components, plate law of the chosen model) as fields;
      // a sector optionally as the full disc, its 2 n mirror images.
      std::vector<Point<2>> unit;
      for (unsigned int j = 0; j <= degree; ++j)
        for (unsigned int i = 0; i <= degree; ++i)
          unit.emplace_back(double(i) / degree, double(j) / degree);
      const Quadrature<2> nodes(unit);
      FEValues<2>         fev(*discretization.mapping, *discretization.fe, nodes,
                      update_values | update_gradients | update_quadrature_points);
      std::vector<Vector<double>>              values(nodes.size(), Vector<double>(6));
      std::vector<std::vector<Tensor<1, 2>>>   grads(nodes.size(), std::vector<Tensor<1, 2>>(6));
      io::VTUPatches<2> vtu({{"displacement", 3}, {"director", 3}, {"growth_radial", 1},
                             {"growth_circumferential", 1}, {"N_rr", 1}, {"N_tt", 1}, {"N_rt", 1},
                             {"M_rr", 1}, {"M_tt", 1}, {"M_rt", 1}});
      for (const auto &cell : discretization.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          fev.reinit(cell);
          fev.get_function_values(U, values);
          fev.get_function_gradients(U, grads);
          std::vector<std::vector<double>> node_values(nodes.size());
          for (unsigned int k = 0; k < nodes.size(); ++k)
            {
              const Point<2>               X = fev.quadrature_point(k);
              std::array<double, kinematics::plate_local_variables> z{};
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
              const auto gr = p.growth_at(X, t);
              const auto st = kinematics::elastic_plate_strains(z, gr, *p.model);
              const Tensor<1, 3> d = p.model->director(z);
              const double r = X.norm(), ca = r > 0 ? X[0] / r : 1, sa = r > 0 ? X[1] / r : 0;
              // Polar components of a symmetric (11, 22, 12) tensor.
              auto polar = [&](const std::array<double, 3> &a) {
                const double rr = ca * ca * a[0] + sa * sa * a[1] + 2 * ca * sa * a[2];
                const double tt = sa * sa * a[0] + ca * ca * a[1] - 2 * ca * sa * a[2];
                const double rt = -ca * sa * a[0] + ca * sa * a[1] + (ca * ca - sa * sa) * a[2];
                return std::array<double, 3>{{rr, tt, rt}};
              };
              const auto resultants = p.plate_law_at(X).resultants(st);
              const auto N          = polar(resultants.membrane);
              const auto M          = polar(resultants.bending);
              const auto gf = p.plate_growth.factors(r, t);
              node_values[k] = {values[k][0], values[k][1], values[k][2], d[0], d[1], d[2], gf[0],
                                gf[1], N[0], N[1], N[2], M[0], M[1], M[2]};
            }
          for_each_sector_image(
            p.domain == "sector" && p.sector_as_full_disc, p.sector_n, [&](const auto &turn, const double reflect) {
                vtu.begin_patch(degree);
                for (unsigned int k = 0; k < nodes.size(); ++k)
                  {
                    std::vector<double> v = node_values[k];
                    for (const unsigned int first : {0u, 3u}) // displacement, director
                      {
                        const auto xy = turn(v[first], v[first + 1]);
                        v[first]      = xy[0];
                        v[first + 1]  = xy[1];
                      }
                    v[10] *= reflect; // N_rt
                    v[13] *= reflect; // M_rt
                    vtu.set_values(k, v);
                    // Reference points + displacement (Warp By Vector shows X + u).
                    const Point<2> X  = fev.quadrature_point(k);
                    const auto     XY = turn(X[0], X[1]);
                    vtu.set_position(k, Point<3>(XY[0], XY[1], 0));
                  }
                vtu.end_patch();
              });
        }
      vtu.set_time(t);
      return vtu.write_output(p.output_directory, name, p.distributed_mesh);
    }

    std::string
    write_rim(const PlateRodDiscretization &discretization, const std::string &name,
              const Vector<double> &U, const double t)
    {
      const PlateRodParameters &p = discretization.parameters;
      const unsigned int        degree = p.degree;
      // The rim rod as a polyline through phi(X(S)) with its frame d1, d2, d3
      // and its strains and resultants (n = dpsi/dnu, m = dpsi/dkappa).
      std::vector<Point<1>> unit;
      for (unsigned int i = 0; i <= degree; ++i)
        unit.emplace_back(double(i) / degree);
      const Quadrature<1> nodes(unit);
      FEFaceValues<2>     fev(*discretization.mapping, *discretization.fe, nodes,
                          update_values | update_gradients | update_quadrature_points |
                            update_normal_vectors);
      std::vector<Vector<double>>            values(nodes.size(), Vector<double>(6));
      std::vector<std::vector<Tensor<1, 2>>> grads(nodes.size(), std::vector<Tensor<1, 2>>(6));
      io::VTUPatches<1> vtu({{"displacement", 3}, {"d1", 3}, {"d2", 3}, {"d3", 3}, {"nu1", 1}, {"nu2", 1}, {"nu3", 1},
                             {"kappa1", 1}, {"kappa2", 1}, {"kappa3", 1}, {"n1", 1}, {"n2", 1},
                             {"n3", 1}, {"m1", 1}, {"m2", 1}, {"m3", 1}});
      for (const auto &cell : discretization.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == rim_id)
            {
              fev.reinit(cell, f);
              fev.get_function_values(U, values);
              fev.get_function_gradients(U, grads);
              std::vector<std::vector<double>> node_values(nodes.size());
              std::vector<Point<2>>            node_points(nodes.size());
              for (unsigned int k = 0; k < nodes.size(); ++k)
                {
                  const Point<2> X     = fev.quadrature_point(k);
                  const auto     frame = kinematics::circular_rim_frame(X, fev.normal_vector(k));
                  const Tensor<1, 2> t2({frame.tangent[0], frame.tangent[1]});
                  std::array<double, kinematics::rim_local_variables> z{};
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
                  auto       ring = p.rim_natural_state(X, frame, t);
                  const auto e    = p.model->rim_strains(
                    z, frame, {{ring.reference_strains[3], ring.reference_strains[4], ring.reference_strains[5]}});
                  const Tensor<2, 3> L = kinematics::rim_rotation(z[6], z[7], z[10], frame.Lambda0);
                  std::vector<double> &v = node_values[k];
                  for (unsigned int c = 0; c < 3; ++c)
                    v.push_back(values[k][c]);
                  for (unsigned int j = 0; j < 3; ++j)
                    for (unsigned int i = 0; i < 3; ++i)
                      v.push_back(L[i][j]);
                  // The stress-free curvature includes the rim's natural curvature (assembly).
                  const auto natural = p.rim_growth->natural_curvature(t);
                  for (unsigned int j = 0; j < 3; ++j)
                    ring.reference_strains[3 + j] += natural[j];
                  const auto resultants = materials::grown_rod_resultants(*p.rim_law, e, ring);
                  for (unsigned int j = 0; j < 6; ++j)
                    v.push_back(e[j]);
                  for (unsigned int j = 0; j < 6; ++j)
                    v.push_back(resultants[j]);
                  node_points[k] = X;
                }
              // The images of a sector's rim as for the plate. A reflection
              // reverses the rim's direction of travel, so the full ring's
              // frame there is (P d1, P d2, -P d3) and the strains and
              // resultants odd under it are the shears nu1, nu2 and the
              // twist kappa3 (n1, n2, m3).
              for_each_sector_image(
                p.domain == "sector" && p.sector_as_full_disc, p.sector_n, [&](const auto &turn, const double reflect) {
                    vtu.begin_patch(degree);
                    for (unsigned int k = 0; k < nodes.size(); ++k)
                      {
                        std::vector<double> v = node_values[k];
                        for (const unsigned int first : {0u, 3u, 6u, 9u}) // displacement, d1, d2, d3
                          {
                            const auto xy = turn(v[first], v[first + 1]);
                            v[first]      = xy[0];
                            v[first + 1]  = xy[1];
                          }
                        if (reflect < 0)
                          for (const unsigned int odd : {9u, 10u, 11u, 12u, 13u, 17u, 18u, 19u, 23u})
                            v[odd] = -v[odd]; // d3, nu1, nu2, kappa3, n1, n2, m3
                        for (unsigned int col = 0; col < v.size(); ++col)
                          vtu.set_value(col, k, v[col]);
                        const auto XY = turn(node_points[k][0], node_points[k][1]);
                        vtu.set_position(k, Point<3>(XY[0], XY[1], 0)); // reference + displacement
                      }
                    vtu.end_patch();
                  });
            }
      vtu.set_time(t);
      return vtu.write_output(p.output_directory, name, p.distributed_mesh);
    }

    std::vector<std::pair<std::string, std::string>>
    write_event(const PlateRodDiscretization &discretization,
                const std::string &           tag,
                const Vector<double> &        U,
                const Vector<double> *        mode,
                const double                  t)
    {
      std::vector<std::pair<std::string, std::string>> files = {
        {"event", write_plate(discretization, "event-" + tag, U, t)}};
      if (mode)
        {
          // The mode added to the state, scaled to a tenth of the radius.
          Vector<double> V = U;
          double         m = 0;
          for (unsigned int i = 0; i < mode->size(); ++i)
            if (discretization.dof_component[i] < 3)
              m = std::max(m, std::abs((*mode)[i]));
          if (m > 0)
            V.add(0.1 * discretization.parameters.radius / m, *mode);
          files.emplace_back("event mode", write_plate(discretization, "event-" + tag + "-mode", V, t));
        }
      return files;
    }
  } // namespace plate_rod
} // namespace cosmo

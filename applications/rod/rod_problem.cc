// The rod: its mesh, unknowns and prescribed values, and the driver
// interface; the energy is assembled in assembly.cc, the states reported in
// postprocess.cc, the run in run.cc.
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <cosmo/io/parameters.h>
#include <cosmo/kinematics/helix.h>

#include "rod_problem.h"

#include <cmath>

namespace cosmo
{
  namespace rod
  {
    void
    RodProblem::make_mesh()
    {
      // Vertices at the nodes' reference positions (the VTU output draws the
      // configuration, not the mesh): a ring's last cell closes on vertex 0.
      triangulation.clear();
      const unsigned int       n = n_nodes();
      std::vector<Point<3>>    vertices(n);
      std::vector<CellData<1>> cells(n_elements);
      for (unsigned int k = 0; k < n; ++k)
        vertices[k] = Point<3>(0, 0, k * element_length());
      if (ring)
        for (unsigned int k = 0; k < n; ++k)
          {
            const double phi = 2 * M_PI * k / n, rho = length / (2 * M_PI);
            vertices[k]      = Point<3>(rho * std::cos(phi), rho * std::sin(phi), 0);
          }
      for (unsigned int e = 0; e < n_elements; ++e)
        {
          cells[e].vertices[0] = e;
          cells[e].vertices[1] = (e + 1) % n;
        }
      triangulation.create_triangulation(vertices, cells, SubCellData());
    }

    void
    RodProblem::setup_system()
    {
      make_mesh();
      fe = std::make_unique<FESystem<1, 3>>(FE_Q<1, 3>(1), 7);
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(*fe);
      for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
        {
          const auto ci = fe->system_to_component_index(i); // (component, vertex)
          local_slot[i] = 7 * ci.second + ci.first;
        }
      node_dofs.assign(n_nodes(), {});
      std::vector<types::global_dof_index> dofs(fe->n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          AssertThrow(cell->vertex_index(0) == cell->active_cell_index(), ExcInternalError());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            node_dofs[cell->vertex_index(local_slot[i] / 7)][local_slot[i] % 7] = dofs[i];
        }
      make_reference();
      fix_element_data();
      roll_gauge = ring && roll_symmetric();
      spin_gauge = !ring && ends[0].support == RodEnd::Support::pinned &&
                   ends[1].support == RodEnd::Support::pinned;
      for (const double s : {0., 0.3 * length, length})
        for (const double t : {start, start + 0.37, start + 1.})
          if (evaluate(distributed_force, s, t).l2_norm() != 0)
            spin_gauge = false;

      constraints.clear();
      for (const auto &p : prescribed_values(start))
        constraints.add_line(p.first);
      constraints.close();
      system.set_nonzero_diagonal(true);
      contact.reset();
      if (contact_radius > 0)
        {
          // The nodes' trapezoidal weights and arclengths, and k = Stiffness B/a^6.
          std::vector<double> w(n_nodes(), element_length()), s(n_nodes());
          if (!ring)
            w.front() = w.back() = 0.5 * element_length();
          for (unsigned int k = 0; k < n_nodes(); ++k)
            s[k] = k * element_length();
          contact = std::make_unique<assembly::SelfContact>(
            contact_radius, contact_stiffness * largest_moment_stiffness() / std::pow(contact_radius, 6), w, s,
            ring ? length : 0.);
        }
      make_pattern({});
      residuals.clear();
      solution = configuration(reference, start);
      load_parameter = start;
    }

    void
    RodProblem::make_reference()
    {
      // Node k's frame and position: straight, a ring, or the natural
      // strains integrated element by element (H_k+1 = H_k exp(h xi)).
      reference.reinit(dof_handler.n_dofs());
      reference_positions.assign(n_nodes(), Tensor<1, 3>());
      const double       h = element_length();
      Tensor<2, 3>       R = unit_symmetric_tensor<3>();
      Tensor<1, 3>       r;
      kinematics::Quaternion<double> previous{{1, 0, 0, 0}};
      for (unsigned int k = 0; k < n_nodes(); ++k)
        {
          if (ring)
            {
              const double phi = 2 * M_PI * k / n_nodes(), rho = length / (2 * M_PI);
              r = Tensor<1, 3>({rho * std::cos(phi), rho * std::sin(phi), 0.});
              const Tensor<1, 3> d1({-std::cos(phi), -std::sin(phi), 0.}), d2({0., 0., 1.}),
                d3({-std::sin(phi), std::cos(phi), 0.});
              for (unsigned int i = 0; i < 3; ++i)
                {
                  R[i][0] = d1[i];
                  R[i][1] = d2[i];
                  R[i][2] = d3[i];
                }
            }
          else if (k > 0 && shape == "natural")
            {
              const auto   n = natural_state((k - 0.5) * h, start);
              Tensor<1, 3> nu, kappa;
              for (unsigned int i = 0; i < 3; ++i)
                {
                  nu[i]    = n.growth * n.reference_strains[i];
                  kappa[i] = n.reference_strains[3 + i];
                }
              r += R * kinematics::helix_position(nu, kappa, h);
              R = R * kinematics::helix_rotation(kappa, h);
            }
          else if (k > 0)
            r[2] = k * h;
          auto q = kinematics::quaternion_of_rotation(R);
          if (q[0] * previous[0] + q[1] * previous[1] + q[2] * previous[2] + q[3] * previous[3] < 0)
            for (auto &x : q)
              x = -x;
          previous = q;
          reference_positions[k] = r;
          for (unsigned int c = 0; c < 4; ++c)
            reference[node_dofs[k][3 + c]] = q[c];
        }
    }

    bool
    RodProblem::roll_symmetric() const
    {
      // A turn of every director frame about its d3 by one angle changes
      // the strains (nu_perp, kappa_perp) by that turn: the energy stays
      // unless the law or the natural strains single out a direction in the
      // (d1, d2) plane. For a quadratic form invariance under a quarter
      // turn is invariance under every turn.
      const std::array<unsigned int, 6> image{{1, 0, 2, 4, 3, 5}};
      const std::array<double, 6>       sign{{1, -1, 1, 1, -1, 1}};
      double scale = 0, asymmetry = 0;
      // (the stiffness where the law varies along the rod: at each sample)
      for (const double s : {0., 0.13, 0.29, 0.5, 0.71, 0.87})
        for (const double t : {start, start + 0.37, start + 1.})
          {
            materials::RodNaturalState n;
            try
              {
                n = natural_state(s * length, t);
              }
            catch (materials::LawRangeError &)
              {
                continue; // (the path will not get there)
              }
            for (const unsigned int k : {0u, 1u, 3u, 4u})
              if (n.reference_strains[k] != 0)
                return false;
            double                 W = 0;
            std::array<double, 6>  dW{};
            std::array<double, 36> K{};
            law->energy_derivatives_at(n.parameter, std::array<double, 6>{}, true, W, dW, K);
            for (unsigned int a = 0; a < 6; ++a)
              for (unsigned int b = 0; b < 6; ++b)
                {
                  scale     = std::max(scale, std::abs(K[6 * a + b]));
                  asymmetry = std::max(asymmetry, std::abs(K[6 * a + b] - sign[a] * sign[b] * K[6 * image[a] + image[b]]));
                }
          }
      return asymmetry <= 1e-12 * scale;
    }

    std::vector<std::pair<types::global_dof_index, double>>
    RodProblem::prescribed_values(const double t) const
    {
      std::vector<std::pair<types::global_dof_index, double>> v;
      auto prescribe = [&](const unsigned int node, const Tensor<1, 3> &u, const Tensor<1, 3> &phi,
                           const bool rotation, const bool position = true) {
        if (position)
          for (unsigned int c = 0; c < 3; ++c)
            v.emplace_back(node_dofs[node][c], u[c]);
        if (!rotation)
          return;
        const auto q = kinematics::quaternion_product(kinematics::quaternion_of_rotation_vector(phi),
                                                      quaternion(reference, node));
        for (unsigned int c = 0; c < 4; ++c)
          v.emplace_back(node_dofs[node][3 + c], q[c]);
      };
      if (ring)
        {
          // Node 0 clamped where it is: the ring's rigid motions.
          prescribe(0, Tensor<1, 3>(), Tensor<1, 3>(), true);
          if (roll_gauge)
            v.emplace_back(node_dofs[n_nodes() / 2][2], 0.);
          return v;
        }
      for (unsigned int k = 0; k < 2; ++k)
        if (ends[k].support != RodEnd::Support::free)
          {
            const auto   u = evaluate(ends[k].displacement, 0, t), p = evaluate(ends[k].rotation, 0, t);
            Tensor<1, 3> ut, pt;
            for (unsigned int i = 0; i < 3; ++i)
              {
                ut[i] = u[i];
                pt[i] = p[i];
              }
            const auto s = ends[k].support;
            prescribe(k == 0 ? 0 : n_nodes() - 1, ut, pt, s != RodEnd::Support::pinned,
                      s != RodEnd::Support::rotation);
          }
      return v;
    }

    Vector<double>
    RodProblem::configuration(const Vector<double> &U, const double t) const
    {
      Vector<double> X = U;
      for (const auto &p : prescribed_values(t))
        X[p.first] = p.second;
      return X;
    }

    Tensor<1, 3>
    RodProblem::displacement(const Vector<double> &X, const unsigned int node) const
    {
      Tensor<1, 3> u;
      for (unsigned int c = 0; c < 3; ++c)
        u[c] = X[node_dofs[node][c]];
      return u;
    }

    Tensor<1, 3>
    RodProblem::position(const Vector<double> &X, const unsigned int node) const
    {
      return reference_positions[node] + displacement(X, node);
    }

    std::vector<Tensor<1, 3>>
    RodProblem::node_positions(const Vector<double> &X) const
    {
      std::vector<Tensor<1, 3>> x(n_nodes());
      for (unsigned int k = 0; k < n_nodes(); ++k)
        x[k] = position(X, k);
      return x;
    }

    void
    RodProblem::make_pattern(const std::vector<std::pair<unsigned int, unsigned int>> &pairs)
    {
      // The elements' couplings, and for each contact pair the position
      // blocks of its two nodes (the prescribed rows and columns condensed).
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      for (const auto &p : pairs)
        for (unsigned int c = 0; c < 3; ++c)
          for (unsigned int d = 0; d < 3; ++d)
            {
              const auto i = node_dofs[p.first][c], j = node_dofs[p.second][d];
              if (!constraints.is_constrained(i) && !constraints.is_constrained(j))
                {
                  dsp.add(i, j);
                  dsp.add(j, i);
                }
            }
      system.reinit(dsp, 0);
      contact_pattern = pairs;
    }

    Tensor<1, 3>
    RodProblem::chord(const Vector<double> &X, const unsigned int e) const
    {
      const unsigned int b = (e + 1) % n_nodes();
      return (reference_positions[b] - reference_positions[e]) + (displacement(X, b) - displacement(X, e));
    }

    kinematics::Quaternion<double>
    RodProblem::quaternion(const Vector<double> &X, const unsigned int node) const
    {
      kinematics::Quaternion<double> q;
      for (unsigned int c = 0; c < 4; ++c)
        q[c] = X[node_dofs[node][3 + c]];
      return q;
    }

    int
    RodProblem::residual(const Vector<double> &U, Vector<double> &R)
    {
      if (const auto *e = residuals.find(U, load_parameter))
        {
          R = e->R;
          return 0;
        }
      io::PhaseTimer::Scope scope(timer, "assembly (residual)");
      return assemble(U, load_parameter, &R, false);
    }

    int
    RodProblem::setup_jacobian(const Vector<double> &U)
    {
      {
        io::PhaseTimer::Scope scope(timer, "assembly (Jacobian)");
        if (assemble(U, load_parameter, nullptr, true) != 0)
          return 1;
      }
      io::PhaseTimer::Scope scope(timer, "factorization");
      try
        {
          system.factorize();
        }
      catch (std::exception &e)
        {
          factorization.clear();
          record.say(std::string("  factorization failed: ") + e.what());
          return 1;
        }
      factorization.set(U, load_parameter);
      return 0;
    }

    int
    RodProblem::solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst)
    {
      io::PhaseTimer::Scope scope(timer, "solve");
      system.solve(rhs, dst, {});
      constraints.set_zero(dst);
      return 0;
    }

    void
    RodProblem::residual_weights(Vector<double> &w) const
    {
      // Nodal forces against F = sqrt(EA B)/L, between the stretching scale
      // EA and the buckling scale B/L^2; nodal moments against F L.
      const double F = std::sqrt(largest_force_stiffness() * largest_moment_stiffness()) / length;
      w.reinit(n_unknowns());
      for (const auto &node : node_dofs)
        for (unsigned int c = 0; c < 7; ++c)
          w[node[c]] = c < 3 ? 1 / F : 1 / (F * length);
    }

    void
    RodProblem::mode_mask(Vector<double> &mask) const
    {
      mask.reinit(n_unknowns());
      mask = 1;
      constraints.set_zero(mask);
    }


    std::array<double, 6>
    RodProblem::element_strains(const Vector<double> &X, const unsigned int e, const double t) const
    {
      const unsigned int b   = (e + 1) % n_nodes();
      auto               q_b = quaternion(X, b);
      if (ring && e + 1 == n_elements)
        {
          const double turns = evaluate(seam_twist, 0, t)[0];
          q_b = kinematics::quaternion_product(q_b, kinematics::twist_quaternion(turns));
        }
      return kinematics::helicoidal_strains(Tensor<1, 3>(), quaternion(X, e), chord(X, e), q_b, element_length());
    }
  } // namespace rod
} // namespace cosmo

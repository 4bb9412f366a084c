// The rod's assembly: each element's energy and derivatives (element.h)
// with its dead loads, the supports' loads and self-contact, assembled by
// the library's EnergyAssembler (doc/theory-rod.md 2-5).
#include <cosmo/assembly/energy_assembler.h>

#include "element.h"
#include "rod_problem.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace cosmo
{
  namespace rod
  {
    namespace
    {
      struct Scratch
      {
        std::array<double, n_local> x{};
      };

    } // namespace

    void
    RodProblem::fix_element_data()
    {
      // No expression names t: the natural states and forces are the start's
      // at every load (a LawRangeError there is the parse's, raised before).
      fixed_natural.clear();
      fixed_force.clear();
      if (element_data_depend_on_load || law->parameter_depends_on_load())
        return;
      const double h = element_length();
      std::vector<materials::RodNaturalState> natural(n_elements);
      std::vector<Tensor<1, 3>>               force(n_elements);
      for (unsigned int e = 0; e < n_elements; ++e)
        {
          const double s = (e + 0.5) * h;
          natural[e]     = natural_state(s, start);
          const auto f   = evaluate(distributed_force, s, start);
          for (unsigned int i = 0; i < 3; ++i)
            force[e][i] = f[i];
        }
      fixed_natural = std::move(natural);
      fixed_force   = std::move(force);
    }

    RodElementData
    RodProblem::element_data(const double t) const
    {
      RodElementData d;
      d.t          = t;
      d.h          = element_length();
      d.n_elements = n_elements;
      d.ring       = ring;
      d.penalty    = largest_moment_stiffness() / d.h;
      for (unsigned int k = 0; k < 2; ++k)
        {
          d.free_end[k] = !ring && (ends[k].support == RodEnd::Support::free ||
                                     ends[k].support == RodEnd::Support::rotation);
          const auto F  = evaluate(ends[k].force, 0, t);
          for (unsigned int i = 0; i < 3; ++i)
            d.end_force[k][i] = F[i];
        }
      if (ring)
        d.seam = kinematics::twist_quaternion(evaluate(seam_twist, 0, t)[0]);
      if (spin_gauge)
        {
          const Vector<double> X0 = configuration(reference, t);
          d.spin_gauge            = true;
          d.spin_axis             = position(X0, n_nodes() - 1) - position(X0, 0);
          d.spin_axis /= d.spin_axis.norm();
          const auto q0           = quaternion(reference, 0);
          d.reference_0_conjugate = {{q0[0], -q0[1], -q0[2], -q0[3]}};
        }
      return d;
    }

    void
    RodProblem::element_contribution(const RodElementData &      d,
                                     const Vector<double> &      X,
                                     const unsigned int          e,
                                     std::array<double, 14> &    x,
                                     const bool                  jacobian,
                                     assembly::CellContribution &c) const
    {
      for (unsigned int i = 0; i < n_local; ++i)
        x[local_slot[i]] = X[c.dof_indices[i]];
      // Refused: a quaternion far from the unit sphere or a relative rotation past the limit.
      kinematics::Quaternion<double> q_a{{x[3], x[4], x[5], x[6]}}, q_b{{x[10], x[11], x[12], x[13]}};
      if (ring && e + 1 == n_elements)
        q_b = kinematics::quaternion_product(q_b, d.seam);
      const auto norm2 = [](const kinematics::Quaternion<double> &q) {
        return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
      };
      if (norm2(q_a) < 0.25 || norm2(q_b) < 0.25 ||
          !kinematics::relative_rotation_admissible(kinematics::relative_quaternion(q_a, q_b), rotation_limit))
        {
          c.admissible = false;
          return;
        }
      const double         s  = (e + 0.5) * d.h;
      const Tensor<1, 3> chord0 = reference_positions[(e + 1) % n_nodes()] - reference_positions[e];
      Tensor<1, 3>       f;
      if (!fixed_force.empty())
        f = fixed_force[e];
      else
        {
          const Vector<double> fv = evaluate(distributed_force, s, d.t);
          for (unsigned int i = 0; i < 3; ++i)
            f[i] = fv[i];
        }
      const std::array<double, n_ad>  y = chord_variables(x, chord0);
      double                          W = 0;
      std::array<double, n_ad>        gy{};
      std::array<double, n_ad * n_ad> Hy{};
      try
        {
          const auto natural = fixed_natural.empty() ? natural_state(s, d.t) : fixed_natural[e];
          element_energy_derivatives(y, d, *law, natural, e, jacobian, W, gy, Hy);
        }
      catch (materials::LawRangeError &error)
        {
          // Outside the law's range (a family's parameter, a table's grid):
          // refused, the step cut, and the reason kept for the message if
          // the path cannot go on.
          c.admissible = false;
          refusals.note(error.what());
          return;
        }
      if (!std::isfinite(W))
        {
          c.admissible = false;
          return;
        }
      std::array<double, n_local>           g;
      std::array<double, n_local * n_local> H{};
      W += load_energy(x, d, f, e, g);
      spread_to_nodes(gy, Hy, jacobian, g, H);
      // Scalars: the energy, then the loads of the supports at A and B.
      c.scalars[0] = W;
      for (unsigned int i = 0; i < n_local; ++i)
        {
          c.residual(i) = g[local_slot[i]];
          if (jacobian)
            for (unsigned int j = 0; j < n_local; ++j)
              c.hessian(i, j) = H[n_local * local_slot[i] + local_slot[j]];
        }
      if (!ring && e == 0 && ends[0].support != RodEnd::Support::free)
        {
          const auto load = nodal_load(&g[0], q_a);
          std::copy(load.begin(), load.end(), c.scalars.begin() + 1);
        }
      if (!ring && e + 1 == n_elements && ends[1].support != RodEnd::Support::free)
        {
          const auto load = nodal_load(&g[7], q_b);
          std::copy(load.begin(), load.end(), c.scalars.begin() + 7);
        }
    }

    double
    RodProblem::add_contact(const std::vector<Tensor<1, 3>> &x, Vector<double> &R, const bool jacobian)
    {
      // Each pair's E(x_i, x_j) of the positions, whose DoFs are the
      // displacements: its gradient (g, -g) and Hessian [[K, -K], [-K, K]]
      // on the free ones.
      double energy = 0;
      for (const auto &term : contact->terms(x))
        {
          energy += term.energy;
          const std::array<unsigned int, 2> nodes{{term.i, term.j}};
          for (unsigned int a = 0; a < 2; ++a)
            for (unsigned int c = 0; c < 3; ++c)
              {
                const auto row = node_dofs[nodes[a]][c];
                if (constraints.is_constrained(row))
                  continue;
                R[row] += (a == 0 ? 1. : -1.) * term.gradient_i[c];
                if (jacobian)
                  for (unsigned int b = 0; b < 2; ++b)
                    for (unsigned int d = 0; d < 3; ++d)
                      {
                        const auto column = node_dofs[nodes[b]][d];
                        if (!constraints.is_constrained(column))
                          system.matrix.add(row, column, (a == b ? 1. : -1.) * term.hessian[c][d]);
                      }
              }
        }
      return energy;
    }

    int
    RodProblem::load_derivative(const Vector<double> &U, const double t, Vector<double> &dR)
    {
      const bool ends_only = fixed_natural.size() == n_elements && !contact && !ring &&
                             !ends[0].force_depends_on_load && !ends[1].force_depends_on_load;
      if (!ends_only)
        return BifurcationProblem::load_derivative(U, t, dR);
      // (the base class's step, so that both give the same numbers)
      const double h = 1e-6 * (1 + std::abs(t));
      dR.reinit(n_unknowns());
      assembly::AssemblyTarget target;
      target.residual    = &dR;
      target.constraints = &constraints;
      for (const double sign : {1., -1.})
        {
          const Vector<double> X = configuration(U, t + sign * h);
          const RodElementData d = element_data(t + sign * h);
          for (const auto &cell : dof_handler.active_cell_iterators())
            if (cell->active_cell_index() == 0 || cell->active_cell_index() + 1 == n_elements)
              {
                assembly::CellContribution c(n_local, 0, 13);
                c.reset(false);
                cell->get_dof_indices(c.dof_indices);
                std::array<double, 14> x;
                element_contribution(d, X, cell->active_cell_index(), x, false, c);
                if (!c.admissible)
                  return 1;
                c.residual *= sign / (2 * h);
                assembly::add_cell_contribution(c, target);
              }
        }
      return 0;
    }

    int
    RodProblem::assemble(const Vector<double> &U, const double t, Vector<double> *R, const bool jacobian)
    {
      const Vector<double> X = configuration(U, t);
      const RodElementData d = element_data(t);
      auto worker = [&](const DoFHandler<1, 3>::active_cell_iterator &cell, Scratch &sc,
                        assembly::CellContribution &c) {
        element_contribution(d, X, cell->active_cell_index(), sc.x, jacobian, c);
      };
      Vector<double> jacobian_residual;
      if (!R)
        R = &jacobian_residual;
      R->reinit(n_unknowns());
      // (the nodes' positions once, for the pattern's check and the contact's terms)
      const std::vector<Tensor<1, 3>> x = contact ? node_positions(X) : std::vector<Tensor<1, 3>>();
      if (jacobian && contact)
        {
          // A pair that touches and that the pattern does not hold: the
          // pattern is made again with the pairs closer than 3a, a margin
          // for the next steps (and MUMPS analyses it again).
          const auto touching = contact->pairs_within(x, 2 * contact->radius());
          if (!std::includes(contact_pattern.begin(), contact_pattern.end(), touching.begin(), touching.end()))
            make_pattern(contact->pairs_within(x, 3 * contact->radius()));
        }
      if (jacobian)
        system.clear();
      assembly::AssemblyTarget target;
      target.residual    = R;
      target.jacobian    = jacobian;
      target.system      = &system;
      target.constraints = &constraints;
      auto totals        = assembly::EnergyAssembler<1, 3>::assemble(dof_handler, worker, Scratch(),
                                                                    assembly::CellContribution(n_local, 0, 13),
                                                                    target);
      if (!totals.admissible)
        return 1;
      if (contact)
        totals.scalars[0] += add_contact(x, *R, jacobian);
      if (!std::isfinite(totals.scalars[0]))
        return 1;
      // (kept for the drivers' next request and the state's description)
      residuals.store(U, t, *R, totals.scalars);
      return 0;
    }
  } // namespace rod
} // namespace cosmo

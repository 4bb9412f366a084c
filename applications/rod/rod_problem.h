#ifndef cosmo_applications_rod_problem_h
#define cosmo_applications_rod_problem_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/assembly/self_contact.h>
#include <cosmo/io/output.h>
#include <cosmo/io/run_record.h>
#include <cosmo/kinematics/rod_element.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/critical_point_study.h>
#include <cosmo/solvers/factorization_mark.h>

#include "parameters.h"

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

/**
 * A whole special Cosserat rod (doc/theory-rod.md): two-node helicoidal
 * elements on a Triangulation<1,3>, each node's unknowns its position (3)
 * and a quaternion (4) whose norm an energy penalty holds at 1; the energy
 * assembled by assembly::EnergyAssembler and factorized by
 * assembly::BorderedSystem, the path followed by the suite's drivers.
 *
 * Prescribed values (clamped and pinned ends) are not unknowns: the state's
 * configuration takes them from their expressions at t whatever U holds
 * there, and their rows and columns are condensed (homogeneous
 * constraints), so that R, J and dR/dt are those of the free unknowns.
 */
namespace cosmo
{
  namespace rod
  {
    using namespace dealii;

    /// What a converged state shows (steps.csv, summary.json).
    struct RodState
    {
      double                t      = 0;
      double                energy = 0;
      Tensor<1, 3>          end_position;     ///< of end B (a ring: of the node opposite node 0)
      std::array<double, 6> end_loads[2]{};   ///< force and moment the supports apply at A and B
      double                max_rotation = 0; ///< largest relative rotation of an element
      /// A ring's link, twist and writhe (doc/theory-rod.md 8); NaN for an open rod.
      double                link = NAN, twist = NAN, writhe = NAN;
      /// With self-contact: the smallest distance minus 2a of the pairs that may touch, and how many touch.
      double                contact_gap   = NAN;
      unsigned int          contact_pairs = 0;
      double                contact_force = 0; ///< the sum of the touching pairs' forces
      int                   n_negative   = -1;
      unsigned int          branch       = 0;
    };

    class RodRun;

    /// What every element of one assembly shares: the load parameter and its data (assembly.cc).
    struct RodElementData
    {
      double                         t = 0, h = 0, penalty = 0;
      unsigned int                   n_elements = 0;
      bool                           ring = false, free_end[2]{};
      Tensor<1, 3>                   end_force[2];
      kinematics::Quaternion<double> seam{{1, 0, 0, 0}}; ///< a ring's rotation across its seam
      /// Both ends pinned: the spin about the line of the pins is held at
      /// node 0 (its rotation from the reference has no component along it).
      bool                           spin_gauge = false;
      Tensor<1, 3>                   spin_axis;
      kinematics::Quaternion<double> reference_0_conjugate{{1, 0, 0, 0}};
    };

    class RodProblem : public solvers::BifurcationProblem, public RodParameters
    {
    public:
      void
      setup_system();
      void
      set_quiet(const bool q)
      {
        record.set_quiet(q);
      }

      unsigned int
      n_unknowns() const override
      {
        return dof_handler.n_dofs();
      }
      int
      residual(const Vector<double> &U, Vector<double> &R) override;
      int
      setup_jacobian(const Vector<double> &U) override;
      int
      solve_with_jacobian(const Vector<double> &rhs, Vector<double> &dst) override;
      bool
      solves_exactly() const override
      {
        return true;
      }
      /**
       * dR/dt. Where t enters only through the ends' prescribed values (no
       * expression of the elements, no end force and no ring's seam names
       * it; no contact), the central difference of the two end elements
       * alone: the others' contributions are the same at t +- h and cancel
       * exactly in the whole residual's difference. Else that difference
       * (the base class's).
       */
      int
      load_derivative(const Vector<double> &U, double lambda, Vector<double> &dR) override;
      void
      residual_weights(Vector<double> &w) const override;
      void
      mode_mask(Vector<double> &mask) const override;
      void
      set_load_parameter(const double t) override
      {
        load_parameter = t;
      }
      void
      converged_step(const Vector<double> &U, const solvers::StepReport &report) override;
      std::vector<std::pair<std::string, std::string>>
      quantity_columns() const override;
      std::vector<std::pair<std::string, std::string>>
      write_fields(const std::string &tag) const override;
      std::vector<std::pair<std::string, std::string>>
      write_event_fields(const std::string &tag, const Vector<double> &U, const Vector<double> *mode) const override;
      int
      n_negative_eigenvalues() override
      {
        return system.n_negative_eigenvalues({}, 0);
      }
      /// dst = J src with the last assembled Hessian (tests of the assembly).
      void
      jacobian_vmult(const Vector<double> &src, Vector<double> &dst) const
      {
        system.vmult(dst, src, {});
      }
      double
      jacobian_abs_form(const Vector<double> &v) const override
      {
        return system.absolute_quadratic_form(v);
      }
      double
      unknowns_scale(const Vector<double> &) const override
      {
        return std::min(length, 1.);
      }
      void
      located_event(const Event &e, const Vector<double> &U, const Vector<double> *mode) override;

      /// U with the prescribed values at t: what the element energies see.
      Vector<double>
      configuration(const Vector<double> &U, double t) const;
      /// Node k's position (its reference position plus its displacement,
      /// which is what a state's vector holds) and quaternion in a configuration.
      Tensor<1, 3>
      position(const Vector<double> &X, unsigned int node) const;
      /// Every node's position in a configuration.
      std::vector<Tensor<1, 3>>
      node_positions(const Vector<double> &X) const;
      /// Node k's displacement in a state or a mode.
      Tensor<1, 3>
      displacement(const Vector<double> &X, unsigned int node) const;
      /// Element e's chord r_b - r_a in a configuration: the reference's
      /// chord plus the difference of the displacements, so that its
      /// round-off is that of the displacements, not of the positions
      /// (eps L/h of the strain with positions on a fine mesh).
      Tensor<1, 3>
      chord(const Vector<double> &X, unsigned int element) const;
      kinematics::Quaternion<double>
      quaternion(const Vector<double> &X, unsigned int node) const;
      /// Element e's strains in a configuration X at t (the seam's rotation included).
      std::array<double, 6>
      element_strains(const Vector<double> &X, unsigned int element, double t) const;
      /// A ring's centreline polygon, the d1 of its elements' midframes normal
      /// to each segment, and the first one's as the last element's frame
      /// continues across the seam (turned by its twist).
      Tensor<1, 3>
      ribbon(const Vector<double> &X, double t, std::vector<Tensor<1, 3>> &x, std::vector<Tensor<1, 3>> &m) const;
      /// A ring, or a rod clamped at both ends: link, twist and writhe are reported ('Link, twist and writhe').
      bool
      reports_link() const
      {
        return topology && (ring || (ends[0].support == RodEnd::Support::clamped &&
                                     ends[1].support == RodEnd::Support::clamped));
      }
      /// A clamped rod's twist, writhe and link (Tw + Wr) at X, if its ends'
      /// tangents lie along the line joining them (doc/theory-rod.md 8.1).
      void
      clamped_link(const Vector<double> &X, double t, RodState &s) const;
      /// The state's summary (energy, end position and loads, rotations) at U.
      RodState
      describe(const Vector<double> &U, double t);
      unsigned int
      n_nodes() const
      {
        return ring ? n_elements : n_elements + 1;
      }
      double
      element_length() const
      {
        return length / n_elements;
      }

      Vector<double>                       solution;
      double                               load_parameter = 0;
      std::vector<RodState>                states;
      std::vector<solvers::EventRecord>    located_events;
      /// What each located event shows (its supports' loads, end, topology).
      std::vector<RodState>                event_states;
      io::RunRecord                        record{"rod"};
      mutable io::PhaseTimer               timer;

    private:
      friend class RodRun; // its checkpoint holds steps_row

      Triangulation<1, 3>       triangulation;
      std::unique_ptr<FESystem<1, 3>> fe;
      DoFHandler<1, 3>          dof_handler;
      AffineConstraints<double> constraints;
      /// node_dofs[k][c]: the DoF of component c (0-2 position, 3-6 quaternion) of node k.
      std::vector<std::array<types::global_dof_index, 7>> node_dofs;
      /// local_slot[i]: where the cell's DoF i goes in (r_a, q_a, r_b, q_b).
      std::array<unsigned int, 14> local_slot{};
      /// The reference configuration (zero displacements and unit quaternions)
      /// and the nodes' reference positions.
      Vector<double>            reference;
      std::vector<Tensor<1, 3>> reference_positions;
      assembly::BorderedSystem  system;
      /// Self-contact (null without): the pairs of nodes the matrix's pattern
      /// holds, sorted; the pattern is made again when a pair not in it
      /// touches (doc/theory-rod.md 9).
      std::unique_ptr<assembly::SelfContact>              contact;
      std::vector<std::pair<unsigned int, unsigned int>> contact_pattern;
      /// The Hessian's pattern: the elements' and the pairs' position blocks.
      void
      make_pattern(const std::vector<std::pair<unsigned int, unsigned int>> &pairs);
      /// Adds the contact's gradient (and Hessian) at the nodes' positions x to R (and the matrix); returns its energy.
      double
      add_contact(const std::vector<Tensor<1, 3>> &x, Vector<double> &R, bool jacobian);
      solvers::FactorizationMark factorization;
      solvers::ResidualCache    residuals;
      /// Why the last refused state was refused by the law (thread-safe: noted by the assembly's workers).
      class Refusals
      {
      public:
        void
        note(const std::string &why) const
        {
          std::lock_guard<std::mutex> lock(mutex);
          last = why;
        }
        /// `message`, with the last refusal's reason if there was one.
        std::string
        explain(const std::string &message) const
        {
          std::lock_guard<std::mutex> lock(mutex);
          return last.empty() ? message : "the law refused the next state: " + last + " (" + message + ")";
        }

      private:
        mutable std::mutex  mutex;
        mutable std::string last;
      } refusals;

      void
      make_mesh();
      void
      make_reference();
      /// Whether turning every frame about its d3 by one angle leaves the energy (an isotropic ring).
      bool
      roll_symmetric() const;
      /// A ring's 7th gauge: the out-of-plane position of the node opposite node 0 held.
      bool roll_gauge = false;
      /// Both ends pinned and no distributed force: the spin about the pins' line is a symmetry, held at node 0.
      bool spin_gauge = false;
      /// The prescribed DoFs and their values at t.
      std::vector<std::pair<types::global_dof_index, double>>
      prescribed_values(double t) const;
      RodElementData
      element_data(double t) const;
      /**
       * Each element's natural state and distributed force, evaluated once
       * when no expression depends on t (else empty: evaluated per
       * assembly, where muparser and its allocations cost a third of a
       * residual at 10^4 elements, benchmarks/README.md).
       */
      std::vector<materials::RodNaturalState> fixed_natural;
      std::vector<Tensor<1, 3>>               fixed_force;
      void
      fix_element_data();
      /// Element e's energy and derivatives in the configuration X (x: its 14 local values).
      void
      element_contribution(const RodElementData &      d,
                           const Vector<double> &      X,
                           unsigned int                e,
                           std::array<double, 14> &    x,
                           bool                        jacobian,
                           assembly::CellContribution &c) const;
      /// R (and with `jacobian` the Hessian) at U and t; 0, or 1 where the state is refused.
      int
      assemble(const Vector<double> &U, double t, Vector<double> *R, bool jacobian);
    };
  } // namespace rod
} // namespace cosmo

#endif

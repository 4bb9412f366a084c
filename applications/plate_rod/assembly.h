#ifndef cosmo_applications_plate_rod_assembly_h
#define cosmo_applications_plate_rod_assembly_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <cosmo/assembly/bordered_system.h>
#include <cosmo/assembly/energy_assembler.h>
#include <cosmo/solvers/newton.h>

#include "discretization.h"
#include "parameters.h"

#include <array>

/**
 * The energy of part 3 and its derivatives at a state: the plate's membrane,
 * bending and transverse shear and the rim rod's, differentiated per
 * quadrature point (assembly.cc) and assembled on the discretization into
 * the residual and, on request, the Hessian of the problem's system. It
 * keeps what its last assemblies found (the state, the energies, the last
 * two residuals), so that a residual or an energy asked again at the same
 * state is not assembled again.
 */
namespace cosmo
{
  namespace plate_rod
  {
    using namespace dealii;

    class PlateRodAssembly
    {
    public:
      /// On the problem's parameters, discretization and system, which outlive it.
      PlateRodAssembly(const PlateRodParameters &    parameters,
                       const PlateRodDiscretization &discretization,
                       assembly::BorderedSystem &    system)
        : parameters(parameters)
        , discretization(discretization)
        , system(system)
      {}

      /// The residual R at U and the load t (with `jacobian` the Hessian into
      /// the system too); 0, or 1 if the energy is not finite there.
      int
      assemble(const Vector<double> &U, double t, Vector<double> *R, bool jacobian);
      /// R(U) at t as one of the last two assemblies left it, if one was at
      /// (U, t): then (U, t) is the last assembled state again. Whether it was.
      bool
      recall(const Vector<double> &U, const double t, Vector<double> &R)
      {
        const auto *e = residuals.find(U, t);
        if (!e)
          return false;
        R                = e->R;
        assembled_at     = U;
        assembled_load   = t;
        assembled_energy = {{e->scalars[0], e->scalars[1]}};
        return true;
      }
      /// Forget the kept residuals (new parameters or a new discretization
      /// change what R depends on).
      void
      clear()
      {
        residuals.clear();
      }
      /// Whether the last assembly (or recall) was at U and t.
      bool
      assembled(const Vector<double> &U, const double t) const
      {
        return t == assembled_load && solvers::same_point(U, assembled_at);
      }
      /// The plate's and the rim's energy at the last assembled state.
      const std::array<double, 2> &
      energies() const
      {
        return assembled_energy;
      }
      /// Their sum, the total energy there.
      double
      energy() const
      {
        return assembled_energy[0] + assembled_energy[1];
      }

    private:
      const PlateRodParameters &    parameters;
      const PlateRodDiscretization &discretization;
      /// The Hessian's target: the problem factorizes and solves with it.
      assembly::BorderedSystem &system;

      Vector<double>        assembled_at; ///< the state of the last assembly
      double                assembled_load = 0;
      std::array<double, 2> assembled_energy{}; ///< its plate and rim energies
      /// The last two assemblies' residuals, with their energies.
      solvers::ResidualCache residuals;

      /// The cell loop's work space and what its cells share (assembly.cc).
      struct Scratch;
      struct CellLoopData;
      /// The plate's membrane, bending and transverse shear on one cell.
      void
      plate_of_cell(const CellLoopData &                         d,
                    const DoFHandler<2>::active_cell_iterator &cell,
                    Scratch &                                    sc,
                    assembly::CellContribution &                 c) const;
      /// The transverse shear of one cell by assumed covariant strains; returns its energy.
      double
      assumed_shear_of_cell(const CellLoopData &d, Scratch &sc, assembly::CellContribution &c) const;
      /// The rim rod on the cell's rim faces.
      void
      rim_of_cell(const CellLoopData &                         d,
                  const DoFHandler<2>::active_cell_iterator &cell,
                  Scratch &                                    sc,
                  assembly::CellContribution &                 c) const;
    };
  } // namespace plate_rod
} // namespace cosmo

#endif

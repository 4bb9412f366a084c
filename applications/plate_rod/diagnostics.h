#ifndef cosmo_applications_plate_rod_diagnostics_h
#define cosmo_applications_plate_rod_diagnostics_h

#include <deal.II/lac/vector.h>

#include <cosmo/solvers/arclength.h>

#include "discretization.h"

#include <string>
#include <utility>
#include <vector>

/**
 * What part 3 shows of a state U at the load parameter t: its diagnostics
 * (energies are the assembly's, the rest here: deflections, the rim's
 * Fourier amplitudes, the mode classification), the rows of steps.csv and
 * the VTU files of the plate and the rim (vtu_output.cc). They read the
 * discretization and its parameters only, not the problem: functions of
 * (discretization, U, t), as a postprocessor sees a state.
 */
namespace cosmo
{
  namespace plate_rod
  {
    using namespace dealii;

    /// What one state looks like, for steps.csv and summary.json.
    struct PlateRodState
    {
      double              t = 0;
      double              plate_energy = 0, rod_energy = 0;
      double              w_centre = 0, max_abs_w = 0, max_abs_inplane = 0;
      double              rim_radial_strain = 0; ///< mean u_r / R on the rim
      std::vector<double> rim_w_amplitude;  ///< |Fourier coefficient| of w on the rim, m = k step
      std::vector<double> rim_ur_amplitude; ///< same for the radial displacement
      int                 n_negative = -1;
      double              smallest_eigenvalue = 0;
      unsigned int        branch = 0; ///< of the continuation (0 the first)
      double              constraint_violation = 0; ///< PlateRodDiscretization::constraint_violation
    };

    /// Number of rim Fourier modes reported (m = k sector_step(), k = 0 .. n_rim_modes - 1).
    constexpr unsigned int n_rim_modes = 9;

    /// Diagnostics of a state at load t (deflections, rim Fourier amplitudes; not the
    /// energies, which the assembly gives).
    PlateRodState
    analyse(const PlateRodDiscretization &d,
            const Vector<double> &        U,
            double                        t,
            unsigned int                  n_modes = n_rim_modes);

    /// How clear a classification is: the smaller over the larger of the
    /// two type measures (half the range of w, the largest in-plane
    /// displacement) and of the two largest rim Fourier amplitudes; near 1
    /// the mode is a mix (e.g. of a near-double eigenvalue) and its type or
    /// number can flip under round-off.
    struct ModeMargins
    {
      double type   = 0;
      double number = 0;
    };
    /// Mode type and number of a perturbation: dominant rim Fourier number and whether the
    /// out-of-plane part dominates (and, if asked, how clearly).
    std::pair<unsigned int, bool>
    classify_mode(const PlateRodDiscretization &d,
                  const Vector<double> &        mode,
                  ModeMargins *                 margins = nullptr);

    /// steps.csv's columns (name, unit), the rim's modes those the domain admits.
    std::vector<std::pair<std::string, std::string>>
    steps_columns(const PlateRodDiscretization &d);
    /// steps.csv's row of a converged state (its energies and stability included).
    std::vector<double>
    steps_row(const PlateRodParameters &   p,
              const solvers::StepReport &  report,
              const PlateRodState &        s);

    /// plate VTU `name`.vtu in the output directory, or `name`.pvtu of a distributed mesh's
    /// pieces, of U at t; returns the file name written (for the .pvd series).
    std::string
    write_plate(const PlateRodDiscretization &d,
                const std::string &           name,
                const Vector<double> &        U,
                double                        t);
    /// The same for the rim rod.
    std::string
    write_rim(const PlateRodDiscretization &d,
              const std::string &           name,
              const Vector<double> &        U,
              double                        t);
    /// A located event's plate files: event-`tag` of U and, with a mode,
    /// event-`tag`-mode of U plus the mode (each kind with its file name).
    std::vector<std::pair<std::string, std::string>>
    write_event(const PlateRodDiscretization &d,
                const std::string &           tag,
                const Vector<double> &        U,
                const Vector<double> *        mode,
                double                        t);
  } // namespace plate_rod
} // namespace cosmo

#endif

#ifndef cosmo_assembly_rod_strain_control_h
#define cosmo_assembly_rod_strain_control_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace cosmo
{
  namespace assembly
  {
    using namespace dealii;

    /**
     * What a reduced rod is asked to do with its six strains e = (nu, kappa)
     * along a path in the load parameter t: each strain is prescribed (ramped
     * from the reference (0,0,1,0,0,0) to a target, straight or through
     * waypoints) or free, its resultant dPsi/de held at t times a target
     * (resultant control: the equilibrium of Psi - t nbar.e under dead
     * loads nbar; zero by default). Section "Rod strains" of a parameter
     * file; the strain rows of ReducedRodProblem's residual read it.
     */
    class RodStrainControl
    {
    public:
      /// Section "Rod strains": Mode, Strains, Free strains, Resultants, Path.
      static void
      declare_strain_parameters(ParameterHandler &prm);
      void
      parse_strain_parameters(ParameterHandler &prm);

      /// Override the target strains (prescribed ones reach them at t = 1).
      void
      set_target_strains(const std::array<double, 6> &strains)
      {
        target_strains = strains;
        waypoints.clear();
      }
      const std::array<double, 6> &
      get_target_strains() const
      {
        return target_strains;
      }
      /// Target resultants of the free strains (reached at t = 1).
      void
      set_target_resultants(const std::array<double, 6> &n)
      {
        target_resultants = n;
      }
      void
      set_free_strains(const std::array<bool, 6> &free)
      {
        strain_is_free = free;
      }
      const std::array<bool, 6> &
      free_strains() const
      {
        return strain_is_free;
      }

      /// The prescribed strains at t (the free ones' entries are their reference values).
      std::array<double, 6>
      prescribed_strains_at(double t) const;
      /// d(prescribed strains)/dt at t (the path's slope; 0 beyond its end).
      std::array<double, 6>
      prescribed_strain_rate(double t) const;
      /// The resultants the free strains are held at, t times the targets (0 for prescribed strains).
      std::array<double, 6>
      resultants_at(double t) const;
      /// Whether some free strain's resultant is held at a nonzero target.
      bool
      holds_resultants() const
      {
        for (const double n : target_resultants)
          if (n != 0)
            return true;
        return false;
      }

    protected:
      std::array<double, 6>              target_strains{{0, 0, 1, 0, 0, 0}};
      std::array<bool, 6>                strain_is_free{};
      std::array<double, 6>              target_resultants{};
      std::string                        mode = "natural shape";
      std::vector<std::array<double, 6>> waypoints; ///< 'Path' (empty: straight ramp)
    };
  } // namespace assembly
} // namespace cosmo

#endif

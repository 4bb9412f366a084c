#ifndef cosmo_materials_rod_laws_table_h
#define cosmo_materials_rod_laws_table_h

#include <cosmo/materials/rod_law.h>

#include <string>
#include <vector>

/**
 * The nonlinear rod law of a constitutive table, registered as 'table'
 * (doc/theory-rod.md 4.2): the table.h5 of a `strip` or `rod_cross_section`
 * run over two strains (x_a, x_b), the other strains condensed as in the
 * table (free ones relaxed at their held resultants). On each grid cell the
 * energy is the bicubic Hermite interpolant of the tabulated energy Psi,
 * its gradient (the axis strains' resultants) and its cross derivative
 * (the condensed stiffness K_ab): C1 across cells, so that resultants and
 * tangent are the derivatives of one energy. The other four strains enter
 * through a quadratic energy with the table's (uncondensed) stiffness of
 * those strains at its natural state: a ribbon's stiff directions
 * (stretching, shear, in-plane bending). The natural state is the table
 * energy's minimum (the axis strains there; the others at the straight
 * rod's nu = (0, 0, 1), kappa = 0).
 *
 * A strain outside the grid, or in a cell with a point that did not
 * converge (a hole), is refused with LawRangeError naming the strain and
 * the range.
 */
namespace cosmo
{
  namespace materials
  {
    class TableRodLaw : public RodLaw
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &section) override;
      /// Read table.h5 (io::InputError naming `section`/'Table file' unless it is one).
      void
      read(const std::string &file, const std::string &section);

      void
      energy_derivatives(const std::array<double, 6> &e,
                         bool                         with_hessian,
                         double &                     W,
                         std::array<double, 6> &      dW,
                         std::array<double, 36> &     ddW) const override;
      std::optional<std::array<double, 6>>
      natural_strains_at(double p) const override;
      bool
      gives_natural_strains() const override
      {
        return true;
      }
      std::string
      description() const override;
      /// 'Table file' a strip or rod_cross_section parameter file: computed by the run.
      ComputedInput
      computed_input() const override;
      void
      read_computed(const std::string &directory, const std::string &note) override;

      /// The table's energy, its gradient and Hessian in the axis strains (x_a, x_b).
      void
      table_energy(double x_a, double x_b, double &W, std::array<double, 2> &g, std::array<double, 3> &H) const;

      unsigned int axis_a = 3, axis_b = 5; ///< the table's strains (indices)

    private:
      std::string           file, section_name, computed_note;
      bool                  pending = false; ///< a parameter file, not yet computed
      std::vector<double>   x, y;                      ///< the axes
      std::vector<double>   f, fx, fy, fxy;            ///< per node (i n2 + j)
      std::vector<double>   kxx, kyy;                  ///< condensed diagonal stiffnesses per node
      double                stiffness_tolerance = 0.01;
      double                resolution          = 0;   ///< largest relative stiffness error at the nodes
      std::vector<bool>     converged;
      std::array<double, 6> natural{{0, 0, 1, 0, 0, 0}}; ///< the strains at the energy's minimum
      double                natural_energy = 0;
      std::array<double, 36> others{};                 ///< stiffness of the other four strains (6x6, zero in the axes)
      unsigned int           holes = 0;

      /// The minimum of the interpolated energy (Newton from the lowest node).
      void
      find_natural_state();
      /// The converged grid point nearest the natural state (i n2 + j).
      std::size_t
      nearest_node() const;
      /// `others`: the tabulated stiffness of the other four strains at the grid point nearest the natural state.
      void
      set_other_stiffness(const std::vector<double> &stiffness);
      /// io::InputError if the interpolant's stiffness misses the table's near the natural state.
      void
      check_resolution();
    };
  } // namespace materials
} // namespace cosmo

#endif

#ifndef cosmo_solvers_step_control_h
#define cosmo_solvers_step_control_h

#include <deal.II/base/parameter_handler.h>

namespace cosmo
{
  namespace solvers
  {
    /**
     * The step control both continuation drivers read, each from its own
     * section (entered; each declares the entries with its own defaults and
     * words): the first, smallest and largest step, the number of steps, and
     * the growth of the step after an easy one. `Settings` is
     * ContinuationSettings or ArclengthSettings, which name these alike.
     */
    template <typename Settings>
    void
    parse_step_control(dealii::ParameterHandler &prm, Settings &s)
    {
      s.initial_step    = prm.get_double("Initial step");
      s.minimum_step    = prm.get_double("Minimum step");
      s.maximum_step    = prm.get_double("Maximum step");
      s.maximum_steps   = prm.get_integer("Maximum number of steps");
      s.easy_iterations = prm.get_integer("Easy step iterations");
      s.growth_factor   = prm.get_double("Step growth factor");
    }
  } // namespace solvers
} // namespace cosmo

#endif

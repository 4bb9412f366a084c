#include <cosmo/kinematics/plate_model.h>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<kinematics::PlateModel>;
  } // namespace plugins
} // namespace cosmo

// The helicoidal rod element's quaternion of a rotation matrix (rod_element.h).
#include <cosmo/kinematics/rod_element.h>

namespace cosmo
{
  namespace kinematics
  {
    Quaternion<double>
    quaternion_of_rotation(const Tensor<2, 3> &R)
    {
      // Shepperd: of 4 q0^2 = 1 + tr R and 4 qi^2 = 1 + 2 R_ii - tr R take
      // the largest, so that the division below is by at least 1/2.
      const double       tr = trace(R);
      Quaternion<double> q;
      unsigned int       k = 0;
      for (unsigned int i = 1; i < 3; ++i)
        if (R[i][i] > R[k][k])
          k = i;
      if (tr >= R[k][k])
        {
          q[0] = 0.5 * std::sqrt(1. + tr);
          q[1] = (R[2][1] - R[1][2]) / (4. * q[0]);
          q[2] = (R[0][2] - R[2][0]) / (4. * q[0]);
          q[3] = (R[1][0] - R[0][1]) / (4. * q[0]);
          return q;
        }
      const unsigned int i = k, j = (k + 1) % 3, l = (k + 2) % 3;
      q[i + 1] = 0.5 * std::sqrt(1. + 2. * R[i][i] - tr);
      q[0]     = (R[l][j] - R[j][l]) / (4. * q[i + 1]);
      q[j + 1] = (R[j][i] + R[i][j]) / (4. * q[i + 1]);
      q[l + 1] = (R[l][i] + R[i][l]) / (4. * q[i + 1]);
      return q;
    }
  } // namespace kinematics
} // namespace cosmo

#include <cosmo/kinematics/helix.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace cosmo
{
  namespace kinematics
  {
    const std::array<std::string, 6> strain_names = {
      {"nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"}};
    const std::array<std::string, 6> resultant_names = {
      {"n1", "n2", "n3", "m1", "m2", "m3"}};

    RodStrains::RodStrains() = default;

    RodStrains::RodStrains(const std::array<double, 6> &e)
    {
      for (unsigned int i = 0; i < 3; ++i)
        {
          nu[i]    = e[i];
          kappa[i] = e[i + 3];
        }
    }

    std::array<double, 6>
    RodStrains::as_array() const
    {
      return {{nu[0], nu[1], nu[2], kappa[0], kappa[1], kappa[2]}};
    }

    RodStrains
    RodStrains::reference()
    {
      return RodStrains(std::array<double, 6>{{0, 0, 1, 0, 0, 0}});
    }

    HelixGeometry
    helix_geometry(const RodStrains &e)
    {
      HelixGeometry h;
      const double  k = e.kappa.norm();
      h.curvature_rate = k;
      const double speed = e.nu.norm();
      if (k < 1e-14 * std::max(1.0, speed))
        {
          // Straight centreline along nu (possibly twisted about itself).
          h.axis   = (speed > 0 ? e.nu / speed : Tensor<1, 3>({0, 0, 1}));
          h.radius = 0;
          h.pitch  = std::numeric_limits<double>::infinity();
          return h;
        }
      h.axis                  = e.kappa / k;
      const double       vpar = e.nu * h.axis;
      const Tensor<1, 3> vperp = e.nu - vpar * h.axis;
      const double       vp    = vperp.norm();
      // A centreline along the axis (nu parallel to kappa) is straight.
      h.radius = (vp < 1e-12 * std::max(1.0, speed)) ? 0. : vp / k;
      h.pitch                  = 2 * M_PI * std::abs(vpar) / k;
      const double tol         = 1e-12 * std::max(1.0, speed);
      h.handedness = (h.radius == 0 || std::abs(vpar) < tol) ? 0 : (vpar > 0 ? 1 : -1);
      // Circular helix of radius a, axial speed c per unit turning angle:
      // curvature a/(a^2+c^2), torsion c/(a^2+c^2) (signed by handedness).
      if (h.radius == 0)
        {
          // Straight: no curvature, and torsion of a line is undefined; the
          // sense of the twist of the frame about it is still meaningful.
          h.torsion_sign = (e.nu * e.kappa >= 0) ? 1 : -1;
          return h;
        }
      const double c = vpar / k;
      const double d = h.radius * h.radius + c * c;
      h.curvature    = d > 0 ? h.radius / d : 0;
      h.torsion      = d > 0 ? c / d : 0;
      return h;
    }

    std::string
    HelixGeometry::description() const
    {
      std::ostringstream s;
      if (radius == 0 && !std::isfinite(pitch))
        s << "straight centreline";
      else if (radius == 0)
        s << "straight centreline twisted about itself, " << curvature_rate
          << " rad per unit length, " << (torsion_sign >= 0 ? "right" : "left") << "-handed";
      else if (handedness == 0)
        s << "planar circle of radius " << radius;
      else
        s << (handedness > 0 ? "right" : "left") << "-handed helix, radius "
          << radius << ", pitch " << pitch;
      return s.str();
    }
  } // namespace kinematics
} // namespace cosmo

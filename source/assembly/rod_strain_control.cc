#include <cosmo/assembly/rod_strain_control.h>
#include <cosmo/io/parameters.h>
#include <cosmo/kinematics/helix.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace assembly
  {
    void
    RodStrainControl::declare_strain_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rod strains");
      prm.declare_entry("Mode", "natural shape",
                        Patterns::Selection("prescribed strains|natural shape"),
                        "prescribed strains: the six strains are ramped from the "
                        "reference (0,0,1,0,0,0) to 'Strains' (except 'Free strains'); "
                        "natural shape: all six strains are free, their resultants vanish "
                        "('Strains', 'Free strains' and 'Path' must then be left unset).");
      prm.declare_entry("Strains", "0, 0, 1, 0, 0, 0",
                        Patterns::List(Patterns::Double(), 6, 6),
                        "Target strains nu1, nu2, nu3, kappa1, kappa2, kappa3 in the "
                        "director frame (nu dimensionless, kappa per unit reference "
                        "length); reached at load parameter t = 1.");
      prm.declare_entry("Free strains", "",
                        Patterns::MultipleSelection("nu1|nu2|nu3|kappa1|kappa2|kappa3"),
                        "In 'prescribed strains' mode: strains left free (their "
                        "resultant vanishes, or reaches its entry of 'Resultants'), e.g. "
                        "'nu3' for twisting at zero axial force.");
      prm.declare_entry("Resultants", "0, 0, 0, 0, 0, 0",
                        Patterns::List(Patterns::Double(), 6, 6),
                        "Target resultants n1, n2, n3, m1, m2, m3 (force E L^2, moment E L^3) "
                        "of the free strains, ramped as t times the target (reached at t = 1): "
                        "resultant control, e.g. a tension n3 with nu3 free, a torque m3 with "
                        "kappa3 free. The entry of a prescribed strain must be 0 (a strain is "
                        "prescribed or its resultant is).");
      prm.declare_entry("Path", "", Patterns::Anything(),
                        "A path through strain space instead of the straight ramp to "
                        "'Strains': waypoints of six strains separated by ';', e.g. "
                        "'0,0,1,0.5,0,0; 0,0,1,0.5,0,1' (bend, then twist while bent). The "
                        "load parameter t runs through them at equal intervals from the "
                        "reference; the last waypoint is reached at t = 1. A free strain "
                        "must not change along the path.");
      prm.leave_subsection();
    }

    namespace
    {
      /// 'Mode = natural shape' (section 'Rod strains' entered): all six strains are unknowns
      /// there, so what prescribes or frees a strain has no effect, and a user who set it
      /// meant something else.
      void
      refuse_prescriptions_in_natural_shape(ParameterHandler &prm)
      {
        for (const auto &[entry, unset] :
             std::vector<std::pair<std::string, std::string>>{{"Strains", "0, 0, 1, 0, 0, 0"},
                                                              {"Free strains", ""},
                                                              {"Path", ""},
                                                              {"Resultants", "0, 0, 0, 0, 0, 0"}})
          {
            const std::string text = prm.get(entry);
            bool              is_unset = text == unset;
            if (!is_unset && (entry == "Strains" || entry == "Resultants"))
              try
                {
                  is_unset = Utilities::string_to_double(Utilities::split_string_list(text, ',')) ==
                             (entry == "Strains" ? std::vector<double>{0, 0, 1, 0, 0, 0} :
                                                   std::vector<double>(6, 0.));
                }
              catch (...)
                {}
            if (!is_unset)
              throw io::InputError("Rod strains", entry, text,
                                   "nothing in 'Mode = natural shape' (all six strains are free "
                                   "there and this entry is ignored): set 'Mode = prescribed "
                                   "strains' to use it, or remove it");
          }
      }

      /// A strain of a size no rod has (a shear or stretch of 100, a curvature of 100 turns per
      /// unit length) is a typing error, and would only make the nonlinear solver wander.
      void
      check_strain_sizes(const std::string &entry, const std::string &text, const std::array<double, 6> &v)
      {
        for (unsigned int k = 0; k < 6; ++k)
          if (std::abs(v[k]) > (k < 3 ? 100. : 200. * M_PI))
            {
              std::ostringstream m;
              m << "strains of a rod: |nu| <= 100 and |kappa| <= 200 pi per unit length ("
                << kinematics::strain_names[k] << " = " << v[k] << " is not)";
              throw io::InputError("Rod strains", entry, text, m.str());
            }
      }
    } // namespace

    void
    RodStrainControl::parse_strain_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Rod strains");
      mode         = prm.get("Mode");
      if (mode == "natural shape")
        refuse_prescriptions_in_natural_shape(prm);
      const auto e = io::get_double_list(prm, "Strains", 6, "Rod strains");
      check_strain_sizes("Strains", prm.get("Strains"), {{e[0], e[1], e[2], e[3], e[4], e[5]}});
      std::copy(e.begin(), e.end(), target_strains.begin());
      {
        const auto n = io::get_double_list(prm, "Resultants", 6, "Rod strains");
        std::copy(n.begin(), n.end(), target_resultants.begin());
        for (unsigned int k = 0; k < 6; ++k)
          if (!std::isfinite(target_resultants[k]))
            throw io::InputError("Rod strains", "Resultants", prm.get("Resultants"),
                                 "six finite numbers");
      }
      const auto free_names = Utilities::split_string_list(prm.get("Free strains"), ',');
      strain_is_free.fill(mode == "natural shape");
      for (const auto &name : free_names)
        for (unsigned int k = 0; k < 6; ++k)
          if (kinematics::strain_names[k] == name)
            strain_is_free[k] = true;
      if (mode == "prescribed strains")
        {
          const auto ref = kinematics::RodStrains::reference().as_array();
          for (unsigned int k = 0; k < 6; ++k)
            if (strain_is_free[k] && target_strains[k] != ref[k])
              throw io::InputError("Rod strains", "Strains", prm.get("Strains"),
                                   kinematics::strain_names[k] +
                                     " is in 'Free strains' and set here to a value other "
                                     "than its reference: a strain is either prescribed or "
                                     "free (leave it at the reference value)");
          for (unsigned int k = 0; k < 6; ++k)
            if (!strain_is_free[k] && target_resultants[k] != 0)
              throw io::InputError("Rod strains", "Resultants", prm.get("Resultants"),
                                   kinematics::resultant_names[k] + " = " +
                                     io::format_number(target_resultants[k]) + " for the prescribed " +
                                     kinematics::strain_names[k] +
                                     ": a resultant can only be prescribed for a strain in 'Free "
                                     "strains' (a strain is prescribed or its resultant is)");
        }
      waypoints.clear();
      const std::string path_text = prm.get("Path");
      for (const auto &point : Utilities::split_string_list(path_text, ';'))
        {
          std::vector<double> v;
          try
            {
              v = Utilities::string_to_double(Utilities::split_string_list(point, ','));
            }
          catch (...)
            {}
          if (v.size() != 6)
            throw io::InputError("Rod strains", "Path", path_text,
                                 "waypoints of six numbers separated by ';' ('" + point +
                                   "' is not six numbers)");
          for (const double x : v)
            if (!std::isfinite(x))
              throw io::InputError("Rod strains", "Path", path_text,
                                   "waypoints of six finite numbers ('" + point +
                                     "' has nan or inf)");
          waypoints.push_back({{v[0], v[1], v[2], v[3], v[4], v[5]}});
          check_strain_sizes("Path", path_text, waypoints.back());
        }
      if (!waypoints.empty())
        {
          target_strains = waypoints.back();
          // A strip cannot be asked for a strain twice: free (its resultant
          // vanishes) and prescribed by the path.
          const auto ref = kinematics::RodStrains::reference().as_array();
          for (unsigned int k = 0; k < 6; ++k)
            if (strain_is_free[k])
              for (const auto &w : waypoints)
                if (w[k] != ref[k])
                  throw io::InputError("Rod strains", "Path", path_text,
                                       "the path prescribes " + kinematics::strain_names[k] +
                                         ", which 'Free strains' (or the natural-shape mode) "
                                         "leaves free: a strain is either prescribed or free");
        }
      prm.leave_subsection();
    }

    std::array<double, 6>
    RodStrainControl::prescribed_strains_at(const double t) const
    {
      const auto            ref = kinematics::RodStrains::reference().as_array();
      std::array<double, 6> e;
      if (waypoints.empty())
        {
          for (unsigned int k = 0; k < 6; ++k)
            e[k] = ref[k] + t * (target_strains[k] - ref[k]);
          return e;
        }
      // Piecewise linear through reference, waypoint 1, ..., waypoint K.
      const unsigned int K   = waypoints.size();
      const double       x   = std::min(std::max(t, 0.), 1.) * K;
      const unsigned int seg = std::min(static_cast<unsigned int>(x), K - 1);
      const auto &       a   = seg == 0 ? ref : waypoints[seg - 1];
      const auto &       b   = waypoints[seg];
      for (unsigned int k = 0; k < 6; ++k)
        e[k] = a[k] + (x - seg) * (b[k] - a[k]);
      return e;
    }

    std::array<double, 6>
    RodStrainControl::resultants_at(const double t) const
    {
      std::array<double, 6> n;
      for (unsigned int k = 0; k < 6; ++k)
        n[k] = strain_is_free[k] ? t * target_resultants[k] : 0.;
      return n;
    }

    std::array<double, 6>
    RodStrainControl::prescribed_strain_rate(const double t) const
    {
      const auto            ref = kinematics::RodStrains::reference().as_array();
      std::array<double, 6> r{};
      if (waypoints.empty())
        {
          for (unsigned int k = 0; k < 6; ++k)
            r[k] = target_strains[k] - ref[k];
          return r;
        }
      if (t < 0 || t > 1)
        return r;
      const unsigned int K   = waypoints.size();
      const unsigned int seg = std::min(static_cast<unsigned int>(t * K), K - 1);
      const auto &       a   = seg == 0 ? ref : waypoints[seg - 1];
      for (unsigned int k = 0; k < 6; ++k)
        r[k] = K * (waypoints[seg][k] - a[k]);
      return r;
    }
  } // namespace assembly
} // namespace cosmo

#ifndef cosmo_applications_plate_rod_parameters_h
#define cosmo_applications_plate_rod_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <cosmo/analysis/plate_rod_thresholds.h>
#include <cosmo/io/output.h>
#include <cosmo/kinematics/plate_model.h>
#include <cosmo/materials/plate_growth.h>
#include <cosmo/materials/plate_law.h>
#include <cosmo/materials/rod_growth.h>
#include <cosmo/materials/rod_law.h>
#include <cosmo/solvers/arclength.h>
#include <cosmo/solvers/newton.h>

#include <array>
#include <memory>
#include <string>

/**
 * The parameters of part 3, typed and parsed once (doc/user-guide-plate-rod.md):
 * the plate, its law and growth, the rim's law and growth, the model, the
 * mesh, the path and the output, with what follows from them alone (the
 * thickness, growth and laws at a point, the rim's natural state, the
 * mismatch and the closed forms). PlateRodProblem is a problem on these.
 */
namespace cosmo
{
  namespace plate_rod
  {
    using namespace dealii;

    struct PlateRodParameters
    {
      static void
      declare_parameters(ParameterHandler &prm);
      /// Reads and checks every entry (io::InputError naming the entry).
      void
      parse_parameters(ParameterHandler &prm);

      /// The plate's thickness at X ('Thickness' times 'Thickness profile').
      double
      thickness_at(const Point<2> &X) const;
      /// The plate law with the thickness at X.
      materials::PlateLawAt
      plate_law_at(const Point<2> &X) const
      {
        return materials::PlateLawAt(*plate_law, thickness_at(X));
      }
      kinematics::PlateGrowthAtPoint
      growth_at(const Point<2> &X, double t) const;
      double
      rod_growth_at(double t) const
      {
        return rim_growth->factor(t);
      }
      /// The closed-form Kirchhoff thresholds for this plate and rim (small strain).
      analysis::PlateRod
      closed_form_setting() const;
      /// The rim's law ('Rim rod / Law').
      const materials::RodLaw &
      rod_law() const
      {
        return *rim_law;
      }
      /// Where the rim's strains are measured from at X on the rim at load t:
      /// the discrete ring's reference strains, the rim's growth and, as
      /// weights on the shears, the square root of the model's shear factor
      /// (the Kirchhoff penalty: GA1, GA2 times the factor).
      materials::RodNaturalState
      rim_natural_state(const Point<2> &X, const kinematics::RimFrame &frame, double t) const;
      /// The closed-form thresholds for this problem (summary.json's "closed_form"), the first
      /// of them (NaN if the growth is not uniform and isotropic) and a text for the log.
      io::JSON
      closed_forms(double &first_mismatch, std::string &text) const;
      /// Mismatch Delta = plate growth strain - rod growth strain at load parameter t (uniform
      /// isotropic plate growth only; NaN otherwise).
      double
      mismatch(double t) const;
      /// io::InputError (entry 'Rim rod / Stiffnesses' = text) unless every rim stiffness is
      /// positive and at most 1e8 times the plate's.
      void
      check_rim_stiffness(const std::string &entry, const std::string &text) const;

      double                         radius = 1, thickness = 0.01;
      /// 'Plate / Thickness profile': h(X) = thickness f(x, y, r); null when f = 1.
      std::shared_ptr<FunctionParser<3>> thickness_profile;
      std::string                        thickness_profile_text = "1";
      std::string                    domain = "full disc";
      unsigned int                   sector_n = 2; ///< sector angle pi / sector_n
      std::string                    sector_mesh = "stretched"; ///< 'Mesh / Sector mesh'
      bool                           sector_as_full_disc = false; ///< plate VTUs: the sector's 2 n images
      unsigned int                   refinements = 3, degree = 2;
      /// 'Mesh / Distributed': the mesh divided over the MPI ranks (doc/parallel-runs.md).
      bool                           distributed_mesh = false;
      /// The registered plate model named by 'Model / Model' (kinematics/plate_model.h).
      std::unique_ptr<kinematics::PlateModel> model;
      /// 'Model / Shear integration' (assumed strain: assembly/assumed_shear.h).
      enum class ShearIntegration
      {
        assumed_strain, ///< tied on the edges and by interior moments (the default)
        interior_tying, ///< tied at interior Gauss points (MITC9 of Bucalem and Bathe)
        stabilized,
        reduced
      };
      ShearIntegration               shear_integration = ShearIntegration::assumed_strain;
      /// 'Model / Deformation = in-plane only': u3, theta1, theta2 held at 0.
      bool                           in_plane_only       = false;
      double                         shear_stabilization = 0.03;
      /// 'Plate material / Law'.
      std::shared_ptr<const materials::PlateLaw> plate_law;
      materials::PlateGrowth         plate_growth;
      /// 'Rim rod / Law' and 'Rim rod / Growth kind'.
      std::shared_ptr<const materials::RodLaw>       rim_law;
      std::shared_ptr<const materials::RodGrowthLaw> rim_growth;
      /// The rim law's stiffnesses in the natural state (the closed forms use
      /// them) and its largest coupling K_ab / sqrt(K_aa K_bb).
      std::array<double, 6>          rod_stiffness{{0.1, 0.1, 0.1, 1e-6, 1e-6, 1e-6}};
      double                         stiffness_coupling = 0;
      /// 'Rim rod / Stiffness file' (empty: not given).
      std::string                    stiffness_file;
      double                         path_start = 0;
      bool                           stop_at_first_event = false;
      solvers::NewtonSettings        newton_settings;
      solvers::ArclengthSettings     arclength_settings;
      std::string                    output_directory;
    };
  } // namespace plate_rod
} // namespace cosmo

#endif

// One of the two translation units that instantiate the nested Sacado types
// (with surface_layer.cc; energy_derivatives.h): the expensive ones to compile.
#include <deal.II/base/utilities.h>

#include <cosmo/io/parameters.h>
#include <cosmo/materials/material.h>

#include <cosmo/materials/energy_derivatives.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace cosmo
{
  namespace plugins
  {
    template class Registry<materials::HyperelasticLaw>;
  } // namespace plugins

  namespace materials
  {
    namespace
    {
      // Fe = F Fg^-1 for a constant Fg^-1, in the AD number type.
      template <typename Number>
      std::array<Number, 9>
      elastic_part(const std::array<Number, 9> &F, const Tensor<2, 3> &Fg_inv)
      {
        std::array<Number, 9> Fe;
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            {
              Number s = F[3 * i] * Fg_inv[0][j];
              s += F[3 * i + 1] * Fg_inv[1][j];
              s += F[3 * i + 2] * Fg_inv[2][j];
              Fe[3 * i + j] = s;
            }
        return Fe;
      }
    } // namespace

    void
    GrowingMaterial::evaluate(const Tensor<2, 3> &F,
                              const Tensor<2, 3> &Fg,
                              const bool          tangent,
                              EnergyDerivatives & out) const
    {
      const double       Jg     = determinant(Fg);
      const Tensor<2, 3> Fg_inv = invert(Fg);
      // Admissibility first, in plain doubles: the log of a non-positive J
      // would turn every derivative into NaN.
      const double J = determinant(F);
      out.admissible = (J > 0 && Jg > 0);
      if (!out.admissible)
        {
          out.energy = std::numeric_limits<double>::infinity();
          return;
        }
      std::array<double, 9> f;
      for (unsigned int a = 0; a < 9; ++a)
        f[a] = F[a / 3][a % 3];
      internal::differentiate<9>(
        f,
        [&](const auto &x) { return Jg * law->energy(elastic_part(x, Fg_inv)); },
        tangent, out.energy, out.P, out.C);
    }

    std::shared_ptr<const HyperelasticLaw>
    HyperelasticLaw::create(const std::string &name, const double young, const double poisson)
    {
      std::shared_ptr<HyperelasticLaw> l = plugins::Registry<HyperelasticLaw>::create(name);
      l->mu     = young / (2 * (1 + poisson));
      l->lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
      return l;
    }

    void
    MaterialLibrary::declare_parameters(ParameterHandler &prm)
    {
      for (unsigned int k = 1; k <= max_materials; ++k)
        {
          prm.enter_subsection("Material " + std::to_string(k));
          prm.declare_entry("Regions",
                            k == 1 ? "1" : "",
                            Patterns::Anything(),
                            "Comma-separated regions of the cross-section made of this "
                            "material, each a region (material) id 0..255 or a region "
                            "name. Built-in sections: id 1 (and 2 for the second region of "
                            "two-region sections), names `section` (single-region shapes), "
                            "`lower`/`upper` (bilayer), `left`/`right` (half disc). gmsh "
                            "meshes: physical surface tags, or their physical names. "
                            "Empty: this section is unused.");
          prm.declare_entry("Name", "material " + std::to_string(k), Patterns::Anything(),
                            "A name for output.");
          prm.declare_entry("Hyperelastic law",
                            "neo-Hookean",
                            Patterns::Selection(plugins::Registry<HyperelasticLaw>::names()),
                            "Stored energy of the elastic part Fe (the registered laws, "
                            "source/materials/hyperelastic_laws/). " +
                              plugins::Registry<HyperelasticLaw>::documentation());
          prm.declare_entry("Young's modulus", "1", Patterns::Double(0),
                            "Small-strain Young's modulus E (units of stress; the "
                            "resultants come out in E times length^2, moments E length^3).");
          prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-0.999, 0.49999),
                            "Small-strain Poisson's ratio (below 1/2; nearly "
                            "incompressible materials need element degree >= 2).");
          prm.declare_entry("Density", "1", Patterns::Double(0),
                            "Mass per reference volume (only for the section's mass "
                            "properties: mass per length, mass centre, mass moments).");
          GrowthTensor::declare_parameters(prm);
          prm.leave_subsection();
        }
    }

    void
    MaterialLibrary::parse_parameters(ParameterHandler &prm)
    {
      materials.clear();
      region_lists.clear();
      region_to_material.clear();
      for (unsigned int k = 1; k <= max_materials; ++k)
        {
          const std::string section = "Material " + std::to_string(k);
          prm.enter_subsection(section);
          const std::string text = prm.get("Regions");
          std::vector<std::string> items;
          for (const auto &item : Utilities::split_string_list(text, ','))
            if (!item.empty())
              items.push_back(item);
          // Integer ids are checked and mapped now, as before names existed;
          // names wait for resolve_regions(). Something that starts like a
          // number but is not a region id is an error here.
          std::vector<int> regions;
          for (const auto &item : items)
            {
              const bool numeric = std::isdigit(static_cast<unsigned char>(item[0])) ||
                                   item[0] == '-' || item[0] == '+' || item[0] == '.';
              if (!numeric)
                continue;
              const bool digits =
                std::all_of(item.begin(), item.end(), [](unsigned char c) {
                  return std::isdigit(c);
                });
              if (!digits || item.size() > 3 || std::stoi(item) > 255)
                throw io::InputError(section, "Regions", text,
                                     "'" + item + "' is neither a region id (an integer "
                                                  "0..255) nor a region name");
              regions.push_back(std::stoi(item));
            }
          if (!items.empty())
            {
              GrowingMaterial m;
              m.name    = prm.get("Name");
              m.section = section;
              const double E = prm.get_double("Young's modulus");
              if (!(E > 0 && E <= 1e100))
                throw io::InputError(section, "Young's modulus", prm.get("Young's modulus"),
                                     "must be positive and at most 1e100 (its products with "
                                     "itself and the lengths must stay finite in double "
                                     "precision)");
              m.law = HyperelasticLaw::create(prm.get("Hyperelastic law"), E,
                                              prm.get_double("Poisson's ratio"));
              m.growth.parse_parameters(prm, section);
              m.density = prm.get_double("Density");
              for (const int r : regions)
                {
                  if (region_to_material.count(r))
                    throw io::InputError(section, "Regions", prm.get("Regions"),
                                         "region " + std::to_string(r) +
                                           " is already given to Material " +
                                           std::to_string(region_to_material[r] + 1));
                  region_to_material[r] = materials.size();
                }
              materials.push_back(std::move(m));
              region_lists.push_back({section, text, items});
            }
          prm.leave_subsection();
        }
      if (materials.empty())
        throw io::InputError("Material 1", "Regions", "", "at least one material needs regions");
    }

    void
    MaterialLibrary::resolve_regions(const std::map<std::string, types::material_id> &names)
    {
      auto available = [&names]() {
        if (names.empty())
          return std::string("no named regions (use region ids)");
        std::string list;
        for (const auto &n : names)
          list += (list.empty() ? "" : ", ") + n.first + " (" +
                  std::to_string(static_cast<unsigned int>(n.second)) + ")";
        return list;
      };
      region_to_material.clear();
      for (unsigned int m = 0; m < region_lists.size(); ++m)
        {
          const RegionList &list = region_lists[m];
          for (const auto &item : list.items)
            {
              // Ids were validated by parse_parameters().
              types::material_id r;
              std::string        label;
              if (std::isdigit(static_cast<unsigned char>(item[0])))
                {
                  r     = static_cast<types::material_id>(std::stoi(item));
                  label = "region " + item;
                }
              else
                {
                  const auto it = names.find(item);
                  if (it == names.end())
                    throw io::InputError(list.section, "Regions", list.text,
                                         "unknown region '" + item +
                                           "'; this section has: " + available());
                  r     = it->second;
                  label = "region '" + item + "' (" +
                          std::to_string(static_cast<unsigned int>(r)) + ")";
                }
              if (region_to_material.count(r))
                throw io::InputError(list.section, "Regions", list.text,
                                     label + " is already given to " +
                                       materials[region_to_material[r]].section);
              region_to_material[r] = m;
            }
        }
    }

    const GrowingMaterial &
    MaterialLibrary::material(const types::material_id region) const
    {
      const auto it = region_to_material.find(region);
      if (it == region_to_material.end())
        throw io::InputError("Material 1..4", "Regions", "",
                             "no material covers region " + std::to_string(region) +
                               " of the mesh");
      return materials[it->second];
    }

    void
    MaterialLibrary::check_regions(const std::vector<types::material_id> &ids) const
    {
      for (const auto id : ids)
        material(id);
    }

    double
    MaterialLibrary::max_young() const
    {
      double E = 0;
      for (const auto &m : materials)
        E = std::max(E, m.law->young());
      return E;
    }

    std::vector<std::string>
    MaterialLibrary::descriptions() const
    {
      std::vector<std::string> d;
      for (const auto &m : materials)
        {
          std::ostringstream s;
          s << m.name << ": "
            << m.law->name() << ", E = " << m.law->young() << ", Poisson " << m.law->poisson()
            << ", growth "
            << m.growth.description();
          d.push_back(s.str());
        }
      return d;
    }
  } // namespace materials
} // namespace cosmo

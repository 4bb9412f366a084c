// The rectangle Width x Height, and the bilayer: the same rectangle in two layers.
#include <deal.II/grid/grid_generator.h>

#include <cosmo/geometry/section_shape.h>
#include <cosmo/io/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace cosmo
{
  namespace geometry
  {
    namespace
    {
      unsigned int
      repetitions(const double length, const double cell)
      {
        return std::max(1, static_cast<int>(std::lround(length / cell)));
      }

      /// The nearest side of the box (left 0, right 1, bottom 2, top 3),
      /// which is robust to round-off in the refined vertices.
      types::boundary_id
      rectangle_side(const Point<2> &c, const double width, const double height)
      {
        const std::array<double, 4> d = {{std::abs(c[0] + width / 2),
                                          std::abs(c[0] - width / 2),
                                          std::abs(c[1] + height / 2),
                                          std::abs(c[1] - height / 2)}};
        return static_cast<types::boundary_id>(std::min_element(d.begin(), d.end()) -
                                               d.begin());
      }
    } // namespace

    class RectangleSection : public SectionShape
    {
    public:
      void
      parse_parameters(ParameterHandler &prm) override
      {
        width  = get_positive_length(prm, "Width");
        height = get_positive_length(prm, "Height");
      }

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        // Nearly square cells.
        const double                     cell = std::min(width, height);
        const unsigned int               nx = repetitions(width, cell), ny = repetitions(height, cell);
        std::vector<std::vector<double>> steps = {std::vector<double>(nx, width / nx),
                                                  std::vector<double>(ny, height / ny)};
        return mesh(tria, steps, refinements, {{"section", 1}}, nullptr);
      }

    protected:
      SectionMesh
      mesh(Triangulation<2> &                                         tria,
           const std::vector<std::vector<double>> &                   steps,
           const unsigned int                                         refinements,
           const std::map<std::string, types::material_id> &          regions,
           const std::function<types::material_id(const Point<2> &)> &region_of) const
      {
        GridGenerator::subdivided_hyper_rectangle(tria, steps,
                                                  Point<2>(-width / 2, -height / 2),
                                                  Point<2>(width / 2, height / 2));
        tria.refine_global(refinements);
        const double w = width, h = height;
        return label_builtin_mesh(tria, regions, region_of,
                                  {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}},
                                  [w, h](const Point<2> &c) { return rectangle_side(c, w, h); });
      }

      double width = 1, height = 1;
    };

    /// Two layers, the interface a mesh line at X2 = -Height/2 + Layer fraction Height.
    class BilayerSection : public RectangleSection
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry("Layer fraction", "0.5", Patterns::Double(0, 1),
                          "Bilayer: thickness fraction of the lower layer (region 1).");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        RectangleSection::parse_parameters(prm);
        layer_fraction = prm.get_double("Layer fraction");
        if (!(layer_fraction > 0 && layer_fraction < 1))
          throw io::InputError("Cross-section", "Layer fraction", prm.get("Layer fraction"),
                               "must lie strictly between 0 and 1");
      }

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        // One row of cells per layer, about square.
        const double                     cell = std::min(width, height) / 2;
        const unsigned int               nx   = repetitions(width, cell);
        std::vector<std::vector<double>> steps = {
          std::vector<double>(nx, width / nx),
          {layer_fraction * height, (1 - layer_fraction) * height}};
        const double y_interface = -height / 2 + layer_fraction * height;
        return mesh(tria, steps, refinements, {{"lower", 1}, {"upper", 2}},
                    [y_interface](const Point<2> &c) {
                      return types::material_id(c[1] < y_interface ? 1 : 2);
                    });
      }

    private:
      double layer_fraction = 0.5;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          RectangleSection,
                          "rectangle",
                          "the rectangle `Width` (along X1) x `Height` (along X2); region "
                          "`section` = 1, boundary parts `left` = 0, `right` = 1, `bottom` = 2, "
                          "`top` = 3.")
    COSMO_REGISTER_PLUGIN(SectionShape,
                          BilayerSection,
                          "bilayer",
                          "the rectangle in two layers, `lower` = 1 below and `upper` = 2 above "
                          "X2 = -Height/2 + `Layer fraction` Height; boundary parts as the "
                          "rectangle's.")
  } // namespace geometry
} // namespace cosmo

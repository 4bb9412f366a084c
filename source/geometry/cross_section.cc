#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <cosmo/geometry/cross_section.h>
#include <cosmo/io/parameters.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <csignal>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <regex>
#include <sstream>

namespace cosmo
{
  namespace geometry
  {
    namespace
    {
      /**
       * The boundary of an ellipse x = a r cos(p), y = b r sin(p), as a chart
       * in (r, p): new boundary points stay on r = 1. Periodic in p.
       */
      class EllipseManifold : public ChartManifold<2, 2, 2>
      {
      public:
        EllipseManifold(const double a, const double b)
          : ChartManifold<2, 2, 2>(Tensor<1, 2>({0., 2 * M_PI}))
          , a(a)
          , b(b)
        {}
        std::unique_ptr<Manifold<2, 2>>
        clone() const override
        {
          return std::make_unique<EllipseManifold>(a, b);
        }
        Point<2>
        pull_back(const Point<2> &x) const override
        {
          const double u = x[0] / a, v = x[1] / b;
          double       p = std::atan2(v, u);
          if (p < 0)
            p += 2 * M_PI;
          return Point<2>(std::sqrt(u * u + v * v), p);
        }
        Point<2>
        push_forward(const Point<2> &c) const override
        {
          return Point<2>(a * c[0] * std::cos(c[1]), b * c[0] * std::sin(c[1]));
        }

      private:
        double a, b;
      };

      unsigned int
      repetitions(const double length, const double cell)
      {
        return std::max(1, static_cast<int>(std::lround(length / cell)));
      }

      bool
      is_geo_file(const std::string &file)
      {
        std::string ext = std::filesystem::path(file).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) {
          return std::tolower(c);
        });
        return ext == ".geo";
      }

      /// The executable for `program`: itself if it contains a '/', else
      /// the first match in PATH; empty if there is none.
      std::string
      find_program(const std::string &program)
      {
        if (program.empty())
          return "";
        if (program.find('/') != std::string::npos)
          return ::access(program.c_str(), X_OK) == 0 ? program : "";
        const char *path = std::getenv("PATH");
        for (const auto &dir : Utilities::split_string_list(path ? path : "", ':'))
          {
            const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
            if (::access(candidate.c_str(), X_OK) == 0 &&
                !std::filesystem::is_directory(candidate))
              return candidate;
          }
        return "";
      }

      /// Quote for /bin/sh: file names may contain blanks or quotes.
      std::string
      shell_quote(const std::string &s)
      {
        std::string q = "'";
        for (const char c : s)
          q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
        return q + "'";
      }

      /// A fresh directory under the system temporary directory, removed
      /// (with its contents) when this object goes out of scope, also when
      /// meshing fails with an exception.
      class TemporaryDirectory
      {
      public:
        TemporaryDirectory()
        {
          // Unique across processes (pid, clock, random) and within one
          // (counter); create_directory fails if the name is taken.
          static unsigned int counter = 0;
          std::random_device  random;
          const auto          base = std::filesystem::temp_directory_path();
          for (unsigned int attempt = 0; attempt < 100; ++attempt)
            {
              const std::string name =
                "cosmo-gmsh-" + std::to_string(::getpid()) + "-" +
                std::to_string(counter++) + "-" + std::to_string(random() % 1000000) + "-" +
                std::to_string(
                  std::chrono::steady_clock::now().time_since_epoch().count() % 1000000);
              std::error_code ec;
              if (std::filesystem::create_directory(base / name, ec))
                {
                  path = base / name;
                  return;
                }
            }
          throw std::runtime_error("cannot create a temporary directory in " +
                                   base.string());
        }
        ~TemporaryDirectory()
        {
          std::error_code ec;
          std::filesystem::remove_all(path, ec);
        }
        TemporaryDirectory(const TemporaryDirectory &) = delete;
        TemporaryDirectory &
        operator=(const TemporaryDirectory &) = delete;

        std::filesystem::path path;
      };

      /// What a gmsh log says about a failure: its error lines without the
      /// summary boilerplate, or else its last lines.
      std::string
      gmsh_output_tail(const std::string &log_file)
      {
        std::ifstream            in(log_file);
        std::vector<std::string> lines, errors;
        for (std::string line; std::getline(in, line);)
          {
            while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
              line.pop_back();
            if (line.empty())
              continue;
            lines.push_back(line);
            static const std::regex boilerplate(
              "Error *: *(-+|Mesh generation error summary|[0-9]+ (warning|error)s?|"
              "Check the full log.*)");
            if (line.rfind("Error", 0) == 0 && !std::regex_match(line, boilerplate))
              errors.push_back(line);
          }
        const auto &shown = errors.empty() ? lines : errors;
        std::string tail;
        for (std::size_t i = shown.size() > 5 ? shown.size() - 5 : 0; i < shown.size(); ++i)
          tail += "\n    " + shown[i];
        return tail.empty() ? " (no output)" : tail;
      }

      /**
       * Mesh the .geo `geo` into `directory`/section.msh, an all-quadrilateral
       * first-order mesh in MSH 2.2: triangles are recombined
       * (RecombineAll) and everything is then split into quadrilaterals
       * (SubdivisionAlgorithm 1, which also halves the element size), since
       * deal.II's Triangulation<2> here needs quadrilaterals.
       * Returns the .msh path; throws a std::runtime_error with gmsh's
       * messages if gmsh fails.
       */
      std::string
      run_gmsh(const std::string &          program,
               const std::string &          geo,
               const double                 mesh_size,
               const std::filesystem::path &directory,
               std::string &                summary)
      {
        const std::string msh = (directory / "section.msh").string();
        const std::string log = (directory / "gmsh.log").string();
        std::ostringstream size;
        size.precision(17);
        size << mesh_size;
        // Mesh.Algorithm 8 (Frontal-Delaunay for quads) gives the best
        // quadrilaterals, but some builds (Debian's gmsh 4.8.4) crash in it;
        // then Frontal-Delaunay (6), which recombines just as well here.
        std::string crashed;
        for (const int algorithm : {8, 6})
          {
            std::string options =
              " -2 -format msh22 -setnumber Mesh.RecombineAll 1"
              " -setnumber Mesh.SubdivisionAlgorithm 1 -setnumber Mesh.Algorithm " +
              std::to_string(algorithm);
            if (mesh_size > 0)
              options += " -clmax " + size.str() +
                         " -setnumber Mesh.CharacteristicLengthMax " + size.str();
            const std::string command = shell_quote(program) + " " + shell_quote(geo) + options +
                                        " -o " + shell_quote(msh) + " < /dev/null > " +
                                        shell_quote(log) + " 2>&1";
            std::error_code ec;
            std::filesystem::remove(msh, ec);
            const int status = std::system(command.c_str());
            if (status == -1)
              throw std::runtime_error("cannot start the gmsh program '" + program + "'");
            // The shell reports a signal of its child as 128 + signal.
            const int signal = WIFSIGNALED(status) ? WTERMSIG(status) :
                               (WIFEXITED(status) && WEXITSTATUS(status) > 128) ?
                                                     WEXITSTATUS(status) - 128 :
                                                     0;
            // std::system ignores SIGINT/SIGQUIT in this process while gmsh
            // runs; a user's Ctrl-C that killed gmsh is passed on, not taken
            // for a crash or for bad input.
            if (signal == SIGINT || signal == SIGQUIT || signal == SIGTERM)
              {
                std::error_code ignore;
                std::filesystem::remove_all(directory, ignore);
                std::raise(signal);
              }
            const bool crashed_here = (signal == SIGSEGV || signal == SIGABRT ||
                                       signal == SIGBUS || signal == SIGFPE ||
                                       signal == SIGILL);
            if (crashed_here && algorithm == 8)
              {
                crashed = " (gmsh crashed with Mesh.Algorithm 8, used 6)";
                continue;
              }
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
                !std::filesystem::exists(msh))
              throw std::runtime_error(
                "gmsh failed to mesh this file (exit status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status) +
                ", run as: " + program + " " + geo + options + "); gmsh says:" +
                gmsh_output_tail(log));
            summary = "meshed by " + program + " with Mesh.Algorithm " +
                      std::to_string(algorithm) + crashed +
                      (mesh_size > 0 ? ", mesh size " + size.str() : std::string());
            return msh;
          }
        throw std::runtime_error("gmsh crashed (with Mesh.Algorithm 8 and 6); gmsh says:" +
                                 gmsh_output_tail(log));
      }

      /// What deal.II's reader does not check: the physical names, and
      /// whether all cells are first-order quadrilaterals.
      struct MshContents
      {
        std::map<std::string, types::boundary_id> boundary_names;
        std::map<std::string, types::material_id> region_names;
        unsigned int                              n_quadrilaterals = 0;
        std::map<std::string, unsigned int>       n_unsupported; ///< by kind
      };

      /**
       * Scan an ASCII .msh (format 2 or 4): `$PhysicalNames` (lines
       * `dim tag "name"`) and the element types in `$Elements`. gmsh element
       * types: 3 is the 4-node quadrilateral; 1, 8, 26-28 (lines) and 15
       * (points) are lower-dimensional; anything else is a cell deal.II
       * cannot use here.
       */
      MshContents
      scan_msh(const std::string &file)
      {
        std::ifstream in(file);
        if (!in)
          throw std::runtime_error("cannot open this file");
        MshContents c;
        double      version = 0;
        auto        next    = [&](std::string &line) {
          if (!std::getline(in, line))
            throw std::runtime_error("the file ends inside a section");
          while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
        };
        auto count_type = [&](const int type) {
          if (type == 3)
            ++c.n_quadrilaterals;
          else if (type == 2 || type == 9 || (type >= 20 && type <= 25))
            ++c.n_unsupported["triangles"];
          else if (type == 10 || type == 16 || (type >= 36 && type <= 41))
            ++c.n_unsupported["higher-order quadrilaterals"];
          else if (!(type == 1 || type == 8 || type == 15 || (type >= 26 && type <= 28)))
            ++c.n_unsupported["3d or other elements (type " + std::to_string(type) + ")"];
        };
        std::string line;
        while (std::getline(in, line))
          {
            while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
              line.pop_back();
            if (line == "$MeshFormat")
              {
                next(line);
                std::istringstream s(line);
                int                file_type = 0;
                s >> version >> file_type;
                if (!s || file_type != 0)
                  throw std::runtime_error("not an ASCII gmsh mesh (save it with "
                                           "Mesh.Binary = 0)");
              }
            else if (line == "$PhysicalNames")
              {
                next(line);
                const int n = Utilities::string_to_int(line);
                for (int i = 0; i < n; ++i)
                  {
                    next(line);
                    std::istringstream s(line);
                    int                dim = -1, tag = -1;
                    s >> dim >> tag;
                    const auto a = line.find('"'), b = line.rfind('"');
                    if (!s || a == std::string::npos || b <= a)
                      throw std::runtime_error("bad $PhysicalNames line '" + line + "'");
                    const std::string name = line.substr(a + 1, b - a - 1);
                    if (dim == 1)
                      c.boundary_names[name] = static_cast<types::boundary_id>(tag);
                    else if (dim == 2)
                      c.region_names[name] = static_cast<types::material_id>(tag);
                  }
              }
            else if (line == "$Elements")
              {
                next(line);
                std::istringstream header(line);
                long               n_blocks = 0;
                header >> n_blocks;
                if (version < 4)
                  // n, then `id type n_tags tags... nodes...` per element
                  for (long i = 0; i < n_blocks; ++i)
                    {
                      next(line);
                      std::istringstream s(line);
                      long               id = 0;
                      int                type = 0;
                      s >> id >> type;
                      count_type(type);
                    }
                else
                  // blocks `dim tag type n` (4.1; 4.0 swaps dim and tag),
                  // each followed by its n elements
                  for (long i = 0; i < n_blocks; ++i)
                    {
                      next(line);
                      std::istringstream s(line);
                      long               a = 0, b = 0, n = 0;
                      int                type = 0;
                      s >> a >> b >> type >> n;
                      for (long e = 0; e < n; ++e)
                        {
                          next(line);
                          count_type(type);
                        }
                    }
              }
          }
        if (version == 0)
          throw std::runtime_error("no $MeshFormat section: not a gmsh .msh file");
        return c;
      }

      /// Face classification for the built-in rectangle and bilayer: the
      /// nearest side of the box, which is robust to round-off in the
      /// refined vertices.
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

    void
    CrossSectionGeometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cross-section");
      prm.declare_entry("Shape",
                        "circle",
                        Patterns::Selection(
                          "circle|ellipse|rectangle|annulus|bilayer|half disc|gmsh"),
                        "circle (Radius), ellipse (Semi-axes, along X1 and X2), "
                        "rectangle (Width along X1, Height along X2), annulus (Radius, "
                        "Inner radius), bilayer (rectangle; region 1 below, region 2 "
                        "above X2 = -Height/2 + Layer fraction*Height), half disc (circle; "
                        "region 1 for X1 < 0, region 2 for X1 > 0), gmsh (Mesh file). "
                        "Built-in single-region shapes are region 1. Names usable for "
                        "Regions and boundary selections: regions `section` (single-region "
                        "shapes), `lower`/`upper` (bilayer), `left`/`right` (half disc); "
                        "boundary parts `outer` (circle, ellipse, half disc, annulus), "
                        "`inner` (annulus), `left`/`right`/`bottom`/`top` (rectangle, "
                        "bilayer); gmsh: its physical names.");
      prm.declare_entry("Radius", "1", Patterns::Double(0), "Outer radius (length unit).");
      prm.declare_entry("Semi-axes", "1, 0.5", Patterns::List(Patterns::Double(0), 2, 2),
                        "Ellipse semi-axes a (along X1), b (along X2).");
      prm.declare_entry("Width", "1", Patterns::Double(0), "Extent along X1 (rectangle, bilayer).");
      prm.declare_entry("Height", "1", Patterns::Double(0), "Extent along X2 (rectangle, bilayer).");
      prm.declare_entry("Inner radius", "0.5", Patterns::Double(0), "Annulus inner radius.");
      prm.declare_entry("Layer fraction", "0.5", Patterns::Double(0, 1),
                        "Bilayer: thickness fraction of the lower layer (region 1).");
      prm.declare_entry("Mesh file", "", Patterns::Anything(),
                        "The section when Shape = gmsh: an ASCII gmsh .msh (format 2 or 4) "
                        "of quadrilaterals, or a gmsh .geo, which is meshed by running "
                        "`Gmsh program` (2D, all quadrilaterals: triangles recombined, then "
                        "every element subdivided into quadrilaterals; see Mesh size). "
                        "Physical surface tags are the region ids and physical line tags "
                        "the boundary ids; physical names can be used for Regions and "
                        "boundary selections. The deal.II mesh is straight-sided: curved "
                        "boundaries are polygons, a geometry error of O(h^2) in the element "
                        "size h (refinement does not reduce it), whatever the element "
                        "degree (`Polynomial degree` of the application). A relative path "
                        "is relative to the working directory.");
      prm.declare_entry("Gmsh program", "gmsh", Patterns::Anything(),
                        "The gmsh executable used to mesh a .geo Mesh file: a name looked "
                        "up in PATH, or a path.");
      prm.declare_entry("Mesh size", "0", Patterns::Double(0),
                        "Maximum element size (length unit) gmsh may use for a .geo "
                        "(-clmax); 0: the sizes the .geo gives its points. The quadrilateral "
                        "subdivision halves the elements again, so cells come out about "
                        "half this size.");
      prm.declare_entry("Global refinements", "3", Patterns::Integer(0, 10),
                        "Uniform refinements of the coarse mesh (each quarters the cells).");
      prm.leave_subsection();
    }

    void
    CrossSectionGeometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Cross-section");
      shape       = prm.get("Shape");
      radius      = prm.get_double("Radius");
      const auto ab = io::get_double_list(prm, "Semi-axes", 2, "Cross-section");
      semi_axis_1 = ab[0];
      semi_axis_2 = ab[1];
      width          = prm.get_double("Width");
      height         = prm.get_double("Height");
      inner_radius   = prm.get_double("Inner radius");
      layer_fraction = prm.get_double("Layer fraction");
      mesh_file      = prm.get("Mesh file");
      gmsh_program   = prm.get("Gmsh program");
      mesh_size      = prm.get_double("Mesh size");
      refinements    = prm.get_integer("Global refinements");
      auto positive  = [&](const std::string &entry, double v) {
        if (!(v > 0))
          throw io::InputError("Cross-section", entry, prm.get(entry), "must be positive");
      };
      if (shape == "circle" || shape == "half disc" || shape == "annulus")
        positive("Radius", radius);
      if (shape == "rectangle" || shape == "bilayer")
        {
          positive("Width", width);
          positive("Height", height);
        }
      if (shape == "ellipse" && !(semi_axis_1 > 0 && semi_axis_2 > 0))
        throw io::InputError("Cross-section", "Semi-axes", prm.get("Semi-axes"),
                             "two positive numbers");
      if (shape == "annulus" && !(inner_radius > 0 && inner_radius < radius))
        throw io::InputError("Cross-section", "Inner radius", prm.get("Inner radius"),
                             "must lie between 0 and Radius = " + prm.get("Radius"));
      if (shape == "bilayer" && !(layer_fraction > 0 && layer_fraction < 1))
        throw io::InputError("Cross-section", "Layer fraction", prm.get("Layer fraction"),
                             "must lie strictly between 0 and 1");
      if (shape == "gmsh")
        {
          // Fail at parse time for what can be checked without meshing.
          std::ifstream in(mesh_file);
          if (!in)
            throw io::InputError("Cross-section", "Mesh file", mesh_file,
                                 "cannot open this file (an ASCII gmsh .msh or a gmsh .geo "
                                 "is expected; a relative path is relative to the working "
                                 "directory)");
          if (is_geo_file(mesh_file) && find_program(gmsh_program).empty())
            throw io::InputError("Cross-section", "Mesh file", mesh_file,
                                 "a .geo needs the gmsh program, but 'Gmsh program' = '" +
                                   gmsh_program +
                                   "' is not found (install gmsh, or give its path)");
        }
      prm.leave_subsection();
    }

    void
    CrossSectionGeometry::create_triangulation(Triangulation<2> &tria) const
    {
      tria.clear();
      if (shape == "circle" || shape == "half disc")
        {
          GridGenerator::hyper_ball(tria, Point<2>(), radius);
        }
      else if (shape == "ellipse")
        {
          GridGenerator::hyper_ball(tria, Point<2>(), 1.0);
          const double a = semi_axis_1, b = semi_axis_2;
          GridTools::transform([a, b](const Point<2> &p) { return Point<2>(a * p[0], b * p[1]); },
                               tria);
          tria.set_manifold(0, EllipseManifold(a, b));
          TransfiniteInterpolationManifold<2> interior;
          interior.initialize(tria);
          tria.set_manifold(1, interior);
        }
      else if (shape == "annulus")
        {
          GridGenerator::hyper_shell(tria, Point<2>(), inner_radius, radius, 0, true);
        }
      else if (shape == "rectangle" || shape == "bilayer")
        {
          // Nearly square cells; the bilayer interface is a mesh line.
          const double cell = std::min(width, height) /
                              (shape == "bilayer" ? 2. : 1.);
          std::vector<std::vector<double>> steps(2);
          const unsigned int nx = repetitions(width, cell);
          steps[0].assign(nx, width / nx);
          if (shape == "rectangle")
            {
              const unsigned int ny = repetitions(height, cell);
              steps[1].assign(ny, height / ny);
            }
          else
            steps[1] = {layer_fraction * height, (1 - layer_fraction) * height};
          GridGenerator::subdivided_hyper_rectangle(tria, steps,
                                                    Point<2>(-width / 2, -height / 2),
                                                    Point<2>(width / 2, height / 2));
        }
      else if (shape == "gmsh")
        {
          auto fail = [&](const std::string &reason) {
            throw io::InputError("Cross-section", "Mesh file", mesh_file, reason);
          };
          if (!std::filesystem::exists(mesh_file))
            fail("this file does not exist (a relative path is relative to the working "
                 "directory)");
          // A .geo is meshed into a temporary directory that lives until the
          // mesh has been read (and is removed also if that fails).
          std::unique_ptr<TemporaryDirectory> scratch;
          std::string                         msh = mesh_file;
          meshing_summary.clear();
          if (is_geo_file(mesh_file))
            {
              const std::string program = find_program(gmsh_program);
              if (program.empty())
                fail("a .geo needs the gmsh program, but 'Gmsh program' = '" + gmsh_program +
                     "' is not found (install gmsh, or give its path)");
              try
                {
                  scratch = std::make_unique<TemporaryDirectory>();
                  msh = run_gmsh(program, mesh_file, mesh_size, scratch->path, meshing_summary);
                }
              catch (std::exception &e)
                {
                  fail(e.what());
                }
            }
          MshContents contents;
          try
            {
              contents = scan_msh(msh);
            }
          catch (std::exception &e)
            {
              fail(std::string("not a readable ASCII gmsh mesh: ") + e.what());
            }
          if (!contents.n_unsupported.empty())
            {
              std::string what;
              for (const auto &k : contents.n_unsupported)
                what += (what.empty() ? "" : ", ") + std::to_string(k.second) + " " + k.first;
              fail("the mesh has " + what + " besides " +
                   std::to_string(contents.n_quadrilaterals) +
                   " first-order quadrilaterals; only those can be used (in the .geo: "
                   "Recombine Surface, or mesh the .geo here, which makes quadrilaterals)");
            }
          if (contents.n_quadrilaterals == 0)
            fail("the mesh has no 2D cells (no surface was meshed; in a .geo, check that "
                 "the curve loops are closed and the Plane Surface is defined)");
          GridIn<2>     grid_in(tria);
          std::ifstream in(msh);
          try
            {
              grid_in.read_msh(in);
            }
          catch (std::exception &e)
            {
              fail(std::string("not a readable ASCII gmsh mesh: ") + e.what());
            }
          if (tria.n_active_cells() == 0 || !tria.all_reference_cells_are_hyper_cube())
            fail("the mesh read has no cells or cells that are not quadrilaterals");
          if (!meshing_summary.empty())
            meshing_summary += ", " + std::to_string(tria.n_active_cells()) + " cells";
          boundary_parts = contents.boundary_names;
          regions        = contents.region_names;
        }

      // Region ids: everything is region 1 unless the shape has two regions.
      if (shape != "gmsh")
        for (const auto &cell : tria.active_cell_iterators())
          cell->set_material_id(1);
      tria.refine_global(refinements);
      if (shape == "bilayer")
        {
          const double y_interface = -height / 2 + layer_fraction * height;
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_material_id(cell->center()[1] < y_interface ? 1 : 2);
        }
      else if (shape == "half disc")
        {
          if (refinements == 0)
            throw io::InputError("Cross-section", "Global refinements", "0",
                                 "a half disc needs at least 1 refinement so that X1 = 0 "
                                 "is a mesh line");
          for (const auto &cell : tria.active_cell_iterators())
            cell->set_material_id(cell->center()[0] < 0 ? 1 : 2);
        }

      // Boundary ids and names of the built-in shapes, from the face centres
      // of the refined mesh (so they do not depend on how GridGenerator
      // colours its coarse mesh; later uniform refinement keeps them).
      if (shape != "gmsh")
        {
          boundary_parts.clear();
          regions.clear();
          std::function<types::boundary_id(const Point<2> &)> id_of =
            [](const Point<2> &) { return types::boundary_id(0); };
          if (shape == "annulus")
            {
              boundary_parts = {{"outer", 0}, {"inner", 1}};
              const double r_mid = (inner_radius + radius) / 2;
              id_of = [r_mid](const Point<2> &c) {
                return types::boundary_id(c.norm() < r_mid ? 1 : 0);
              };
            }
          else if (shape == "rectangle" || shape == "bilayer")
            {
              boundary_parts = {{"left", 0}, {"right", 1}, {"bottom", 2}, {"top", 3}};
              const double w = width, h = height;
              id_of          = [w, h](const Point<2> &c) { return rectangle_side(c, w, h); };
            }
          else
            boundary_parts = {{"outer", 0}};
          for (const auto &cell : tria.active_cell_iterators())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                cell->face(f)->set_boundary_id(id_of(cell->face(f)->center()));
          if (shape == "bilayer")
            regions = {{"lower", 1}, {"upper", 2}};
          else if (shape == "half disc")
            regions = {{"left", 1}, {"right", 2}};
          else
            regions = {{"section", 1}};
        }

      applied_shift = Point<2>();
      if (shape == "gmsh")
        {
          const SectionProperties p = properties(tria, 1);
          if (p.centroid.norm() > 1e-12 * p.diameter)
            {
              applied_shift = -p.centroid;
              GridTools::shift(Tensor<1, 2>(applied_shift), tria);
            }
        }
    }

    const std::map<std::string, types::boundary_id> &
    CrossSectionGeometry::boundary_part_ids() const
    {
      return boundary_parts;
    }

    const std::map<std::string, types::material_id> &
    CrossSectionGeometry::region_ids() const
    {
      return regions;
    }

    SectionProperties
    CrossSectionGeometry::properties(const Triangulation<2> &tria, const unsigned int degree)
    {
      SectionProperties  p;
      MappingQ<2>        mapping(std::max(1u, degree));
      const QGauss<2>    quadrature(std::max(1u, degree) + 1);
      // Geometry only: a scalar Q1 element would do, FE_Nothing avoids DoFs.
      const FE_Nothing<2> fe;
      FEValues<2>        fe_values(mapping, fe, quadrature, update_quadrature_points | update_JxW_values);
      double             mx = 0, my = 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          fe_values.reinit(cell);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<2> &x  = fe_values.quadrature_point(q);
              const double    dA = fe_values.JxW(q);
              p.area += dA;
              mx += x[0] * dA;
              my += x[1] * dA;
              p.I22 += x[0] * x[0] * dA;
              p.I11 += x[1] * x[1] * dA;
              p.I12 += x[0] * x[1] * dA;
            }
        }
      p.centroid = Point<2>(mx / p.area, my / p.area);
      p.diameter = GridTools::diameter(tria);
      return p;
    }


    void
    BoundarySelection::parse(const std::string &         spec,
                             const std::string &         section,
                             const std::string &         entry,
                             const CrossSectionGeometry &geometry)
    {
      everything = false;
      parts.clear();
      ids.clear();
      arcs.clear();
      const auto &names     = geometry.boundary_part_ids();
      auto        available = [&names]() {
        std::string list;
        for (const auto &n : names)
          list += n.first + ", ";
        return list + "all, arc A B";
      };
      for (const std::string &item : Utilities::split_string_list(spec, ','))
        {
          if (item.empty())
            continue;
          if (item == "all")
            everything = true;
          else if (item.rfind("arc", 0) == 0 &&
                   (item.size() == 3 || std::isspace(static_cast<unsigned char>(item[3]))))
            {
              std::istringstream s(item.substr(3));
              double             a = 0, b = 0;
              std::string        rest;
              if (!(s >> a >> b) || (s >> rest))
                throw io::InputError(section, entry, spec,
                                     "'" + item +
                                       "': expected 'arc A B' with two angles in degrees");
              if (!(a < b && b - a <= 360))
                throw io::InputError(section, entry, spec,
                                     "'" + item + "': 'arc A B' needs A < B and B - A <= 360 "
                                                  "(degrees, counterclockwise from X1)");
              arcs.emplace_back(a, b);
            }
          else
            {
              const auto it = names.find(item);
              if (it == names.end())
                throw io::InputError(section, entry, spec,
                                     "unknown boundary part '" + item +
                                       "'; this section has: " + available());
              parts.emplace_back(it->first, it->second);
              ids.insert(it->second);
            }
        }
    }

    bool
    BoundarySelection::contains(const typename Triangulation<2>::face_iterator &face) const
    {
      if (!face->at_boundary())
        return false;
      if (everything || ids.count(face->boundary_id()))
        return true;
      if (arcs.empty())
        return false;
      const Point<2> c     = face->center();
      const double   theta = std::atan2(c[1], c[0]) * 180 / M_PI;
      // Half-open [A, B): a midpoint exactly on an arc end (0 or 90 degrees
      // on a symmetric mesh) belongs to the arc that starts there, so that
      // 'arc -90 90' and 'arc 90 270' split the boundary without sharing a
      // face. The tolerance keeps round-off from moving it across.
      const double tolerance = 1e-9;
      for (const auto &arc : arcs)
        {
          double d = std::fmod(theta - arc.first, 360.);
          if (d < 0)
            d += 360;
          if (d >= 360 - tolerance || d < arc.second - arc.first - tolerance)
            return true;
        }
      return false;
    }

    bool
    BoundarySelection::empty() const
    {
      return !everything && parts.empty() && arcs.empty();
    }

    std::string
    BoundarySelection::description() const
    {
      if (everything)
        return "the whole boundary";
      std::ostringstream s;
      for (const auto &p : parts)
        s << (s.tellp() > 0 ? ", " : "") << p.first << " (boundary id "
          << static_cast<unsigned int>(p.second) << ")";
      for (const auto &a : arcs)
        s << (s.tellp() > 0 ? ", " : "") << "arc " << a.first << ".." << a.second << " deg";
      return empty() ? std::string("none") : s.str();
    }
  } // namespace geometry
} // namespace cosmo

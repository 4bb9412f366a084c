// A section from gmsh: an ASCII .msh, or a .geo meshed here by running the gmsh program.
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <cosmo/geometry/section_shape.h>
#include <cosmo/io/parameters.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

namespace cosmo
{
  namespace geometry
  {
    namespace
    {
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
    } // namespace

    /**
     * Physical surface tags become region ids and physical line tags boundary
     * ids, their names those of the regions and boundary parts. A mesh from a
     * file is not centred by construction: CrossSectionGeometry shifts it.
     */
    class GmshSection : public SectionShape
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
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
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        mesh_file    = prm.get("Mesh file");
        gmsh_program = prm.get("Gmsh program");
        mesh_size    = prm.get_double("Mesh size");
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

      SectionMesh
      create_triangulation(Triangulation<2> &tria, const unsigned int refinements) const override
      {
        SectionMesh result;
        result.centred_by_construction = false;
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
        if (is_geo_file(mesh_file))
          {
            // On a distributed mesh every rank reads the same coarse mesh:
            // the first rank meshes the .geo and sends the .msh (or gmsh's
            // complaint) to the others, which need no gmsh run of their own.
            const MPI_Comm     comm  = tria.get_communicator();
            const bool         first = Utilities::MPI::this_mpi_process(comm) == 0;
            std::string        error, text;
            scratch = std::make_unique<TemporaryDirectory>();
            if (first)
              try
                {
                  const std::string program = find_program(gmsh_program);
                  if (program.empty())
                    throw std::runtime_error("a .geo needs the gmsh program, but 'Gmsh program' = '" +
                                             gmsh_program +
                                             "' is not found (install gmsh, or give its path)");
                  msh = run_gmsh(program, mesh_file, mesh_size, scratch->path,
                                 result.meshing_summary);
                  std::ifstream     in(msh);
                  std::stringstream all;
                  all << in.rdbuf();
                  text = all.str();
                }
              catch (std::exception &e)
                {
                  error = e.what();
                }
            if (Utilities::MPI::n_mpi_processes(comm) > 1)
              {
                error                  = Utilities::MPI::broadcast(comm, error, 0);
                text                   = Utilities::MPI::broadcast(comm, text, 0);
                result.meshing_summary = Utilities::MPI::broadcast(comm, result.meshing_summary, 0);
                if (!first && error.empty())
                  {
                    msh = (std::filesystem::path(scratch->path) / "section.msh").string();
                    std::ofstream(msh) << text;
                  }
              }
            if (!error.empty())
              fail(error);
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
        if (!result.meshing_summary.empty())
          result.meshing_summary += ", " + std::to_string(tria.n_active_cells()) + " cells";
        result.boundary_parts = contents.boundary_names;
        result.regions        = contents.region_names;
        // Region and boundary ids are the file's, inherited by the children.
        tria.refine_global(refinements);
        return result;
      }

    private:
      std::string mesh_file;
      std::string gmsh_program = "gmsh";
      double      mesh_size    = 0;
    };

    COSMO_REGISTER_PLUGIN(SectionShape,
                          GmshSection,
                          "gmsh",
                          "the section of `Mesh file` (quadrilaterals; physical surface tags "
                          "are the region ids, physical line tags the boundary ids, their "
                          "physical names usable for Regions and boundary selections; shifted "
                          "to put its centroid at the origin).")
  } // namespace geometry
} // namespace cosmo

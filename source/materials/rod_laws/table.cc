// The nonlinear rod law of a constitutive table (rod_laws/table.h): bicubic
// Hermite on the table's energy, resultants and condensed cross stiffness.
#include <deal.II/base/hdf5.h>
#include <deal.II/lac/full_matrix.h>

#include <cosmo/io/output.h>
#include <cosmo/io/parameters.h>
#include <cosmo/materials/rod_laws/table.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace cosmo
{
  namespace materials
  {
    namespace
    {
      const std::array<std::string, 6> strain_names{{"nu1", "nu2", "nu3", "kappa1", "kappa2", "kappa3"}};

      unsigned int
      strain_index(const std::string &name)
      {
        const auto it = std::find(strain_names.begin(), strain_names.end(), name);
        if (it == strain_names.end())
          throw std::runtime_error("unknown strain '" + name + "'");
        return static_cast<unsigned int>(it - strain_names.begin());
      }

      /**
       * The cubic Hermite basis on an interval of width h in the local
       * u = (x - x0)/h: for the value at node `node` (0 or 1) or, with
       * `slope`, for its derivative; value, d/dx and d2/dx2 in x.
       */
      std::array<double, 3>
      hermite(const double u, const double h, const unsigned int node, const bool slope)
      {
        if (!slope)
          {
            const double v = 1 - 3 * u * u + 2 * u * u * u, d = (-6 * u + 6 * u * u) / h,
                         dd = (-6 + 12 * u) / (h * h);
            return node == 0 ? std::array<double, 3>{{v, d, dd}} : std::array<double, 3>{{1 - v, -d, -dd}};
          }
        if (node == 0)
          return {{h * (u - 2 * u * u + u * u * u), 1 - 4 * u + 3 * u * u, (-4 + 6 * u) / h}};
        return {{h * (-u * u + u * u * u), -2 * u + 3 * u * u, (-2 + 6 * u) / h}};
      }

      /// The cell [v_i, v_i+1] holding v; false outside the axis (beyond round-off).
      bool
      locate(const std::vector<double> &axis, const double v, unsigned int &i, double &u)
      {
        const double range = axis.back() - axis.front(), slack = 1e-12 * range;
        if (!(v >= axis.front() - slack && v <= axis.back() + slack))
          return false;
        const auto it = std::upper_bound(axis.begin(), axis.end(), v);
        i = static_cast<unsigned int>(std::clamp<long>(it - axis.begin() - 1, 0, long(axis.size()) - 2));
        u = (v - axis[i]) / (axis[i + 1] - axis[i]);
        return true;
      }

      /**
       * K_AB - K_AF K_FF^-1 K_FB (row-major 2 x 2, A = (a, b)): the axes'
       * stiffness with the free strains F relaxed; its cross entry is the
       * interpolant's data, the diagonal measures how well the grid
       * resolves the law.
       */
      std::array<double, 4>
      condensed_axes(const double *K, const unsigned int a, const unsigned int b,
                     const std::vector<unsigned int> &relaxed)
      {
        const std::array<unsigned int, 2> A{{a, b}};
        std::array<double, 4>             condensed;
        FullMatrix<double>                KFF(relaxed.size(), relaxed.size());
        for (unsigned int r = 0; r < relaxed.size(); ++r)
          for (unsigned int c = 0; c < relaxed.size(); ++c)
            KFF(r, c) = K[6 * relaxed[r] + relaxed[c]];
        if (!relaxed.empty())
          KFF.gauss_jordan();
        for (unsigned int r = 0; r < 2; ++r)
          for (unsigned int c = 0; c < 2; ++c)
            {
              condensed[2 * r + c] = 0.5 * (K[6 * A[r] + A[c]] + K[6 * A[c] + A[r]]);
              for (unsigned int k = 0; k < relaxed.size(); ++k)
                for (unsigned int l = 0; l < relaxed.size(); ++l)
                  condensed[2 * r + c] -= K[6 * A[r] + relaxed[k]] * KFF(k, l) * K[6 * relaxed[l] + A[c]];
            }
        return condensed;
      }
    } // namespace

    void
    TableRodLaw::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Table stiffness tolerance", "0.01", Patterns::Double(0),
                        "Law = table: the largest relative difference, at the grid point "
                        "nearest the natural state, between the interpolant's second "
                        "derivatives and the tabulated (condensed) stiffnesses; a coarser "
                        "table is refused (its tangent, and thresholds near the natural "
                        "state, would be off by that much). The largest difference over the "
                        "grid is in the log.");
      prm.declare_entry("Table file", "", Patterns::Anything(),
                        "Law = table: the table.h5 of a strip or rod_cross_section "
                        "constitutive table, or the parameter file of one, which the run "
                        "computes itself (its output in the run's directory 'table', reused "
                        "while that file's parameters and the files they name are unchanged): a "
                        "constitutive table over two strains, the free strains' resultants "
                        "held at zero (e.g. a ribbon's (kappa1, kappa3) with nu1, nu2, nu3, "
                        "kappa2 free). Its energy, interpolated bicubically (C1) from the "
                        "tabulated energy, resultants and condensed stiffness, is the law "
                        "in the two strains; the other four enter with the table's "
                        "stiffness at the natural state, which is the energy's minimum. A "
                        "strain outside the grid, or in a cell with an unconverged point, "
                        "is refused (the path stops with the strain and the range named).");
    }

    void
    TableRodLaw::parse_parameters(ParameterHandler &prm, const std::string &section)
    {
      stiffness_tolerance = prm.get_double("Table stiffness tolerance");
      file                = prm.get("Table file");
      section_name        = section;
      pending             = file.size() > 4 && file.substr(file.size() - 4) == ".prm";
      if (!pending)
        read(file, section);
    }

    RodLaw::ComputedInput
    TableRodLaw::computed_input() const
    {
      if (!pending)
        return {};
      // A strip's file has its section 'Strip'; anything else is part 1's.
      std::ifstream in(file);
      std::string   line, application = "rod_cross_section";
      while (std::getline(in, line))
        if (line.find("subsection Strip") != std::string::npos)
          application = "strip";
      return {application, file, "Table file", "table"};
    }

    void
    TableRodLaw::read_computed(const std::string &directory, const std::string &note)
    {
      const std::string prm_file = file;
      read(directory + "/table.h5", section_name);
      pending       = false;
      computed_note = note + " from " + prm_file;
    }

    void
    TableRodLaw::read(const std::string &file_name, const std::string &section)
    {
      file         = file_name;
      section_name = section;
      std::vector<double> energy, resultants, stiffness, flags;
      std::string         free, held;
      try
        {
          HDF5::File h5(file, HDF5::File::FileAccessMode::open);
          axis_a     = strain_index(h5.get_attribute<std::string>("strain_1_name"));
          axis_b     = strain_index(h5.get_attribute<std::string>("strain_2_name"));
          free       = h5.get_attribute<std::string>("free_strains");
          held       = h5.get_attribute<std::string>("held_resultants");
          x          = h5.open_dataset("strain_1").read<std::vector<double>>();
          y          = h5.open_dataset("strain_2").read<std::vector<double>>();
          energy     = h5.open_dataset("energy").read<std::vector<double>>();
          resultants = h5.open_dataset("resultants").read<std::vector<double>>();
          stiffness  = h5.open_dataset("stiffness").read<std::vector<double>>();
          flags      = h5.open_dataset("converged").read<std::vector<double>>();
        }
      catch (std::exception &e)
        {
          throw io::InputError(section, "Table file", file,
                               "a table.h5 of a strip or rod_cross_section constitutive table (" +
                                 std::string(e.what()).substr(0, 200) + ")");
        }
      const std::size_t n = x.size() * y.size();
      if (x.size() < 2 || y.size() < 2 || energy.size() != n || resultants.size() != 6 * n ||
          stiffness.size() != 36 * n || flags.size() != n)
        throw io::InputError(section, "Table file", file,
                             "a table of at least 2 x 2 points with energy, resultants, stiffness and "
                             "converged on its grid");
      // Free strains relaxed at held resultants other than zero: the energy
      // is then not the potential of the axes' resultants.
      for (std::size_t at = held.find('='); at != std::string::npos; at = held.find('=', at + 1))
        if (std::stod(held.substr(at + 1)) != 0)
          throw io::InputError(section, "Table file", file,
                               "a table whose free strains' resultants are held at zero (held: " + held + ")");
      std::vector<unsigned int> relaxed; // free strains, condensed out of the cross stiffness
      for (unsigned int k = 0; k < 6; ++k)
        if (k != axis_a && k != axis_b && free.find(strain_names[k]) != std::string::npos)
          relaxed.push_back(k);
      f.assign(n, 0.);
      fx = fy = fxy = kxx = kyy = f;
      converged.assign(n, false);
      holes = 0;
      for (std::size_t p = 0; p < n; ++p)
        {
          converged[p] = flags[p] == 1 && std::isfinite(energy[p]);
          holes += !converged[p];
          if (!converged[p])
            continue;
          const double *K = &stiffness[36 * p];
          f[p]            = energy[p];
          fx[p]           = resultants[6 * p + axis_a];
          fy[p]           = resultants[6 * p + axis_b];
          const auto condensed = condensed_axes(K, axis_a, axis_b, relaxed);
          fxy[p]               = condensed[1];
          kxx[p]               = condensed[0];
          kyy[p]               = condensed[3];
        }
      // The resolution at the lowest point first: a grid too coarse for the
      // law has no convex interpolant there, and says so.
      std::size_t lowest = 0;
      for (std::size_t p = 0; p < n; ++p)
        if (converged[p] && (!converged[lowest] || f[p] < f[lowest]))
          lowest = p;
      natural[axis_a] = x[lowest / y.size()];
      natural[axis_b] = y[lowest % y.size()];
      check_resolution();
      find_natural_state();
      set_other_stiffness(stiffness);
    }

    std::size_t
    TableRodLaw::nearest_node() const
    {
      std::size_t nearest = 0;
      double      best    = std::numeric_limits<double>::infinity();
      for (unsigned int a = 0; a < x.size(); ++a)
        for (unsigned int b = 0; b < y.size(); ++b)
          if (converged[a * y.size() + b])
            if (const double d = std::hypot((x[a] - natural[axis_a]) / (x.back() - x.front()),
                                            (y[b] - natural[axis_b]) / (y.back() - y.front()));
                d < best)
              {
                best    = d;
                nearest = a * y.size() + b;
              }
      return nearest;
    }

    void
    TableRodLaw::set_other_stiffness(const std::vector<double> &stiffness)
    {
      // (at the grid point nearest the natural state)
      const double *K = &stiffness[36 * nearest_node()];
      for (unsigned int k = 0; k < 6; ++k)
        for (unsigned int l = 0; l < 6; ++l)
          others[6 * k + l] = (k == axis_a || k == axis_b || l == axis_a || l == axis_b) ?
                                0. :
                                0.5 * (K[6 * k + l] + K[6 * l + k]);
    }

    void
    TableRodLaw::check_resolution()
    {
      // The interpolant's second derivatives at the nodes against the
      // tabulated (condensed) stiffnesses: the grid's resolution of the law.
      // Where it is coarse for the law's curvature (a ribbon's quartic
      // twist stiffening) the cubics between the nodes bend otherwise.
      resolution = 0;
      double            at_natural = 0;
      const std::size_t nearest    = nearest_node();
      for (unsigned int i = 0; i < x.size(); ++i)
        for (unsigned int j = 0; j < y.size(); ++j)
          {
            const std::size_t p = i * y.size() + j;
            if (!converged[p])
              continue;
            double                W;
            std::array<double, 2> g;
            std::array<double, 3> H;
            try
              {
                table_energy(x[i], y[j], W, g, H);
              }
            catch (LawRangeError &)
              {
                continue; // (a node whose cell holds a hole)
              }
            const double scale = std::max(std::abs(kxx[p]), std::abs(kyy[p]));
            const double error = std::max(std::abs(H[0] - kxx[p]), std::abs(H[2] - kyy[p])) / scale;
            resolution         = std::max(resolution, error);
            if (p == nearest)
              at_natural = error;
          }
      if (at_natural > stiffness_tolerance)
        throw io::InputError(section_name, "Table file", file,
                             "a table fine enough for its law: at the node nearest the natural state the "
                             "interpolated stiffness differs from the tabulated one by " +
                               io::format_number(at_natural) + " (relative), more than 'Table stiffness "
                               "tolerance' = " + io::format_number(stiffness_tolerance) +
                               "; refine the grid there");
    }

    void
    TableRodLaw::table_energy(const double x_a, const double x_b, double &W, std::array<double, 2> &g,
                              std::array<double, 3> &H) const
    {
      unsigned int i = 0, j = 0;
      double       u = 0, v = 0;
      auto         outside = [&](const unsigned int k, const double value, const std::vector<double> &axis) {
        return LawRangeError("the strain " + strain_names[k] + " = " + io::format_number(value) +
                             " is outside the table's range [" + io::format_number(axis.front()) + ", " +
                             io::format_number(axis.back()) + "] (" + section_name + "/Table file = " + file + ")");
      };
      if (!locate(x, x_a, i, u))
        throw outside(axis_a, x_a, x);
      if (!locate(y, x_b, j, v))
        throw outside(axis_b, x_b, y);
      const std::size_t n2 = y.size();
      W = 0;
      g = {};
      H = {};
      for (unsigned int p = 0; p < 2; ++p)
        for (unsigned int q = 0; q < 2; ++q)
          {
            const std::size_t node = (i + p) * n2 + (j + q);
            if (!converged[node])
              throw LawRangeError("the strains (" + strain_names[axis_a] + ", " + strain_names[axis_b] + ") = (" +
                                  io::format_number(x_a) + ", " + io::format_number(x_b) +
                                  ") lie in a cell of the table with a point that did not converge (" +
                                  section_name + "/Table file = " + file + ")");
            const auto   Hu = hermite(u, x[i + 1] - x[i], p, false), Gu = hermite(u, x[i + 1] - x[i], p, true);
            const auto   Hv = hermite(v, y[j + 1] - y[j], q, false), Gv = hermite(v, y[j + 1] - y[j], q, true);
            const double c[4] = {f[node], fx[node], fy[node], fxy[node]};
            const std::array<double, 3> *bu[4] = {&Hu, &Gu, &Hu, &Gu}, *bv[4] = {&Hv, &Hv, &Gv, &Gv};
            for (unsigned int k = 0; k < 4; ++k)
              {
                const auto &A = *bu[k], &B = *bv[k];
                W += c[k] * A[0] * B[0];
                g[0] += c[k] * A[1] * B[0];
                g[1] += c[k] * A[0] * B[1];
                H[0] += c[k] * A[2] * B[0];
                H[1] += c[k] * A[1] * B[1];
                H[2] += c[k] * A[0] * B[2];
              }
          }
    }

    void
    TableRodLaw::find_natural_state()
    {
      // Newton on the interpolant from the lowest converged node (in `natural`).
      double                a = natural[axis_a], b = natural[axis_b], W = 0;
      std::array<double, 2> g;
      std::array<double, 3> H;
      const double          scale_a = x.back() - x.front(), scale_b = y.back() - y.front();
      bool                  done    = false;
      try
        {
          for (unsigned int it = 0; it < 50 && !done; ++it)
            {
              table_energy(a, b, W, g, H);
              const double det = H[0] * H[2] - H[1] * H[1];
              if (!(H[0] > 0 && det > 0))
                break;
              const double da = -(H[2] * g[0] - H[1] * g[1]) / det, db = -(H[0] * g[1] - H[1] * g[0]) / det;
              a += da;
              b += db;
              done = std::abs(da) <= 1e-14 * scale_a && std::abs(db) <= 1e-14 * scale_b;
            }
          table_energy(a, b, W, g, H);
        }
      catch (LawRangeError &)
        {
          done = false;
        }
      if (!done)
        throw io::InputError(section_name, "Table file", file,
                             "a table whose energy has a minimum inside its grid, in a cell of converged "
                             "points (the natural state; Newton from the lowest point did not find one)");
      natural[axis_a] = a;
      natural[axis_b] = b;
      natural_energy  = W;
    }

    void
    TableRodLaw::energy_derivatives(const std::array<double, 6> &e,
                                    const bool                   with_hessian,
                                    double &                     W,
                                    std::array<double, 6> &      dW,
                                    std::array<double, 36> &     ddW) const
    {
      std::array<double, 2> g;
      std::array<double, 3> H;
      table_energy(natural[axis_a] + e[axis_a], natural[axis_b] + e[axis_b], W, g, H);
      W -= natural_energy;
      // The other four strains: 1/2 e_o . K_oo e_o (zero rows and columns in the axes).
      for (unsigned int k = 0; k < 6; ++k)
        {
          dW[k] = 0;
          for (unsigned int l = 0; l < 6; ++l)
            dW[k] += others[6 * k + l] * e[l];
          W += 0.5 * dW[k] * e[k];
        }
      dW[axis_a] = g[0];
      dW[axis_b] = g[1];
      if (!with_hessian)
        return;
      ddW                          = others;
      ddW[7 * axis_a]              = H[0];
      ddW[6 * axis_a + axis_b]     = H[1];
      ddW[6 * axis_b + axis_a]     = H[1];
      ddW[7 * axis_b]              = H[2];
    }

    std::optional<std::array<double, 6>>
    TableRodLaw::natural_strains_at(const double) const
    {
      return natural;
    }

    std::string
    TableRodLaw::description() const
    {
      std::ostringstream m;
      m << "table: " << file << ", (" << strain_names[axis_a] << ", " << strain_names[axis_b] << ") on "
        << x.size() << " x " << y.size() << " points in [" << x.front() << ", " << x.back() << "] x ["
        << y.front() << ", " << y.back() << "]" << (holes ? ", " + std::to_string(holes) + " unconverged" : "")
        << ", bicubic Hermite (its stiffness at the nodes within " << resolution
        << " of the table's); natural state at its minimum (" << natural[axis_a] << ", " << natural[axis_b] << ")"
        << (computed_note.empty() ? "" : "; " + computed_note);
      return m.str();
    }

    COSMO_REGISTER_PLUGIN(RodLaw,
                          TableRodLaw,
                          "table",
                          "the nonlinear law of a strip or rod_cross_section constitutive table "
                          "(table.h5) over two strains, bicubic Hermite (C1) in them: 'Table file'.")
  } // namespace materials
} // namespace cosmo

#include <deal.II/base/hdf5.h>

#include <cosmo/io/ranks.h>
#include <cosmo/kinematics/helix.h>

#include <hdf5_hl.h>

#include <iomanip>
#include <numeric>
#include <sstream>

#include "constitutive_table_h5.h"

// table.h5 of a constitutive table (constitutive_table.cc): the datasets with
// their units and meaning as attributes, the strain axes as HDF5 dimension
// scales (h5py: dataset.dims), the run's description as file attributes.

namespace cosmo
{
  namespace assembly
  {
    namespace
    {
      std::string
      joined(const std::vector<std::string> &items)
      {
        std::string out;
        for (const auto &i : items)
          out += (out.empty() ? "" : ", ") + i;
        return out;
      }

      std::string
      unit_of_strain(const unsigned int k, const TableDescription &d)
      {
        return k < 3 ? "1" : "1/" + d.length_unit;
      }

      /// The HDF5 coordinates (i, j, a, b, ...) of the entries of `points` (p = i n2 + j) in a
      /// dataset [n1, n2, trailing...], in row-major order, and their values from `all`.
      struct Selection
      {
        std::vector<hsize_t> coordinates;
        std::vector<double>  values;
      };
      Selection
      select(const std::vector<unsigned int> &points, const unsigned int n2,
             const std::vector<hsize_t> &trailing, const std::vector<double> &all)
      {
        hsize_t per_point = 1;
        for (const auto t : trailing)
          per_point *= t;
        Selection s;
        for (const unsigned int p : points)
          for (hsize_t c = 0; c < per_point; ++c)
            {
              s.coordinates.push_back(p / n2);
              s.coordinates.push_back(p % n2);
              hsize_t rest = c;
              std::vector<hsize_t> tail(trailing.size());
              for (int d = int(trailing.size()) - 1; d >= 0; --d)
                {
                  tail[d] = rest % trailing[d];
                  rest /= trailing[d];
                }
              s.coordinates.insert(s.coordinates.end(), tail.begin(), tail.end());
              s.values.push_back(all[per_point * p + c]);
            }
        return s;
      }

      /// table.h5's attributes: what the table is, its strains and units, the run's parameters.
      void
      write_table_attributes(HDF5::File &            file,
                             const TableDescription &d,
                             const unsigned int      first,
                             const unsigned int      second)
      {
        const auto &names  = kinematics::strain_names;
        const auto &rnames = kinematics::resultant_names;
        file.set_attribute("application", d.application);
        file.set_attribute("version", d.version);
        file.set_attribute("format", std::string("cosmo constitutive table 2"));
        file.set_attribute("strain_1_name", names[first]);
        file.set_attribute("strain_2_name", names[second]);
        file.set_attribute("strain_order", joined({names.begin(), names.end()}));
        file.set_attribute("resultant_order", joined({rnames.begin(), rnames.end()}));
        std::vector<std::string> free, units;
        std::ostringstream       held;
        held << std::setprecision(17);
        for (unsigned int k = 0; k < 6; ++k)
          {
            if (d.free_strains[k])
              {
                free.push_back(names[k]);
                held << (held.tellp() > 0 ? ", " : "") << rnames[k] << " = " << d.held_resultants[k];
              }
            units.push_back(names[k] + ": " + unit_of_strain(k, d));
          }
        file.set_attribute("free_strains", free.empty() ? std::string("(none)") : joined(free));
        file.set_attribute("held_resultants",
                           held.tellp() > 0 ? held.str() : std::string("(no free strains)"));
        file.set_attribute("strain_units", joined(units));
        file.set_attribute("length_unit", d.length_unit);
        file.set_attribute("parameters", d.parameters);
      }

      /// A strain axis of table.h5 (its values, units and meaning).
      void
      write_axis(HDF5::File &               file,
                 const std::string &        name,
                 const std::vector<double> &data,
                 const std::string &        units,
                 const std::string &        what)
      {
        auto ds = file.create_dataset<double>(name, {data.size()});
        if (io::ranks::rank() == 0)
          {
            std::vector<hsize_t> c(data.size());
            std::iota(c.begin(), c.end(), hsize_t(0));
            ds.write_selection(data, c);
          }
        else
          ds.write_none<double>();
        ds.set_attribute("units", units);
        ds.set_attribute("description", what);
      }

      /// Writes the datasets [n1, n2, trailing...] of table.h5 over the
      /// grid: of each, the entries of this rank's `points` (p = i n2 + j).
      struct GridWriter
      {
        HDF5::File &                     file;
        const hsize_t                    n1, n2;
        const std::vector<unsigned int> &points;

        HDF5::DataSet
        write(const std::string &          name,
              const std::vector<hsize_t> & trailing,
              const std::vector<double> &  data,
              const std::string &          units,
              const std::string &          what) const
        {
          std::vector<hsize_t> dims = {n1, n2};
          dims.insert(dims.end(), trailing.begin(), trailing.end());
          auto       ds  = file.create_dataset<double>(name, dims);
          const auto sel = select(points, n2, trailing, data);
          if (sel.values.empty())
            ds.write_none<double>();
          else
            ds.write_selection(sel.values, sel.coordinates);
          ds.set_attribute("units", units);
          ds.set_attribute("description", what);
          return ds;
        }

        /// The mask of the converged points, as integers (`converged`: 1 or 0 per point).
        void
        write_converged(const std::vector<double> &converged) const
        {
          const auto       sel = select(points, n2, {}, converged);
          std::vector<int> mask(sel.values.size());
          for (unsigned int p = 0; p < mask.size(); ++p)
            mask[p] = sel.values[p] != 0;
          auto c = file.create_dataset<int>("converged", {n1, n2});
          if (mask.empty())
            c.write_none<int>();
          else
            c.write_selection(mask, sel.coordinates);
          c.set_attribute("units", std::string("1"));
          c.set_attribute("description",
                          std::string("boolean mask: 1 where the point converged, 0 where it did not "
                                      "(its other entries are NaN)"));
        }
      };

      /// Dimension scales (HDF5 high-level API) of the closed table.h5:
      /// energy, resultants, stiffness and converged are indexed by
      /// (strain_1, strain_2, component...). One rank only.
      void
      set_dimension_scales(const std::string &file_name, const unsigned int first, const unsigned int second)
      {
        const auto &names = kinematics::strain_names;
        const hid_t f     = H5Fopen(file_name.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
        AssertThrow(f >= 0, ExcMessage("cannot reopen " + file_name));
        const hid_t d1 = H5Dopen2(f, "strain_1", H5P_DEFAULT), d2 = H5Dopen2(f, "strain_2", H5P_DEFAULT);
        H5DSset_scale(d1, names[first].c_str());
        H5DSset_scale(d2, names[second].c_str());
        for (const char *name : {"energy", "resultants", "stiffness", "converged"})
          {
            const hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
            H5DSattach_scale(ds, d1, 0);
            H5DSattach_scale(ds, d2, 1);
            H5DSset_label(ds, 0, names[first].c_str());
            H5DSset_label(ds, 1, names[second].c_str());
            if (std::string(name) == "resultants")
              H5DSset_label(ds, 2, "resultant");
            if (std::string(name) == "stiffness")
              {
                H5DSset_label(ds, 2, "resultant");
                H5DSset_label(ds, 3, "strain");
              }
            H5Dclose(ds);
          }
        H5Dclose(d1);
        H5Dclose(d2);
        H5Fclose(f);
      }
    } // namespace

    namespace internal
    {
      void
      write_table_h5(const std::string &              file_name,
                     const TableDescription &         d,
                     const unsigned int               first,
                     const unsigned int               second,
                     const std::vector<double> &      s1,
                     const std::vector<double> &      s2,
                     const std::vector<unsigned int> &points,
                     const std::vector<double> &      energy,
                     const std::vector<double> &      resultants,
                     const std::vector<double> &      stiffness,
                     const std::vector<double> &      converged)
      {
        const auto &names  = kinematics::strain_names;
        const auto &rnames = kinematics::resultant_names;
        {
          HDF5::File          file(file_name, HDF5::File::FileAccessMode::create, MPI_COMM_WORLD);
          const hsize_t       n1 = s1.size(), n2 = s2.size();
          const GridWriter    grid{file, n1, n2, points};
          // The axes: the same values from every rank, written by rank 0.
          write_axis(file, "strain_1", s1, unit_of_strain(first, d),
                     "the first grid axis: values of the strain " + names[first]);
          write_axis(file, "strain_2", s2, unit_of_strain(second, d),
                     "the second grid axis: values of the strain " + names[second]);
          grid.write("energy", {}, energy, d.energy_unit + " (per unit reference length)",
                     "energy per unit reference length Psi at (strain_1[i], strain_2[j]); NaN where not converged");
          auto r = grid.write("resultants", {6}, resultants,
                              d.force_unit + " (n1, n2, n3), " + d.moment_unit + " (m1, m2, m3)",
                              "resultants dPsi/d(strains) at (i, j), component k of `components`; NaN where not converged");
          r.set_attribute("components", joined({rnames.begin(), rnames.end()}));
          auto K = grid.write("stiffness", {6, 6}, stiffness,
                              "unit of resultant a per unit of strain b",
                              "tangent stiffness K[i, j, a, b] = d(resultant a)/d(strain b), the "
                              "section's 6x6 with its field condensed and all six strains as variables "
                              "(symmetric; for the stiffness with the free strains' resultants held, "
                              "condense them: K_pp - K_pf K_ff^-1 K_fp); NaN where not converged");
          K.set_attribute("rows", joined({rnames.begin(), rnames.end()}));
          K.set_attribute("columns", joined({names.begin(), names.end()}));
          grid.write_converged(converged);

          write_table_attributes(file, d, first, second);
        }
        // Closed by every rank; the dimension scales are rank 0's.
        io::ranks::barrier();
        if (io::ranks::rank() != 0)
          return;
        set_dimension_scales(file_name, first, second);
      }
    } // namespace internal
  } // namespace assembly
} // namespace cosmo

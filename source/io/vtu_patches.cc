#include <deal.II/base/exceptions.h>

#include <cosmo/io/output.h>
#include <cosmo/io/ranks.h>
#include <cosmo/io/vtu_patches.h>

#include <cmath>
#include <sstream>

namespace cosmo
{
  namespace io
  {
    template <int dim>
    VTUPatches<dim>::VTUPatches(const std::vector<std::pair<std::string, unsigned int>> &fields,
                                const std::vector<std::string> &cell_fields)
      : cell_names(cell_fields)
      , cell_values(cell_fields.size())
    {
      for (const auto &f : fields)
        {
          AssertThrow(f.second == 1 || f.second == 3,
                      ExcMessage("a VTU field is a scalar or a 3-vector: " + f.first));
          if (f.second == 3)
            vectors.emplace_back(names.size(), names.size() + 2, f.first,
                                 DataComponentInterpretation::component_is_part_of_vector);
          for (unsigned int c = 0; c < f.second; ++c)
            names.push_back(f.first);
        }
    }

    template <int dim>
    void
    VTUPatches<dim>::begin_patch(const unsigned int n_subdivisions)
    {
      AssertThrow(!open, ExcMessage("begin_patch() before end_patch()"));
      DataOutBase::Patch<dim, 3> patch;
      patch.n_subdivisions       = n_subdivisions;
      patch.reference_cell       = ReferenceCells::get_hypercube<dim>();
      patch.points_are_available = true;
      unsigned int n_points      = 1;
      for (int d = 0; d < dim; ++d)
        n_points *= n_subdivisions + 1;
      // Data rows, then the three coordinates of the points.
      patch.data.reinit(names.size() + 3, n_points);
      patches.push_back(std::move(patch));
      for (auto &v : cell_values)
        v.push_back(0);
      open = true;
    }

    template <int dim>
    void
    VTUPatches<dim>::set_cell_value(const unsigned int field, const int value)
    {
      AssertThrow(open && field < cell_values.size(), ExcMessage("set_cell_value() outside a patch"));
      cell_values[field].back() = value;
    }

    template <int dim>
    void
    VTUPatches<dim>::set_position(const unsigned int k, const Point<3> &x)
    {
      auto &data = patches.back().data;
      for (unsigned int c = 0; c < 3; ++c)
        data(names.size() + c, k) = x[c];
    }

    template <int dim>
    void
    VTUPatches<dim>::set_value(const unsigned int column, const unsigned int k, const double v)
    {
      patches.back().data(column, k) = v;
    }

    template <int dim>
    void
    VTUPatches<dim>::set_values(const unsigned int k, const std::vector<double> &values)
    {
      AssertThrow(values.size() == names.size(),
                  ExcMessage("set_values() needs " + std::to_string(names.size()) + " values"));
      for (unsigned int c = 0; c < values.size(); ++c)
        patches.back().data(c, k) = values[c];
    }

    template <int dim>
    void
    VTUPatches<dim>::end_patch()
    {
      auto &             patch = patches.back();
      const unsigned int p = patch.n_subdivisions, np = p + 1, n = names.size();
      // Corner v has the index bits (i, j, k) = (v & 1, v & 2, v & 4).
      for (unsigned int v = 0; v < GeometryInfo<dim>::vertices_per_cell; ++v)
        {
          unsigned int pt = 0, stride = 1;
          for (int d = 0; d < dim; ++d, stride *= np)
            if (v & (1u << d))
              pt += p * stride;
          patch.vertices[v] = Point<3>(patch.data(n, pt), patch.data(n + 1, pt), patch.data(n + 2, pt));
        }
      patch.patch_index = patches.size() - 1;
      open              = false;
    }

    template <int dim>
    void
    VTUPatches<dim>::write(const std::string &file) const
    {
      AssertThrow(!open, ExcMessage("write() before end_patch()"));
      DataOutBase::VtkFlags flags;
      // zlib's fastest level: deal.II's default (the best compression) took
      // 0.28 s of a 5.4 s rod path for its two event files, this a third of
      // that for files ~15 % larger (benchmarks/README.md, the rod).
      flags.compression_level = DataOutBase::VtkFlags::best_speed;
      // One Lagrange cell per patch (of its degree): the element as computed.
      flags.write_higher_order_cells = true;
      if (std::isfinite(time))
        flags.time = time; // FieldData TIME: ParaView animates in the load parameter
      std::ostringstream xml;
      DataOutBase::write_vtu(patches, names, vectors, flags, xml);
      std::string text = xml.str();
      if (!cell_names.empty())
        {
          // deal.II writes point data only: the integer cell fields go in a
          // CellData block before the PointData (one cell per patch).
          std::ostringstream cells;
          cells << "    <CellData>\n";
          for (unsigned int f = 0; f < cell_names.size(); ++f)
            {
              cells << "    <DataArray type=\"Int32\" Name=\"" << cell_names[f]
                    << "\" format=\"ascii\">\n";
              for (const int v : cell_values[f])
                cells << v << ' ';
              cells << "\n    </DataArray>\n";
            }
          cells << "    </CellData>\n";
          const std::size_t at = text.find("<PointData");
          AssertThrow(at != std::string::npos, ExcInternalError());
          const std::size_t line = text.rfind('\n', at);
          text.insert(line == std::string::npos ? at : line + 1, cells.str());
        }
      write_file_atomically(file, [&](std::ostream &out) { out << text; });
    }

    template <int dim>
    std::string
    VTUPatches<dim>::write_pieces(const std::string &file, MPI_Comm comm) const
    {
      const std::string  suffix = ".vtu";
      AssertThrow(file.size() > suffix.size() &&
                    file.compare(file.size() - suffix.size(), suffix.size(), suffix) == 0,
                  ExcMessage("write_pieces: '" + file + "' does not end in .vtu"));
      const std::string  path   = file.substr(0, file.size() - suffix.size());
      const std::size_t  slash  = path.rfind('/');
      const std::string  stem   = slash == std::string::npos ? path : path.substr(slash + 1);
      const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
      const unsigned int size = Utilities::MPI::n_mpi_processes(comm);
      auto piece = [&](const unsigned int r) { return "." + Utilities::int_to_string(r, 4) + ".vtu"; };
      write(path + piece(rank));
      if (rank == 0)
        {
          std::vector<std::string> pieces;
          for (unsigned int r = 0; r < size; ++r)
            pieces.push_back(stem + piece(r));
          std::ostringstream xml;
          DataOutBase::write_pvtu_record(xml, pieces, names, vectors, DataOutBase::VtkFlags());
          std::string text = xml.str();
          if (!cell_names.empty())
            {
              std::ostringstream cells;
              cells << "    <PCellData>\n";
              for (const auto &name : cell_names)
                cells << "      <PDataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\"/>\n";
              cells << "    </PCellData>\n";
              const std::size_t at = text.find("<PPointData");
              AssertThrow(at != std::string::npos, ExcInternalError());
              const std::size_t line = text.rfind('\n', at);
              text.insert(line == std::string::npos ? at : line + 1, cells.str());
            }
          write_file_atomically(path + ".pvtu", [&](std::ostream &out) { out << text; });
        }
      return stem + ".pvtu";
    }

    template <int dim>
    std::string
    VTUPatches<dim>::write_output(const std::string &directory,
                                  const std::string &name,
                                  const bool         distributed_mesh) const
    {
      if (distributed_mesh)
        return write_pieces(ranks::shared_directory() + "/" + name + ".vtu", MPI_COMM_WORLD);
      write(directory + "/" + name + ".vtu");
      return name + ".vtu";
    }

    template class VTUPatches<1>;
    template class VTUPatches<2>;
    template class VTUPatches<3>;
  } // namespace io
} // namespace cosmo

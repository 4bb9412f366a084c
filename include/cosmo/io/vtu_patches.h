#ifndef cosmo_io_vtu_patches_h
#define cosmo_io_vtu_patches_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

/**
 * VTU output built point by point, for what DataOut cannot give directly:
 * a field on a curve or a surface in 3D (the rim, a strip, a surface layer),
 * a section swept along its helix, a 2D section lifted into 3D so that its
 * 3-vectors stay 3-vectors. Each patch is a Q_p cell with (p + 1)^dim points
 * in lexicographic order (first index fastest), each with a position in 3D
 * and the values of the fields; scalars and 3-vectors (named once, written
 * as VTU vectors) in the order given; integer cell fields (e.g. the region)
 * one value per patch. Each patch is written as one VTK Lagrange cell of its
 * degree (ParaView >= 5.5 draws it curved; its Nonlinear Subdivision Level
 * refines the view), so a Q2 field is shown as Q2, not as linear pieces.
 * TIME field data carries the load parameter. Written atomically
 * (io::write_file_atomically).
 */
namespace cosmo
{
  namespace io
  {
    using namespace dealii;

    template <int dim>
    class VTUPatches
    {
    public:
      /// The fields: (name, 1) for a scalar, (name, 3) for a vector.
      explicit VTUPatches(const std::vector<std::pair<std::string, unsigned int>> &fields,
                          const std::vector<std::string> &cell_fields = {});

      /// Start a patch of n_subdivisions per direction (the element degree).
      void
      begin_patch(unsigned int n_subdivisions);

      /// Point k of the current patch: its position.
      void
      set_position(unsigned int k, const Point<3> &x);

      /// Point k of the current patch: the value of column `column` (a vector's components are consecutive columns).
      void
      set_value(unsigned int column, unsigned int k, double v);

      /// Point k of the current patch: all columns at once, in order.
      void
      set_values(unsigned int k, const std::vector<double> &values);

      /// The current patch's value of integer cell field `field` (order of the constructor).
      void
      set_cell_value(unsigned int field, int value);

      /// Close the current patch (its corner vertices are its corner points).
      void
      end_patch();

      /// The number of data columns (scalars count one, vectors three).
      unsigned int
      n_columns() const
      {
        return names.size();
      }

      /// The load parameter of the state, written as the VTU's TIME field data (ParaView's time).
      void
      set_time(const double t)
      {
        time = t;
      }

      /// Write all patches to `file` (.vtu), atomically.
      void
      write(const std::string &file) const;

      /**
       * Patches divided over the ranks of `comm` (a distributed mesh, each
       * rank with its own cells'): every rank calls this with the same
       * `file` (`<directory>/<stem>.vtu`). Each writes its patches as the
       * piece `<stem>.<rank>.vtu` (4 digits), rank 0 the record
       * `<stem>.pvtu` that lists them, which ParaView opens as one data set.
       * Returns the record's name without its directory (for a .pvd).
       */
      std::string
      write_pieces(const std::string &file, MPI_Comm comm) const;

      /**
       * An application's output file `name`: `directory`/`name`.vtu, or on a
       * mesh distributed over MPI_COMM_WORLD (`distributed_mesh`) the pieces
       * and record `name`.pvtu in the run's shared directory (rank k > 0 runs
       * in a directory of its own, io/ranks.h). Returns the file name
       * written, without its directory (for a .pvd).
       */
      std::string
      write_output(const std::string &directory, const std::string &name, bool distributed_mesh) const;

    private:
      std::vector<std::string> names;
      std::vector<std::tuple<unsigned int, unsigned int, std::string,
                             DataComponentInterpretation::DataComponentInterpretation>>
                                             vectors;
      std::vector<DataOutBase::Patch<dim, 3>> patches;
      std::vector<std::string>                cell_names;
      std::vector<std::vector<int>>           cell_values; ///< per cell field, per patch
      bool                                    open = false;
      double                                  time = std::numeric_limits<double>::quiet_NaN();
    };
  } // namespace io
} // namespace cosmo

#endif

#ifndef cosmo_source_assembly_constitutive_table_h5_h
#define cosmo_source_assembly_constitutive_table_h5_h

// The HDF5 writer of a constitutive table (table.h5), apart from the loop
// that computes the table (constitutive_table.cc) because the two share
// nothing but the arrays handed over. Internal to source/assembly.

#include <cosmo/assembly/constitutive_table.h>

#include <string>
#include <vector>

namespace cosmo
{
  namespace assembly
  {
    namespace internal
    {
      /**
       * table.h5, written by all ranks together (each its own points, a
       * collective MPI-IO write; one rank alone without mpirun): the
       * datasets with their units and meaning as attributes, the strain
       * axes as HDF5 dimension scales (h5py: dataset.dims), the run's
       * description as file attributes. `points`: the grid points (i n2 +
       * j) this rank holds in energy, resultants, stiffness and converged.
       */
      void
      write_table_h5(const std::string &              file_name,
                     const TableDescription &         d,
                     unsigned int                     first,
                     unsigned int                     second,
                     const std::vector<double> &      s1,
                     const std::vector<double> &      s2,
                     const std::vector<unsigned int> &points,
                     const std::vector<double> &      energy,
                     const std::vector<double> &      resultants,
                     const std::vector<double> &      stiffness,
                     const std::vector<double> &      converged);
    } // namespace internal
  }   // namespace assembly
} // namespace cosmo

#endif

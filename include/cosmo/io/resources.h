#ifndef cosmo_io_resources_h
#define cosmo_io_resources_h

#include <deal.II/grid/tria.h>

#include <functional>
#include <string>

/**
 * A problem too large for the machine is refused before the work starts
 * (exit 1, naming the entries), not left to run for hours or to die with
 * std::bad_alloc.
 */
namespace cosmo
{
  namespace io
  {
    /**
     * Estimated peak memory [bytes] of a run with n unknowns of a 2D problem
     * of element degree p: the process (~0.2 GB) plus the sparse direct
     * factorization, whose fill grows like N log N under nested dissection.
     * Calibrated on plate_rod (Q2, 6 fields): 195, 245 and 475 MB peak at
     * 4902, 19 014 and 74 886 unknowns (benchmarks/README.md); the model
     * gives 5 kB per unknown at 75k and is within a factor 2 above it.
     */
    double
    estimated_memory(double n_unknowns, unsigned int degree);

    /// The machine's physical memory [bytes].
    double
    physical_memory();

    /**
     * Throw InputError(section, entry, value, ...) if estimated_memory() of
     * n_unknowns exceeds the physical memory; the message gives both.
     */
    void
    check_memory(double             n_unknowns,
                 unsigned int       degree,
                 const std::string &section,
                 const std::string &entry,
                 const std::string &value);

    /**
     * The memory of a table or a study of n_points points, bytes_per_point
     * each (its results in memory, in the CSV table and in the HDF5 or
     * checkpoint copies), beside the problem's own (problem_bytes): throw
     * InputError(section, entry, value, ...) naming the estimate and the
     * memory available if it exceeds the physical memory; otherwise return
     * the estimate [bytes], for the log.
     */
    double
    check_points_memory(double             n_points,
                        double             bytes_per_point,
                        double             problem_bytes,
                        const std::string &section,
                        const std::string &entry,
                        const std::string &value);

    /// "12.3 MB", "4.56 GB": a size for the log.
    std::string
    format_bytes(double bytes);

    /**
     * Before each refinement of `tria`: check_memory() of the mesh it would
     * make (2^dim children per cell), with unknowns_per_cell unknowns per
     * cell. Connected to the triangulation's pre_refinement signal, so it
     * applies to whatever refines the mesh (a section shape, a plate
     * domain); disconnect the returned connection when the mesh is made.
     */
    template <int dim>
    boost::signals2::connection
    guard_refinement(dealii::Triangulation<dim> &tria,
                     double                      unknowns_per_cell,
                     unsigned int                degree,
                     const std::string &         section,
                     const std::string &         entry,
                     const std::string &         value)
    {
      return tria.signals.pre_refinement.connect([&tria, unknowns_per_cell, degree, section, entry, value]() {
        const double cells = static_cast<double>(tria.n_active_cells()) * (1u << dim);
        check_memory(cells * unknowns_per_cell, degree, section, entry, value);
      });
    }
  } // namespace io
} // namespace cosmo

#endif

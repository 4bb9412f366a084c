#ifndef cosmo_materials_section_stiffness_h
#define cosmo_materials_section_stiffness_h

#include <array>
#include <string>

/**
 * A part-1 section's 6x6 stiffness as the rod laws read it: from a
 * rod_cross_section summary.json (the `quadratic` law's 'Stiffness file',
 * the `section` law's members), and the test that it is positive definite.
 */
namespace cosmo
{
  namespace materials
  {
    /**
     * The 6x6 "stiffness" of the rod_cross_section summary.json `file`,
     * row-major; io::InputError naming `entry` of `section` if the file
     * cannot be read or is not JSON, or the matrix is not 6 rows of 6
     * finite numbers (the message says how many were found).
     */
    std::array<double, 36>
    read_summary_stiffness(const std::string &file, const std::string &section, const std::string &entry);

    /**
     * 0 if the symmetric part of K (row-major) is positive definite (by
     * Cholesky, a pivot above 1e-12 of its diagonal entry), otherwise the
     * size of the leading block that is not.
     */
    unsigned int
    indefinite_leading_block(const std::array<double, 36> &K);
  } // namespace materials
} // namespace cosmo

#endif

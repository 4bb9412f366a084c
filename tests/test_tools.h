#ifndef cosmo_tests_test_tools_h
#define cosmo_tests_test_tools_h

// Minimal assertion helpers for the validation programs: every check prints
// the measured value, the reference and the tolerance, and a failed check
// makes the program exit with status 1 (ctest reports it).

#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>
#include <map>
#include <iomanip>
#include <iostream>
#include <string>

namespace cosmo_test
{
  inline int &
  failures()
  {
    static int n = 0;
    return n;
  }

  /// |value - reference| <= rtol |reference| + atol
  inline void
  check_close(const std::string &what,
              const double       value,
              const double       reference,
              const double       rtol,
              const double       atol = 0)
  {
    const double err = std::abs(value - reference);
    const bool   ok  = std::isfinite(value) && err <= rtol * std::abs(reference) + atol;
    std::cout << (ok ? "  ok    " : "  FAIL  ") << std::left << std::setw(44) << what
              << std::right << std::setprecision(10) << " value " << std::setw(17) << value
              << "  reference " << std::setw(17) << reference << "  rel.err "
              << std::setprecision(3)
              << (reference != 0 ? err / std::abs(reference) : err) << "  (rtol " << rtol
              << ", atol " << atol << ")\n";
    if (!ok)
      ++failures();
  }

  inline void
  check(const std::string &what, const bool condition)
  {
    std::cout << (condition ? "  ok    " : "  FAIL  ") << what << "\n";
    if (!condition)
      ++failures();
  }

  inline int
  report()
  {
    if (failures() > 0)
      std::cout << failures() << " check(s) FAILED\n";
    else
      std::cout << "all checks passed\n";
    return failures() > 0 ? 1 : 0;
  }

  using Cases = std::map<std::string, std::function<void()>>;

  /**
   * `program <case> <arguments...>`: run the named case (after the caller
   * has read the extra arguments) and report. Status 2 on bad usage, 1 on a
   * failed check or an exception, 0 otherwise.
   */
  inline int
  run_case(const std::string &program,
           const std::string &arguments,
           const Cases &      cases,
           int                argc,
           char **            argv,
           int                min_argc,
           int                max_argc)
  {
    if (argc < min_argc || argc > max_argc || !cases.count(argv[1]))
      {
        std::cerr << "usage: " << program << " <case> " << arguments << "; cases:";
        for (const auto &c : cases)
          std::cerr << " " << c.first;
        std::cerr << "\n";
        return 2;
      }
    try
      {
        cases.at(argv[1])();
      }
    catch (std::exception &e)
      {
        std::cout << "FAIL: exception: " << e.what() << "\n";
        return 1;
      }
    return report();
  }
} // namespace cosmo_test

#endif

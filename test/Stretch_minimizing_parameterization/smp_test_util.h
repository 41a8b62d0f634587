// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Always-on checks for the tests (assert() vanishes under NDEBUG in Release builds).

#ifndef SMP_TEST_UTIL_H
#define SMP_TEST_UTIL_H

#include <cstdlib>
#include <iostream>
#include <string>

namespace smp_test {

inline int& failures()
{
  static int n = 0;
  return n;
}

inline int& checks()
{
  static int n = 0;
  return n;
}

// Prints the closing line that CTest logs show, and the exit status.
inline int summary()
{
  std::cout << (checks() - failures()) << " passed, " << failures() << " failed" << std::endl;
  return failures() == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Built with the sanitizers (SMP_SANITIZE), which run the code about ten times slower: the long
// runs on the largest meshes (many steps, where what is checked is a figure, not a code path
// that the smaller meshes miss) are left to the release build, which runs every case.
#if defined(SMP_TEST_SANITIZED)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif

inline std::string data_file(const std::string& name) { return std::string(SMP_TEST_DATA_DIR) + "/" + name; }

} // namespace smp_test

// Records a failure with its location and message, and goes on.
#define SMP_CHECK(cond, msg)                                                              \
  do {                                                                                    \
    ++smp_test::checks();                                                                 \
    if(!(cond)) {                                                                         \
      ++smp_test::failures();                                                             \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond " -- " << msg  \
                << std::endl;                                                             \
    }                                                                                     \
  } while(false)

#endif // SMP_TEST_UTIL_H

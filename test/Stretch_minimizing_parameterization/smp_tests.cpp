// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tests in one executable, `smp_tests NAME [ARGUMENTS]` running the test NAME (CTest runs
// each on its own). Each test file keeps its code in a namespace of its name, so that CMake can
// compile the files of a group as one translation unit (CMakeLists.txt): the package's templates
// are then instantiated once per group instead of once per test.

#include <cstring>
#include <iostream>

#include "smp_test_list.h" // SMP_TESTS(X): X(name) for each test, made by CMakeLists.txt

#define SMP_DECLARE_TEST(name) namespace name { int run_test(int argc, char** argv); }
SMP_TESTS(SMP_DECLARE_TEST)

int main(int argc, char** argv)
{
  struct Test { const char* name; int (*run)(int, char**); };
#define SMP_TEST_ENTRY(name) {#name, &name::run_test},
  const Test tests[] = {SMP_TESTS(SMP_TEST_ENTRY)};
  for(const Test& test : tests)
    if(argc > 1 && std::strcmp(argv[1], test.name) == 0)
      return test.run(argc - 1, argv + 1);
  std::cerr << "usage: smp_tests NAME [ARGUMENTS], NAME one of:";
  for(const Test& test : tests)
    std::cerr << " " << test.name;
  std::cerr << std::endl;
  return 2;
}

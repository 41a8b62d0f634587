// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the tools read their command line: the options a user sees and one positional MESH.

#ifndef SMP_TOOLS_SMP_COMMAND_LINE_H
#define SMP_TOOLS_SMP_COMMAND_LINE_H

#include <boost/program_options.hpp>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstdlib>
#include <iostream>
#include <new>
#include <string>

namespace smp_tools {

// One clear line "TOOL: message", then the exit status: 2 for a wrong command line, 1 for a
// failure.
[[noreturn]] inline void fail(const std::string& tool, const std::string& message, int status = 1)
{
  std::cerr << tool << ": " << message << std::endl;
  std::exit(status);
}

// Keeps the memory the tools free for their next allocations. A run allocates and frees blocks
// of the same sizes over and over (a factorization per Newton step and per chart, on several
// threads), which glibc's allocator, by default, mostly returns to the system and then takes
// back page by page, each page a fault, and page faults are costly on virtual machines. Blocks
// below 32 MiB now come from the heap, and up to 128 MiB of free memory at its top stay there;
// larger blocks (the systems of large meshes) are still mapped apart and returned when freed.
inline void keep_freed_memory()
{
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
}

// `run(argc, argv)`, what it throws made a message and exit status 1 (the tools write their
// outputs atomically, so this never leaves a partial file).
template <typename Run>
int run_guarded(const std::string& tool, Run run, int argc, char** argv)
{
  keep_freed_memory();
  try {
    return run(argc, argv);
  } catch(const std::bad_alloc&) {
    fail(tool, "out of memory: the mesh is too large for the memory available");
  } catch(const std::exception& e) {
    fail(tool, std::string("unexpected error: ") + e.what());
  }
}

// Parses `argv` into the variables of `described` and `input` (the MESH). With --help, or
// without MESH, prints `usage` and the options and exits (0 for --help, else 2); a command line
// the parser refuses exits with "TOOL: why" and status 2.
inline boost::program_options::variables_map
parse_command_line(int argc, char** argv, const std::string& tool, const boost::program_options::options_description& described,
                   std::string& input, const std::string& usage)
{
  namespace po = boost::program_options;
  po::options_description all;
  all.add(described).add_options()("mesh", po::value(&input));
  po::positional_options_description positional;
  positional.add("mesh", 1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    po::notify(vm);
  } catch(const po::error& e) {
    fail(tool, std::string(e.what()) + " (run without arguments for the options)", 2);
  }
  if(vm.count("help") || input.empty()) {
    (input.empty() && !vm.count("help") ? std::cerr : std::cout) << usage << described;
    std::exit(vm.count("help") ? 0 : 2);
  }
  return vm;
}

} // namespace smp_tools

#endif // SMP_TOOLS_SMP_COMMAND_LINE_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command a user runs (smp-parameterize, smp-remesh): it starts the tool's program with
// transparent huge pages for the memory of malloc (glibc's tunable glibc.malloc.hugetlb, which
// is read at the start of a process only), unless the environment sets that tunable already.
// The tools allocate and fault in fresh memory all along (a factorization per Newton step and
// per chart), a page fault per 4 KiB page, and page faults are costly on virtual machines; a
// huge page takes one fault for 2 MiB. A launcher linked with nothing else starts at once,
// where a program that restarted itself would load its libraries (SuiteSparse, BLAS, Cairo) twice.
//
// The program is looked for beside the launcher in `libexec/` (the build tree), then where the
// install puts it relative to the launcher.

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace {

// The directory of this executable, with its trailing '/'; empty if unknown.
std::string own_directory()
{
  std::vector<char> path(4096);
  const ssize_t n = readlink("/proc/self/exe", path.data(), path.size() - 1);
  if(n <= 0)
    return std::string();
  const std::string file(path.data(), std::size_t(n));
  const std::size_t slash = file.rfind('/');
  return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

void ask_for_huge_pages()
{
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if(tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr)
    return;
  const std::string value = tunables != nullptr && *tunables != '\0' ? std::string(tunables) + ":glibc.malloc.hugetlb=1"
                                                                       : std::string("glibc.malloc.hugetlb=1");
  setenv("GLIBC_TUNABLES", value.c_str(), 1); // if it fails, the program runs without
#endif
}

} // namespace

int main(int, char** argv)
{
  ask_for_huge_pages();
  const std::string here = own_directory();
  const std::string candidates[] = {here + "libexec/" SMP_PROGRAM, here + SMP_PROGRAM_FROM_BINDIR "/" SMP_PROGRAM};
  int error = ENOENT;
  for(const std::string& program : candidates) {
    if(here.empty() || access(program.c_str(), X_OK) != 0)
      continue;
    execv(program.c_str(), argv);
    error = errno; // only returns on failure
  }
  std::cerr << SMP_PROGRAM << ": cannot start the program (" << candidates[0] << " or " << candidates[1]
            << "): " << std::strerror(error) << std::endl;
  return 1;
}

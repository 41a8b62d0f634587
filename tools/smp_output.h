// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the tools write their files: through a temporary name renamed at the end, so that a
// failure (a full disk, a crash) never leaves a file that looks complete.

#ifndef SMP_TOOLS_SMP_OUTPUT_H
#define SMP_TOOLS_SMP_OUTPUT_H

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace smp_tools {

// Writes `text` to `file`; false, with `error`, if it could not (nothing is left then).
inline bool write_atomically(const std::filesystem::path& file, const std::string& text, std::string& error)
{
  const std::filesystem::path temporary = file.string() + ".part";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.flush();
    if(!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      error = "cannot write " + file.string();
      return false;
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if(ec) {
    std::filesystem::remove(temporary, ec);
    error = "cannot write " + file.string() + ": " + ec.message();
    return false;
  }
  return true;
}

} // namespace smp_tools

#endif // SMP_TOOLS_SMP_OUTPUT_H

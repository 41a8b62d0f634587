// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the tools write their files: through a temporary name renamed at the end, so that a
// failure (a full disk, a crash) never leaves a file that looks complete; and the text of a
// mesh file, numbers included.

#ifndef SMP_TOOLS_SMP_OUTPUT_H
#define SMP_TOOLS_SMP_OUTPUT_H

#include <charconv>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <type_traits>

namespace smp_tools {

// Text built piece by piece; a floating-point number is written in the shortest form that
// reads back as the same double (std::to_chars: exact, and much faster than a stream at 17
// digits, which matters for meshes of millions of corners).
class Text
{
public:
  Text& operator<<(const std::string& s) { m_text += s; return *this; }
  Text& operator<<(const char* s) { m_text += s; return *this; }
  Text& operator<<(char c) { m_text += c; return *this; }
  template <typename Number, typename = std::enable_if_t<std::is_arithmetic<Number>::value> >
  Text& operator<<(Number x)
  {
    char buffer[64];
    const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), x);
    m_text.append(buffer, r.ptr);
    return *this;
  }
  const std::string& str() const { return m_text; }

private:
  std::string m_text;
};

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

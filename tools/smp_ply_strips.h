// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef SMP_TOOLS_SMP_PLY_STRIPS_H
#define SMP_TOOLS_SMP_PLY_STRIPS_H

// The triangles of a PLY file stored as triangle strips (element tristrips, as Stanford's
// scanned meshes are): CGAL's PLY reader reads faces only, so the strips element is renamed
// "face" in the header and read by it (ASCII and binary alike), each strip as one list of
// indices, which is then unrolled into its triangles.

#include <CGAL/IO/PLY.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace smp_tools {
namespace internal {

// The triangles of the strips `strips` (lists of vertex indices; -1, read as the largest value
// of a signed or an unsigned 32-bit index, restarts a strip), appended to `triangles`: in a
// run v0 v1 v2 v3 ..., the triangle ending at vertex k is (v_{k-2}, v_{k-1}, v_k) for even k and
// (v_{k-1}, v_{k-2}, v_k) for odd k, so that all keep the orientation of the first. Triangles
// with a repeated vertex, which only join runs, are left out. False, with a message, if an
// index is out of range.
inline bool unroll_triangle_strips(const std::vector<std::vector<std::size_t> >& strips, std::size_t vertices,
                                   std::vector<std::vector<std::size_t> >& triangles, std::string& error)
{
  const std::size_t restart_signed = (std::numeric_limits<std::size_t>::max)();
  const std::size_t restart_unsigned = (std::numeric_limits<std::uint32_t>::max)();
  for(const std::vector<std::size_t>& strip : strips) {
    std::size_t run = 0; // vertices of the current run so far
    std::size_t a = 0, b = 0; // its last two
    for(std::size_t v : strip) {
      if(v == restart_signed || v == restart_unsigned) {
        run = 0;
        continue;
      }
      if(v >= vertices) {
        error = "a triangle strip has a vertex index out of range (" + std::to_string(v) + ", " +
                std::to_string(vertices) + " vertices)";
        return false;
      }
      if(run >= 2 && a != b && b != v && a != v)
        triangles.push_back(run % 2 == 0 ? std::vector<std::size_t>{a, b, v} : std::vector<std::size_t>{b, a, v});
      a = b;
      b = v;
      ++run;
    }
  }
  return true;
}

// Whether the PLY header of `file` declares triangle strips (`element tristrips`).
inline bool ply_has_triangle_strips(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for(int lines = 0; lines < 1000 && std::getline(in, line) && line.rfind("end_header", 0) != 0; ++lines)
    if(line.rfind("element tristrips", 0) == 0)
      return true;
  return false;
}

// Reads `file`, a PLY file whose header declares `element tristrips`, into `points` and the
// triangles of its strips. False, with a message, if it cannot be read so.
template <typename Point>
bool read_ply_triangle_strips(const std::string& file, std::vector<Point>& points,
                              std::vector<std::vector<std::size_t> >& triangles, std::string& error)
{
  std::ifstream in(file, std::ios::binary);
  std::stringstream renamed(std::ios::in | std::ios::out | std::ios::binary);
  bool found = false, ended = false;
  for(std::string line; !ended && std::getline(in, line);) {
    if(!found && line.rfind("element tristrips", 0) == 0) {
      line.replace(0, 17, "element face");
      found = true;
    }
    ended = line.rfind("end_header", 0) == 0;
    renamed << line << '\n';
  }
  if(!found || !ended) {
    error = "cannot read the triangle strips of " + file;
    return false;
  }
  if(in.peek() != std::ifstream::traits_type::eof())
    renamed << in.rdbuf(); // the data, as they are
  std::vector<std::vector<std::size_t> > strips;
  points.clear();
  if(!CGAL::IO::read_PLY(renamed, points, strips, CGAL::parameters::verbose(false))) {
    error = "cannot read the triangle strips of " + file +
            " (element tristrips needs a list property vertex_indices of 32-bit integers)";
    return false;
  }
  triangles.clear();
  return unroll_triangle_strips(strips, points.size(), triangles, error);
}

} // namespace internal
} // namespace smp_tools

#endif // SMP_TOOLS_SMP_PLY_STRIPS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the translation units of the fuzz harness share: the byte reader that draws inputs and
// options, the promise check, and the three checks (each in a file of its own, so that the
// harness compiles on several cores).

#ifndef SMP_FUZZ_SMP_H
#define SMP_FUZZ_SMP_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

namespace smp_fuzz {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;

// inputs above these sizes are skipped: each run must stay short
constexpr std::size_t max_polygons = 3000;
constexpr std::size_t max_soup_points = 48;

inline void promise(bool kept, const char* what)
{
  if(!kept) {
    std::fprintf(stderr, "broken promise: %s\n", what);
    std::abort();
  }
}

// Reads the bytes in order; past the end, zeros.
struct Bytes
{
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;

  bool empty() const { return at >= size; }
  std::uint8_t byte() { return at < size ? data[at++] : 0; }
  double unit() { return byte() / 255.; }
  double coordinate()
  {
    static const double special[] = {0., 1., -1., 0.5, 1e300, -1e300, 1e-300, 4.9e-324,
                                     std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::quiet_NaN(), 1e-9, 1e9};
    const std::uint8_t kind = byte();
    if(kind < 160)
      return (kind % 16) * 0.25 - 2.; // a small lattice: repeated points, flat and degenerate faces
    if(kind < 220)
      return special[kind % (sizeof(special) / sizeof(double))];
    double d = 0.;
    std::uint8_t raw[sizeof(double)];
    for(std::uint8_t& r : raw) r = byte();
    std::memcpy(&d, raw, sizeof(double));
    return d;
  }
};

// The atlas keeps its promises: a uv per corner in the unit square and a chart per polygon
// (fuzz_atlas.cpp).
void check_atlas(const std::vector<Point_3>& points, const std::vector<std::vector<std::size_t> >& polygons,
                 Bytes& options);

// The parameterizer on a mesh: an error code, or a finite map of the component
// (fuzz_parameterizer.cpp).
void check_parameterizer(Mesh& mesh, Bytes& options);

// Remeshes `mesh`: a valid triangle mesh of finite points that is what the report says, or an
// error with a message (fuzz_remeshing.cpp).
void check_remeshing(const Mesh& mesh, Bytes& options);

} // namespace smp_fuzz

#endif // SMP_FUZZ_SMP_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_BORDER_SAMPLING_H
#define CGAL_SMP_INTERNAL_REMESH_BORDER_SAMPLING_H

// The vertices of a new mesh along the border loops of the old one: evenly spaced by 3D arc
// length, on the old border edges, so that the new mesh keeps the old border loops.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A point of a border edge: (1 - t) * from + t * to, vertices by index.
struct Edge_location
{
  int from = 0, to = 0;
  double t = 0.;

  template <typename Point>
  Point in(const std::vector<Point>& at) const
  {
    Point p{};
    for(std::size_t i = 0; i < p.size(); ++i)
      p[i] = (1. - t) * at[std::size_t(from)][i] + t * at[std::size_t(to)][i];
    return p;
  }
};

// Points along the closed polyline `loop` (vertices by index into `xyz`), spaced by about
// `spacing` in 3D, at least three, the first at the loop's first vertex.
inline std::vector<Edge_location> sample_loop(const std::vector<int>& loop, const std::vector<Vec3>& xyz, double spacing)
{
  const std::size_t n = loop.size();
  std::vector<double> length(n);
  double total = 0.;
  for(std::size_t k = 0; k < n; ++k) {
    length[k] = norm3(sub3(xyz[std::size_t(loop[(k + 1) % n])], xyz[std::size_t(loop[k])]));
    total += length[k];
  }
  std::vector<Edge_location> samples;
  if(!(total > 0.) || !std::isfinite(total))
    return samples;
  const double ratio = total / spacing;
  const std::size_t count = std::size_t((std::max)(3., std::isfinite(ratio) ? std::round((std::min)(ratio, 1e9)) : 3.));
  std::size_t edge = 0;
  double before = 0.; // arc length at the start of `edge`
  for(std::size_t s = 0; s < count; ++s) {
    const double at = total * double(s) / double(count);
    while(edge + 1 < n && before + length[edge] <= at) {
      before += length[edge];
      ++edge;
    }
    Edge_location e;
    e.from = loop[edge];
    e.to = loop[(edge + 1) % n];
    e.t = length[edge] > 0. ? (std::min)(1., (at - before) / length[edge]) : 0.;
    samples.push_back(e);
  }
  return samples;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_BORDER_SAMPLING_H

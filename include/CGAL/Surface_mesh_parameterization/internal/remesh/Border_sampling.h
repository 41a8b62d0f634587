// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_BORDER_SAMPLING_H
#define CGAL_SMP_INTERNAL_REMESH_BORDER_SAMPLING_H

// The vertices of a new mesh along the border loops of the old one: evenly spaced by 3D arc
// length, on the old border edges, so that the new mesh keeps the old border loops. Where two
// stretches of border lie on each other (the two sides of a cut that opened a closed surface),
// both get the same points, so that the new mesh can be closed again along the cut.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
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

  // the same for a value given per vertex
  double in(const std::vector<double>& at) const { return (1. - t) * at[std::size_t(from)] + t * at[std::size_t(to)]; }
};

// The 3D length of the edge from vertex `a` to vertex `b`, times the mean of their `scale`
// (none: 1).
inline double scaled_length(int a, int b, const std::vector<Vec3>& xyz, const std::vector<double>& scale)
{
  const double length = norm3(sub3(xyz[std::size_t(b)], xyz[std::size_t(a)]));
  return scale.empty() ? length : 0.5 * (scale[std::size_t(a)] + scale[std::size_t(b)]) * length;
}

// Points at even steps of 3D arc length along the polyline `v` (vertices by index into `xyz`),
// the length scaled by `scale` (per vertex, linear along each edge; none: 1), about `spacing`
// apart and at least `fewest` steps: the first at its first vertex, the last at its last vertex;
// none if it has no length.
inline std::vector<Edge_location> sample_polyline(const std::vector<int>& v, const std::vector<Vec3>& xyz,
                                                  const std::vector<double>& scale, double spacing, std::size_t fewest)
{
  const std::size_t edges = v.empty() ? 0 : v.size() - 1;
  std::vector<double> length(edges);
  double total = 0.;
  for(std::size_t i = 0; i < edges; ++i) {
    length[i] = scaled_length(v[i], v[i + 1], xyz, scale);
    total += length[i];
  }
  std::vector<Edge_location> points;
  if(!(total > 0.) || !std::isfinite(total))
    return points;
  const double ratio = total / spacing, least = double(fewest);
  const std::size_t count = std::size_t((std::max)(least, std::isfinite(ratio) ? std::round((std::min)(ratio, 1e9)) : least));
  std::size_t edge = 0;
  double before = 0.; // arc length at the start of `edge`
  for(std::size_t j = 0; j <= count; ++j) {
    const double at = total * double(j) / double(count);
    while(edge + 1 < edges && before + length[edge] <= at) {
      before += length[edge];
      ++edge;
    }
    Edge_location e;
    e.from = v[edge];
    e.to = v[edge + 1];
    e.t = j == count ? 1. : length[edge] > 0. ? (std::min)(1., (at - before) / length[edge]) : 0.;
    points.push_back(e);
  }
  return points;
}

// Points along the closed polyline `loop` (vertices by index into `xyz`), spaced by about
// `spacing` in 3D (scaled as sample_polyline() says), at least three, the first at the loop's
// first vertex.
inline std::vector<Edge_location> sample_loop(const std::vector<int>& loop, const std::vector<Vec3>& xyz,
                                              const std::vector<double>& scale, double spacing)
{
  std::vector<int> closed = loop;
  if(!loop.empty())
    closed.push_back(loop.front());
  std::vector<Edge_location> samples = sample_polyline(closed, xyz, scale, spacing, 3);
  if(!samples.empty())
    samples.pop_back(); // the first one again
  return samples;
}

// The border edges of `loops` that lie on another border edge the other way (the edge from a
// position to a position, where one goes from the second to the first): per loop and edge k
// (from its vertex k to the next), that edge as (loop, edge), or (-1, -1). Edges of no length
// have none.
inline std::vector<std::vector<std::pair<int, int> > > twin_border_edges(const std::vector<std::vector<int> >& loops,
                                                                        const std::vector<Vec3>& xyz)
{
  typedef std::array<double, 6> Key;
  const auto key = [&xyz](int a, int b) {
    const Vec3 &p = xyz[std::size_t(a)], &q = xyz[std::size_t(b)];
    return Key{{p[0], p[1], p[2], q[0], q[1], q[2]}};
  };
  std::map<Key, std::pair<int, int> > edges;
  for(std::size_t l = 0; l < loops.size(); ++l)
    for(std::size_t k = 0; k < loops[l].size(); ++k)
      edges.emplace(key(loops[l][k], loops[l][(k + 1) % loops[l].size()]), std::make_pair(int(l), int(k)));
  std::vector<std::vector<std::pair<int, int> > > twin(loops.size());
  for(std::size_t l = 0; l < loops.size(); ++l) {
    const std::size_t n = loops[l].size();
    twin[l].assign(n, std::make_pair(-1, -1));
    for(std::size_t k = 0; k < n; ++k) {
      const int a = loops[l][k], b = loops[l][(k + 1) % n];
      if(xyz[std::size_t(a)] == xyz[std::size_t(b)])
        continue;
      const auto it = edges.find(key(b, a));
      if(it != edges.end())
        twin[l][k] = it->second;
    }
  }
  return twin;
}

// Points along the border loops `loops` (vertices by index into `xyz`), one list per loop,
// spaced by about `spacing` in 3D (scaled as sample_polyline() says; `scale` is the same at
// vertices of the same position). A loop none of whose edges lies on another border edge
// (twin_border_edges()) is sampled by sample_loop(). The other loops are cut into stretches at
// the vertices where their edges stop or start lying on others, or go on along another stretch
// (the ends and the tip of a cut): each stretch gets a point at its first vertex and points
// evenly spaced by arc length between its ends, counted and placed from the end of smaller
// coordinates, so that the two sides of a cut get the same points bit for bit. `cut` tells
// whether any edge lies on another.
inline std::vector<std::vector<Edge_location> > sample_loops(const std::vector<std::vector<int> >& loops,
                                                             const std::vector<Vec3>& xyz, const std::vector<double>& scale,
                                                             double spacing, bool& cut)
{
  const std::vector<std::vector<std::pair<int, int> > > twin = twin_border_edges(loops, xyz);
  std::vector<std::vector<Edge_location> > samples(loops.size());
  cut = false;
  for(std::size_t l = 0; l < loops.size(); ++l) {
    const std::vector<int>& loop = loops[l];
    const std::size_t n = loop.size();
    const std::vector<std::pair<int, int> >& t = twin[l];
    if(std::all_of(t.begin(), t.end(), [](const std::pair<int, int>& e) { return e.first < 0; })) {
      samples[l] = sample_loop(loop, xyz, scale, spacing);
      continue;
    }
    cut = true;
    // vertex k (between edges k - 1 and k) starts a stretch unless both edges lie on two edges
    // that follow each other the other way round, and are not each other's
    std::vector<std::size_t> starts;
    for(std::size_t k = 0; k < n; ++k) {
      const std::pair<int, int>& before = t[(k + n - 1) % n];
      const std::pair<int, int>& after = t[k];
      bool goes_on = (before.first < 0) == (after.first < 0);
      if(goes_on && after.first >= 0) {
        const std::size_t m = loops[std::size_t(after.first)].size();
        goes_on = after.first == before.first && std::size_t(after.second + 1) % m == std::size_t(before.second) &&
                  !(after.first == int(l) && std::size_t(after.second) == (k + n - 1) % n);
      }
      if(!goes_on)
        starts.push_back(k);
    }
    // a loop all on another: from its vertex of smallest coordinates, as the other's
    if(starts.empty())
      starts.push_back(std::size_t(std::min_element(loop.begin(), loop.end(), [&xyz](int a, int b) {
                                     return xyz[std::size_t(a)] < xyz[std::size_t(b)];
                                   }) - loop.begin()));
    for(std::size_t s = 0; s < starts.size(); ++s) {
      const std::size_t first = starts[s];
      std::size_t edges = (s + 1 < starts.size() ? starts[s + 1] : starts[0] + n) - first;
      if(edges == 0) edges = n;
      // the stretch's vertices, from its end of smaller coordinates (at equal ends, its second
      // vertex of smaller coordinates first)
      std::vector<int> v;
      for(std::size_t i = 0; i <= edges; ++i)
        v.push_back(loop[(first + i) % n]);
      const Vec3 &head = xyz[std::size_t(v.front())], &tail = xyz[std::size_t(v.back())];
      const bool reversed = tail < head || (tail == head && xyz[std::size_t(v[v.size() - 2])] < xyz[std::size_t(v[1])]);
      if(reversed)
        std::reverse(v.begin(), v.end());
      // (a stretch of no length has none: its point is the next one's)
      std::vector<Edge_location> points = sample_polyline(v, xyz, scale, spacing, 1);
      if(points.empty())
        continue;
      // the stretch's first vertex and its inner points, in the loop's order
      if(reversed)
        std::reverse(points.begin(), points.end());
      samples[l].insert(samples[l].end(), points.begin(), points.end() - 1);
    }
    if(samples[l].size() < 3) // too short a loop to be cut into stretches
      samples[l] = sample_loop(loop, xyz, scale, spacing);
  }
  return samples;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_BORDER_SAMPLING_H

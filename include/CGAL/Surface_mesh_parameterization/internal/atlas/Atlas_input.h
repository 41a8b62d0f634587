// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_ATLAS_INPUT_H
#define CGAL_SMP_INTERNAL_ATLAS_ATLAS_INPUT_H

// The first stage of the atlas: a polygon soup checked, welded and triangulated, with the way
// back to the input's polygons and corners. Nothing is repaired in place: the input's vertex
// positions and polygon order are what the uv corners are written for.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <functional>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Triangles of a soup. `vertex[t][k]` is an input vertex index (the first input vertex at that
// position: duplicates are welded); `polygon[t]` the input polygon the triangle comes from and
// `corner[t][k]` the corner of that polygon. Polygons whose corners span no triangle (fewer than
// three distinct positions) have no triangle and are listed in `flat_polygons`.
struct Atlas_triangles
{
  std::vector<Vec3> xyz;                         // the input's positions, as doubles
  std::vector<std::array<int, 3> > vertex;
  std::vector<std::size_t> polygon;
  std::vector<std::array<int, 3> > corner;
  std::vector<std::size_t> flat_polygons;
  std::vector<int> weld;                         // per input vertex: the first input vertex at its position
  std::size_t welded_vertices = 0;               // input vertices merged into an earlier one
};

// Hash of an edge given as its two vertex indices, smaller first.
struct Edge_hash
{
  std::size_t operator()(const std::pair<int, int>& e) const
  {
    return std::hash<long long>()((static_cast<long long>(e.first) << 32) ^ static_cast<long long>(e.second));
  }
};

// Splits one polygon (its corners already welded, consecutive repeats removed) into triangles
// of corner indices: a quad along its shorter diagonal, larger polygons by CGAL's minimal-area
// hole triangulation, a fan if that fails.
inline void triangulate_polygon(const std::vector<Vec3>& p, std::vector<std::array<int, 3> >& out)
{
  out.clear();
  const int n = int(p.size());
  if(n == 3) {
    out.push_back({0, 1, 2});
    return;
  }
  if(n == 4) {
    const double d02 = norm3(sub3(p[2], p[0])), d13 = norm3(sub3(p[3], p[1]));
    if(d02 <= d13) {
      out.push_back({0, 1, 2});
      out.push_back({0, 2, 3});
    } else {
      out.push_back({1, 2, 3});
      out.push_back({1, 3, 0});
    }
    return;
  }
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_3> polyline;
  for(const Vec3& q : p)
    polyline.emplace_back(q[0], q[1], q[2]);
  std::vector<std::tuple<int, int, int> > triples;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polyline, std::back_inserter(triples));
  for(const auto& t : triples)
    out.push_back({std::get<0>(t), std::get<1>(t), std::get<2>(t)});
  if(out.size() != std::size_t(n - 2)) {
    out.clear();
    for(int k = 1; k + 1 < n; ++k)
      out.push_back({0, k, k + 1});
  }
}

// Reads the soup into `out`. Returns an empty string, or why the soup cannot be used: a
// coordinate that is not finite, a corner index out of range.
template <typename PointRange, typename PolygonRange>
std::string make_atlas_triangles(const PointRange& points, const PolygonRange& polygons, Atlas_triangles& out)
{
  out = Atlas_triangles();
  out.xyz.reserve(points.size());
  for(const auto& p : points) {
    const Vec3 q = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      return "vertex " + std::to_string(out.xyz.size()) + " has a coordinate that is not finite";
    out.xyz.push_back(q);
  }
  const std::size_t nv = out.xyz.size();

  // weld: every vertex to the first one at its position
  std::vector<int>& weld = out.weld;
  weld.resize(nv);
  {
    std::map<Vec3, int> first;
    for(std::size_t v = 0; v < nv; ++v) {
      const auto it = first.emplace(out.xyz[v], int(v)).first;
      weld[v] = it->second;
      if(it->second != int(v))
        ++out.welded_vertices;
    }
  }

  std::vector<int> ring, ring_corner;
  std::vector<Vec3> ring_xyz;
  std::vector<std::array<int, 3> > pieces, seen;
  std::size_t index = 0;
  for(const auto& polygon : polygons) {
    ring.clear();
    ring_corner.clear();
    int k = 0;
    for(const auto corner : polygon) {
      const long long c = static_cast<long long>(corner);
      if(c < 0 || std::size_t(c) >= nv)
        return "polygon " + std::to_string(index) + " has a vertex index out of range";
      const int v = weld[std::size_t(c)];
      if(ring.empty() || ring.back() != v) {
        ring.push_back(v);
        ring_corner.push_back(k);
      }
      ++k;
    }
    while(ring.size() > 1 && ring.back() == ring.front()) {
      ring.pop_back();
      ring_corner.pop_back();
    }
    if(ring.size() < 3) {
      out.flat_polygons.push_back(index++);
      continue;
    }
    ring_xyz.clear();
    for(int v : ring)
      ring_xyz.push_back(out.xyz[std::size_t(v)]);
    triangulate_polygon(ring_xyz, pieces);
    bool any = false;
    seen.clear();
    for(const auto& t : pieces) {
      const std::array<int, 3> v = {ring[t[0]], ring[t[1]], ring[t[2]]};
      if(v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
        continue; // a polygon that visits a vertex twice: this piece spans nothing
      std::array<int, 3> key = v;
      std::sort(key.begin(), key.end());
      if(std::find(seen.begin(), seen.end(), key) != seen.end())
        continue; // or covers a triangle again (in any orientation): it would overlap it
      seen.push_back(key);
      out.vertex.push_back(v);
      out.polygon.push_back(index);
      out.corner.push_back({ring_corner[t[0]], ring_corner[t[1]], ring_corner[t[2]]});
      any = true;
    }
    if(!any)
      out.flat_polygons.push_back(index);
    ++index;
  }
  return std::string();
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_ATLAS_INPUT_H

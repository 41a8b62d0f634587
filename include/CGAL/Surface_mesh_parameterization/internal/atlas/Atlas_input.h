// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_ATLAS_INPUT_H
#define CGAL_SMP_INTERNAL_ATLAS_ATLAS_INPUT_H

// The first stage of the atlas: a polygon soup checked, welded and triangulated, with the way
// back to the input's polygons and corners. Nothing is repaired in place: the input's vertex
// positions and polygon order are what the uv corners are written for.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/triangulate_loop.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/number_utils.h>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Triangles of a soup. `vertex[t][k]` is an input vertex index (the first input vertex at that
// position: duplicates are welded), or, in a polygon that repeats earlier ones, a copy of one
// appended to `xyz` (see separate_repeated_polygons()); `polygon[t]` the input polygon the triangle comes from and
// `corner[t][k]` the corner of that polygon. Polygons whose corners span no triangle (fewer than
// three distinct positions) have no triangle and are listed in `flat_polygons`.
struct Atlas_triangles
{
  std::vector<Vec3> xyz;                         // the input's positions, as doubles, then the copies
  std::vector<std::array<int, 3> > vertex;
  std::vector<std::size_t> polygon;
  std::vector<std::array<int, 3> > corner;
  std::vector<std::size_t> flat_polygons;
  std::vector<int> weld;                         // per input vertex: the first input vertex at its position
  std::size_t welded_vertices = 0;               // input vertices merged into an earlier one
  double length_unit = 1.;                       // the input's length of a unit of `xyz`
};

// Hash of an edge given as its two vertex indices, smaller first.
struct Edge_hash
{
  std::size_t operator()(const std::pair<int, int>& e) const
  {
    return std::hash<long long>()((static_cast<long long>(e.first) << 32) ^ static_cast<long long>(e.second));
  }
};

// Hash of a position, for welding: equal positions (0 and -0 alike) have one hash.
struct Position_hash
{
  std::size_t operator()(const Vec3& p) const
  {
    std::size_t h = 0;
    for(const double c : p)
      boost::hash_combine(h, c + 0.); // -0 + 0 is +0
    return h;
  }
};

// Whether the fan of polygon `p` from its corner `a` has only triangles that turn like the
// polygon: each triangle's normal within 90 degrees of `normal` (newell_normal() of `p`), none
// flat.
inline bool fan_turns_like_polygon(const std::vector<Vec3>& p, const Vec3& normal, std::size_t a)
{
  const std::size_t n = p.size();
  for(std::size_t k = 1; k + 1 < n; ++k)
    if(!(dot3(cross3(sub3(p[(a + k) % n], p[a]), sub3(p[(a + k + 1) % n], p[a])), normal) > 0.))
      return false;
  return true;
}

// Splits one polygon (its corners already welded, consecutive repeats removed) into triangles
// of corner indices. Readers of polygon files split a polygon into a fan, mostly from its first
// corner, or from the first corner that sees all of it, and the stretch they see is that of the
// fan's triangles: the polygon is split into the fan from its first corner whose triangles all
// turn like the polygon (a convex polygon: its first corner), so that the atlas measures and
// bounds what they draw. A polygon without such a corner: a quad along its shorter diagonal, a
// larger polygon by triangulate_loop().
inline void triangulate_polygon(const std::vector<Vec3>& p, std::vector<std::array<int, 3> >& out)
{
  out.clear();
  const std::size_t n = p.size();
  if(n == 3) {
    out.push_back({0, 1, 2});
    return;
  }
  const Vec3 normal = newell_normal(p);
  for(std::size_t a = 0; a < n; ++a)
    if(fan_turns_like_polygon(p, normal, a)) {
      for(std::size_t k = 1; k + 1 < n; ++k)
        out.push_back({int(a), int((a + k) % n), int((a + k + 1) % n)});
      return;
    }
  if(n == 4) {
    if(norm3(sub3(p[2], p[0])) <= norm3(sub3(p[3], p[1]))) {
      out.push_back({0, 1, 2});
      out.push_back({0, 2, 3});
    } else {
      out.push_back({1, 2, 3});
      out.push_back({1, 3, 0});
    }
    return;
  }
  triangulate_loop(p, [](int, int) { return true; }, out);
}

// Whether a triangle (in the scaled coordinates, the largest in [1/2, 1)) is too small for its
// lengths and area to be computed (their squares would underflow): a soup whose coordinates
// span more than double precision at one scale (e.g. 1e233 beside 1) has it laid out without
// area, rather than as a triangle of arbitrary shape and orientation.
inline bool too_small(const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double limit = std::ldexp(1., -480);
  for(int i = 0; i < 3; ++i)
    if(std::abs(a[i] - b[i]) >= limit || std::abs(b[i] - c[i]) >= limit || std::abs(c[i] - a[i]) >= limit)
      return false;
  return true;
}

// Splits a closed walk over vertices (none twice in a row), with the polygon corner of each
// step, into simple loops: where the walk comes back to a vertex, the part since its last visit
// is a loop of its own. A polygon that touches itself at a vertex (a bow-tie) gives its two
// halves; one that goes back and forth (a, b, a, c) gives loops without area.
inline void split_into_simple_loops(const std::vector<int>& ring, const std::vector<int>& corner,
                                    std::vector<std::pair<std::vector<int>, std::vector<int> > >& loops)
{
  loops.clear();
  std::vector<int> walk, walk_corner;
  std::unordered_map<int, std::size_t> position; // of the vertices on `walk`
  for(std::size_t i = 0; i < ring.size(); ++i) {
    const auto it = position.find(ring[i]);
    if(it != position.end()) {
      const std::size_t j = it->second;
      loops.emplace_back(std::vector<int>(walk.begin() + std::ptrdiff_t(j), walk.end()),
                         std::vector<int>(walk_corner.begin() + std::ptrdiff_t(j), walk_corner.end()));
      for(std::size_t k = j; k < walk.size(); ++k)
        position.erase(walk[k]);
      walk.resize(j);
      walk_corner.resize(j);
    }
    position[ring[i]] = walk.size();
    walk.push_back(ring[i]);
    walk_corner.push_back(corner[i]);
  }
  loops.emplace_back(walk, walk_corner);
}

// Gives copies of their vertices to the triangles of a polygon that repeats an earlier polygon
// (the same vertices, in any order: a two-sided surface, whose polygons are all there turned
// over too, or polygons listed twice): the k-th repetition takes the k-th copies (appended to
// `m.xyz`), so that each copy of the surface is charted on its own, as the surface alone would
// be, rather than cut along every edge, which has four sides there. `rings` holds the sorted
// vertices of every polygon with triangles, from `ring_begin[p]` to `ring_begin[p + 1]` (empty
// for the others).
inline void separate_repeated_polygons(Atlas_triangles& m, const std::vector<int>& rings,
                                       const std::vector<std::size_t>& ring_begin)
{
  const std::size_t np = ring_begin.size() - 1, nv = m.xyz.size();
  const auto ring = [&](std::size_t p) {
    return std::make_pair(rings.begin() + std::ptrdiff_t(ring_begin[p]), rings.begin() + std::ptrdiff_t(ring_begin[p + 1]));
  };
  std::vector<std::pair<std::size_t, std::size_t> > by_hash; // (hash of the ring, polygon)
  by_hash.reserve(np);
  for(std::size_t p = 0; p < np; ++p) {
    std::size_t h = ring_begin[p + 1] - ring_begin[p];
    for(auto it = ring(p).first; it != ring(p).second; ++it)
      h = h * 0x9E3779B97F4A7C15ull + std::size_t(*it) + 1;
    if(ring_begin[p + 1] > ring_begin[p])
      by_hash.emplace_back(h, p);
  }
  std::sort(by_hash.begin(), by_hash.end());
  std::vector<std::size_t> repeat(np, 0); // earlier polygons with the same vertices
  bool any = false;
  std::map<std::vector<int>, std::size_t> seen; // the rings of one hash, and how often met
  for(std::size_t a = 0, b = 0; a < by_hash.size(); a = b) {
    for(b = a + 1; b < by_hash.size() && by_hash[b].first == by_hash[a].first; ++b) {}
    if(b == a + 1)
      continue;
    any = true;
    seen.clear();
    for(std::size_t i = a; i < b; ++i) { // the polygons of one hash, in their order
      const auto r = ring(by_hash[i].second);
      repeat[by_hash[i].second] = seen[std::vector<int>(r.first, r.second)]++;
    }
  }
  if(!any)
    return;
  std::unordered_map<std::size_t, int> copy; // repetition * nv + vertex -> its copy
  for(std::size_t t = 0; t < m.vertex.size(); ++t) {
    const std::size_t k = repeat[m.polygon[t]];
    if(k == 0)
      continue;
    for(int& v : m.vertex[t]) {
      const auto it = copy.emplace(k * nv + std::size_t(v), int(m.xyz.size())).first;
      if(it->second == int(m.xyz.size()))
        m.xyz.push_back(m.xyz[std::size_t(v)]);
      v = it->second;
    }
  }
}

// Reads the soup into `out`, its coordinates scaled by a power of two (`length_unit`). Returns
// an empty string, or why the soup cannot be used: a coordinate that is not finite, a corner
// index out of range.
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

  // weld: every vertex to the first one at its position (before the scaling below, which may
  // take tiny differences to zero)
  std::vector<int>& weld = out.weld;
  weld.resize(nv);
  {
    std::unordered_map<Vec3, int, Position_hash> first(nv);
    for(std::size_t v = 0; v < nv; ++v) {
      const auto it = first.emplace(out.xyz[v], int(v)).first;
      weld[v] = it->second;
      if(it->second != int(v))
        ++out.welded_vertices;
    }
  }

  // the indices checked, and the vertices that polygons use
  std::vector<char> used(nv, 0);
  std::size_t index = 0;
  for(const auto& polygon : polygons) {
    for(const auto corner : polygon) {
      const long long c = static_cast<long long>(corner);
      if(c < 0 || std::size_t(c) >= nv)
        return "polygon " + std::to_string(index) + " has a vertex index out of range";
      used[std::size_t(weld[std::size_t(c)])] = 1;
    }
    ++index;
  }

  // the largest coordinate of a vertex in use scaled into [1/2, 1) by a power of two: lengths,
  // areas and their products stay finite whatever the input's unit (exact, but for tiny
  // coordinates)
  double largest = 0.;
  for(std::size_t v = 0; v < nv; ++v)
    if(used[v])
      largest = (std::max)({largest, std::abs(out.xyz[v][0]), std::abs(out.xyz[v][1]), std::abs(out.xyz[v][2])});
  if(largest > 0.) {
    int exponent = 0;
    std::frexp(largest, &exponent);
    out.length_unit = std::ldexp(1., exponent);
    for(Vec3& q : out.xyz)
      for(double& c : q)
        c = std::ldexp(c, -exponent);
  }

  std::vector<int> ring, ring_corner;
  std::vector<Vec3> ring_xyz;
  std::vector<std::array<int, 3> > pieces;
  std::set<std::array<int, 3> > seen; // the triangles of the polygon, as sorted vertices
  std::vector<std::pair<std::vector<int>, std::vector<int> > > loops;
  std::vector<int> sorted_rings;                         // of the polygons with triangles
  std::vector<std::size_t> ring_begin(1, 0);
  index = 0;
  for(const auto& polygon : polygons) {
    ring.clear();
    ring_corner.clear();
    int k = 0;
    for(const auto corner : polygon) {
      const int v = weld[std::size_t(static_cast<long long>(corner))];
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
      ring_begin.push_back(sorted_rings.size());
      continue;
    }
    bool any = false;
    const auto add_triangle = [&](const std::array<int, 3>& v, const std::array<int, 3>& c) {
      if(too_small(out.xyz[std::size_t(v[0])], out.xyz[std::size_t(v[1])], out.xyz[std::size_t(v[2])]))
        return;
      out.vertex.push_back(v);
      out.polygon.push_back(index);
      out.corner.push_back(c);
      any = true;
    };
    if(ring.size() == 3) { // three distinct vertices: the triangle itself
      add_triangle({ring[0], ring[1], ring[2]}, {ring_corner[0], ring_corner[1], ring_corner[2]});
    } else {
      // a ring that passes a vertex again: the planar region it bounds if it is one (a polygon
      // with holes written as one, see triangulate_planar_ring()), else each simple loop
      // triangulated; a triangle covered twice (in any orientation) kept once
      split_into_simple_loops(ring, ring_corner, loops);
      seen.clear();
      // the triangles `pieces` of positions along `loop` (vertices, corners)
      const auto add_pieces = [&](const std::vector<int>& loop, const std::vector<int>& loop_corner) {
        for(const auto& t : pieces) {
          const std::array<int, 3> v = {loop[t[0]], loop[t[1]], loop[t[2]]};
          std::array<int, 3> key = v;
          std::sort(key.begin(), key.end());
          if(seen.insert(key).second)
            add_triangle(v, {loop_corner[t[0]], loop_corner[t[1]], loop_corner[t[2]]});
        }
      };
      bool region = false;
      if(loops.size() > 1) {
        ring_xyz.clear();
        for(int v : ring)
          ring_xyz.push_back(out.xyz[std::size_t(v)]);
        region = triangulate_planar_ring(ring_xyz, ring, pieces);
      }
      if(region) {
        add_pieces(ring, ring_corner);
      } else {
        for(const auto& loop : loops) {
          if(loop.first.size() < 3)
            continue; // a walk there and back: no area
          ring_xyz.clear();
          for(int v : loop.first)
            ring_xyz.push_back(out.xyz[std::size_t(v)]);
          triangulate_polygon(ring_xyz, pieces);
          add_pieces(loop.first, loop.second);
        }
      }
    }
    if(!any) {
      out.flat_polygons.push_back(index);
    } else {
      sorted_rings.insert(sorted_rings.end(), ring.begin(), ring.end());
      std::sort(sorted_rings.begin() + std::ptrdiff_t(ring_begin.back()), sorted_rings.end());
    }
    ring_begin.push_back(sorted_rings.size());
    ++index;
  }
  separate_repeated_polygons(out, sorted_rings, ring_begin);
  return std::string();
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_ATLAS_INPUT_H

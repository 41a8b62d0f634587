// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_TRIANGULATE_LOOP_H
#define CGAL_SMP_INTERNAL_ATLAS_TRIANGULATE_LOOP_H

// Triangles over a closed loop of points, without new points, that depend on the loop alone.
// CGAL's hole triangulation does not, when it searches through a 3D Delaunay triangulation (its
// fast search, and its default): the triangles it picks depend on where that triangulation's
// cells lie in memory, so that a call gives another result after other allocations. Its other
// two searches are deterministic: a 2D constrained Delaunay triangulation when the loop is
// nearly planar, and the exhaustive search over all triangulations, cubic in the loop's size.
// Longer loops that are not planar are cut by ear clipping.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <array>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

typedef std::array<int, 3> Loop_triangle;

// Loops up to this size that are not planar get CGAL's exhaustive search (a few milliseconds),
// here and in the holes of a chart (Chart_parameterization.h).
constexpr std::size_t exhaustive_loop_size = 64;

// Ear clipping of the loop `p`: the ear with the smallest inner angle first (the advancing-front
// rule: sharp corners closed first keep the triangles well shaped), the inner side told by the
// loop's Newell normal, ties broken by position along the loop; a reflex ear only when no other
// is left. An ear is cut only if `allowed(a, b)` accepts its new side between loop positions a
// and b; false if none is. No ear is tested for other points of the loop inside it: the loops
// that come here are not planar (or not simple), where that test means nothing.
template <typename Allowed>
bool clip_ears(const std::vector<Vec3>& p, const Allowed& allowed, std::vector<Loop_triangle>& out)
{
  out.clear();
  const int n = int(p.size());
  if(n < 3)
    return false;
  Vec3 normal = {0., 0., 0.};
  for(int i = 0; i < n; ++i) {
    const Vec3& a = p[std::size_t(i)];
    const Vec3& b = p[std::size_t((i + 1) % n)];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  std::vector<int> before(p.size()), after(p.size());
  for(int i = 0; i < n; ++i) {
    before[std::size_t(i)] = (i + n - 1) % n;
    after[std::size_t(i)] = (i + 1) % n;
  }
  auto inner_angle = [&](int i) {
    const Vec3& o = p[std::size_t(i)];
    const Vec3 a = sub3(p[std::size_t(before[std::size_t(i)])], o), b = sub3(p[std::size_t(after[std::size_t(i)])], o);
    const double angle = angle3(a, b);
    if(!std::isfinite(angle)) // an overflow: last (the ears' order needs comparable keys)
      return 2. * CGAL_PI;
    return dot3(cross3(b, a), normal) < 0. ? 2. * CGAL_PI - angle : angle;
  };
  typedef std::pair<double, int> Ear; // inner angle, position
  std::vector<double> key(p.size());
  std::set<Ear> ears, blocked;
  for(int i = 0; i < n; ++i) {
    key[std::size_t(i)] = inner_angle(i);
    ears.emplace(key[std::size_t(i)], i);
  }
  for(int left = n; left > 3;) {
    if(ears.empty())
      return false;
    const int i = ears.begin()->second;
    ears.erase(ears.begin());
    const int a = before[std::size_t(i)], b = after[std::size_t(i)];
    if(!allowed(a, b)) {
      blocked.emplace(key[std::size_t(i)], i);
      continue;
    }
    out.push_back(Loop_triangle{{a, i, b}});
    after[std::size_t(a)] = b;
    before[std::size_t(b)] = a;
    --left;
    for(int j : {a, b}) { // their ears changed: each can be tried again
      ears.erase(Ear(key[std::size_t(j)], j));
      blocked.erase(Ear(key[std::size_t(j)], j));
      key[std::size_t(j)] = inner_angle(j);
      ears.emplace(key[std::size_t(j)], j);
    }
  }
  const int i = ears.empty() ? blocked.begin()->second : ears.begin()->second;
  out.push_back(Loop_triangle{{before[std::size_t(i)], i, after[std::size_t(i)]}});
  return true;
}

// Triangles over the loop `p` (positions along it, each triangle in the loop's orientation),
// none of whose new sides (between positions a and b) is refused by `allowed(a, b)`: CGAL's
// planar or exhaustive search where it applies, else ear clipping. False if none is found.
template <typename Allowed>
bool triangulate_loop(const std::vector<Vec3>& p, const Allowed& allowed, std::vector<Loop_triangle>& out)
{
  out.clear();
  const std::size_t n = p.size();
  if(n < 3)
    return false;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_3> polyline;
  for(const Vec3& q : p)
    polyline.emplace_back(q[0], q[1], q[2]);
  std::vector<std::tuple<int, int, int> > triples;
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::triangulate_hole_polyline(polyline, std::back_inserter(triples),
                                 CGAL::parameters::use_2d_constrained_delaunay_triangulation(true)
                                     .use_delaunay_triangulation(false)
                                     .do_not_use_cubic_algorithm(n > exhaustive_loop_size));
  bool found = triples.size() == n - 2;
  for(const auto& t : triples) {
    const Loop_triangle q{{std::get<0>(t), std::get<1>(t), std::get<2>(t)}};
    for(std::size_t k = 0; k < 3; ++k) {
      const int a = q[k], b = q[(k + 1) % 3];
      const bool side = (a + 1) % int(n) == b || (b + 1) % int(n) == a;
      found = found && (side || allowed(a, b));
    }
    out.push_back(q);
  }
  return found || clip_ears(p, allowed, out);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_TRIANGULATE_LOOP_H

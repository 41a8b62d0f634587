// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_TRIANGULATE_LOOP_H
#define CGAL_SMP_INTERNAL_ATLAS_TRIANGULATE_LOOP_H

// Triangles over a closed loop of points, without new points, that depend on the loop alone.
// CGAL's hole triangulation does not, when it searches through a 3D Delaunay triangulation (its
// fast search, and its default): the triangles it picks depend on where that triangulation's
// cells lie in memory, so that a call gives another result after other allocations. Its
// exhaustive search over all triangulations (cubic in the loop's size) is deterministic; its
// planar path is not robust: it projects along a computed normal inside its predicates, which
// then disagree with one another on nearly degenerate loops (a precondition fails, found by the
// fuzz harness). Nearly planar loops are therefore projected here once, to points of the plane
// on which CGAL's 2D constrained Delaunay triangulation decides exactly; longer loops that are
// not planar are cut by ear clipping.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <map>
#include <queue>
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

// Newell's normal of the loop `p`: twice its vector area, the loop turning counterclockwise
// about it (an exact normal of a planar loop, and a mean one of any other).
inline Vec3 newell_normal(const std::vector<Vec3>& p)
{
  Vec3 normal = {0., 0., 0.};
  for(std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
    normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
    normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return normal;
}

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
  const Vec3 normal = newell_normal(p);
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

// Whether every new side of the triangles `t` over a loop of `n` positions (a side that is not
// between neighbours along the loop) is accepted by `allowed(a, b)`.
template <typename Allowed>
bool new_sides_allowed(const std::vector<Loop_triangle>& t, std::size_t n, const Allowed& allowed)
{
  for(const Loop_triangle& q : t)
    for(std::size_t k = 0; k < 3; ++k) {
      const int a = q[k], b = q[(k + 1) % 3];
      if((a + 1) % int(n) != b && (b + 1) % int(n) != a && !allowed(a, b))
        return false;
    }
  return true;
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel Loop_kernel;
// A constrained Delaunay triangulation of the positions along a loop (vertex info), with an
// integer per face that tells the region it lies in.
typedef CGAL::Constrained_triangulation_face_base_2<Loop_kernel,
                                                    CGAL::Triangulation_face_base_with_info_2<int, Loop_kernel> >
    Loop_face;
typedef CGAL::Constrained_Delaunay_triangulation_2<
    Loop_kernel,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<int, Loop_kernel>, Loop_face>,
    CGAL::No_constraint_intersection_tag>
    Loop_cdt;

// The points `p` of a loop projected on the plane of its mean normal (centred, scaled to a unit
// box, the loop turning counterclockwise about the normal), in `plane`, if the loop is nearly
// planar: its mean squared distance to that plane at most (extent / 4)^2, the largest side of
// its bounding box as `extent` (CGAL's rule with the box's largest side for its height, so that
// it does not depend on how the loop lies in space). The points are rounded once here; every
// decision after is CGAL's exact predicates on them.
inline bool project_nearly_planar_loop(const std::vector<Vec3>& p, std::vector<Loop_kernel::Point_2>& plane)
{
  const std::size_t n = p.size();
  if(n < 3)
    return false;
  // centred and scaled to a unit box: where the loop lies makes the products below neither
  // overflow nor underflow
  Vec3 low = p[0], high = p[0];
  for(const Vec3& q : p)
    for(std::size_t i = 0; i < 3; ++i) {
      low[i] = (std::min)(low[i], q[i]);
      high[i] = (std::max)(high[i], q[i]);
    }
  double extent = 0.;
  Vec3 centre;
  for(std::size_t i = 0; i < 3; ++i) {
    extent = (std::max)(extent, high[i] - low[i]);
    centre[i] = low[i] + 0.5 * (high[i] - low[i]);
  }
  if(!(extent > 0.) || !std::isfinite(extent))
    return false;
  std::vector<Vec3> q(n);
  Vec3 mean = {0., 0., 0.};
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < 3; ++i) {
      q[j][i] = (p[j][i] - centre[i]) / extent;
      mean[i] += q[j][i] / double(n);
    }
  Vec3 normal = {0., 0., 0.};
  for(std::size_t j = 0; j < n; ++j) {
    const Vec3 c = cross3(sub3(q[j], mean), sub3(q[(j + 1) % n], mean));
    for(std::size_t i = 0; i < 3; ++i)
      normal[i] += c[i];
  }
  const double length = norm3(normal);
  if(!(length > 0.) || !std::isfinite(length))
    return false;
  for(double& c : normal)
    c /= length;
  double squared_distances = 0.;
  for(const Vec3& x : q) {
    const double d = dot3(sub3(x, mean), normal);
    squared_distances += d * d;
  }
  if(squared_distances > double(n) / 16.)
    return false;
  // (u, v, normal) right-handed: the loop turns counterclockwise in (u, v)
  const std::size_t away = std::size_t(std::max_element(normal.begin(), normal.end(),
                                                        [](double a, double b) { return std::abs(a) < std::abs(b); }) -
                                       normal.begin());
  Vec3 axis = {0., 0., 0.};
  axis[(away + 1) % 3] = 1.;
  Vec3 u = cross3(axis, normal);
  const double u_length = norm3(u);
  for(double& c : u)
    c /= u_length;
  const Vec3 v = cross3(normal, u);

  plane.clear();
  plane.reserve(n);
  for(std::size_t j = 0; j < n; ++j)
    plane.emplace_back(dot3(q[j], u), dot3(q[j], v));
  return true;
}

// The constrained Delaunay triangulation of the loop `p` projected on its plane, each triangle in
// the loop's orientation, if the loop is nearly planar (project_nearly_planar_loop()) and its
// projection is a simple polygon (decided exactly on the rounded points, so that a degenerate
// loop is found not simple instead of breaking the triangulation).
inline bool triangulate_planar_loop(const std::vector<Vec3>& p, std::vector<Loop_triangle>& out)
{
  out.clear();
  const std::size_t n = p.size();
  std::vector<Loop_kernel::Point_2> polygon;
  if(!project_nearly_planar_loop(p, polygon))
    return false;
  typedef Loop_kernel K;
  typedef Loop_cdt Cdt;
  std::vector<std::pair<K::Point_2, int> > plane;
  plane.reserve(n);
  for(std::size_t j = 0; j < n; ++j)
    plane.emplace_back(polygon[j], int(j));
  if(!CGAL::is_simple_2(polygon.begin(), polygon.end(), K()))
    return false;
  Cdt cdt;
  cdt.insert(plane.begin(), plane.end());
  if(cdt.dimension() != 2 || cdt.number_of_vertices() != n)
    return false;
  std::vector<Cdt::Vertex_handle> vertex(n);
  for(Cdt::Vertex_handle h : cdt.finite_vertex_handles())
    vertex[std::size_t(h->info())] = h;
  for(std::size_t j = 0; j < n; ++j)
    cdt.insert_constraint(vertex[j], vertex[(j + 1) % n]);
  // outside: reached from the infinite faces without crossing the loop
  for(Cdt::Face_handle f : cdt.all_face_handles())
    f->info() = 0;
  std::queue<Cdt::Face_handle> front;
  front.push(cdt.infinite_face());
  while(!front.empty()) {
    const Cdt::Face_handle f = front.front();
    front.pop();
    if(f->info() != 0)
      continue;
    f->info() = 1;
    for(int i = 0; i < 3; ++i)
      if(!cdt.is_constrained(Cdt::Edge(f, i)))
        front.push(f->neighbor(i));
  }
  const bool ccw = CGAL::orientation_2(polygon.begin(), polygon.end(), K()) == CGAL::COUNTERCLOCKWISE;
  for(Cdt::Face_handle f : cdt.finite_face_handles())
    if(f->info() == 0) {
      const Loop_triangle t{{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}};
      out.push_back(ccw ? t : Loop_triangle{{t[0], t[2], t[1]}});
    }
  return out.size() == n - 2;
}

// The constrained Delaunay triangulation of the region bounded by a ring that passes some of its
// vertices twice or more (`id[j]` the vertex at position j, `p[j]` its point): a polygon with
// holes written as one polygon, which runs along a bridge to each hole, round it and back. The
// ring is projected as by project_nearly_planar_loop(); its sides run an even number of times
// (the bridges) bound nothing, the others bound the region, where they wind an odd number of
// times. Triangles of positions (the first of each vertex), in the ring's orientation. False if
// the ring is not nearly planar, two of its vertices project to one point, its sides cross, or
// the triangles do not cover the area the ring winds around (a ring that overlaps itself).
inline bool triangulate_planar_ring(const std::vector<Vec3>& p, const std::vector<int>& id,
                                    std::vector<Loop_triangle>& out)
{
  out.clear();
  const std::size_t n = p.size();
  std::vector<Loop_kernel::Point_2> plane;
  if(id.size() != n || !project_nearly_planar_loop(p, plane))
    return false;
  typedef Loop_kernel K;
  typedef Loop_cdt Cdt;
  std::map<int, int> first; // vertex -> its first position
  std::vector<std::pair<K::Point_2, int> > points;
  for(std::size_t j = 0; j < n; ++j)
    if(first.emplace(id[j], int(j)).second)
      points.emplace_back(plane[j], int(j));
  Cdt cdt;
  cdt.insert(points.begin(), points.end());
  if(cdt.dimension() != 2 || cdt.number_of_vertices() != points.size())
    return false;
  std::vector<Cdt::Vertex_handle> vertex(n);
  for(Cdt::Vertex_handle h : cdt.finite_vertex_handles())
    vertex[std::size_t(h->info())] = h;
  std::map<std::pair<int, int>, int> sides; // (first positions, smaller first) -> times run
  double twice_area = 0.;
  for(std::size_t j = 0; j < n; ++j) {
    const int a = first[id[j]], b = first[id[(j + 1) % n]];
    ++sides[std::minmax(a, b)];
    twice_area += plane[j].x() * plane[(j + 1) % n].y() - plane[(j + 1) % n].x() * plane[j].y();
  }
  try {
    for(const auto& side : sides)
      if(side.second % 2 == 1 && side.first.first != side.first.second)
        cdt.insert_constraint(vertex[std::size_t(side.first.first)], vertex[std::size_t(side.first.second)]);
  } catch(const std::exception&) { // two sides cross
    return false;
  }
  // the number of bounding sides crossed from the infinite faces: breadth first, a side at a time
  for(Cdt::Face_handle f : cdt.all_face_handles())
    f->info() = -1;
  std::queue<Cdt::Face_handle> front, beyond;
  beyond.push(cdt.infinite_face());
  for(int crossed = 0; !beyond.empty(); ++crossed) {
    front.swap(beyond);
    while(!front.empty()) {
      const Cdt::Face_handle f = front.front();
      front.pop();
      if(f->info() >= 0)
        continue;
      f->info() = crossed;
      for(int i = 0; i < 3; ++i)
        if(f->neighbor(i)->info() < 0)
          (cdt.is_constrained(Cdt::Edge(f, i)) ? beyond : front).push(f->neighbor(i));
    }
  }
  const bool ccw = twice_area > 0.;
  double covered = 0.;
  for(Cdt::Face_handle f : cdt.finite_face_handles())
    if(f->info() % 2 == 1) {
      const Loop_triangle t{{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}};
      out.push_back(ccw ? t : Loop_triangle{{t[0], t[2], t[1]}});
      covered += std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
    }
  return !out.empty() && std::abs(covered - 0.5 * std::abs(twice_area)) <= 1e-9 * covered;
}

// Triangles over the loop `p` (positions along it, each triangle in the loop's orientation),
// none of whose new sides (between positions a and b) is refused by `allowed(a, b)`: by
// triangulate_planar_loop() if it applies, else by CGAL's exhaustive search if the loop is short
// enough, else by ear clipping. False if none is found.
template <typename Allowed>
bool triangulate_loop(const std::vector<Vec3>& p, const Allowed& allowed, std::vector<Loop_triangle>& out)
{
  const std::size_t n = p.size();
  if(triangulate_planar_loop(p, out) && new_sides_allowed(out, n, allowed))
    return true;
  out.clear();
  if(n < 3)
    return false;
  if(n <= exhaustive_loop_size) {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
    std::vector<K::Point_3> polyline;
    for(const Vec3& q : p)
      polyline.emplace_back(q[0], q[1], q[2]);
    std::vector<std::tuple<int, int, int> > triples;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(
        polyline, std::back_inserter(triples),
        CGAL::parameters::use_2d_constrained_delaunay_triangulation(false).use_delaunay_triangulation(false));
    for(const auto& t : triples)
      out.push_back(Loop_triangle{{std::get<0>(t), std::get<1>(t), std::get<2>(t)}});
    if(out.size() == n - 2 && new_sides_allowed(out, n, allowed))
      return true;
  }
  return clip_ears(p, allowed, out);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_TRIANGULATE_LOOP_H

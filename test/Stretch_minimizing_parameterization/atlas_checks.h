// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every atlas must be, checked independently of how it was made: every corner a uv in the
// unit square, every polygon of positive uv area in its own corner order, the corners of a
// polygon in one chart, and no two uv triangles overlapping (exact predicates and constructions).

#ifndef SMP_ATLAS_CHECKS_H
#define SMP_ATLAS_CHECKS_H

#include <CGAL/Box_intersection_d/Box_with_handle_d.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <boost/variant.hpp>

#include <array>
#include <cstddef>
#include <string>
#include <variant>
#include <vector>

namespace smp_test {

// The value of type T an intersection holds, or null: CGAL 5 returns a boost::variant, CGAL 6 a
// std::variant.
template <typename T, typename... U>
const T* alternative_if(const boost::variant<U...>& v) { return boost::get<T>(&v); }
template <typename T, typename... U>
const T* alternative_if(const std::variant<U...>& v) { return std::get_if<T>(&v); }

struct Atlas_check
{
  std::size_t outside = 0;      // corners outside [0,1]^2 (or not finite)
  std::size_t not_positive = 0; // triangles of zero or negative uv area, among the ones of positive 3D area
  std::size_t overlaps = 0;     // pairs of uv triangles whose interiors meet
  std::size_t wrong_size = 0;   // polygons whose uv list is not as long as the polygon
};

// `triangles`: the polygons split into corner triples (polygon, corner a, b, c), e.g. by fans;
// `positive3d[i]`: whether triangle i has 3D area (its uv then has to be positive).
inline Atlas_check check_atlas(const CGAL::Surface_mesh_parameterization::Atlas& atlas,
                               const std::vector<std::array<std::size_t, 4> >& triangles,
                               const std::vector<char>& positive3d)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel K;
  Atlas_check r;
  for(const auto& polygon : atlas.uv)
    for(const auto& q : polygon)
      if(!(q[0] >= 0. && q[0] <= 1. && q[1] >= 0. && q[1] <= 1.))
        ++r.outside;
  std::vector<K::Triangle_2> tri;
  typedef CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t,
                                                     CGAL::Box_intersection_d::ID_EXPLICIT> Box;
  std::vector<Box> boxes;
  for(std::size_t i = 0; i < triangles.size(); ++i) {
    const auto& t = triangles[i];
    const auto& uv = atlas.uv[t[0]];
    if(std::max({t[1], t[2], t[3]}) >= uv.size()) { ++r.wrong_size; continue; }
    const K::Point_2 a(uv[t[1]][0], uv[t[1]][1]), b(uv[t[2]][0], uv[t[2]][1]), c(uv[t[3]][0], uv[t[3]][1]);
    const CGAL::Orientation o = CGAL::orientation(a, b, c);
    if(o != CGAL::POSITIVE) {
      if(positive3d[i]) ++r.not_positive;
      continue; // a flat uv triangle has no interior to overlap with
    }
    tri.emplace_back(a, b, c);
    boxes.emplace_back(tri.back().bbox(), tri.size() - 1);
  }
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const K::Triangle_2 &s = tri[x.handle()], &t = tri[y.handle()];
    const auto result = CGAL::intersection(s, t);
    if(!result) return;
    if(alternative_if<K::Triangle_2>(*result) != nullptr || alternative_if<std::vector<K::Point_2> >(*result) != nullptr)
      ++r.overlaps;
  });
  return r;
}

} // namespace smp_test

#endif // SMP_ATLAS_CHECKS_H

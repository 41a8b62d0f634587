// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_FLIP_FREE_STEP_H
#define CGAL_SMP_INTERNAL_FLIP_FREE_STEP_H

// What keeps a step of the polish a bijection: how far a positive triangle can move along a
// direction before it folds, and whether a moved border loop is still a simple polygon; and
// whether a chart's outline keeps its triangles apart.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Box_intersection_d/Box_with_handle_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_2/Segment_2_Segment_2.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The smallest t > 0 at which the triangle (x[t0], x[t1], x[t2]), positive at t = 0, becomes
// flat when its corners move to x + t dir; +inf if it never does.
inline double first_fold(const std::vector<Vec2>& x, const std::vector<Vec2>& dir, const std::array<int, 3>& t)
{
  auto diff = [](const Vec2& a, const Vec2& b) { return Vec2{a[0] - b[0], a[1] - b[1]}; };
  auto cross2 = [](const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; };
  const Vec2 e1 = diff(x[t[1]], x[t[0]]), e2 = diff(x[t[2]], x[t[0]]);
  const Vec2 d1 = diff(dir[t[1]], dir[t[0]]), d2 = diff(dir[t[2]], dir[t[0]]);
  // twice the signed area along the step: a t^2 + b t + c, c > 0
  const double a = cross2(d1, d2), b = cross2(e1, d2) + cross2(d1, e2), c = cross2(e1, e2);
  double root = HUGE_VAL;
  if(a == 0.) {
    if(b < 0.) root = -c / b;
  } else {
    const double disc = b * b - 4. * a * c;
    if(disc >= 0.) {
      // both roots without cancellation
      const double q = -0.5 * (b + (b < 0. ? -1. : 1.) * std::sqrt(disc));
      const double r1 = q / a, r2 = c / q;
      if(r1 > 0.) root = (std::min)(root, r1);
      if(r2 > 0.) root = (std::min)(root, r2);
    }
  }
  return root;
}

// Whether a closed loop of points is a simple polygon: candidate pairs of non-adjacent edges by
// their boxes, then an exact test (touching counts as crossing). Keeps its buffers between calls.
class Simple_loop_check
{
public:
  // `loop`: indices into `points`, in order.
  bool operator()(const std::vector<Vec2>& points, const std::vector<int>& loop)
  {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
    const std::size_t nb = loop.size();
    m_boxes.resize(nb);
    for(std::size_t i = 0; i < nb; ++i) {
      const Vec2& p = points[std::size_t(loop[i])];
      const Vec2& q = points[std::size_t(loop[(i + 1) % nb])];
      m_boxes[i] = Box(Bbox_2((std::min)(p[0], q[0]), (std::min)(p[1], q[1]),
                              (std::max)(p[0], q[0]), (std::max)(p[1], q[1])), &loop[i]);
    }
    m_boxes_copy.assign(m_boxes.begin(), m_boxes.end());
    const int* base = loop.data();
    bool simple = true;
    auto check = [&](const Box& a, const Box& b) {
      if(!simple) return;
      const std::size_t i = std::size_t(a.handle() - base), j = std::size_t(b.handle() - base);
      if(i == j || (i + 1) % nb == j || (j + 1) % nb == i) return;
      auto point = [&](std::size_t e) { const Vec2& p = points[std::size_t(loop[e % nb])]; return K::Point_2(p[0], p[1]); };
      if(CGAL::do_intersect(K::Segment_2(point(i), point(i + 1)), K::Segment_2(point(j), point(j + 1))))
        simple = false;
    };
    CGAL::box_intersection_d(m_boxes.begin(), m_boxes.end(), m_boxes_copy.begin(), m_boxes_copy.end(), check,
                             Box_intersection_d::Box_traits_d<Box>(), 10, Box_intersection_d::CLOSED,
                             Box_intersection_d::COMPLETE);
    return simple;
  }

private:
  typedef Box_intersection_d::Box_with_handle_d<double, 2, const int*, Box_intersection_d::ID_FROM_HANDLE> Box;
  std::vector<Box> m_boxes, m_boxes_copy;
};

// Whether the outline of a flat chart (its border edges, `outline`, indices into `points`, in
// any order) keeps the chart's triangles apart: no two of its edges cross, or run along each
// other for a length unless they are at the same place (the two sides of a slit); touching at
// a point is allowed (two corners of a cut at one place). Two triangles of a flip-free chart
// overlap only where its outline does so. Exact predicates.
inline bool outline_is_simple(const std::vector<Vec2>& points, const std::vector<std::array<int, 2> >& outline)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef Box_intersection_d::Box_with_handle_d<double, 2, const std::array<int, 2>*, Box_intersection_d::ID_FROM_HANDLE> Box;
  auto point = [&points](int v) { return K::Point_2(points[std::size_t(v)][0], points[std::size_t(v)][1]); };
  // segments ab and cd cross at a point inside both, or overlap along a length
  auto meet = [](const K::Point_2& a, const K::Point_2& b, const K::Point_2& c, const K::Point_2& d) {
    const CGAL::Orientation oc = CGAL::orientation(a, b, c), od = CGAL::orientation(a, b, d);
    if(oc != CGAL::COLLINEAR || od != CGAL::COLLINEAR)
      return oc * od < 0 && CGAL::orientation(c, d, a) * CGAL::orientation(c, d, b) < 0;
    // on one line: the two intervals share more than a point
    const bool x = a.x() != b.x();
    const double a1 = x ? a.x() : a.y(), b1 = x ? b.x() : b.y(), c1 = x ? c.x() : c.y(), d1 = x ? d.x() : d.y();
    return (std::min)((std::max)(a1, b1), (std::max)(c1, d1)) > (std::max)((std::min)(a1, b1), (std::min)(c1, d1));
  };
  std::vector<Box> boxes;
  boxes.reserve(outline.size());
  for(const std::array<int, 2>& e : outline)
    boxes.emplace_back(point(e[0]).bbox() + point(e[1]).bbox(), &e);
  bool simple = true;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    const std::array<int, 2>& e = *x.handle();
    const std::array<int, 2>& f = *y.handle();
    const K::Point_2 a = point(e[0]), b = point(e[1]), c = point(f[0]), d = point(f[1]);
    // one edge twice, or the two sides of a slit, at the same place
    const bool same = (a == d && b == c) || (a == c && b == d);
    if(simple && !same && meet(a, b, c, d))
      simple = false;
  });
  return simple;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_FLIP_FREE_STEP_H

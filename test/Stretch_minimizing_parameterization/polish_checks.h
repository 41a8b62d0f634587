// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tests of the polish share: areas, displacements, the simplicity of a border loop
// (exact predicates) and the names of the stop reasons.

#ifndef SMP_TEST_POLISH_CHECKS_H
#define SMP_TEST_POLISH_CHECKS_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_energy_polisher.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace SI = CGAL::Surface_mesh_parameterization::internal;
using SI::Vec2;
using SI::Triangle;

inline double signed_area(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

inline double total_signed_area(const SI::Flat_triangles& m, const std::vector<Vec2>& uv)
{
  double s = 0.;
  for(const Triangle& t : m.tri) s += signed_area(uv[t[0]], uv[t[1]], uv[t[2]]);
  return s;
}

inline double max_displacement(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
  double d = 0.;
  for(std::size_t v = 0; v < a.size(); ++v)
    d = (std::max)(d, std::hypot(a[v][0] - b[v][0], a[v][1] - b[v][1]));
  return d;
}

// Independent O(n^2) check that a closed polygon is simple: no two non-adjacent edges meet.
inline bool simple_loop(const std::vector<int>& loop, const std::vector<Vec2>& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  const std::size_t n = loop.size();
  auto pt = [&](std::size_t i) { return P(uv[loop[i % n]][0], uv[loop[i % n]][1]); };
  auto on_segment = [](const P& p, const P& a, const P& b) {
    return CGAL::collinear(a, b, p) && CGAL::collinear_are_ordered_along_line(a, p, b);
  };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 2; j < n; ++j) {
      if(i == 0 && j == n - 1) continue; // adjacent through the wrap
      const P a = pt(i), b = pt(i + 1), c = pt(j), d = pt(j + 1);
      const CGAL::Orientation o1 = CGAL::orientation(a, b, c), o2 = CGAL::orientation(a, b, d);
      const CGAL::Orientation o3 = CGAL::orientation(c, d, a), o4 = CGAL::orientation(c, d, b);
      const bool none_collinear = o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR
                                  && o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR;
      if(none_collinear && o1 != o2 && o3 != o4)
        return false;
      if(on_segment(c, a, b) || on_segment(d, a, b) || on_segment(a, c, d) || on_segment(b, c, d))
        return false;
    }
  return true;
}

inline const char* stop_name(SI::Sander_polish_stop s)
{
  switch(s) {
    case SI::Sander_polish_stop::NOT_RUN: return "not run";
    case SI::Sander_polish_stop::CONVERGED: return "converged";
    case SI::Sander_polish_stop::ITERATION_CAP: return "iteration cap";
    case SI::Sander_polish_stop::TIME_BUDGET: return "time budget";
    case SI::Sander_polish_stop::VISITOR: return "visitor";
    case SI::Sander_polish_stop::NO_PROGRESS: return "no progress";
  }
  return "?";
}

#endif // SMP_TEST_POLISH_CHECKS_H

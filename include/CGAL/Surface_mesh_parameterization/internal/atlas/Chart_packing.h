// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H

// Packing the flattened charts into the unit square: every chart scaled to the same texel
// density (uv area = surface area before the final scale), turned to its smallest bounding
// rectangle (CGAL's min_rectangle_2 of its convex hull), and the rectangles placed by a
// bottom-left skyline, with a gutter between them given in texels of a square texture.
// Charts only ever share the square through disjoint rectangles, so no two charts overlap.

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/min_quadrilateral_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

struct Packing_settings
{
  unsigned int resolution = 1024; // texels along a side of the square texture
  double gutter = 2.;             // texels left between two charts and along the square's sides
};

struct Packing_result
{
  double utilization = 0.;        // area of the charts / area of the square
  double side = 0.;               // side of the square in the charts' surface units
};

// Turns `uv` in place so that its smallest bounding rectangle is axis-aligned, wider than high,
// with its lower left corner at the origin. Returns its width and height.
inline Vec2 align_chart(std::vector<Vec2>& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_2> points, hull, rectangle;
  points.reserve(uv.size());
  for(const Vec2& q : uv)
    points.emplace_back(q[0], q[1]);
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  double c = 1., s = 0.;
  if(hull.size() >= 3) {
    CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(rectangle));
    if(rectangle.size() == 4) {
      const double dx = rectangle[1].x() - rectangle[0].x(), dy = rectangle[1].y() - rectangle[0].y();
      const double l = std::hypot(dx, dy);
      if(l > 0.) { c = dx / l; s = dy / l; }
    }
  }
  double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
  for(Vec2& q : uv) {
    q = {c * q[0] + s * q[1], -s * q[0] + c * q[1]};
    xmin = (std::min)(xmin, q[0]); xmax = (std::max)(xmax, q[0]);
    ymin = (std::min)(ymin, q[1]); ymax = (std::max)(ymax, q[1]);
  }
  const bool turn = ymax - ymin > xmax - xmin;
  for(Vec2& q : uv)
    q = turn ? Vec2{ymax - q[1], q[0] - xmin} : Vec2{q[0] - xmin, q[1] - ymin};
  return turn ? Vec2{ymax - ymin, xmax - xmin} : Vec2{xmax - xmin, ymax - ymin};
}

// Bottom-left skyline placement of rectangles (w, h) in a strip of width `width`: positions of
// their lower left corners, each rectangle possibly turned by 90 degrees (`turned`). Returns
// the height used.
inline double skyline_pack(const std::vector<Vec2>& size, double width, std::vector<Vec2>& at,
                           std::vector<char>& turned)
{
  struct Segment { double x, y, w; };
  std::vector<Segment> sky = {Segment{0., 0., width}};
  std::vector<std::size_t> order(size.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&size](std::size_t a, std::size_t b) {
    return size[a][1] != size[b][1] ? size[a][1] > size[b][1] : a < b;
  });
  at.assign(size.size(), Vec2{0., 0.});
  turned.assign(size.size(), 0);
  double height = 0.;
  for(std::size_t i : order) {
    double best_top = HUGE_VAL, best_x = 0., best_y = 0.;
    bool best_turn = false;
    for(int turn = 0; turn < 2; ++turn) {
      const double w = turn ? size[i][1] : size[i][0], h = turn ? size[i][0] : size[i][1];
      if(w > width) continue;
      for(std::size_t k = 0; k < sky.size(); ++k) {
        const double x = sky[k].x;
        if(x + w > width * (1. + 1e-12)) break;
        double y = 0.; // the highest segment under [x, x + w)
        for(std::size_t j = k; j < sky.size() && sky[j].x < x + w; ++j)
          y = (std::max)(y, sky[j].y);
        if(y + h < best_top || (y + h == best_top && x < best_x)) {
          best_top = y + h; best_x = x; best_y = y; best_turn = turn != 0;
        }
      }
    }
    const double w = best_turn ? size[i][1] : size[i][0];
    at[i] = {best_x, best_y};
    turned[i] = best_turn;
    height = (std::max)(height, best_top);
    // the skyline above [best_x, best_x + w) is now best_top
    std::vector<Segment> next;
    for(const Segment& s : sky) {
      const double a = s.x, b = s.x + s.w;
      if(b <= best_x || a >= best_x + w) { next.push_back(s); continue; }
      if(a < best_x) next.push_back(Segment{a, s.y, best_x - a});
      if(b > best_x + w) next.push_back(Segment{best_x + w, s.y, b - best_x - w});
    }
    next.push_back(Segment{best_x, best_top, w});
    std::sort(next.begin(), next.end(), [](const Segment& p, const Segment& q) { return p.x < q.x; });
    sky.clear();
    for(const Segment& s : next) // merge equal heights
      if(!sky.empty() && sky.back().y == s.y && sky.back().x + sky.back().w == s.x)
        sky.back().w += s.w;
      else
        sky.push_back(s);
  }
  return height;
}

// Packs the charts (`uv[c]`, each in its own frame, `area_3d[c]` its surface area) into the
// unit square, in place.
inline Packing_result pack_charts(std::vector<std::vector<Vec2> >& uv, const std::vector<double>& area_uv,
                                  const std::vector<double>& area_3d, const Packing_settings& settings)
{
  Packing_result r;
  const std::size_t n = uv.size();
  if(n == 0) return r;
  double total_3d = 0.;
  for(double a : area_3d) total_3d += a;
  if(!(total_3d > 0.)) total_3d = 1.;
  // one texel density; a chart without surface area gets the size of a small one
  std::vector<Vec2> size(n);
  double charts_area = 0.;
  for(std::size_t c = 0; c < n; ++c) {
    double s = area_uv[c] > 0. && area_3d[c] > 0. ? std::sqrt(area_3d[c] / area_uv[c]) : 0.;
    Vec2 extent = align_chart(uv[c]);
    if(!(s > 0.) || !std::isfinite(s)) {
      const double e = (std::max)(extent[0], extent[1]);
      s = e > 0. ? 1e-4 * std::sqrt(total_3d) / e : 1.;
    }
    for(Vec2& q : uv[c]) q = {s * q[0], s * q[1]};
    size[c] = {s * extent[0], s * extent[1]};
    charts_area += s * s * area_uv[c];
  }

  // The gutter depends on the side of the square, which depends on the gutter: pack again
  // until the square the packing needs is the one its gutter was computed for.
  const double texel = 1. / double((std::max)(settings.resolution, 1u));
  double side = std::sqrt(total_3d / 0.6), gutter = 0., extent = 0.;
  std::vector<Vec2> at, best_at, padded(n);
  std::vector<char> turned, best_turned;
  for(int round = 0; round < 20; ++round) {
    gutter = settings.gutter * texel * side;
    double widest = 0., area = 0.;
    for(std::size_t c = 0; c < n; ++c) {
      padded[c] = {size[c][0] + gutter, size[c][1] + gutter};
      widest = (std::max)(widest, (std::min)(padded[c][0], padded[c][1]));
      area += padded[c][0] * padded[c][1];
    }
    extent = HUGE_VAL;
    for(double f = 1.0; f <= 1.6; f += 0.05) { // strip widths around the square of the area
      const double width = (std::max)(widest, f * std::sqrt(area));
      const double height = skyline_pack(padded, width, at, turned);
      const double s = (std::max)(width, height);
      if(s < extent) { extent = s; best_at = at; best_turned = turned; }
    }
    if(extent <= side && extent >= side * (1. - 1e-3)) break;
    side = extent;
  }
  // charts sit half a gutter inside their padded rectangles: a gutter apart, and half a
  // gutter inside the square
  side = (std::max)(side, extent);
  for(std::size_t c = 0; c < n; ++c) {
    const double x0 = best_at[c][0] + 0.5 * gutter, y0 = best_at[c][1] + 0.5 * gutter;
    for(Vec2& q : uv[c]) {
      const Vec2 p = best_turned[c] ? Vec2{size[c][1] - q[1], q[0]} : q;
      q = {(std::min)((x0 + p[0]) / side, 1.), (std::min)((y0 + p[1]) / side, 1.)};
    }
  }
  r.side = side;
  r.utilization = charts_area / (side * side);
  return r;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H

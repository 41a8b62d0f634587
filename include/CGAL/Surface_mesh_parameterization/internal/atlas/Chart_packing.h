// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H

// Packing the flattened charts into the unit square: every chart scaled to the same texel
// density (uv area = surface area before the final scale), turned to its smallest bounding
// rectangle (CGAL's min_rectangle_2 of its convex hull), then placed by a bottom-left
// skyline on a grid of texels (charts nest into the hollows of the ones below), with a gutter
// between them given in texels of a square texture.
// Charts only ever occupy disjoint cells, widened by half the gutter, so no two charts overlap.

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

// A chart seen from below and from above on a grid: per column of cells, the lowest and the
// highest row its triangles may touch (their boxes, widened by `pad` cells), -1 if none.
struct Chart_profile
{
  std::vector<long> bottom, top;
  long width() const { return long(bottom.size()); }
};

inline Chart_profile chart_profile(const std::vector<Vec2>& uv, const std::vector<Triangle>& tri, double scale, long pad)
{
  Chart_profile p;
  long columns = 0;
  for(const Vec2& q : uv) columns = (std::max)(columns, long(std::floor(q[0] * scale)) + 1);
  p.bottom.assign(std::size_t(columns + 2 * pad), -1);
  p.top.assign(p.bottom.size(), -1);
  for(const Triangle& t : tri) {
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for(int v : t) {
      x0 = (std::min)(x0, uv[std::size_t(v)][0]); x1 = (std::max)(x1, uv[std::size_t(v)][0]);
      y0 = (std::min)(y0, uv[std::size_t(v)][1]); y1 = (std::max)(y1, uv[std::size_t(v)][1]);
    }
    const long c0 = long(std::floor(x0 * scale)), c1 = long(std::floor(x1 * scale)) + 2 * pad;
    const long r0 = long(std::floor(y0 * scale)), r1 = long(std::floor(y1 * scale)) + 2 * pad;
    for(long c = c0; c <= c1; ++c) {
      long& b = p.bottom[std::size_t(c)];
      long& u = p.top[std::size_t(c)];
      b = b < 0 ? r0 : (std::min)(b, r0);
      u = (std::max)(u, r1);
    }
  }
  return p;
}

// Places every chart, largest first, at the column where it comes to rest lowest on the
// skyline of the charts placed before (each also tried turned by 90 degrees): charts nest
// into each other's hollows from above. Returns the side of the square used, in cells.
inline long skyline_place(const std::vector<Chart_profile>& straight, const std::vector<Chart_profile>& turned,
                          const std::vector<double>& area, long width, std::vector<long>& at_x,
                          std::vector<long>& at_y, std::vector<char>& is_turned)
{
  const std::size_t n = straight.size();
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&area](std::size_t a, std::size_t b) {
    return area[a] != area[b] ? area[a] > area[b] : a < b;
  });
  std::vector<long> sky(std::size_t(width), 0);
  at_x.assign(n, 0); at_y.assign(n, 0); is_turned.assign(n, 0);
  long used = 0, height = 0;
  for(std::size_t i : order) {
    long best_top = -1, best_x = 0, best_y = 0;
    bool best_turned = false;
    for(int k = 0; k < 2; ++k) {
      const Chart_profile& p = k ? turned[i] : straight[i];
      for(long x = 0; x + p.width() <= width; ++x) {
        long y = 0;
        for(long c = 0; c < p.width(); ++c)
          if(p.bottom[std::size_t(c)] >= 0) y = (std::max)(y, sky[std::size_t(x + c)] - p.bottom[std::size_t(c)]);
        long top = 0;
        for(long c = 0; c < p.width(); ++c)
          if(p.top[std::size_t(c)] >= 0) top = (std::max)(top, y + p.top[std::size_t(c)] + 1);
        if(best_top < 0 || top < best_top) {
          best_top = top; best_x = x; best_y = y; best_turned = k != 0;
        }
      }
    }
    if(best_top < 0) return -1; // wider than the strip
    const Chart_profile& p = best_turned ? turned[i] : straight[i];
    for(long c = 0; c < p.width(); ++c)
      if(p.top[std::size_t(c)] >= 0) {
        long& s = sky[std::size_t(best_x + c)];
        s = (std::max)(s, best_y + p.top[std::size_t(c)] + 1);
        used = (std::max)(used, best_x + c + 1);
      }
    at_x[i] = best_x; at_y[i] = best_y; is_turned[i] = best_turned;
    height = (std::max)(height, best_top);
  }
  return (std::max)(used, height);
}

// Packs the charts (`uv[c]`, each in its own frame, with its triangles `tri[c]`, its uv area
// and its surface area) into the unit square, in place: on a grid of `resolution` cells a
// side, each chart's triangles widened by half the gutter, so that two charts are at least a
// gutter apart and never overlap.
inline Packing_result pack_charts(std::vector<std::vector<Vec2> >& uv, const std::vector<std::vector<Triangle> >& tri,
                                  const std::vector<double>& area_uv, const std::vector<double>& area_3d,
                                  const Packing_settings& settings)
{
  Packing_result r;
  const std::size_t n = uv.size();
  if(n == 0) return r;
  double total_3d = 0.;
  for(double a : area_3d) total_3d += a;
  if(!(total_3d > 0.)) total_3d = 1.;
  // one texel density; a chart without surface area gets the size of a small one
  double charts_area = 0.;
  std::vector<double> area(n);
  std::vector<std::vector<Vec2> > turned_uv(n);
  for(std::size_t c = 0; c < n; ++c) {
    double s = area_uv[c] > 0. && area_3d[c] > 0. ? std::sqrt(area_3d[c] / area_uv[c]) : 0.;
    const Vec2 extent = align_chart(uv[c]);
    if(!(s > 0.) || !std::isfinite(s)) {
      const double e = (std::max)(extent[0], extent[1]);
      s = e > 0. ? 1e-4 * std::sqrt(total_3d) / e : 1.;
    }
    for(Vec2& q : uv[c]) q = {s * q[0], s * q[1]};
    turned_uv[c].reserve(uv[c].size());
    for(const Vec2& q : uv[c]) turned_uv[c].push_back({s * extent[1] - q[1], q[0]}); // +90 degrees
    area[c] = s * s * area_uv[c];
    charts_area += area[c];
  }

  // cells per surface unit: the square of `resolution` cells should hold the charts; shrink
  // until it does, then grow while it still does
  const long cells = long((std::max)(settings.resolution, 16u));
  const long pad = long(std::ceil(0.5 * settings.gutter));
  double scale = double(cells) * std::sqrt(0.5 / total_3d), best_scale = 0.;
  std::vector<long> x, y, best_x, best_y;
  std::vector<char> turned, best_turned;
  long best_side = 0;
  for(int round = 0; round < 12; ++round) {
    std::vector<Chart_profile> straight(n), rotated(n);
    bool fits = true;
    for(std::size_t c = 0; c < n && fits; ++c) {
      straight[c] = chart_profile(uv[c], tri[c], scale, pad);
      rotated[c] = chart_profile(turned_uv[c], tri[c], scale, pad);
      fits = (std::min)(straight[c].width(), rotated[c].width()) <= cells;
    }
    const long side = fits ? skyline_place(straight, rotated, area, cells, x, y, turned) : -1;
    if(side > 0 && side <= cells) {
      if(scale > best_scale) {
        best_scale = scale; best_side = side; best_x = x; best_y = y; best_turned = turned;
      }
      if(side > 0.97 * double(cells)) break;
      scale *= (std::min)(1.5, 0.99 * double(cells) / double(side));
    } else {
      scale *= side > 0 ? (std::max)(0.5, 0.98 * double(cells) / double(side)) : 0.7;
    }
  }
  if(best_scale == 0.) { // could not fit at any tried scale: one chart per row of the square
    best_scale = scale;
    best_x.assign(n, 0); best_y.assign(n, 0); best_turned.assign(n, 0);
    long row = 0;
    for(std::size_t c = 0; c < n; ++c) {
      best_y[c] = row;
      const Chart_profile p = chart_profile(uv[c], tri[c], scale, pad);
      long top = 0;
      for(long t : p.top) top = (std::max)(top, t + 1);
      row += top;
    }
    best_side = (std::max)(row, cells);
  }
  const double side = double((std::max)(best_side, 1L));
  for(std::size_t c = 0; c < n; ++c) {
    const std::vector<Vec2>& from = best_turned[c] ? turned_uv[c] : uv[c];
    std::vector<Vec2> placed(from.size());
    for(std::size_t v = 0; v < from.size(); ++v)
      placed[v] = {(std::min)((double(best_x[c] + pad) + from[v][0] * best_scale) / side, 1.),
                   (std::min)((double(best_y[c] + pad) + from[v][1] * best_scale) / side, 1.)};
    uv[c].swap(placed);
  }
  r.side = side / best_scale;
  r.utilization = charts_area * best_scale * best_scale / (side * side);
  return r;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H

// Packing the flattened charts into the unit square: every chart scaled to the same texel
// density (uv area = surface area before the final scale), turned to its smallest bounding
// rectangle (CGAL's min_rectangle_2 of its convex hull), then rasterized on a grid of texels
// and placed, largest first and in four quarter turns, where it rests lowest among the
// charts before it (into their hollows too, not only on top of them), with a gutter between
// charts given in texels of a square texture.
// Charts only ever occupy disjoint cells, each widened by half the gutter, so no two overlap.
// (One header, a little longer than most: the rasterization, the placement and the scale search
// share the packing's grid.) The charts are rasterized on several threads; the layout does not
// depend on their number.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/Cell_bitmap.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Second_thread.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/sort_by_vertex.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/exceptions.h>
#include <CGAL/min_quadrilateral_2.h>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

struct Packing_settings
{
  unsigned int resolution = 1024; // texels along a side of the square texture
  double gutter = 2.;             // texels left between two charts and along the square's sides
  unsigned int coarse_resolution = 256; // of the layouts that only estimate the utilization
  double goal = 0.52;             // utilization below which the longest chart is cut across
  int max_cut_rounds = 16;        // cuts kept at most (and twice as many taken back)
  unsigned int threads = 0;       // rasterizing the charts (0: one per core)
};

struct Packing_result
{
  double utilization = 0.;        // area of the charts / area of the square
  double side = 0.;               // side of the square in the charts' surface units
  double scale = 0.;              // texels per surface unit
  double fill = 0.;               // the square's share that the charts' gutter-widened cells take (0: unknown)
};

// Turns `uv` in place so that its smallest bounding rectangle is axis-aligned, wider than high,
// with its lower left corner at the origin. Returns its width and height.
inline Vec2 align_chart(std::vector<Vec2>& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_2> points, hull;
  points.reserve(uv.size());
  for(const Vec2& q : uv)
    points.emplace_back(q[0], q[1]);
  CGAL::convex_hull_2(points.begin(), points.end(), std::back_inserter(hull));
  double c = 1., s = 0.;
  if(hull.size() >= 3) {
    // On a hull of extreme proportions, CGAL's min_rectangle_2 fails an assertion (with exact
    // constructions too) or, without assertions, may give corners far off: any turn is a valid
    // one, so such a chart keeps its own.
    std::vector<K::Point_2> rectangle;
    try {
      CGAL::min_rectangle_2(hull.begin(), hull.end(), std::back_inserter(rectangle));
    } catch(const CGAL::Failure_exception&) {
      rectangle.clear();
    }
    if(rectangle.size() == 4) {
      const double dx = rectangle[1].x() - rectangle[0].x(), dy = rectangle[1].y() - rectangle[0].y();
      const double l = std::hypot(dx, dy);
      if(l > 0. && std::isfinite(l)) { c = dx / l; s = dy / l; }
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

// The length of a flattened chart (of uv area `area_uv` and surface area `area_3d`) along
// the long side of its smallest bounding rectangle, in surface units; `along` receives the
// position of each triangle's centroid along that side.
inline double chart_length(const std::vector<Vec2>& chart_uv, const std::vector<Triangle>& tri, double area_uv,
                           double area_3d, std::vector<double>& along)
{
  std::vector<Vec2> uv = chart_uv;
  const Vec2 extent = align_chart(uv);
  along.resize(tri.size());
  for(std::size_t i = 0; i < tri.size(); ++i)
    along[i] = (uv[std::size_t(tri[i][0])][0] + uv[std::size_t(tri[i][1])][0] + uv[std::size_t(tri[i][2])][0]) / 3.;
  return area_uv > 0. && area_3d > 0. ? extent[0] * std::sqrt(area_3d / area_uv) : 0.;
}

// The cells a chart may touch, per row: sorted disjoint spans [first, second) of columns.
// Every triangle covers the cells its rows cut out of it, widened by `pad` cells all round and
// shifted by `pad`, so that the chart's uv at `scale` sits at (pad, pad) + uv * scale.
struct Chart_mask
{
  typedef std::pair<long, long> Span;
  std::vector<std::vector<Span> > rows;
  long width = 0;
  std::vector<std::pair<long, long> > widest; // (span width, row), the widest span of each row first
  std::vector<long> test_order;               // the rows a fit is tested on, in order
  long height() const { return long(rows.size()); }
};

// The rows of a chart that hold spans, in the order a fit tries them: the widest few first
// (they collide most), then the others from coarse to fine (the middle row, the middles of
// the halves, of the quarters, ...), so that whatever lies in the chart's way is met after a
// few rows wherever it is, instead of after most rows when the wide ones are all on one side.
inline void order_tests(Chart_mask& m)
{
  const std::size_t first = (std::min)(m.widest.size(), std::size_t(4));
  std::vector<char> listed(m.rows.size(), 0);
  m.test_order.clear();
  for(std::size_t i = 0; i < first; ++i) {
    m.test_order.push_back(m.widest[i].second);
    listed[std::size_t(m.widest[i].second)] = 1;
  }
  std::vector<std::pair<long, long> > level{{0L, m.height()}}, next; // row ranges [a, b)
  while(!level.empty()) {
    next.clear();
    for(const auto& range : level) {
      if(range.first >= range.second) continue;
      const long middle = range.first + (range.second - range.first) / 2;
      if(!listed[std::size_t(middle)] && !m.rows[std::size_t(middle)].empty())
        m.test_order.push_back(middle);
      next.emplace_back(range.first, middle);
      next.emplace_back(middle + 1, range.second);
    }
    level.swap(next);
  }
}

// Merges the spans of one row into sorted disjoint ones.
inline void merge_spans(std::vector<Chart_mask::Span>& row)
{
  std::sort(row.begin(), row.end());
  std::size_t k = 0;
  for(std::size_t i = 0; i < row.size(); ++i) {
    if(k > 0 && row[i].first <= row[k - 1].second)
      row[k - 1].second = (std::max)(row[k - 1].second, row[i].second);
    else
      row[k++] = row[i];
  }
  row.resize(k);
}

// Widens [x0, x1] by the part of the segment (a, b) in the band r <= y <= r + 1: its ends in
// the band and its crossings of the band's lines.
inline void widen_by_band_part(const Vec2& a, const Vec2& b, long r, double& x0, double& x1)
{
  for(const Vec2* q : {&a, &b})
    if((*q)[1] >= double(r) && (*q)[1] <= double(r + 1)) { x0 = (std::min)(x0, (*q)[0]); x1 = (std::max)(x1, (*q)[0]); }
  for(double y : {double(r), double(r + 1)})
    if((a[1] - y) * (b[1] - y) < 0.) {
      const double x = a[0] + (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]);
      x0 = (std::min)(x0, x); x1 = (std::max)(x1, x);
    }
}

// Sets the cells of `cells` that the polygon `p` (a triangle or a segment, `n` corners) cuts:
// per row of cells, the columns of the polygon's part in that row.
inline void set_cut_cells(Cell_bitmap& cells, const Vec2* p, int n)
{
  double y_low = HUGE_VAL, y_top = -HUGE_VAL;
  for(int i = 0; i < n; ++i) { y_low = (std::min)(y_low, p[i][1]); y_top = (std::max)(y_top, p[i][1]); }
  const long r0 = (std::max)(0L, long(std::floor(y_low))), r1 = (std::max)(r0, long(std::floor(y_top)));
  if(r0 == r1 && y_low >= double(r0)) { // within one band (small on a fine grid): its corners
    double x0 = HUGE_VAL, x1 = -HUGE_VAL;
    for(int i = 0; i < n; ++i) { x0 = (std::min)(x0, p[i][0]); x1 = (std::max)(x1, p[i][0]); }
    const long c0 = (std::max)(0L, long(std::floor(x0)));
    cells.set(r0, c0, (std::max)(c0, long(std::floor(x1))));
    return;
  }
  for(long r = r0; r <= r1; ++r) {
    double x0 = HUGE_VAL, x1 = -HUGE_VAL;
    for(int i = 0; i < n; ++i)
      widen_by_band_part(p[i], p[(i + 1) % n], r, x0, x1);
    if(x0 > x1) continue;
    const long c0 = (std::max)(0L, long(std::floor(x0))), c1 = (std::max)(c0, long(std::floor(x1)));
    cells.set(r, c0, c1);
  }
}

// The outline of a chart: the sides of its triangles (each in its triangle's direction) less
// the pairs of opposite sides, that is, the sides between two of its triangles. Where every
// triangle is counterclockwise, the outline's winding number at a point counts the triangles
// over it.
inline std::vector<std::array<int, 2> > chart_outline(const std::vector<Triangle>& tri)
{
  std::vector<std::array<int, 2> > outline;
  std::vector<std::array<int, 3> > sides; // (lower vertex, higher vertex, +1 from lower to higher, else -1)
  sides.reserve(3 * tri.size());
  for(const Triangle& t : tri)
    for(int k = 0; k < 3; ++k) {
      const int a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
      sides.push_back(a < b ? std::array<int, 3>{a, b, 1} : std::array<int, 3>{b, a, -1});
    }
  sort_by_vertex(sides, [](const std::array<int, 3>& s) { return s[0]; });
  for(std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    int net = 0;
    for(; j < sides.size() && sides[j][0] == sides[i][0] && sides[j][1] == sides[i][1]; ++j)
      net += sides[j][2];
    for(; net > 0; --net) outline.push_back({sides[i][0], sides[i][1]});
    for(; net < 0; ++net) outline.push_back({sides[i][1], sides[i][0]});
    i = j;
  }
  return outline;
}

// The mask of the chart (`uv` times `scale`, its triangles `tri`, gutter cells `pad`), from its
// `outline` (chart_outline(), or empty) if every triangle is counterclockwise at that scale,
// else triangle by triangle: the same cells, the outline's in a time that goes with the
// chart's border and rows rather than with its triangles.
inline Chart_mask chart_mask(const std::vector<Vec2>& uv, const std::vector<Triangle>& tri,
                             const std::vector<std::array<int, 2> >& outline, double scale, long pad)
{
  Chart_mask m;
  double x_high = 0., y_high = 0.;
  for(const Triangle& t : tri)
    for(int i = 0; i < 3; ++i) {
      x_high = (std::max)(x_high, uv[std::size_t(t[std::size_t(i)])][0] * scale);
      y_high = (std::max)(y_high, uv[std::size_t(t[std::size_t(i)])][1] * scale);
    }
  // the cells the triangles cut, per row, widened by `pad` all round (shifted by `pad`)
  const long rows = tri.empty() ? 0 : long(std::floor(y_high)) + 1, columns = long(std::floor(x_high)) + 1;
  Cell_bitmap cells(rows + 2 * pad, columns + 2 * pad);
  const auto at = [&uv, scale](int v) { return Vec2{uv[std::size_t(v)][0] * scale, uv[std::size_t(v)][1] * scale}; };
  const bool by_outline = !outline.empty() && std::all_of(tri.begin(), tri.end(), [&at](const Triangle& t) {
    return twice_signed_area(at(t[0]), at(t[1]), at(t[2])) > 0.;
  });
  if(!by_outline) {
    for(const Triangle& t : tri) {
      const Vec2 p[3] = {at(t[0]), at(t[1]), at(t[2])};
      set_cut_cells(cells, p, 3);
    }
  } else {
    // The same cells from the outline alone: those it cuts, and those whose centre the
    // triangles cover (the outline winds around it). A cell that the triangles cut but the
    // outline does not is covered all over (the number of triangles over a point changes only
    // across the outline), its centre too.
    std::vector<std::pair<long, std::pair<double, int> > > crossings; // (row, (x, +1 upwards / -1))
    for(const std::array<int, 2>& side : outline) {
      const Vec2 p[2] = {at(side[0]), at(side[1])};
      set_cut_cells(cells, p, 2);
      // the centre lines y = r + 1/2 that the side crosses, a line through an end counted once
      const long first = (std::max)(0L, long(std::ceil((std::min)(p[0][1], p[1][1]) - 0.5)));
      const long last = (std::min)(rows - 1, long(std::floor((std::max)(p[0][1], p[1][1]) - 0.5)));
      for(long r = first; r <= last; ++r) {
        const double y = double(r) + 0.5;
        if((p[0][1] <= y) == (p[1][1] <= y)) continue;
        crossings.push_back({r, {p[0][0] + (p[1][0] - p[0][0]) * (y - p[0][1]) / (p[1][1] - p[0][1]), p[1][1] > p[0][1] ? 1 : -1}});
      }
    }
    std::sort(crossings.begin(), crossings.end());
    for(std::size_t i = 0; i < crossings.size();) {
      const long r = crossings[i].first;
      int winding = 0;
      double from = 0.;
      for(; i < crossings.size() && crossings[i].first == r; ++i) {
        const int before = winding;
        winding += crossings[i].second.second;
        if(before == 0 && winding != 0) from = crossings[i].second.first;
        if(before != 0 && winding == 0) { // the cells whose centre c + 1/2 is in [from, x]
          const long c0 = (std::max)(0L, long(std::ceil(from - 0.5)));
          const long c1 = (std::min)(columns - 1, long(std::floor(crossings[i].second.first - 0.5)));
          if(c0 <= c1) cells.set(r, c0, c1);
        }
      }
    }
  }
  cells.dilate(2 * pad);
  m.rows.resize(std::size_t(cells.rows()));
  for(long r = 0; r < cells.rows(); ++r) {
    auto& row = m.rows[std::size_t(r)];
    cells.runs(r, row);
    long w = 0;
    for(const Chart_mask::Span& span : row) {
      w = (std::max)(w, span.second - span.first);
      m.width = (std::max)(m.width, span.second);
    }
    if(w > 0) m.widest.emplace_back(w, r);
  }
  std::sort(m.widest.begin(), m.widest.end(), std::greater<std::pair<long, long> >());
  order_tests(m);
  return m;
}

// The mask of a chart rasterized triangle by triangle.
inline Chart_mask chart_mask(const std::vector<Vec2>& uv, const std::vector<Triangle>& tri, double scale, long pad)
{
  return chart_mask(uv, tri, std::vector<std::array<int, 2> >(), scale, pad);
}

// The widest span of the widest row of `m`.
inline Chart_mask::Span widest_span(const Chart_mask& m)
{
  Chart_mask::Span best(0, 0);
  for(const Chart_mask::Span& s : m.rows[std::size_t(m.widest.front().second)])
    if(s.second - s.first > best.second - best.first) best = s;
  return best;
}

// Whether a place that makes the square `side` and puts the chart's top at `top` is better than
// the best one so far (`best_side`, `best_top`; -1: none): the smaller square, then the lower top.
inline bool better_place(long side, long top, long best_side, long best_top)
{
  return best_side < 0 || side < best_side || (side == best_side && top < best_top);
}

// The cells taken so far in a strip of `width` columns: per row as in Chart_mask (the free
// runs between them are where a chart may go) and as bits (where a chart's span is tested),
// with what gives the longest free run of a row left of any column (rows above the top are free).
class Occupancy
{
public:
  explicit Occupancy(long width) : width_(width), taken_(0, width)
  {
    for(leaves_ = 1; leaves_ < width; leaves_ *= 2) {}
    longest_run_.assign(std::size_t(2 * leaves_), 0);
    lowest_end_.assign(std::size_t(2 * leaves_), 0);
  }
  long height() const { return long(rows_.size()); }

  // Whether `m` fits with its corner at (x, y); if not, `next_x` receives an x > `x` below
  // which it does not fit either: the span that collided has to reach a free run of its row
  // long enough for it (searched up to a corner x of `last`). The row of `m` that collided is
  // tested first next time (`first_row`, -1: none): what blocks a chart at one x mostly
  // blocks it a little further on too.
  bool fits(const Chart_mask& m, long x, long y, long last, long& first_row, long& next_x) const
  {
    if(first_row >= 0 && collides(m, first_row, x, y, last, next_x))
      return false;
    for(const long r : m.test_order)
      if(r != first_row && collides(m, r, x, y, last, next_x)) {
        first_row = r;
        return false;
      }
    return true;
  }

  void take(const Chart_mask& m, long x, long y)
  {
    if(rows_.size() < std::size_t(y + m.height())) {
      rows_.resize(std::size_t(y + m.height()));
      inner_run_.resize(rows_.size(), 0);
      row_end_.resize(rows_.size(), 0);
      taken_.add_rows(height());
    }
    for(long r = 0; r < m.height(); ++r) {
      auto& row = rows_[std::size_t(y + r)];
      if(m.rows[std::size_t(r)].empty()) continue;
      for(const Chart_mask::Span& s : m.rows[std::size_t(r)]) {
        row.emplace_back(x + s.first, x + s.second);
        taken_.set(y + r, x + s.first, x + s.second - 1);
      }
      merge_spans(row);
      long run = 0, end = 0;
      for(const Chart_mask::Span& s : row) { run = (std::max)(run, s.first - end); end = s.second; }
      inner_run_[std::size_t(y + r)] = run;
      row_end_[std::size_t(y + r)] = end;
      update_rows_tree(y + r);
    }
  }

  // The place for `m` that keeps the square [0, side]^2 holding everything smallest (the
  // square so far is `side`), then the chart's top lowest, then leftmost, if it is better
  // than (`best_side`, `best_top`) (-1: nothing yet); they and (`at_x`, `at_y`) are then
  // updated. Rows are searched upwards from `from` only while they may lead to a better place,
  // and in a row only the free runs under the chart's widest span that are long enough for it.
  bool best_place(const Chart_mask& m, long side, long& best_side, long& best_top, long& at_x, long& at_y,
                  long from = 0) const
  {
    if(m.widest.empty()) return false;
    const long wide_row = m.widest.front().second;
    const Chart_mask::Span wide = widest_span(m);
    const std::size_t probes = (std::min)(m.widest.size(), std::size_t(4));
    const long bound = best_side < 0 ? width_ : best_side; // no square beyond this side
    bool found = false;
    for(long y = from; y + m.height() <= bound; ++y) {
      // past these rows, no place is better: either the square or the top grows
      if(best_side >= 0 && (best_side == side ? y + m.height() >= best_top : y + m.height() > best_side)) break;
      // the chart's right end, past which a place here is no better than the best one: once a
      // place grows the square, one in a higher row has to keep it smaller, or as small with
      // a lower top (the leftmost place in the row is the only one weighed, so leaving out
      // those past this end changes nothing, and rows without room for it are passed at once)
      const long end = best_side < 0 || y + m.height() < best_top ? bound : best_side - 1;
      bool room = true; // rows whose longest free run is shorter than the chart's span there
      for(std::size_t i = 0; i < probes && room; ++i)
        room = y + m.widest[i].second >= height() || free_run(y + m.widest[i].second, end) >= m.widest[i].first;
      if(!room) { // on to the next row where the widest row has room (`end` only shrinks as y grows)
        y = first_row_with_room(y + wide_row + 1, m.widest.front().first, end) - wide_row - 1;
        continue;
      }
      const long r = y + wide_row, right = end - m.width; // the last corner x worth trying
      long gap_begin = 0, x_found = -1, first_row = -1;
      const std::size_t spans = r < height() ? rows_[std::size_t(r)].size() : 0;
      for(std::size_t i = 0; i <= spans && x_found < 0; ++i) {
        const long gap_end = i < spans ? rows_[std::size_t(r)][i].first : width_;
        // the chart's corner x such that its widest span lies in [gap_begin, gap_end)
        const long last = (std::min)(gap_end - wide.second, right);
        for(long x = (std::max)(0L, gap_begin - wide.first); x <= last;) {
          long next = x + 1;
          if(fits(m, x, y, last, first_row, next)) { x_found = x; break; }
          x = (std::max)(next, x + 1);
        }
        if(i < spans) gap_begin = rows_[std::size_t(r)][i].second;
        if(gap_begin - wide.first > right) break;
      }
      if(x_found < 0) continue;
      const long square = (std::max)({side, x_found + m.width, y + m.height()});
      if(better_place(square, y + m.height(), best_side, best_top)) {
        best_side = square; best_top = y + m.height(); at_x = x_found; at_y = y;
        found = true;
      }
    }
    return found;
  }

private:
  long width_;
  std::vector<std::vector<Chart_mask::Span> > rows_;
  Cell_bitmap taken_;
  std::vector<long> inner_run_, row_end_; // per row: longest free run before its last taken cell; that cell's end
  // the same over the rows of each node of a complete binary tree on the rows (the root at 1,
  // the row r at leaves_ + r): the longest inner run, the lowest end
  long leaves_ = 1;
  std::vector<long> longest_run_, lowest_end_;

  void update_rows_tree(long row)
  {
    std::size_t i = std::size_t(leaves_ + row);
    longest_run_[i] = inner_run_[std::size_t(row)];
    lowest_end_[i] = row_end_[std::size_t(row)];
    for(i /= 2; i >= 1; i /= 2) {
      longest_run_[i] = (std::max)(longest_run_[2 * i], longest_run_[2 * i + 1]);
      lowest_end_[i] = (std::min)(lowest_end_[2 * i], lowest_end_[2 * i + 1]);
    }
  }

  // the first row from `from` on with a free run of `length` cells left of column `end`
  // (free_run()), or a row at least `leaves_` if none: the first node to the right of the path
  // up from `from` that holds such a row, then down to its leftmost one
  long first_row_with_room(long from, long length, long end) const
  {
    if(from >= leaves_) return from;
    const auto room = [&](std::size_t i) { return longest_run_[i] >= length || end - lowest_end_[i] >= length; };
    std::size_t i = std::size_t(leaves_ + from);
    while(!room(i)) {
      for(; i % 2 == 1; i /= 2) // a right child: up to the first left child on the way
        if(i == 1) return leaves_;
      ++i;
    }
    while(i < std::size_t(leaves_))
      i = room(2 * i) ? 2 * i : 2 * i + 1;
    return long(i) - leaves_;
  }

  // whether row `r` of `m` meets a taken cell with the chart's corner at (x, y); if so, `next_x`
  // as in fits()
  bool collides(const Chart_mask& m, long r, long x, long y, long last, long& next_x) const
  {
    if(y + r >= height())
      return false;
    for(const Chart_mask::Span& s : m.rows[std::size_t(r)]) {
      long met = taken_.first_set(y + r, x + s.first, x + s.second);
      if(met == x + s.second) continue;
      const long length = s.second - s.first;
      for(;;) {
        const long free = taken_.run_end(y + r, met);
        next_x = free - s.first;
        if(next_x > last || free + length > width_) return true;
        met = taken_.first_set(y + r, free, free + length);
        if(met == free + length) return true;
      }
    }
    return false;
  }

  // the longest free run of `row` left of column `bound`
  long free_run(long row, long bound) const
  {
    const long end = row_end_[std::size_t(row)];
    return end < bound ? (std::max)(inner_run_[std::size_t(row)], bound - end) : inner_run_[std::size_t(row)];
  }
};

// For chart i's mask in quarter turn k, the first of `masks` with the same cells, as 4 j + l
// for chart j's mask in turn l (charts in order, each turn by turn): masks of one class are
// copies (the turns of a symmetric chart, the charts of a part repeated).
inline std::vector<std::array<std::size_t, 4> > copies_of(const std::vector<std::array<Chart_mask, 4> >& masks)
{
  std::vector<std::array<std::size_t, 4> > first(masks.size());
  std::unordered_multimap<std::size_t, std::size_t> by_hash;
  for(std::size_t i = 0; i < masks.size(); ++i)
    for(std::size_t k = 0; k < 4; ++k) {
      const Chart_mask& m = masks[i][k];
      std::size_t h = 0;
      boost::hash_combine(h, m.width);
      for(const std::vector<Chart_mask::Span>& row : m.rows) {
        boost::hash_combine(h, row.size());
        for(const Chart_mask::Span& span : row) {
          boost::hash_combine(h, span.first);
          boost::hash_combine(h, span.second);
        }
      }
      const auto range = by_hash.equal_range(h);
      const auto copy = std::find_if(range.first, range.second, [&](const auto& e) {
        const Chart_mask& other = masks[e.second / 4][e.second % 4];
        return other.width == m.width && other.rows == m.rows;
      });
      first[i][k] = copy != range.second ? copy->second : 4 * i + k;
      if(copy == range.second)
        by_hash.emplace(h, 4 * i + k);
    }
  return first;
}

// Places the charts, the largest `size` first, each in the quarter turn and at the place that
// keeps the square holding them all smallest: inside the square so far where the chart's top
// rests lowest, else where the square grows least (ties: the lower turn). Returns the side of
// the square, -1 if it would exceed `limit` cells. A turn whose mask is that of a lower turn
// (a chart symmetric under the half turn, as small compact ones often are) is not searched: it
// would find the same place, and the lower turn wins ties. With `threads` >= 2, a second thread
// searches the higher half of the turns left while this one searches the others (or this one
// after them, if the other has not started by then): the place of each half is the best of its
// turns whatever the other half found (that only bounds the search), so the layout is the same.
inline long place_charts(const std::vector<std::array<Chart_mask, 4> >& masks, const std::vector<double>& size,
                         long limit, std::vector<long>& at_x, std::vector<long>& at_y, std::vector<int>& turn,
                         unsigned int threads = 1)
{
  const std::size_t n = masks.size();
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&size](std::size_t a, std::size_t b) {
    return size[a] != size[b] ? size[a] > size[b] : a < b;
  });
  Occupancy occupancy(limit);
  at_x.assign(n, 0); at_y.assign(n, 0); turn.assign(n, 0);
  long side = 0;
  struct Place { long side = -1, top = -1, x = 0, y = 0; int turn = 0; };
  const std::vector<std::array<std::size_t, 4> > copy = copies_of(masks);
  // per chart, its turns to search, in order (`turns[i].first`), and how many (`.second`)
  std::vector<std::pair<std::array<int, 4>, int> > turns(n);
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 4; ++k)
      if(std::find(copy[i].begin(), copy[i].begin() + k, copy[i][std::size_t(k)]) == copy[i].begin() + k)
        turns[i].first[std::size_t(turns[i].second++)] = k;
  // Per class of copies (copies_of()), the row and the square where a mask of it was last
  // placed. No lower row has a place for that mask in that square (its search found the best,
  // and cells are only ever taken since), so while the square stays the same, the search for a
  // copy (a part repeated: bolts, a gear's teeth) starts at that row. A search from there that
  // finds no place in the square starts again from the bottom: a place that grows the square
  // may lie lower.
  struct Placed { long y = 0, side = -1; };
  std::vector<Placed> placed(4 * n);
  // the best place of chart i in the lower half of its turns (or the higher one if `higher`) if
  // better than `p`, else `p`
  const auto best_of = [&](std::size_t i, bool higher, Place p) {
    const int count = turns[i].second, middle = (count + 1) / 2;
    for(int j = higher ? middle : 0; j < (higher ? count : middle); ++j) {
      const int k = turns[i].first[std::size_t(j)];
      const Chart_mask& m = masks[i][std::size_t(k)];
      const Placed& before = placed[copy[i][std::size_t(k)]];
      if(before.side == side) {
        Place q = p;
        if(occupancy.best_place(m, side, q.side, q.top, q.x, q.y, before.y))
          q.turn = k;
        if(q.side == side) { // in the square: no place below `before.y` is
          p = q;
          continue;
        }
      }
      if(occupancy.best_place(m, side, p.side, p.top, p.x, p.y))
        p.turn = k;
    }
    return p;
  };
  Place half; // of the higher turns (before the thread: its task writes there until it stops)
  std::unique_ptr<Second_thread> second;
  if(threads >= 2 && n >= 2)
    second = std::make_unique<Second_thread>();
  for(std::size_t i : order) {
    Place p;
    if(second) {
      second->hand_over([&best_of, &half, i] { half = best_of(i, true, Place()); });
      const auto start = std::chrono::steady_clock::now();
      p = best_of(i, false, Place());
      // the thread may start on its half as late as this one took for its own
      if(second->withdraw(std::chrono::steady_clock::now() - start))
        p = best_of(i, true, p);
      else if(half.side >= 0 && better_place(half.side, half.top, p.side, p.top))
        p = half;
    } else { // the higher turns bounded by the place of the others
      p = best_of(i, true, best_of(i, false, Place()));
    }
    if(p.side < 0)
      return -1;
    at_x[i] = p.x; at_y[i] = p.y; turn[i] = p.turn;
    occupancy.take(masks[i][std::size_t(p.turn)], p.x, p.y);
    side = p.side;
    placed[copy[i][std::size_t(p.turn)]] = Placed{p.y, side};
  }
  return side;
}

// The chart `uv` (its lower left corner at the origin, `extent` wide and high) turned by
// `k` quarter turns counterclockwise, its lower left corner again at the origin.
inline std::vector<Vec2> turned_chart(const std::vector<Vec2>& uv, const Vec2& extent, int k)
{
  std::vector<Vec2> out(uv.size());
  for(std::size_t v = 0; v < uv.size(); ++v) {
    const Vec2& q = uv[v];
    switch(k) {
      case 1: out[v] = {extent[1] - q[1], q[0]}; break;
      case 2: out[v] = {extent[0] - q[0], extent[1] - q[1]}; break;
      case 3: out[v] = {q[1], extent[0] - q[0]}; break;
      default: out[v] = q;
    }
  }
  return out;
}

// The charts of an atlas made ready for packing: each scaled to one texel density (its uv area
// equal to its surface area), turned to its smallest bounding rectangle, in its four quarter
// turns.
struct Packing_input
{
  std::vector<std::array<std::vector<Vec2>, 4> > turned_uv;
  std::vector<Vec2> extent;       // of each chart not turned (turned by a quarter: the other way round)
  const std::vector<std::vector<Triangle> >* tri = nullptr;
  std::vector<std::vector<std::array<int, 2> > > outline; // of each chart (chart_outline())
  std::vector<double> area;       // uv area at that density
  double charts_area = 0., longest = 0., total_3d = 0.;
};

// A layout of the charts on a grid of cells: the scale (cells per surface unit), the side of
// the square holding them, and each chart's corner, quarter turn and shift (in cells, added
// to its turned uv times the scale: see half_turned()).
struct Packing_layout
{
  double scale = 0.;
  long side = 0;
  double taken = 0.; // cells of the charts (each widened by the gutter)
  std::vector<long> x, y;
  std::vector<int> turn;
  std::vector<Vec2> shift;
};

inline Packing_input prepare_packing(std::vector<std::vector<Vec2> >& uv, const std::vector<std::vector<Triangle> >& tri,
                                     const std::vector<double>& area_uv, const std::vector<double>& area_3d,
                                     unsigned int threads = 1)
{
  Packing_input in;
  const std::size_t n = uv.size();
  in.tri = &tri;
  for(double a : area_3d) in.total_3d += a;
  if(!(in.total_3d > 0.)) in.total_3d = 1.;
  in.area.resize(n);
  in.turned_uv.resize(n);
  in.extent.resize(n);
  in.outline.resize(n);
  std::vector<double> length(n);
  parallel_for_each(n, thread_count(threads), [&](std::size_t c) {
    // a chart without surface area gets the size of a small one
    double s = area_uv[c] > 0. && area_3d[c] > 0. ? std::sqrt(area_3d[c] / area_uv[c]) : 0.;
    Vec2 extent = align_chart(uv[c]);
    if(!(s > 0.) || !std::isfinite(s)) {
      const double e = (std::max)(extent[0], extent[1]);
      s = e > 0. ? 1e-4 * std::sqrt(in.total_3d) / e : 1.;
    }
    for(Vec2& q : uv[c]) q = {s * q[0], s * q[1]};
    extent = {s * extent[0], s * extent[1]};
    in.extent[c] = extent;
    length[c] = extent[0];
    for(int k = 0; k < 4; ++k)
      in.turned_uv[c][std::size_t(k)] = turned_chart(uv[c], extent, k);
    in.outline[c] = chart_outline(tri[c]);
    in.area[c] = s * s * area_uv[c];
  });
  for(std::size_t c = 0; c < n; ++c) { // in order: the sums do not depend on the threads
    in.longest = (std::max)(in.longest, length[c]);
    in.charts_area += in.area[c];
  }
  return in;
}

// The mask of a chart turned by half a turn, from the mask `m` of the chart (`m` mirrored in
// both directions: no triangle rasterized again). Its cells are those of the half-turned chart
// shifted by half_turn_shift().
inline Chart_mask half_turned(const Chart_mask& m)
{
  Chart_mask h;
  h.width = m.width;
  const long height = m.height();
  h.rows.resize(m.rows.size());
  for(long r = 0; r < height; ++r) {
    const auto& from = m.rows[std::size_t(height - 1 - r)];
    auto& to = h.rows[std::size_t(r)];
    to.reserve(from.size());
    for(auto s = from.rbegin(); s != from.rend(); ++s)
      to.emplace_back(m.width - s->second, m.width - s->first);
  }
  h.widest.reserve(m.widest.size());
  for(const auto& w : m.widest)
    h.widest.emplace_back(w.first, height - 1 - w.second);
  std::sort(h.widest.begin(), h.widest.end(), std::greater<std::pair<long, long> >());
  order_tests(h);
  return h;
}

// The shift (in cells) of a chart half turned for its mask half_turned(`m`), `m` being the
// chart's mask at `scale` with `pad`, and `extent` the chart's extent as `m` has it: the part of
// a cell that the chart leaves free in `m`'s last column and row (`m`'s cut columns and rows are
// its width and height less 2 pad).
inline Vec2 half_turn_shift(const Chart_mask& m, const Vec2& extent, double scale, long pad)
{
  return {double(m.width - 2 * pad) - scale * extent[0], double(m.height() - 2 * pad) - scale * extent[1]};
}

// The order in which charts are placed: by their area, or by the geometric mean of their area
// and their bounding box's (a ring, a crescent or a long strip then comes before a compact
// chart of its area: it is hardest to fit late, and smaller charts fill the room it leaves).
enum class Packing_order { AREA, AREA_AND_BOX };

// The cells of the charts' masks (each chart's first turn).
inline double cells_taken(const std::vector<std::array<Chart_mask, 4> >& masks)
{
  double taken = 0.;
  for(const std::array<Chart_mask, 4>& m : masks)
    for(const std::vector<Chart_mask::Span>& row : m[0].rows)
      for(const Chart_mask::Span& span : row) taken += double(span.second - span.first);
  return taken;
}

// The layout at the largest scale found (in at most `tries` packings, from `scale` on) whose
// square fits `cells` cells, each chart widened by `pad` cells; false if none fits.
inline bool search_layout(const Packing_input& in, long cells, long pad, double scale, int tries, Packing_layout& best,
                          unsigned int threads = 1, Packing_order by = Packing_order::AREA, double fill = 0.)
{
  const std::size_t n = in.area.size();
  Packing_layout trial;
  std::vector<double> size = in.area;
  std::vector<std::array<Chart_mask, 4> > masks(n); // of the charts at the scale `masks_at`
  double masks_at = 0.;
  const auto make_masks = [&](double at) {
    if(at == masks_at) return;
    parallel_for_each(n, thread_count(threads), [&](std::size_t c) {
      for(std::size_t k = 0; k < 2; ++k) {
        masks[c][k] = chart_mask(in.turned_uv[c][k], (*in.tri)[c], in.outline[c], at, pad);
        masks[c][k + 2] = half_turned(masks[c][k]);
      }
    });
    masks_at = at;
  };
  // the side of the square at scale `at`, laid out on twice the texture's side so that a scale
  // too large still tells by how much (the layouts that fit are the same), -1 beyond that
  const auto pack = [&](double at) {
    make_masks(at);
    if(by == Packing_order::AREA_AND_BOX)
      for(std::size_t c = 0; c < n; ++c)
        size[c] = std::sqrt(in.area[c] * double(masks[c][0].width) * double(masks[c][0].height()));
    trial.side = place_charts(masks, size, 2 * cells, trial.x, trial.y, trial.turn, thread_count(threads));
    trial.scale = at;
    if(trial.side <= 0 || trial.side > cells || at <= best.scale)
      return trial.side; // not kept
    trial.shift.assign(n, Vec2{0., 0.});
    for(std::size_t c = 0; c < n; ++c)
      if(trial.turn[c] >= 2) { // half_turned() of the chart turned by turn - 2
        const Vec2& e = in.extent[c];
        trial.shift[c] = half_turn_shift(masks[c][std::size_t(trial.turn[c] - 2)],
                                         trial.turn[c] == 3 ? Vec2{e[1], e[0]} : e, at, pad);
      }
    trial.taken = cells_taken(masks);
    best = trial;
    return trial.side;
  };
  // the side grows about linearly with the scale: aim at the texture's side, between the
  // scales found to fit and not to fit, never above the scale where the longest chart alone
  // spans the texture
  const double alone = double(cells - 2 * pad - 2) / in.longest;
  double too_large = HUGE_VAL;
  if(alone > 0. && scale > alone) scale = alone;
  // With the share `fill` of its square that the charts' cells took in a coarser layout, the
  // side at a scale is about that of a square of their cells at that scale over that share: a
  // start whose side this puts far from the window is moved to its middle (the gutter, whole
  // cells, makes the side grow faster than the scale, the more so the more charts)
  for(int step = 0; step < 3 && fill > 0.; ++step) {
    make_masks(scale);
    const double side = std::sqrt(cells_taken(masks) / fill);
    if(!(side > 0.) || std::abs(side / (0.99 * double(cells)) - 1.) < 0.025) break;
    scale *= 0.99 * double(cells) / side;
    if(alone > 0.) scale = (std::min)(scale, alone);
  }
  int misses = 0;
  for(int round = 0; round < tries; ++round) {
    const long side = pack(scale);
    if(side > 0.98 * double(cells) && side <= cells) break;
    if(side < 0 || side > cells) too_large = (std::min)(too_large, scale);
    // a scale that does not fit even twice the texture: a first one is mostly the coarse
    // estimate's, a little too hopeful, and just below it the square is most often in the window
    misses += side < 0;
    double next = side > 0 ? scale * 0.995 * double(cells) / double(side) : (misses == 1 ? 0.985 : 0.85) * scale;
    if(next <= best.scale || next >= too_large)
      next = best.scale > 0. ? (too_large < HUGE_VAL ? std::sqrt(best.scale * too_large) : 1.02 * best.scale)
                             : 0.85 * too_large;
    if(too_large < 1.01 * best.scale) break;
    scale = next;
  }
  return best.scale > 0.;
}

// The utilization of `layout`: the charts' area over the square's.
inline double layout_utilization(const Packing_input& in, const Packing_layout& layout)
{
  return in.charts_area * layout.scale * layout.scale / (double(layout.side) * double(layout.side));
}

// search_layout() with the charts by area, and, if that fills the square below `goal`, by area
// and box too: the layout that fills it better. (Final packings only: the coarse estimates
// are many, and a second order would cost them as much again.)
inline bool search_layouts(const Packing_input& in, long cells, long pad, double scale, int tries, double goal,
                           Packing_layout& best, unsigned int threads, double fill = 0.)
{
  if(!search_layout(in, cells, pad, scale, tries, best, threads, Packing_order::AREA, fill))
    return false;
  if(layout_utilization(in, best) >= goal)
    return true;
  Packing_layout other;
  if(search_layout(in, cells, pad, best.scale, tries, other, threads, Packing_order::AREA_AND_BOX) &&
     layout_utilization(in, other) > layout_utilization(in, best))
    best = std::move(other);
  return true;
}

// The utilization of a coarse layout (`settings.coarse_resolution` cells a side, the gutter in
// proportion), and its scale in cells of the full resolution: cheap, for deciding whether to
// cut charts further, and where the full search starts.
inline Packing_result estimate_packing(const Packing_input& in, const Packing_settings& settings, double scale_hint)
{
  Packing_result r;
  if(in.area.empty()) return r;
  const long cells = long((std::max)(settings.resolution, 16u));
  const long coarse = (std::min)(cells, long((std::max)(settings.coarse_resolution, 16u)));
  const double ratio = double(coarse) / double(cells);
  const long pad = std::lround(0.5 * settings.gutter * ratio);
  const double start = scale_hint > 0. ? scale_hint * ratio : double(coarse) * std::sqrt(0.6 / in.total_3d);
  Packing_layout layout;
  if(!search_layout(in, coarse, pad, start, 10, layout, settings.threads)) return r;
  r.scale = layout.scale / ratio * double(coarse) / double(layout.side);
  r.utilization = layout_utilization(in, layout);
  r.side = double(layout.side) / layout.scale;
  r.fill = layout.taken / (double(layout.side) * double(layout.side));
  return r;
}

// Packs the charts made ready in `in` (prepare_packing()), whose coarse layout is `coarse`
// (estimate_packing() of `in`), into the unit square: `uv[c]` receives chart c placed there.
// On a grid of `resolution` cells a side, each chart's triangles widened by half the gutter, so
// that two charts are at least a gutter apart and never overlap.
inline Packing_result pack_prepared(const Packing_input& in, const Packing_result& coarse, const Packing_settings& settings,
                                    std::vector<std::vector<Vec2> >& uv)
{
  Packing_result r;
  const std::size_t n = in.area.size();
  uv.resize(n);
  if(n == 0) return r;
  const std::vector<std::vector<Triangle> >& tri = *in.tri;
  const long cells = long((std::max)(settings.resolution, 16u));
  const long pad = long(std::ceil(0.5 * settings.gutter));
  // the search ends at a square of 98% to 100% of the texture: the coarse scale, a little too
  // hopeful (its gutter rounds to fewer cells, often none), is aimed at the middle of that window
  const double start = coarse.scale > 0. ? 0.99 * coarse.scale : double(cells) * std::sqrt(0.6 / in.total_3d);
  Packing_layout best;
  if(!search_layouts(in, cells, pad, start, coarse.scale > 0. ? 6 : 10, settings.goal, best, settings.threads,
                     coarse.fill)) {
    // could not fit at any tried scale: one chart per row of a larger square, at a scale where
    // the longest chart spans the texture at most (the start's estimate from the surface area
    // is unbounded for needles, whose extent is not in proportion to their area)
    const double fit = double((std::max)(cells - 2 * pad - 2, 1L)) / in.longest;
    best.scale = in.longest > 0. ? (std::min)(start, fit) : 1.;
    best.x.assign(n, 0); best.y.assign(n, 0); best.turn.assign(n, 0); best.shift.assign(n, Vec2{0., 0.});
    long row = 0, widest = 0;
    for(std::size_t c = 0; c < n; ++c) {
      const Chart_mask m = chart_mask(in.turned_uv[c][0], tri[c], in.outline[c], best.scale, pad);
      best.y[c] = row;
      row += m.height();
      widest = (std::max)(widest, m.width);
    }
    best.side = (std::max)({row, widest, cells});
  }
  const double side = double((std::max)(best.side, 1L));
  for(std::size_t c = 0; c < n; ++c) {
    const std::vector<Vec2>& from = in.turned_uv[c][std::size_t(best.turn[c])];
    std::vector<Vec2> placed(from.size());
    for(std::size_t v = 0; v < from.size(); ++v)
      placed[v] = {(std::min)((double(best.x[c] + pad) + best.shift[c][0] + from[v][0] * best.scale) / side, 1.),
                   (std::min)((double(best.y[c] + pad) + best.shift[c][1] + from[v][1] * best.scale) / side, 1.)};
    uv[c].swap(placed);
  }
  r.side = side / best.scale;
  r.scale = best.scale * double(cells) / side;
  r.utilization = in.charts_area * best.scale * best.scale / (side * side);
  return r;
}

// Packs the charts (`uv[c]`, each in its own frame, with its triangles `tri[c]`, its uv area
// and its surface area) into the unit square, in place (see pack_prepared()). The scale is
// searched on a coarse grid first, from `scale_hint` if given.
inline Packing_result pack_charts(std::vector<std::vector<Vec2> >& uv, const std::vector<std::vector<Triangle> >& tri,
                                  const std::vector<double>& area_uv, const std::vector<double>& area_3d,
                                  const Packing_settings& settings, double scale_hint = 0.)
{
  if(uv.empty()) return Packing_result();
  const Packing_input in = prepare_packing(uv, tri, area_uv, area_3d, settings.threads);
  return pack_prepared(in, estimate_packing(in, settings, scale_hint), settings, uv);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_PACKING_H

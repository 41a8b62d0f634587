// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_STRIP_STRAIGHTENING_H
#define CGAL_SMP_INTERNAL_ATLAS_STRIP_STRAIGHTENING_H

// A chart that is a long, thin strip flattens bent where its surface is (the rounded fillet
// along a curved edge of a CAD model flattens to an arc, a band around a rim to an L or a U):
// it then takes a small share of its bounding rectangle, and the packing fills the hollow of an
// arc with little but thinner arcs. A strip of width w bent with radius R laid out straight has
// its lengths changed by about w / (2 R) only, so such a chart is laid out straight (see
// straighten_strip()), and keeps that layout where its stretch stays low. A thin chart that
// turns sharply (at the corners of a rim) is cut there instead, and one that stays bent (too
// wide for its radius) at every quarter turn (see strip_turn_cut()).

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/Sander_energy_polisher.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_parameterization.h>

#include <CGAL/Box_intersection_d/Box_with_info_d.h>
#include <CGAL/box_intersection_d.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// The border of a chart of triangles `tri` as one loop of chart vertices, the chart on its left
// (the triangles' way round); empty if the border is not one simple loop.
inline std::vector<int> border_loop(const std::vector<Triangle>& tri, std::size_t vertices)
{
  const std::vector<std::array<int, 2> > outline = chart_outline(tri);
  std::vector<int> next(vertices, -1);
  for(const std::array<int, 2>& side : outline) {
    if(next[std::size_t(side[0])] >= 0) return {}; // the border passes twice through a vertex
    next[std::size_t(side[0])] = side[1];
  }
  std::vector<int> loop;
  if(outline.empty()) return loop;
  for(int v = outline.front()[0]; loop.size() <= outline.size(); v = next[std::size_t(v)]) {
    if(v < 0) return {};
    if(!loop.empty() && v == loop.front()) break;
    loop.push_back(v);
  }
  if(loop.size() != outline.size()) return {};
  return loop;
}

// The two ends of a strip whose border is `loop` at `uv`: the pairs of loop positions (first,
// last corner; one corner for a pointed end) of two stretches of border, each at most `reach`
// long, trimmed to their first and last vertex that turns by a tenth of their total: the one
// that turns most, by at least 0.6 pi, then, of those that turn by at least 0.4 pi and leave two
// sides of lengths within a ratio `balance` between the two ends, the one that turns most; false
// if there are none.
inline bool strip_ends(const std::vector<int>& loop, const std::vector<Vec2>& uv, double reach, double balance,
                       std::array<std::pair<std::size_t, std::size_t>, 2>& ends)
{
  const std::size_t n = loop.size();
  if(n < 4) return false;
  std::vector<double> turn(n), length(n); // at each corner; of the side from it to the next
  for(std::size_t i = 0; i < n; ++i) {
    const Vec2& a = uv[std::size_t(loop[(i + n - 1) % n])];
    const Vec2& b = uv[std::size_t(loop[i])];
    const Vec2& c = uv[std::size_t(loop[(i + 1) % n])];
    const Vec2 in{b[0] - a[0], b[1] - a[1]}, out{c[0] - b[0], c[1] - b[1]};
    turn[i] = std::atan2(in[0] * out[1] - in[1] * out[0], in[0] * out[0] + in[1] * out[1]);
    length[i] = std::hypot(out[0], out[1]);
  }
  // the stretch from corner i on that turns most within `reach`, and its turn
  const auto window = [&](std::size_t i, std::size_t& last) {
    double best = turn[i], sum = turn[i], along = 0.;
    last = i;
    for(std::size_t k = 1; k < n; ++k) {
      along += length[(i + k - 1) % n];
      if(along > reach) break;
      sum += turn[(i + k) % n];
      if(sum > best) { best = sum; last = (i + k) % n; }
    }
    return best;
  };
  const auto trimmed = [&](std::size_t first, std::size_t last, double total) {
    while(first != last && turn[first] < 0.1 * total) first = (first + 1) % n;
    while(last != first && turn[last] < 0.1 * total) last = (last + n - 1) % n;
    return std::make_pair(first, last);
  };
  const double least = 0.6 * 3.14159265358979323846;
  const auto span = [n](std::size_t first, std::size_t last) { return (last + n - first) % n; };
  std::size_t first_end = n, last = 0;
  double best = least;
  for(std::size_t i = 0; i < n; ++i) {
    std::size_t l;
    const double t = window(i, l);
    if(t >= best) { best = t; first_end = i; last = l; }
  }
  if(first_end == n) return false;
  ends[0] = trimmed(first_end, last, best);
  // the other end: a stretch after the first one that leaves two sides of about one length
  // between them (within `balance`), the one that turns most
  const std::size_t taken = span(ends[0].first, ends[0].second);
  std::vector<double> along(n + 1, 0.); // border length from the first end's last corner
  for(std::size_t k = 0; k < n; ++k)
    along[k + 1] = along[k] + length[(ends[0].second + k) % n];
  double second = 2. / 3. * least; // the balance of the sides tells the other end as much as its turn
  bool found = false;
  for(std::size_t i = 0; i < n; ++i) {
    if(span(ends[0].first, i) <= taken + 1 || span(ends[0].first, i) + 1 >= n) continue;
    std::size_t l;
    const double t = window(i, l);
    if(t < second || span(ends[0].first, l) < span(ends[0].first, i) || span(ends[0].first, l) + 1 >= n) continue;
    const std::pair<std::size_t, std::size_t> end = trimmed(i, l, t);
    const double one = along[span(ends[0].second, end.first)];
    const double other_side = along[n - taken] - along[span(ends[0].second, end.second)]; // to the first end
    if(!((std::max)(one, other_side) <= balance * (std::min)(one, other_side))) continue;
    second = t;
    ends[1] = end;
    found = true;
  }
  return found;
}

// A polyline by the share of its length up to each point (0 at the first, 1 at the last),
// extended along its first and last segments beyond them.
class Polyline_by_length
{
public:
  Polyline_by_length() = default;
  explicit Polyline_by_length(const std::vector<Vec2>& points)
  {
    for(const Vec2& q : points)
      if(m_points.empty() || std::hypot(q[0] - m_points.back()[0], q[1] - m_points.back()[1]) > 0.) {
        m_at.push_back(m_points.empty() ? 0. : m_at.back() + std::hypot(q[0] - m_points.back()[0], q[1] - m_points.back()[1]));
        m_points.push_back(q);
      }
    m_length = m_at.empty() ? 0. : m_at.back();
    for(double& a : m_at) a = m_length > 0. ? a / m_length : 0.;
  }
  bool valid() const { return m_points.size() >= 2; }
  double length() const { return m_length; }
  const std::vector<double>& shares() const { return m_at; }
  Vec2 at(double t) const
  {
    const std::size_t k = std::size_t(std::upper_bound(m_at.begin() + 1, m_at.end() - 1, t) - m_at.begin()) - 1;
    const double f = (t - m_at[k]) / (m_at[k + 1] - m_at[k]);
    return {m_points[k][0] + f * (m_points[k + 1][0] - m_points[k][0]), m_points[k][1] + f * (m_points[k + 1][1] - m_points[k][1])};
  }

private:
  std::vector<Vec2> m_points;
  std::vector<double> m_at;
  double m_length = 0.;
};

// For each point of `uv`, the stretches k between the segments [first[k], second[k]] and
// [first[k + 1], second[k + 1]] (the sides linear in between, so that the segments in between
// sweep the quadrilateral of their ends) where the point may lie on a segment carried on as a
// line by less than 1.5 times the segment's length beyond its ends: those whose box of the
// segments so carried on, with a margin, holds the point. In increasing order of k.
inline std::vector<std::vector<std::size_t> > stretches_near(const std::vector<Vec2>& uv, const std::vector<Vec2>& first,
                                                             const std::vector<Vec2>& second)
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  double scale = 0.;
  for(const Vec2& p : uv) scale = (std::max)(scale, (std::max)(std::abs(p[0]), std::abs(p[1])));
  std::vector<Box> stretch_boxes, point_boxes;
  for(std::size_t k = 0; k + 1 < first.size(); ++k) {
    double low[2] = {HUGE_VAL, HUGE_VAL}, high[2] = {-HUGE_VAL, -HUGE_VAL};
    for(std::size_t e = k; e <= k + 1; ++e)
      for(double d : {-2., 3.})
        for(int i = 0; i < 2; ++i) {
          const double x = first[e][i] + d * (second[e][i] - first[e][i]);
          low[i] = (std::min)(low[i], x);
          high[i] = (std::max)(high[i], x);
        }
    for(int i = 0; i < 2; ++i) {
      const double margin = 1e-9 * (scale + high[i] - low[i]);
      low[i] -= margin;
      high[i] += margin;
    }
    if(std::isfinite(low[0]) && std::isfinite(low[1]) && std::isfinite(high[0]) && std::isfinite(high[1]))
      stretch_boxes.emplace_back(low, high, k);
  }
  for(std::size_t v = 0; v < uv.size(); ++v) {
    double at[2] = {uv[v][0], uv[v][1]};
    point_boxes.emplace_back(at, at, v);
  }
  std::vector<std::vector<std::size_t> > near(uv.size());
  CGAL::box_intersection_d(point_boxes.begin(), point_boxes.end(), stretch_boxes.begin(), stretch_boxes.end(),
                           [&near](const Box& point, const Box& stretch) { near[point.info()].push_back(stretch.info()); });
  for(std::vector<std::size_t>& k : near) std::sort(k.begin(), k.end());
  return near;
}

// Whether `chart` (flattened, with no slit and no polish pending) fills less than 60% of its
// smallest bounding rectangle, as a bent strip or a band with corners does; then its mean
// `width` (twice its uv area over its perimeter).
inline bool sparse_chart(const Chart_map& chart, double& width)
{
  if(!chart.ok || !chart.slits.empty() || chart.deferred.pending)
    return false;
  const std::vector<Triangle>& tri = chart.flat.tri;
  const std::vector<Vec2>& uv = chart.uv;
  double area = 0.;
  for(const Triangle& t : tri)
    area += 0.5 * twice_signed_area(uv[std::size_t(t[0])], uv[std::size_t(t[1])], uv[std::size_t(t[2])]);
  std::vector<Vec2> aligned = uv;
  const Vec2 extent = align_chart(aligned);
  if(!(area > 0.) || !(area < 0.6 * extent[0] * extent[1]))
    return false;
  double perimeter = 0.;
  for(const std::array<int, 2>& side : chart_outline(tri))
    perimeter += std::hypot(uv[std::size_t(side[1])][0] - uv[std::size_t(side[0])][0],
                            uv[std::size_t(side[1])][1] - uv[std::size_t(side[0])][1]);
  width = 2. * area / perimeter;
  return perimeter > 0.;
}

// The shape of a chart that is a bent strip: its border loop (the chart on its left), its two
// ends (pairs of loop positions, see strip_ends()) and its two sides, each from the first end to
// the second, taken without their vertices of one triangle (the tip of a triangle that sticks
// out of the border, which would come out on one line with its neighbours).
struct Strip_shape
{
  std::vector<int> loop;
  std::array<std::pair<std::size_t, std::size_t>, 2> ends;
  Polyline_by_length first, second;
  double end_length = 0.; // the longer end, from its first corner to its last
  double width = 0.;      // the mean width (see sparse_chart())
};

// Whether `chart` (flattened, with no slit and no polish pending) is a bent strip, and its shape
// into `shape`: it fills less than 60% of its smallest bounding rectangle, and its border is two
// ends (strip_ends(), looked for in stretches three times its mean width long) and two sides at
// least four times as long as the ends and of lengths within 30% of each other.
inline bool bent_strip(const Chart_map& chart, Strip_shape& shape)
{
  if(chart.flat.tri.size() < 2 || !sparse_chart(chart, shape.width))
    return false;
  const std::vector<Triangle>& tri = chart.flat.tri;
  const std::vector<Vec2>& uv = chart.uv;
  shape.loop = border_loop(tri, uv.size());
  const std::vector<int>& loop = shape.loop;
  const std::size_t n = loop.size();
  if(n < 4)
    return false;
  const double balance = 1.3;
  std::array<std::pair<std::size_t, std::size_t>, 2>& ends = shape.ends;
  if(!strip_ends(loop, uv, 3. * shape.width, balance, ends))
    return false;
  std::vector<int> triangles_at(uv.size(), 0);
  for(const Triangle& t : tri)
    for(int v : t) ++triangles_at[std::size_t(v)];
  // a side from the corner `from` to the corner `to` along the loop (backwards if `back`)
  const auto side = [&](std::size_t from, std::size_t to, bool back) {
    std::vector<Vec2> points;
    for(std::size_t i = from;; i = back ? (i + n - 1) % n : (i + 1) % n) {
      if(i == from || i == to || triangles_at[std::size_t(loop[i])] > 1)
        points.push_back(uv[std::size_t(loop[i])]);
      if(i == to) break;
    }
    return Polyline_by_length(points);
  };
  shape.first = side(ends[0].second, ends[1].first, false);
  shape.second = side(ends[0].first, ends[1].second, true);
  if(!shape.first.valid() || !shape.second.valid())
    return false;
  const double shorter = (std::min)(shape.first.length(), shape.second.length());
  const double longer = (std::max)(shape.first.length(), shape.second.length());
  shape.end_length = 0.;
  for(const auto& e : ends) {
    const Vec2 &a = uv[std::size_t(loop[e.first])], &b = uv[std::size_t(loop[e.second])];
    shape.end_length = (std::max)(shape.end_length, std::hypot(b[0] - a[0], b[1] - a[1]));
  }
  return shorter >= 4. * shape.end_length && longer <= balance * shorter;
}

// Lays `chart` out straight if it is a bent strip (bent_strip()). The sides give the segments
// from the point at a share t of the length of one to the point at that share of the other (for
// a strip bent on a circle, its radii); a chart vertex on the segment of t, at a share d of it
// from the first side, goes to (t L, (d - 1/2) w(t)), L the sides' mean length and w(t) the
// segment's length. Where the strip turns sharply, its sides have lengths that no segments pair
// well, and the layout shears the strip: free-border Newton steps on Sander's stretch, the four
// corners pinned, take the shear to where the strip turns (they keep every triangle's
// orientation and the border simple, and refuse a start that is not). The layout is kept if its
// L2 stretch is within `max_stretch` and within a hundredth of the chart's; then true. (A vertex
// beside a pointed end, where the segments shrink to the tip, may be found on no segment: such
// a strip is left bent.)
inline bool straighten_strip(Chart_map& chart, double max_stretch)
{
  Strip_shape shape;
  if(!bent_strip(chart, shape))
    return false;
  const std::vector<Triangle>& tri = chart.flat.tri;
  const std::vector<Vec2>& uv = chart.uv;
  const std::vector<int>& loop = shape.loop;
  const std::array<std::pair<std::size_t, std::size_t>, 2>& ends = shape.ends;
  const Polyline_by_length &first = shape.first, &second = shape.second;
  const double shorter = (std::min)(first.length(), second.length()), end_length = shape.end_length;
  const double length = 0.5 * (first.length() + second.length());
  // The segment of a vertex: where the segment's side of it changes from ahead of it to behind
  // it, between two breaks of the sides; segments are looked for a little beyond the ends, where
  // the vertices of a ragged end are. A segment carried on as a line may pass the vertex
  // elsewhere too, where the strip turns back: the vertex is taken on the segment that holds it,
  // or on the nearest one.
  const auto ahead_of = [](const Vec2& p, const Vec2& a, const Vec2& b) {
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
  };
  const auto ahead = [&](const Vec2& p, double t) { return ahead_of(p, first.at(t), second.at(t)); };
  const double reach = (std::max)(0.01, end_length / shorter);
  std::vector<double> breaks = first.shares();
  breaks.insert(breaks.end(), second.shares().begin(), second.shares().end());
  breaks.push_back(-reach);
  breaks.push_back(1. + reach);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  std::vector<Vec2> first_at(breaks.size()), second_at(breaks.size()); // the segments at the breaks
  for(std::size_t k = 0; k < breaks.size(); ++k) {
    first_at[k] = first.at(breaks[k]);
    second_at[k] = second.at(breaks[k]);
  }
  const std::vector<std::vector<std::size_t> > stretches = stretches_near(uv, first_at, second_at);
  std::vector<Vec2> straight(uv.size());
  // the corners, on the segments of shares 0 and 1 (one corner: a pointed end)
  std::vector<char> corner(uv.size(), 0);
  for(int e = 0; e < 2; ++e) {
    const Vec2 a = first.at(double(e)), b = second.at(double(e));
    const double w = std::hypot(b[0] - a[0], b[1] - a[1]);
    straight[std::size_t(loop[e == 0 ? ends[0].second : ends[1].first])] = {double(e) * length, -0.5 * w};
    straight[std::size_t(loop[e == 0 ? ends[0].first : ends[1].second])] = {double(e) * length, 0.5 * w};
    for(std::size_t c : {ends[std::size_t(e)].first, ends[std::size_t(e)].second}) corner[std::size_t(loop[c])] = 1;
  }
  for(std::size_t v = 0; v < uv.size(); ++v) {
    if(corner[v]) continue;
    const Vec2& p = uv[v];
    double best = HUGE_VAL; // how far the share d is from [0, 1]
    for(std::size_t k : stretches[v]) {
      if(!(ahead_of(p, first_at[k], second_at[k]) <= 0. && ahead_of(p, first_at[k + 1], second_at[k + 1]) > 0.))
        continue;
      double low = breaks[k], high = breaks[k + 1];
      for(int i = 0; i < 50; ++i) {
        const double middle = 0.5 * (low + high);
        (ahead(p, middle) > 0. ? high : low) = middle;
      }
      const double t = 0.5 * (low + high);
      const Vec2 a = first.at(t), b = second.at(t), ab{b[0] - a[0], b[1] - a[1]};
      const double w2 = ab[0] * ab[0] + ab[1] * ab[1];
      if(!(w2 > 0.)) continue;
      const double d = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / w2;
      const double off = d < 0. ? -d : (d > 1. ? d - 1. : 0.);
      if(off < best) {
        best = off;
        straight[v] = {t * length, (d - 0.5) * std::sqrt(w2)};
      }
    }
    if(!(best < 1.5)) // a vertex off its segment by more than the strip is wide: no strip
      return false;
  }
  std::vector<char> pinned(uv.size(), 0);
  for(const auto& e : ends)
    pinned[std::size_t(loop[e.first])] = pinned[std::size_t(loop[e.second])] = 1;
  // the steps of a chart's free-border polish (one thread, 10 at most), the corners pinned
  Sander_polish_settings ps = free_border_polish_settings(Chart_parameterization_settings());
  ps.pin_fixed_border = true;
  const std::vector<int> border(loop.rbegin(), loop.rend()); // the polisher's way round
  if(Sander_energy_polisher<>().polish(chart.flat, std::vector<Triangle>(), pinned, border, straight, ps).status !=
     Sander_polish_status::OK)
    return false;
  const Flat_stretch_summary s = Flat_stretch().evaluate(chart.flat, straight);
  if(s.flipped > 0 || s.degenerate_uv > 0 || !(s.l2 <= max_stretch) || !(s.l2 <= chart.l2 + 0.01))
    return false;
  double turned = 0.; // the chart's orientation, counterclockwise, kept
  for(const Triangle& t : tri)
    turned += twice_signed_area(straight[std::size_t(t[0])], straight[std::size_t(t[1])], straight[std::size_t(t[2])]);
  if(!(turned > 0.))
    return false;
  chart.uv.swap(straight);
  chart.l2 = s.l2;
  return true;
}

// The distance of each vertex of a flattened chart from `source` along its edges in uv
// (Dijkstra's, on Boost's graph).
inline std::vector<double> uv_distances(const std::vector<Triangle>& tri, const std::vector<Vec2>& uv, int source)
{
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                boost::property<boost::edge_weight_t, double> >
      Graph;
  Graph graph(uv.size());
  for(const Triangle& t : tri) // an inner edge twice, once from each side: the same paths
    for(int k = 0; k < 3; ++k) {
      const std::size_t a = std::size_t(t[std::size_t(k)]), b = std::size_t(t[std::size_t((k + 1) % 3)]);
      boost::add_edge(a, b, std::hypot(uv[b][0] - uv[a][0], uv[b][1] - uv[a][1]), graph);
    }
  std::vector<double> distance(uv.size(), HUGE_VAL);
  boost::dijkstra_shortest_paths(
      graph, std::size_t(source),
      boost::distance_map(boost::make_iterator_property_map(distance.begin(), boost::get(boost::vertex_index, graph))));
  return distance;
}

// Where a long thin chart that stays bent is cut across: at its sharp turns, where the line of
// its middle turns by more than a quarter turn within two widths on either side (a band around
// the rim of a CAD part turns at its corners: its straight pieces pack well, the band does not);
// without a sharp turn, wherever its middle line has turned by a quarter turn since the start
// or the last cut (a band around a rounded part, too wide to be laid out straight, packs better
// in quarters of an arc than whole). The chart fills less than 60% of its smallest bounding
// rectangle and is more than eight widths long (its width: twice its area over its perimeter,
// or its mean edge length if longer); its length is the distance in uv along its edges from a
// vertex farthest from another, its middle line the mean position of the vertices in each half
// width of that distance, and a cut leaves the triangles below the turn's distance on one side,
// the sharpest turns first, two widths apart at least. `part` gets the part of each triangle,
// `parts` their number; false if there is no such turn.
inline bool strip_turn_cut(const Chart_map& chart, std::vector<int>& part, int& parts)
{
  double width = 0.;
  if(chart.flat.tri.size() < 8 || !sparse_chart(chart, width))
    return false;
  const std::vector<Triangle>& tri = chart.flat.tri;
  const std::vector<Vec2>& uv = chart.uv;
  std::vector<double> distance = uv_distances(tri, uv, tri[0][0]);
  const std::size_t far = std::size_t(std::max_element(distance.begin(), distance.end(), [](double a, double b) {
                                        return (std::isfinite(a) ? a : -1.) < (std::isfinite(b) ? b : -1.);
                                      }) - distance.begin());
  distance = uv_distances(tri, uv, int(far));
  double length = 0.;
  for(double d : distance)
    if(std::isfinite(d)) length = (std::max)(length, d);
  // the middle line: the mean position of the vertices in each stretch of half a width (or of
  // an edge, where the edges are longer) of distance that holds any
  double edges = 0.;
  for(const Triangle& t : tri)
    for(int k = 0; k < 3; ++k) {
      const Vec2 &a = uv[std::size_t(t[std::size_t(k)])], &b = uv[std::size_t(t[std::size_t((k + 1) % 3)])];
      edges += std::hypot(b[0] - a[0], b[1] - a[1]);
    }
  const double reach = 2. * (std::max)(width, edges / double(3 * tri.size())); // two widths
  const double step = 0.25 * reach;
  if(!(length > 4. * reach) || !(length < 1e5 * step))
    return false;
  const std::size_t bins = std::size_t(length / step) + 1;
  std::vector<Vec2> sum(bins, Vec2{0., 0.});
  std::vector<std::size_t> count(bins, 0);
  for(std::size_t v = 0; v < uv.size(); ++v) {
    if(!std::isfinite(distance[v])) return false; // the chart is in one piece
    const std::size_t b = (std::min)(bins - 1, std::size_t(distance[v] / step));
    sum[b][0] += uv[v][0];
    sum[b][1] += uv[v][1];
    ++count[b];
  }
  std::vector<Vec2> middle;
  std::vector<double> at; // the distance of each point of the middle line
  for(std::size_t b = 0; b < bins; ++b)
    if(count[b] > 0) {
      middle.push_back({sum[b][0] / double(count[b]), sum[b][1] / double(count[b])});
      at.push_back((double(b) + 0.5) * step);
    }
  // the turn at each point of the middle line, from the points two widths before and after
  const std::size_t n = middle.size();
  std::vector<double> turn(n, 0.);
  for(std::size_t i = 0, before = 0, after = 0; i < n; ++i) {
    while(before + 1 < i && at[before + 1] <= at[i] - reach) ++before;
    while(after < n && at[after] < at[i] + reach) ++after;
    if(!(at[before] <= at[i] - reach) || after == n)
      continue;
    const Vec2 &a = middle[before], &m = middle[i], &c = middle[after];
    const Vec2 in{m[0] - a[0], m[1] - a[1]}, out{c[0] - m[0], c[1] - m[1]};
    turn[i] = std::abs(std::atan2(in[0] * out[1] - in[1] * out[0], in[0] * out[0] + in[1] * out[1]));
  }
  // the sharpest turns first, each keeping the others two widths away
  std::vector<std::size_t> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&turn](std::size_t a, std::size_t b) { return turn[a] > turn[b]; });
  std::vector<double> cuts;
  for(std::size_t i : order) {
    if(!(turn[i] > 0.25 * 3.14159265358979323846)) break;
    if(std::none_of(cuts.begin(), cuts.end(), [&](double d) { return std::abs(d - at[i]) < reach; }))
      cuts.push_back(at[i]);
  }
  // no sharp turn: where the direction of the middle line (over a width on either side) has
  // turned by a quarter turn since the last cut, a width from either end at least
  if(cuts.empty()) {
    double heading = 0., last = 0., previous = 0.; // turned so far, at the last cut; the last direction
    bool started = false;
    for(std::size_t i = 0, before = 0, after = 0; i < n; ++i) {
      while(before + 1 < i && at[before + 1] <= at[i] - 0.5 * reach) ++before;
      while(after < n && at[after] < at[i] + 0.5 * reach) ++after;
      if(!(at[before] <= at[i] - 0.5 * reach) || after == n)
        continue;
      const double direction = std::atan2(middle[after][1] - middle[before][1], middle[after][0] - middle[before][0]);
      if(started) {
        double d = direction - previous;
        while(d > 3.14159265358979323846) d -= 2. * 3.14159265358979323846;
        while(d < -3.14159265358979323846) d += 2. * 3.14159265358979323846;
        heading += d;
      }
      previous = direction;
      if(!started) { started = true; continue; }
      if(std::abs(heading - last) > 0.5 * 3.14159265358979323846 && at[i] - (cuts.empty() ? at[0] : cuts.back()) >= reach &&
         at.back() - at[i] >= reach) {
        cuts.push_back(at[i]);
        last = heading;
      }
    }
  }
  if(cuts.empty())
    return false;
  std::sort(cuts.begin(), cuts.end());
  part.resize(tri.size());
  for(std::size_t i = 0; i < tri.size(); ++i) {
    const double d = (distance[std::size_t(tri[i][0])] + distance[std::size_t(tri[i][1])] + distance[std::size_t(tri[i][2])]) / 3.;
    part[i] = int(std::upper_bound(cuts.begin(), cuts.end(), d) - cuts.begin());
  }
  parts = int(cuts.size()) + 1;
  return true;
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_STRIP_STRAIGHTENING_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_BUILD_ATLAS_H
#define CGAL_SMP_INTERNAL_ATLAS_BUILD_ATLAS_H

// The atlas of a triangulated soup: charts grown, flattened and cut while above the stretch
// bound (in two, or in several parts at once when far above it), bent strips laid out
// straight, thin charts that stay bent cut at their sharp turns, packed (the longest cut across
// while the square is poorly filled), then written per polygon corner with the report's
// measures. make_atlas() reads the input and calls it.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Atlas.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Atlas_input.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_growing.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_joining.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_partition.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_parameterization.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Strip_straightening.h>
#include <CGAL/Surface_mesh_parameterization/internal/flip_free_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/wall_clock.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_named_parameters.h>

#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// Tells the two versions of make_atlas() apart: the third argument of the soup's is a sequence
// of named parameters (CGAL's or the package's, which derive from CGAL's), the mesh's a property map.
template <typename T, typename Tag, typename Base>
std::true_type is_named_parameters(const CGAL::Named_function_parameters<T, Tag, Base>*);
std::false_type is_named_parameters(...);
template <typename T>
struct Is_named_parameters : decltype(is_named_parameters(static_cast<const T*>(nullptr))) {};

// The settings of make_atlas() read from named parameters.
struct Atlas_settings
{
  double max_stretch = 1.05;
  int join_rounds = 5;                  // rounds of joining neighbouring charts
  unsigned int threads = 0; // 0: one per core
  Packing_settings packing;
  Chart_parameterization_settings chart;
  std::function<void(const Atlas_progress&)> visitor;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void tell(Atlas_stage stage, std::size_t done, std::size_t total) const
  {
    if(visitor)
      visitor(Atlas_progress{stage, done, total, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
  }
};

// The visitor named parameter as a function of an Atlas_progress (its result is ignored).
template <typename Visitor>
std::function<void(const Atlas_progress&)> make_atlas_visitor(const Visitor& v)
{
  if constexpr(std::is_same<Visitor, CGAL::internal_np::Param_not_found>::value) {
    return {};
  } else {
    static_assert(std::is_invocable<Visitor, const Atlas_progress&>::value,
                  "the visitor of make_atlas() must be callable with a const Atlas_progress&");
    return [v](const Atlas_progress& p) mutable { std::invoke(v, p); };
  }
}

template <typename NamedParameters>
Atlas_settings read_atlas_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Atlas_settings s;
  s.max_stretch = choose_parameter(get_parameter(np, internal_np::max_stretch), s.max_stretch);
  s.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), s.threads);
  s.packing.threads = s.threads;
  s.packing.resolution = choose_parameter(get_parameter(np, internal_np::resolution), s.packing.resolution);
  s.packing.gutter = choose_parameter(get_parameter(np, internal_np::gutter), s.packing.gutter);
  s.chart.polish_iterations = choose_parameter(get_parameter(np, internal_np::polish_iterations), s.chart.polish_iterations);
  s.chart.max_stretch = s.max_stretch;
  s.visitor = make_atlas_visitor(get_parameter(np, CGAL::internal_np::visitor));
  return s;
}

struct Chart_areas
{
  double uv = 0., surface = 0.;
};

inline Chart_areas chart_areas(const Chart_map& chart)
{
  Chart_areas a;
  for(const Triangle& t : chart.flat.tri) {
    const Face_stretch s = triangle_stretch(chart.flat.xyz[t[0]], chart.flat.xyz[t[1]], chart.flat.xyz[t[2]],
                                                chart.uv[t[0]], chart.uv[t[1]], chart.uv[t[2]]);
    a.uv += std::abs(s.area_uv);
    a.surface += s.area_3d;
  }
  return a;
}

// Where a chart is cut across its length: a value of `along` (one per triangle of `chart`, its
// position along the chart's long side), the triangles below it on one side. Of the values
// that leave between 30% and 70% of the surface area on each side, the one whose cut (the
// edges between the two sides) is shortest, its length weighed by 1 + 2 |share - 1/2|: a waist
// of the chart is taken if it is enough shorter than the middle to be worth uneven halves (the
// larger of which may need a cut of its own); a strip of even width is cut in its middle.
inline double cut_position(const std::vector<double>& along, const Flat_triangles& chart)
{
  const std::size_t n = along.size();
  std::vector<std::pair<double, double> > v(n); // (position, area)
  double total = 0.;
  for(std::size_t i = 0; i < n; ++i) {
    const Triangle& t = chart.tri[i];
    v[i] = {along[i], triangle_area(chart.xyz[t[0]], chart.xyz[t[1]], chart.xyz[t[2]])};
    total += v[i].second;
  }
  if(n == 0)
    return 0.;
  std::sort(v.begin(), v.end());
  // the edges inside the chart, each cut by the positions in (low, high]: the cut at t is as
  // long as the edges with low < t less those with high < t
  std::vector<std::pair<double, double> > low, high; // (position, edge length)
  for(const Shared_side& s : shared_sides(chart)) {
    const double length = norm3(sub3(chart.xyz[std::size_t(s.a)], chart.xyz[std::size_t(s.b)]));
    const double p0 = along[std::size_t(s.t0)], p1 = along[std::size_t(s.t1)];
    low.emplace_back((std::min)(p0, p1), length);
    high.emplace_back((std::max)(p0, p1), length);
  }
  const auto prefix = [](std::vector<std::pair<double, double> >& e) {
    std::sort(e.begin(), e.end());
    double sum = 0.;
    for(auto& x : e) x.second = sum += x.second;
  };
  prefix(low);
  prefix(high);
  const auto below = [](const std::vector<std::pair<double, double> >& e, double t) { // length of edges at < t
    const auto it = std::lower_bound(e.begin(), e.end(), std::make_pair(t, -HUGE_VAL));
    return it == e.begin() ? 0. : std::prev(it)->second;
  };
  // without a position in that range (a few triangles of unequal areas): the area median
  double median = v.back().first, best = median, best_cost = HUGE_VAL, sum = 0.;
  bool past_median = false;
  for(std::size_t i = 0; i < n; sum += v[i++].second) {
    if(!past_median && sum + v[i].second >= 0.5 * total) {
      median = v[i].first;
      past_median = true;
    }
    if(i > 0 && v[i].first == v[i - 1].first)
      continue; // the triangles below a position are those before its first
    const double share = total > 0. ? sum / total : double(i) / double(n);
    if(share < 0.3 || share > 0.7)
      continue;
    const double cost = (below(low, v[i].first) - below(high, v[i].first)) * (1. + 2. * std::abs(share - 0.5));
    if(cost < best_cost) {
      best = v[i].first;
      best_cost = cost;
    }
  }
  return best_cost < HUGE_VAL ? best : median;
}

// The packed charts (`uv`, one per chart of `kept`) measured as one map, a triangle of each
// chart's in turn; `flipped` receives, per chart, its triangles oriented against the input, and
// `measured`, its triangles with an area to speak of (in 3D and in uv).
inline Flat_stretch_summary measure_packed_charts(const std::vector<Chart_map>& charts, const std::vector<std::size_t>& kept,
                                                  const std::vector<std::vector<Vec2> >& uv, std::vector<std::size_t>& flipped,
                                                  std::vector<std::size_t>& measured)
{
  Flat_triangles all;
  std::vector<Vec2> all_uv;
  std::vector<std::size_t> chart_of;
  for(std::size_t i = 0; i < kept.size(); ++i) {
    const Chart_map& chart = charts[kept[i]];
    for(const Triangle& t : chart.flat.tri) {
      for(int k = 0; k < 3; ++k) {
        all.xyz.push_back(chart.flat.xyz[std::size_t(t[std::size_t(k)])]);
        all_uv.push_back(uv[i][std::size_t(t[std::size_t(k)])]);
      }
      const int b = int(all.xyz.size());
      all.tri.push_back({b - 3, b - 2, b - 1});
      chart_of.push_back(i);
    }
  }
  Flat_stretch measure;
  const Flat_stretch_summary s = measure.evaluate(all, all_uv);
  // every chart is laid out counterclockwise: a face of negative uv area is flipped, unless it
  // has no area to speak of, in 3D or in uv (the package's measure leaves those out, as here)
  flipped.assign(kept.size(), 0);
  measured.assign(kept.size(), 0);
  for(std::size_t t = 0; t < all.tri.size(); ++t)
    if(measure.used(t)) {
      ++measured[chart_of[t]];
      if(measure.faces()[t].area_uv < 0.)
        ++flipped[chart_of[t]];
    }
  return s;
}

// The stages after the input: charts, their maps, the packing, the uv of the corners of the
// triangles (`corner_written`: per polygon corner, whether it got one; `vertex_uv`: a uv of
// every welded vertex in a chart).
inline void build_atlas(const Atlas_triangles& m, std::size_t number_of_polygons, const Atlas_settings& settings,
                        Atlas& atlas, std::vector<std::vector<char> >& corner_written,
                        std::unordered_map<int, Vec2>& vertex_uv)
{
  Atlas_report& r = atlas.report;
  const std::size_t nt = m.vertex.size();
  auto t0 = std::chrono::steady_clock::now();
  Chart_growing g(m);
  std::vector<char> allowed(nt, 1);
  // a polygon joins a chart while its normal is within 54 degrees of the chart's: wider cones
  // make charts that take longer to flatten and are cut more often for their stretch; the
  // seams of narrower ones are mostly taken back when neighbouring charts are joined below
  const double first_angle = 0.3 * 3.14159265358979323846;
  int n = g.grow(allowed, 0, first_angle, 0);
  std::vector<double> angle(std::size_t(n), first_angle);
  r.seconds_cutting += seconds_since(t0);

  // flatten every chart; a chart above the bound (or that cannot be flattened) is grown again
  // from its own triangles, with a narrower normal cone and fewer polygons
  std::vector<Chart_map> charts(static_cast<std::size_t>(n));
  std::vector<std::vector<std::size_t> > members;
  // the triangles of the charts numbered from `first` on, all among `triangles`
  auto collect = [&](int first, int count, const std::vector<std::size_t>& triangles) {
    members.resize(std::size_t(first + count));
    for(int c = first; c < first + count; ++c) members[std::size_t(c)].clear();
    for(std::size_t t : triangles)
      if(g.chart(t) >= first)
        members[std::size_t(g.chart(t))].push_back(t);
  };
  auto units_of = [&m](const std::vector<std::size_t>& triangles) {
    std::size_t units = triangles.empty() ? 0 : 1;
    for(std::size_t i = 1; i < triangles.size(); ++i)
      units += m.polygon[triangles[i]] != m.polygon[triangles[i - 1]];
    return units;
  };
  std::vector<std::size_t> every(nt);
  for(std::size_t t = 0; t < nt; ++t) every[t] = t;
  collect(0, n, every);
  // grows chart c again as `parts` charts, the parts `part` gives its triangles (each part in
  // one piece; the part of a polygon is that of its first triangle: a polygon's triangles stay
  // together), each within the normal cone of chart c, or whole if `whole`; false if one part
  // would hold them all. Without `whole` (a cut for the stretch bound), each planar region the
  // parts cut goes to one of them first; the cuts for the packing and at turns are placed on
  // purpose, and kept where they are.
  auto split = [&](std::size_t c, std::vector<int> part, int parts, bool whole) {
    const std::vector<std::vector<int> > across = triangles_across(charts[c].flat);
    if(!whole)
      snap_planar_regions(charts[c].flat, across, part);
    join_detached_pieces(across, part);
    const std::vector<std::size_t> triangles = charts[c].triangles;
    std::unordered_map<std::size_t, std::size_t> polygon_first;
    for(std::size_t i = 0; i < triangles.size(); ++i)
      polygon_first.emplace(m.polygon[triangles[i]], i);
    std::vector<std::vector<char> > in(std::size_t(parts), std::vector<char>(nt, 0));
    std::vector<std::size_t> size(std::size_t(parts), 0);
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      const std::size_t j = std::size_t(part[polygon_first[m.polygon[triangles[i]]]]);
      in[j][triangles[i]] = 1;
      ++size[j];
    }
    if(std::find(size.begin(), size.end(), triangles.size()) != size.end())
      return false;
    const int first = int(charts.size());
    int made = 0;
    for(std::size_t j = 0; j < in.size(); ++j)
      if(size[j] > 0)
        made += g.grow(in[j], first + made, whole ? 3.14159265358979323846 : angle[c], 0);
    collect(first, made, triangles);
    charts.resize(std::size_t(first + made));
    angle.resize(std::size_t(first + made), angle[c]);
    charts[c] = Chart_map();
    return true;
  };
  // cuts flattened chart c across its long side, at its narrowest waist about the middle (in
  // two halves grown again whole if `whole`, see split())
  auto cut_across = [&](std::size_t c, const std::vector<double>& along, bool whole) {
    const double at = cut_position(along, charts[c].flat);
    std::vector<int> half(along.size());
    for(std::size_t i = 0; i < along.size(); ++i)
      half[i] = along[i] < at ? 0 : 1;
    return split(c, half, 2, whole);
  };
  // a flattened chart c above the bound is cut in two across its length, or, far above it,
  // into several compact parts at once; one that could not be flattened is grown again with a
  // narrower cone, or, if it is one polygon, split into its triangles laid out alone
  std::vector<Chart_areas> areas; // per chart, measured once it is flattened
  auto cut_if_needed = [&](std::size_t c) {
    if(charts[c].ok && charts[c].l2 <= settings.max_stretch) { // kept
      if(charts[c].slits_closed) // its map glues its slits: no seam there
        for(const auto& slit : charts[c].slits)
          g.close_slit(slit.first);
      return;
    }
    const std::vector<std::size_t> triangles = charts[c].triangles;
    const std::size_t units = units_of(triangles);
    if(units < 2) {
      if(charts[c].ok)
        return;
      std::vector<int> ids(triangles.size(), int(c));
      for(std::size_t i = 1; i < triangles.size(); ++i)
        ids[i] = int(charts.size() + i - 1);
      g.separate(triangles, ids);
      for(std::size_t i = 0; i < triangles.size(); ++i) {
        Chart_map single;
        single.triangles = {triangles[i]};
        make_chart_vertices(m, g, single);
        layout_single_triangle(single);
        single.ok = true;
        single.l2 = 1.;
        if(i == 0) { charts[c] = single; areas[c] = chart_areas(single); }
        else { charts.push_back(single); angle.push_back(0.); members.emplace_back(); }
      }
      return;
    }
    const auto t1 = std::chrono::steady_clock::now();
    const int parts = charts[c].ok ? number_of_parts(charts[c].l2, settings.max_stretch) : 0;
    if(parts > 2 && split(c, partition_chart(charts[c], parts), parts, false)) {
      r.seconds_cutting += seconds_since(t1);
      return;
    }
    if(charts[c].ok) {
      const Chart_areas& a = areas[c];
      std::vector<double> along;
      chart_length(charts[c].uv, charts[c].flat.tri, a.uv, a.surface, along);
      if(cut_across(c, along, false)) {
        r.seconds_cutting += seconds_since(t1);
        return;
      }
    }
    allowed.assign(nt, 0);
    for(std::size_t t : triangles) allowed[t] = 1;
    const double a = angle[c] * 0.6;
    const int first = int(charts.size());
    const int made = g.grow(allowed, first, a, (units + 1) / 2, 2);
    collect(first, made, triangles);
    charts.resize(std::size_t(first + made));
    angle.resize(std::size_t(first + made), a);
    charts[c] = Chart_map(); // emptied: its triangles are in the new charts
    r.seconds_cutting += seconds_since(t1);
  };
  // flattens the charts from `begin` on, and the ones they are cut into, a batch at a time:
  // the charts of a batch on several threads (the corners' union-find is shared: the chart
  // vertices are numbered before), then their cuts in order; told to the visitor if `visit`
  const unsigned int threads = thread_count(settings.threads);
  const std::size_t chunk = 64 * std::size_t(threads); // charts between two visits of the visitor
  std::size_t flattened = 0;
  // (`known`: maps flattened before; a chart whose input is one of theirs takes its map as it is)
  auto settle = [&](std::size_t begin, bool visit, const Chart_parameterization_settings& chart_settings,
                    const std::vector<Chart_map>& known = std::vector<Chart_map>()) {
    for(std::size_t end = begin; begin < charts.size(); begin = end) {
      end = (std::min)(charts.size(), begin + chunk);
      auto t1 = std::chrono::steady_clock::now();
      for(std::size_t c = begin; c < end; ++c) {
        if(charts[c].triangles.empty())
          charts[c].triangles = members[c];
        make_chart_vertices(m, g, charts[c]);
      }
      const std::vector<std::size_t> order = largest_first(charts, begin, end);
      const Chart_parameterization_settings first = first_in_batch(charts, order, chart_settings, threads);
      areas.resize(charts.size());
      parallel_for_each(order.size(), threads, [&](std::size_t i) {
        Chart_map& chart = charts[order[i]];
        const auto same =
            std::find_if(known.begin(), known.end(), [&chart](const Chart_map& k) { return same_input(k, chart); });
        if(same != known.end())
          chart = *same;
        else
          flatten_chart(chart, i == 0 ? first : chart_settings);
        areas[order[i]] = chart.ok ? chart_areas(chart) : Chart_areas(); // a failed chart has no uv
      });
      r.seconds_parameterization += seconds_since(t1);
      flattened += end - begin;
      for(std::size_t c = begin; c < end; ++c)
        cut_if_needed(c);
      if(visit)
        settings.tell(Atlas_stage::FLATTENING, flattened, flattened + charts.size() - end);
    }
  };
  // Until the charts are joined, a map within the bound is left unpolished (the charts joined
  // are flattened again as one): the charts that remain are polished once, after the joins.
  Chart_parameterization_settings deferring = settings.chart;
  deferring.defer_polish = true;
  settle(0, true, deferring);

  // neighbouring charts joined where their union flattens within the bound
  {
    const auto t1 = std::chrono::steady_clock::now();
    join_charts(m, g, charts, deferring, settings.join_rounds, threads);
    std::vector<std::size_t> pending;
    for(std::size_t c = 0; c < charts.size(); ++c)
      if(charts[c].deferred.pending)
        pending.push_back(c);
    pending = largest_first(charts, std::move(pending));
    const Chart_parameterization_settings first = first_in_batch(charts, pending, settings.chart, threads);
    parallel_for_each(pending.size(), threads, [&](std::size_t i) {
      finish_polish(charts[pending[i]], i == 0 ? first : settings.chart);
    });
    for(std::size_t c = 0; c < charts.size(); ++c) // the joined ones, and the polished ones
      areas[c] = charts[c].triangles.empty() || !charts[c].ok ? Chart_areas() : chart_areas(charts[c]);
    r.seconds_parameterization += seconds_since(t1);
  }
  // the bent strips among the charts from `begin` on laid out straight (Strip_straightening.h)
  auto straighten = [&](std::size_t begin) {
    const auto t1 = std::chrono::steady_clock::now();
    parallel_for_each(charts.size() - begin, threads, [&](std::size_t i) {
      Chart_map& chart = charts[begin + i];
      if(!chart.triangles.empty() && straighten_strip(chart, settings.max_stretch))
        areas[begin + i] = chart_areas(chart);
    });
    r.seconds_parameterization += seconds_since(t1);
  };
  straighten(0);
  // undoes the split of chart c: the charts from `before` on dropped, c's map and the growing
  // as they were
  auto take_back = [&](std::size_t c, std::size_t before, Chart_map& whole, Chart_growing::Snapshot& growing) {
    charts.resize(before);
    members.resize(before);
    angle.resize(before);
    areas.resize(before);
    charts[c] = std::move(whole);
    g.restore(std::move(growing));
  };
  // the thin charts that stay bent cut at their sharp turns (strip_turn_cut()), and their pieces
  // in turn, where the pieces' smallest rectangles take less room than the chart's: the straight
  // pieces of a band with corners then pack where its hollow was left unused
  auto room = [&](std::size_t c) { // of chart c's smallest rectangle, in surface units
    std::vector<Vec2> turned = charts[c].uv;
    const Vec2 extent = align_chart(turned);
    return areas[c].uv > 0. ? extent[0] * extent[1] * areas[c].surface / areas[c].uv : 0.;
  };
  for(std::size_t c = 0; c < charts.size(); ++c) {
    std::vector<int> part;
    int parts = 0;
    if(charts[c].triangles.empty() || !strip_turn_cut(charts[c], part, parts))
      continue;
    const std::size_t before = charts.size();
    const double whole_room = room(c);
    Chart_map whole = charts[c];
    Chart_growing::Snapshot growing = g.snapshot();
    const auto t1 = std::chrono::steady_clock::now();
    const bool parted = split(c, part, parts, true);
    r.seconds_cutting += seconds_since(t1);
    if(!parted)
      continue;
    settle(before, false, settings.chart);
    straighten(before);
    // kept if the pieces are flattened within the bound as they are (not cut further)
    double pieces_room = 0.;
    int pieces = 0;
    bool flattened = true;
    for(std::size_t k = before; k < charts.size(); ++k)
      if(!charts[k].triangles.empty()) {
        flattened = flattened && charts[k].ok;
        pieces_room += room(k);
        ++pieces;
      }
    if(!(flattened && pieces == parts && pieces_room < 0.9 * whole_room))
      take_back(c, before, whole, growing);
  }

  // pack the charts that hold triangles; while a coarse packing fills the square poorly, the
  // longest chart (the one that leaves the most room unused around it) is cut across. A cut
  // that does not fill the square better is taken back (its seam would buy nothing) and the
  // next longest chart is tried, until every chart was: then the longest is cut all the same.
  auto t2 = std::chrono::steady_clock::now();
  const double other_stages = r.seconds_cutting + r.seconds_parameterization;
  std::vector<std::size_t> kept;
  std::vector<std::vector<Vec2> > uv;
  std::vector<std::vector<Triangle> > chart_triangles;
  std::vector<double> area_uv, area_3d;
  auto gather = [&]() {
    kept.clear();
    uv.clear();
    chart_triangles.clear();
    area_uv.clear();
    area_3d.clear();
    for(std::size_t c = 0; c < charts.size(); ++c) {
      if(charts[c].triangles.empty()) continue;
      kept.push_back(c);
      area_uv.push_back(areas[c].uv);
      area_3d.push_back(areas[c].surface);
      uv.push_back(charts[c].uv);
      chart_triangles.push_back(charts[c].flat.tri);
    }
  };
  double scale_hint = 0.;
  // the coarse packing, or the final one once the coarse one was found too hopeful; a final
  // packing is kept (`trial`) until the round knows whether its cut stays (`accepted`)
  bool final_estimates = false;
  std::vector<std::vector<Vec2> > trial_uv, accepted_uv;
  Packing_result trial, accepted;
  // a coarse packing and the charts made ready for it: of the last charts estimated
  // (`estimated`), and of the charts as they stand (`current`), where the final packing starts
  struct Coarse_packing
  {
    Packing_input input;
    Packing_result layout;
    bool valid = false;
  } estimated, current;
  auto estimated_utilization = [&]() {
    std::vector<std::vector<Vec2> > turned = uv;
    if(final_estimates) {
      trial = pack_charts(turned, chart_triangles, area_uv, area_3d, settings.packing, scale_hint);
      trial_uv.swap(turned);
      return trial.utilization;
    }
    estimated.input = prepare_packing(turned, chart_triangles, area_uv, area_3d, settings.packing.threads);
    estimated.layout = estimate_packing(estimated.input, settings.packing, scale_hint);
    estimated.valid = true;
    scale_hint = estimated.layout.scale;
    return estimated.layout.utilization;
  };
  gather();
  const int rounds = settings.packing.max_cut_rounds;
  double utilization = rounds > 0 ? estimated_utilization() : 0.;
  current = std::move(estimated);
  std::vector<char> tried, uncuttable; // per chart: its cut was taken back; it cannot be cut
  // the longest chart that may be cut (kept.size() if none), among those not tried if `untried`
  auto longest_chart = [&](bool untried, std::vector<double>& best_along) {
    double longest = 0.;
    std::size_t cut = kept.size();
    std::vector<double> along;
    for(std::size_t i = 0; i < kept.size(); ++i)
      if(!uncuttable[kept[i]] && !(untried && tried[kept[i]]) && units_of(charts[kept[i]].triangles) >= 2) {
        const double l = chart_length(charts[kept[i]].uv, chart_triangles[i], area_uv[i], area_3d[i], along);
        if(l > longest) { longest = l; cut = i; best_along.swap(along); }
      }
    return cut;
  };
  // rounds count the cuts kept; the cuts taken back are bounded too (each flattens a chart's halves)
  int round = 0, taken_back = 0;
  // per chart, the maps of its halves when its cut was taken back: the same cut tried again
  // (forced, or after other cuts) finds the same halves, whose maps are then taken as they are
  std::map<std::size_t, std::vector<Chart_map> > halves_taken_back;
  // The charts before a forced cut: the cut may fill the square worse, and the cuts after it
  // need not make up for that. The rounds end with the charts that filled it best (of those
  // before each forced cut and those the rounds end with): a seam that fills it worse buys nothing.
  struct Cut_state
  {
    double utilization = -1.;
    std::vector<Chart_map> charts;
    std::vector<std::vector<std::size_t> > members;
    std::vector<double> angle;
    std::vector<Chart_areas> areas;
    Chart_growing::Snapshot growing;
    Coarse_packing current;                       // (coarse estimates)
    Packing_result accepted;                      // (final packings)
    std::vector<std::vector<Vec2> > accepted_uv;
  };
  auto cut_rounds = [&]() {
    Cut_state best;
    auto keep_best = [&]() {
      if(!(utilization > best.utilization))
        return;
      best.utilization = utilization;
      best.charts = charts;
      best.members = members;
      best.angle = angle;
      best.areas = areas;
      best.growing = g.snapshot();
      if(final_estimates) {
        best.accepted = accepted;
        best.accepted_uv = accepted_uv;
      } else {
        best.current = current;
      }
    };
    while(round < rounds && taken_back < 2 * rounds && utilization < settings.packing.goal) {
      settings.tell(Atlas_stage::PACKING, std::size_t(round), std::size_t(rounds) + 1);
      tried.resize(charts.size(), 0);
      uncuttable.resize(charts.size(), 0);
      // when every cut was taken back, the longest chart is cut all the same
      std::vector<double> along;
      std::size_t cut = longest_chart(true, along);
      const bool forced = cut == kept.size();
      if(forced)
        cut = longest_chart(false, along);
      if(cut == kept.size())
        break;
      if(forced)
        keep_best();
      const std::size_t c = kept[cut], before = charts.size();
      Chart_map whole = charts[c];
      Chart_growing::Snapshot growing = g.snapshot();
      const auto t3 = std::chrono::steady_clock::now();
      // the chart is within the bound, and may be a union of joined charts: its halves are
      // kept whole, not grown again in the normal cone, which would undo the joins
      cut_across(c, along, true);
      r.seconds_cutting += seconds_since(t3);
      if(charts.size() == before) {
        uncuttable[c] = 1;
        continue;
      }
      settle(before, false, settings.chart, halves_taken_back[c]); // told as packing rounds
      straighten(before);
      gather();
      const double after = estimated_utilization();
      // better by more than the rounding of the charts' areas: those add up to the surface's
      // area whatever the cuts, so a packing of the same scale and side fills the square as
      // before, and another scale or side changes the filling by far more than this
      if(forced || after > utilization * (1. + 1e-4)) {
        halves_taken_back.erase(c);
        utilization = after;
        if(final_estimates) {
          accepted = trial;
          accepted_uv.swap(trial_uv);
        } else {
          current = std::move(estimated);
        }
        if(forced)
          tried.assign(tried.size(), 0); // the others may fill the square better now
        ++round;
        continue;
      }
      halves_taken_back[c].assign(std::make_move_iterator(charts.begin() + std::ptrdiff_t(before)),
                                  std::make_move_iterator(charts.end()));
      take_back(c, before, whole, growing);
      gather();
      tried[c] = 1;
      ++taken_back;
    }
    // (better by more than the rounding of the areas, as a cut kept above)
    if(best.utilization > utilization * (1. + 1e-4)) {
      utilization = best.utilization;
      charts = std::move(best.charts);
      members = std::move(best.members);
      angle = std::move(best.angle);
      areas = std::move(best.areas);
      g.restore(std::move(best.growing));
      if(final_estimates) {
        accepted = std::move(best.accepted);
        accepted_uv = std::move(best.accepted_uv);
      } else {
        current = std::move(best.current);
      }
      gather();
    }
  };
  cut_rounds();
  Packing_result packed;
  if(current.valid) { // the charts as they were last estimated: packed from that estimate
    current.input.tri = &chart_triangles;
    packed = pack_prepared(current.input, current.layout, settings.packing, uv);
  } else {
    packed = pack_charts(uv, chart_triangles, area_uv, area_3d, settings.packing, scale_hint);
  }
  if(utilization >= settings.packing.goal && packed.utilization < settings.packing.goal) {
    // the coarse packing was too hopeful (its cells are coarser, and the gutter can round to
    // none of them): the rounds go on, measured by the final packing
    final_estimates = true;
    utilization = packed.utilization;
    accepted = packed;
    accepted_uv.swap(uv);
    tried.assign(tried.size(), 0);
    gather();
    cut_rounds();
    // a cut taken back restores the charts of the last one kept: their packing is `accepted`
    packed = accepted;
    uv.swap(accepted_uv);
  }
  // The packing rounds the charts' uv: a face that a chart's map squashed to about that
  // rounding (LSCM's map of a needle, kept without a polish) can come out flipped. Such a
  // chart is taken as one that could not be flattened (grown again smaller, or, if it is one
  // polygon, its triangles laid out alone: those keep their orientation), and all are packed again.
  // (A bound on the passes all the same: each takes the flipped charts further apart.)
  // Likewise a chart whose border crosses or runs along itself once packed (a map within the
  // bound that closes the angle at a border vertex to the last digit: the packing's rounding
  // can push one side into the other). Not a chart without an area to speak of (a speck of a
  // mesh far larger, whose triangles the rounding lays on a line): it covers nothing.
  std::vector<std::size_t> flipped, measured_faces;
  auto measure_packed = [&]() {
    Flat_stretch_summary s = measure_packed_charts(charts, kept, uv, flipped, measured_faces);
    for(std::size_t i = 0; i < kept.size(); ++i)
      if(flipped[i] == 0 && measured_faces[i] > 0 && !outline_is_simple(uv[i], chart_outline(chart_triangles[i])))
        flipped[i] = 1;
    return s;
  };
  Flat_stretch_summary measured = measure_packed();
  auto any_flipped = [&flipped]() { return std::any_of(flipped.begin(), flipped.end(), [](std::size_t f) { return f > 0; }); };
  for(int pass = 0; pass < 64 && any_flipped(); ++pass) {
    const std::size_t before = charts.size();
    for(std::size_t i = 0; i < kept.size(); ++i)
      if(flipped[i] > 0) {
        charts[kept[i]].ok = false;
        cut_if_needed(kept[i]);
      }
    settle(before, false, settings.chart);
    straighten(before);
    gather();
    packed = pack_charts(uv, chart_triangles, area_uv, area_3d, settings.packing, scale_hint);
    measured = measure_packed();
  }
  settings.tell(Atlas_stage::PACKING, std::size_t(round) + 1, std::size_t(round) + 1);
  r.utilization = packed.utilization;
  r.charts = kept.size();
  r.seconds_packing = seconds_since(t2) - (r.seconds_cutting + r.seconds_parameterization - other_stages);

  // per polygon corner, in the input's order
  atlas.chart.assign(number_of_polygons, 0);
  corner_written.resize(number_of_polygons);
  for(std::size_t p = 0; p < number_of_polygons; ++p)
    corner_written[p].assign(atlas.uv[p].size(), 0);
  for(std::size_t i = 0; i < kept.size(); ++i) {
    const Chart_map& chart = charts[kept[i]];
    for(std::size_t j = 0; j < chart.triangles.size(); ++j) {
      const std::size_t t = chart.triangles[j];
      const std::size_t p = m.polygon[t];
      atlas.chart[p] = i;
      for(int k = 0; k < 3; ++k) {
        const Vec2& q = uv[i][std::size_t(chart.corner_vertex[3 * j + std::size_t(k)])];
        const std::size_t corner = std::size_t(m.corner[t][std::size_t(k)]);
        atlas.uv[p][corner] = q;
        corner_written[p][corner] = 1;
        vertex_uv.emplace(m.vertex[t][std::size_t(k)], q);
      }
    }
  }
  // polygons without area are in chart 0: with no other polygon, chart 0 holds them alone
  r.charts = (std::max)(kept.size(), std::size_t(number_of_polygons > 0 ? 1 : 0));

  r.l2_stretch = measured.l2;
  r.linf_stretch = measured.linf;
  r.flipped_faces = 0;
  for(std::size_t f : flipped)
    r.flipped_faces += f;

  // seams: edges of two or more sides that are not one glued pair, among the sides of the
  // input's polygons (the diagonals that split them are no edges of the input)
  std::unordered_map<std::pair<int, int>, std::pair<int, int>, Edge_hash> edges; // sides, glued sides
  for(std::size_t t = 0; t < nt; ++t)
    for(int k = 0; k < 3; ++k) {
      const std::size_t size = atlas.uv[m.polygon[t]].size();
      const std::size_t ca = std::size_t(m.corner[t][std::size_t(k)]), cb = std::size_t(m.corner[t][std::size_t((k + 1) % 3)]);
      if(cb != (ca + 1) % size && ca != (cb + 1) % size)
        continue;
      const int a = m.vertex[t][std::size_t(k)], b = m.vertex[t][std::size_t((k + 1) % 3)];
      auto& e = edges[std::make_pair((std::min)(a, b), (std::max)(a, b))];
      ++e.first;
      e.second += g.glued(int(3 * t) + k);
    }
  for(const auto& e : edges) {
    const double l = m.length_unit * norm3(sub3(m.xyz[std::size_t(e.first.first)], m.xyz[std::size_t(e.first.second)]));
    r.edge_length += l;
    if(e.second.first >= 2 && !(e.second.first == 2 && e.second.second == 2))
      r.seam_length += l;
  }
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_BUILD_ATLAS_H

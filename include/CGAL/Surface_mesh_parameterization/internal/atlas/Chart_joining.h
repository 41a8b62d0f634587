// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_JOINING_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_JOINING_H

// Flattened charts joined to their neighbours while the union flattens within the stretch bound
// from the cheap starts (LSCM's map, with the union's slits closed or its holes filled): the
// charts are grown along curvature and cut for their stretch, which places seams where no
// stretch asks for them.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/atlas/Atlas_input.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_growing.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_parameterization.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// Joins the flattened `charts` (chart c holds the triangles of chart c of `g`) in up to `rounds`
// rounds of disjoint pairs, so that the unions of a round flatten on `threads` threads at once
// and the result does not depend on their number. Pairs are tried by the seam length they share
// per triangle of their union, the most first; a union above the bound is taken back (`g` as it
// was) and its pair not tried again; the unions tried hold at most as many triangles as the mesh
// (10^4 at least), so that joining costs about one more flattening of the charts. A joined chart
// b is emptied into chart a. Charts that hold part of a polygon (one laid out by triangles) are
// not joined.
inline void join_charts(const Atlas_triangles& m, Chart_growing& g, std::vector<Chart_map>& charts,
                        const Chart_parameterization_settings& settings, int rounds, unsigned int threads)
{
  std::set<std::pair<int, int> > failed;
  std::size_t budget = (std::max)(m.vertex.size(), std::size_t(10000));
  // a union of two joinable charts is joinable: found once
  std::vector<char> joinable(charts.size());
  for(std::size_t c = 0; c < charts.size(); ++c)
    joinable[c] = g.whole_units(charts[c].triangles);
  for(int round = 0; round < rounds; ++round) {
    // the length of the seams between two charts, by pair
    std::map<std::pair<int, int>, double> shared;
    for(std::size_t c = 0; c < charts.size(); ++c)
      if(charts[c].ok && joinable[c])
        for(std::size_t t : charts[c].triangles)
          for(int k = 0; k < 3; ++k) {
            const int side = int(3 * t) + k, mate = g.mate(side);
            const int d = mate < 0 || g.glued(side) ? -1 : g.chart(std::size_t(mate / 3));
            if(d > int(c) && charts[std::size_t(d)].ok && joinable[std::size_t(d)])
              shared[std::make_pair(int(c), d)] += norm3(sub3(m.xyz[std::size_t(m.vertex[t][std::size_t(k)])],
                                                             m.xyz[std::size_t(m.vertex[t][std::size_t((k + 1) % 3)])]));
          }
    std::vector<std::pair<double, std::pair<int, int> > > candidates;
    for(const auto& e : shared)
      if(!failed.count(e.first))
        candidates.emplace_back(-e.second / double(charts[std::size_t(e.first.first)].triangles.size() +
                                                   charts[std::size_t(e.first.second)].triangles.size()),
                                e.first);
    std::sort(candidates.begin(), candidates.end());
    std::vector<char> busy(charts.size(), 0);
    std::vector<std::pair<int, int> > pairs;
    for(const auto& e : candidates) {
      const std::size_t a = std::size_t(e.second.first), b = std::size_t(e.second.second);
      const std::size_t size = charts[a].triangles.size() + charts[b].triangles.size();
      if(busy[a] || busy[b] || size > budget)
        continue;
      budget -= size;
      busy[a] = busy[b] = 1;
      pairs.push_back(e.second);
    }
    if(pairs.empty())
      break;
    // glued one after the other (the pairs share no corner), flattened at once
    std::vector<Chart_growing::Join_record> records;
    std::vector<Chart_map> unions(pairs.size());
    for(std::size_t i = 0; i < pairs.size(); ++i) {
      const Chart_map &a = charts[std::size_t(pairs[i].first)], &b = charts[std::size_t(pairs[i].second)];
      records.push_back(g.join(a.triangles, b.triangles, pairs[i].first));
      unions[i].triangles = a.triangles;
      unions[i].triangles.insert(unions[i].triangles.end(), b.triangles.begin(), b.triangles.end());
      std::sort(unions[i].triangles.begin(), unions[i].triangles.end()); // a polygon's triangles in a row
      make_chart_vertices(m, g, unions[i]);
    }
    const std::vector<std::size_t> order = largest_first(unions, 0, unions.size());
    const Chart_parameterization_settings first = first_in_batch(unions, order, settings, threads);
    parallel_for_each(order.size(), threads, [&](std::size_t k) {
      flatten_chart(unions[order[k]], k == 0 ? first : settings, false);
    });
    bool any = false;
    for(std::size_t i = 0; i < pairs.size(); ++i) {
      const std::size_t a = std::size_t(pairs[i].first), b = std::size_t(pairs[i].second);
      if(unions[i].ok && unions[i].l2 <= settings.max_stretch) {
        if(unions[i].slits_closed) // its map glues its slits: no seam there
          for(const auto& slit : unions[i].slits)
            g.close_slit(slit.first);
        charts[a] = std::move(unions[i]);
        charts[b] = Chart_map();
        any = true;
      } else {
        g.undo(records[i]);
        failed.insert(pairs[i]);
      }
    }
    if(!any)
      break;
  }
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_JOINING_H

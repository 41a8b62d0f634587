// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_PARTITION_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_PARTITION_H

// A flattened chart far above the stretch bound cut into several compact parts at once, rather
// than halved again and again (each halving flattens all its triangles once more).

#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_parameterization.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/sort_by_vertex.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// How many parts a chart of normalized L2 stretch `l2` is cut into so that its parts may meet
// `bound`: the area distortion that a curved patch forces grows with its area, and the stretch
// in excess of 1 about as its square, so k parts of a k-th of the area each have about a k^2-th
// of the excess. Rounded down (a part still above the bound is cut again; one part too many is
// a seam too many), at most 16; 2 means: halve it.
inline int number_of_parts(double l2, double bound)
{
  const double excess = l2 - 1., allowed = bound - 1.;
  if(!(excess > 0.) || !(allowed > 0.) || !std::isfinite(excess))
    return 2;
  const double k = std::floor(std::sqrt(excess / allowed)); // beyond int (even +inf) near a bound of 1
  return k >= 16. ? 16 : (std::max)(2, int(k));
}

// A part (0 to `parts` - 1) for each triangle of the flattened `chart`: Lloyd's iterations
// (k-means) on the triangles' uv centroids weighted by their surface area, from seeds spread by
// farthest-point sampling, so that the parts are compact (short seams between them).
inline std::vector<int> partition_chart(const Chart_map& chart, int parts)
{
  const std::size_t n = chart.flat.tri.size(), k = std::size_t((std::max)(parts, 1));
  std::vector<Vec2> centroid(n);
  std::vector<double> weight(n);
  for(std::size_t i = 0; i < n; ++i) {
    const Triangle& t = chart.flat.tri[i];
    const Vec2 &a = chart.uv[std::size_t(t[0])], &b = chart.uv[std::size_t(t[1])], &c = chart.uv[std::size_t(t[2])];
    centroid[i] = {(a[0] + b[0] + c[0]) / 3., (a[1] + b[1] + c[1]) / 3.};
    weight[i] = triangle_area(chart.flat.xyz[std::size_t(t[0])], chart.flat.xyz[std::size_t(t[1])],
                              chart.flat.xyz[std::size_t(t[2])]);
  }
  auto squared_distance = [](const Vec2& p, const Vec2& q) {
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
  };
  std::vector<int> label(n, 0);
  if(n == 0)
    return label;
  std::vector<Vec2> center{centroid[0]};
  std::vector<double> nearest(n, HUGE_VAL);
  while(center.size() < k) {
    std::size_t farthest = 0;
    for(std::size_t i = 0; i < n; ++i) {
      nearest[i] = (std::min)(nearest[i], squared_distance(centroid[i], center.back()));
      if(nearest[i] > nearest[farthest]) farthest = i;
    }
    center.push_back(centroid[farthest]);
  }
  // a few iterations place the centers; the labels need not be a converged k-means
  for(int iteration = 0; iteration < 10; ++iteration) {
    for(std::size_t i = 0; i < n; ++i) {
      double best = HUGE_VAL;
      for(std::size_t j = 0; j < k; ++j) {
        const double d = squared_distance(centroid[i], center[j]);
        if(d < best) { best = d; label[i] = int(j); }
      }
    }
    std::vector<Vec2> sum(k, Vec2{0., 0.});
    std::vector<double> total(k, 0.);
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = std::size_t(label[i]);
      sum[j] = {sum[j][0] + weight[i] * centroid[i][0], sum[j][1] + weight[i] * centroid[i][1]};
      total[j] += weight[i];
    }
    for(std::size_t j = 0; j < k; ++j)
      if(total[j] > 0.) center[j] = {sum[j][0] / total[j], sum[j][1] / total[j]};
  }
  return label;
}

// A side two triangles of a chart share: the triangles and the two vertices.
struct Shared_side
{
  int t0, t1, a, b;
};

// The sides the triangles of `chart` share (pairs of sides of the same edge), each once.
inline std::vector<Shared_side> shared_sides(const Flat_triangles& chart)
{
  const std::size_t n = chart.tri.size();
  std::vector<std::array<int, 3> > side_key; // smaller vertex, larger vertex, triangle
  side_key.reserve(3 * n);
  for(std::size_t t = 0; t < n; ++t)
    for(int k = 0; k < 3; ++k) {
      const int a = chart.tri[t][std::size_t(k)], b = chart.tri[t][std::size_t((k + 1) % 3)];
      side_key.push_back({(std::min)(a, b), (std::max)(a, b), int(t)});
    }
  sort_by_vertex(side_key, [](const std::array<int, 3>& k) { return k[0]; });
  std::vector<Shared_side> shared;
  for(std::size_t i = 0; i + 1 < side_key.size(); ++i)
    if(side_key[i][0] == side_key[i + 1][0] && side_key[i][1] == side_key[i + 1][1])
      shared.push_back({side_key[i][2], side_key[i + 1][2], side_key[i][0], side_key[i][1]});
  return shared;
}

// Per triangle of `chart`, the triangles of the chart across its sides.
inline std::vector<std::vector<int> > triangles_across(const Flat_triangles& chart)
{
  std::vector<std::vector<int> > across(chart.tri.size());
  for(const Shared_side& s : shared_sides(chart)) {
    across[std::size_t(s.t0)].push_back(s.t1);
    across[std::size_t(s.t1)].push_back(s.t0);
  }
  return across;
}

// Gives each piece of a part that is cut off from the part's largest piece (through the edges
// of the chart, `across` = triangles_across() of it) to the neighbouring part whose largest
// piece it shares the most edges with, until every part is in one piece (pieces that no other
// part touches stay). Parts chosen in the uv plane can hold pieces that a hole or a fold of the
// chart keeps apart on the surface, and each such piece would become a chart of its own, seams
// all around.
inline void join_detached_pieces(const std::vector<std::vector<int> >& across, std::vector<int>& part)
{
  const std::size_t n = across.size();
  // the largest pieces keep their part and only grow: each round joins at least one piece to
  // one of them, or ends
  for(bool changed = true; changed;) {
    changed = false;
    std::vector<int> piece(n, -1);
    std::vector<std::vector<int> > pieces;
    for(std::size_t seed = 0; seed < n; ++seed) {
      if(piece[seed] >= 0) continue;
      pieces.emplace_back(1, int(seed));
      piece[seed] = int(pieces.size() - 1);
      for(std::size_t i = 0; i < pieces.back().size(); ++i)
        for(int u : across[std::size_t(pieces.back()[i])])
          if(piece[std::size_t(u)] < 0 && part[std::size_t(u)] == part[seed]) {
            piece[std::size_t(u)] = piece[seed];
            pieces.back().push_back(u);
          }
    }
    std::unordered_map<int, std::size_t> largest; // part -> its largest piece (the first, on ties)
    for(std::size_t p = 0; p < pieces.size(); ++p) {
      const int label = part[std::size_t(pieces[p][0])];
      const auto it = largest.find(label);
      if(it == largest.end() || pieces[p].size() > pieces[it->second].size())
        largest[label] = p;
    }
    std::vector<char> anchored(pieces.size(), 0);
    for(const auto& l : largest) anchored[l.second] = 1;
    for(std::size_t p = 0; p < pieces.size(); ++p) {
      if(anchored[p]) continue;
      const int label = part[std::size_t(pieces[p][0])];
      std::map<int, std::size_t> shared; // neighbouring part -> sides shared with its largest piece
      for(int t : pieces[p])
        for(int u : across[std::size_t(t)])
          if(anchored[std::size_t(piece[std::size_t(u)])] && part[std::size_t(u)] != label)
            ++shared[part[std::size_t(u)]];
      if(shared.empty()) continue;
      const auto most = std::max_element(shared.begin(), shared.end(), [](const auto& x, const auto& y) {
        return x.second < y.second;
      });
      for(int t : pieces[p]) part[std::size_t(t)] = most->first;
      changed = true;
    }
  }
}

// Cosine of the largest angle between the normal of a planar region's first triangle and those
// of its other triangles (see snap_planar_regions()).
constexpr double planar_region_cosine = 0.99996192306; // cos(0.5 degree)

// Gives each planar region of the chart `chart` that `part` cuts (triangles joined through
// the chart's edges, `across` = triangles_across() of it, their normals within
// planar_region_cosine of the region's first) whole to the part that holds most of its area, as
// long as two parts or more keep triangles. A plane flattens without stretch whatever its
// outline, so a seam across it buys nothing, while the edges around it (a model's creases,
// mostly) are where a seam costs least.
inline void snap_planar_regions(const Flat_triangles& chart, const std::vector<std::vector<int> >& across,
                                std::vector<int>& part)
{
  const std::size_t n = chart.tri.size();
  std::vector<Vec3> normal(n);
  std::vector<double> area(n);
  for(std::size_t t = 0; t < n; ++t) {
    const Vec3 &a = chart.xyz[std::size_t(chart.tri[t][0])], &b = chart.xyz[std::size_t(chart.tri[t][1])],
               &c = chart.xyz[std::size_t(chart.tri[t][2])];
    normal[t] = cross3(sub3(b, a), sub3(c, a));
    area[t] = 0.5 * norm3(normal[t]);
  }
  const auto coplanar = [&](std::size_t t, const Vec3& seed, double seed_area) {
    return area[t] > 0. && dot3(normal[t], seed) >= planar_region_cosine * 2. * area[t] * 2. * seed_area;
  };
  std::vector<int> snapped = part;
  std::vector<char> seen(n, 0);
  std::vector<int> region;
  std::map<int, double> share; // part -> its area in the region
  for(std::size_t seed = 0; seed < n; ++seed) {
    if(seen[seed] || !(area[seed] > 0.)) continue;
    region.assign(1, int(seed));
    seen[seed] = 1;
    for(std::size_t i = 0; i < region.size(); ++i)
      for(int u : across[std::size_t(region[i])])
        if(!seen[std::size_t(u)] && coplanar(std::size_t(u), normal[seed], area[seed])) {
          seen[std::size_t(u)] = 1;
          region.push_back(u);
        }
    share.clear();
    for(int t : region) share[part[std::size_t(t)]] += area[std::size_t(t)];
    if(share.size() < 2) continue;
    const auto most = std::max_element(share.begin(), share.end(), [](const auto& x, const auto& y) {
      return x.second < y.second;
    });
    for(int t : region) snapped[std::size_t(t)] = most->first;
  }
  if(std::any_of(snapped.begin(), snapped.end(), [&snapped](int p) { return p != snapped.front(); }))
    part.swap(snapped);
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_PARTITION_H

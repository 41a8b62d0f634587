// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_RING_WEIGHTS_H
#define CGAL_SMP_INTERNAL_RING_WEIGHTS_H

// Clamped cotangent start weights (mean-value weights are beside Floater's, which fall back on
// them). Positive, so Tutte's theorem holds for their system.

#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/shape_preserving_weights.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Relative floor of the clamped cotangent weights: a weight below this fraction of the mean
// absolute cotangent weight of its ring (or of its neighbour's, if larger) is raised to it.
// Small enough to leave the weights of well-shaped rings unchanged, large enough to keep the
// matrix an M-matrix.
constexpr double cotangent_floor = 1e-2;

// Cotangent (discrete harmonic) weights cot(alpha) + cot(beta) of the ring, unclamped, and the
// mean of their absolute values. False if a face of the ring has zero area (a cotangent is
// then infinite).
inline bool cotangent_ring_weights(const Vec3& center, const std::vector<Vec3>& ring,
                                   std::vector<double>& weights, double& mean)
{
  const std::size_t d = ring.size();
  weights.assign(d, 0.);
  mean = 0.;
  if(d < 3)
    return false;
  // cot of the angle at `apex` in the triangle (center, a, apex): the same bits from either end
  // of the edge (center, a), since swapping u and v changes neither the dot product nor the
  // norm of the cross product
  auto cot = [&center](const Vec3& apex, const Vec3& a, bool& ok) {
    const Vec3 u = sub3(center, apex), v = sub3(a, apex);
    const double s = norm3(cross3(u, v));
    ok = ok && s > 1e-12 * norm3(u) * norm3(v) && std::isfinite(s);
    return dot3(u, v) / s;
  };
  bool ok = true;
  for(std::size_t k = 0; k < d; ++k) {
    weights[k] = cot(ring[(k + d - 1) % d], ring[k], ok) + cot(ring[(k + 1) % d], ring[k], ok);
    mean += std::abs(weights[k]) / double(d);
  }
  return ok && mean > 0. && std::isfinite(mean);
}

// Clamped cotangent start weights of every row of `dc`, in its ring order: the cotangent weight
// of each edge raised to at least `cotangent_floor` times the mean absolute cotangent weight of
// its ring, or of the neighbour's ring where that is larger. An edge between two interior
// vertices so gets the same weight from both ends, and the system is symmetric: `symmetric`
// tells whether it is. A ring with a face of zero area gets mean-value weights (normalized to
// sum 1: rows are scaled freely), which are not symmetric. False if a ring has neither.
inline bool clamped_cotangent_weights(const Disk_component_base& dc, std::vector<double>& w, bool& symmetric)
{
  const std::size_t rows = dc.number_of_rows();
  w.assign(dc.ring.size(), 0.);
  std::vector<double> mean(rows, -1.); // -1: mean-value weights
  std::vector<Vec3> ring;
  std::vector<double> ring_w;
  symmetric = true;
  for(std::size_t r = 0; r < rows; ++r) {
    const int first = dc.ring_begin[r], last = dc.ring_begin[r + 1];
    ring.clear();
    for(int e = first; e < last; ++e)
      ring.push_back(dc.flat.xyz[dc.ring[e]]);
    const Vec3& center = dc.flat.xyz[dc.interior[r]];
    if(!cotangent_ring_weights(center, ring, ring_w, mean[r])) {
      mean[r] = -1.;
      symmetric = false;
      if(!mean_value_ring_weights(center, ring, ring_w))
        return false;
    }
    std::copy(ring_w.begin(), ring_w.end(), w.begin() + first);
  }
  for(std::size_t r = 0; r < rows; ++r) {
    if(mean[r] < 0.)
      continue;
    for(int e = dc.ring_begin[r]; e < dc.ring_begin[r + 1]; ++e) {
      const int j = dc.row[dc.ring[e]];
      const double m = j >= 0 ? (std::max)(mean[r], mean[std::size_t(j)]) : mean[r];
      w[e] = (std::max)(w[e], cotangent_floor * m);
    }
  }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_RING_WEIGHTS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_RING_WEIGHTS_H
#define CGAL_SMP_INTERNAL_RING_WEIGHTS_H

// Clamped cotangent start weights of a closed one-ring (mean-value weights are beside
// Floater's, which fall back on them). Positive, so Tutte's theorem holds for their system.

#include <CGAL/Surface_mesh_parameterization/internal/shape_preserving_weights.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Relative floor of the clamped cotangent weights: a weight below this fraction of the mean
// absolute cotangent weight of its ring is raised to it. Small enough to leave the weights of
// well-shaped rings unchanged, large enough to keep the matrix an M-matrix.
constexpr double cotangent_floor = 1e-2;

// Cotangent (discrete harmonic) weights cot(alpha) + cot(beta) of the ring, raised to at least
// `cotangent_floor` times their mean absolute value, normalized to sum 1. A ring with a face of
// zero area, where a cotangent is infinite, gets mean-value weights instead.
inline bool clamped_cotangent_ring_weights(const Vec3& center, const std::vector<Vec3>& ring,
                                           std::vector<double>& weights)
{
  const std::size_t d = ring.size();
  weights.assign(d, 0.);
  if(d < 3)
    return false;
  // cot of the angle at `apex` in the triangle (center, a, apex)
  auto cot = [&center](const Vec3& apex, const Vec3& a, bool& ok) {
    const Vec3 u = sub3(center, apex), v = sub3(a, apex);
    const double s = norm3(cross3(u, v));
    ok = ok && s > 1e-12 * norm3(u) * norm3(v) && std::isfinite(s);
    return dot3(u, v) / s;
  };
  bool ok = true;
  double mean = 0.;
  for(std::size_t k = 0; k < d; ++k) {
    weights[k] = cot(ring[(k + d - 1) % d], ring[k], ok) + cot(ring[(k + 1) % d], ring[k], ok);
    mean += std::abs(weights[k]) / double(d);
  }
  if(!ok || !(mean > 0.) || !std::isfinite(mean))
    return mean_value_ring_weights(center, ring, weights);
  double sum = 0.;
  for(double& w : weights) {
    w = (std::max)(w, cotangent_floor * mean);
    sum += w;
  }
  for(double& w : weights)
    w /= sum;
  return true;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_RING_WEIGHTS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SHAPE_PRESERVING_WEIGHTS_H
#define CGAL_SMP_INTERNAL_SHAPE_PRESERVING_WEIGHTS_H

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Floater's (2003) mean-value weights of the ring (neighbours in cyclic order), normalized to
// sum 1. False for a zero-length or non-finite spoke.
inline bool mean_value_ring_weights(const Vec3& center, const std::vector<Vec3>& ring,
                                    std::vector<double>& weights)
{
  const std::size_t d = ring.size();
  weights.assign(d, 0.);
  if(d < 3)
    return false;
  std::vector<double> half_tan(d);
  for(std::size_t k = 0; k < d; ++k)
    half_tan[k] = std::tan(angle3(sub3(ring[k], center), sub3(ring[(k + 1) % d], center)) / 2.);
  double sum = 0.;
  for(std::size_t k = 0; k < d; ++k) {
    const double r = norm3(sub3(ring[k], center));
    if(!(r > 0.) || !std::isfinite(r))
      return false;
    weights[k] = (half_tan[(k + d - 1) % d] + half_tan[k]) / r;
    sum += weights[k];
  }
  if(!(sum > 0.) || !std::isfinite(sum))
    return false;
  for(double& w : weights)
    w /= sum;
  return true;
}

// Floater's (1997) shape-preserving weights of an interior vertex, computed for its whole
// one-ring at once.
//
// The ring is flattened by the geodesic polar map (distances kept, angles scaled to sum to
// 2 pi); for every ring point q_k, the ring edge (q_r, q_{r+1}) hit by the ray from q_k through
// the origin gives a triangle containing the origin, whose barycentric coordinates are
// averaged over k. The weights are positive, sum to one, and reproduce planar rings exactly.
//
// A cone vertex whose scaled ring has an angle above pi has the origin outside the flattened
// ring, where the construction is undefined; mean-value weights (also positive, also with
// linear precision) are used for such a ring instead.
//
// Returns false when the weights are undefined: fewer than three neighbours, a zero-length
// or non-finite spoke, or a ring with zero total angle.
class Shape_preserving_ring_weights
{
public:
  // `ring` lists the neighbours in cyclic order; on success `weights[k]` is the weight of ring[k].
  bool compute(const Vec3& center, const std::vector<Vec3>& ring, std::vector<double>& weights)
  {
    const std::size_t d = ring.size();
    weights.assign(d, 0.);
    if(d < 3)
      return false;

    m_radius.resize(d);
    m_angle.resize(d);
    double total_angle = 0.;
    for(std::size_t k = 0; k < d; ++k) {
      const Vec3 a = sub3(ring[k], center), b = sub3(ring[(k + 1) % d], center);
      m_radius[k] = norm3(a);
      if(!(m_radius[k] > 0.) || !std::isfinite(m_radius[k]))
        return false;
      m_angle[k] = angle3(a, b);
      total_angle += m_angle[k];
    }
    if(!(total_angle > 0.) || !std::isfinite(total_angle))
      return false;

    const double pi = 3.14159265358979323846;
    const double scale = 2. * pi / total_angle;
    double max_scaled = 0.;
    for(double a : m_angle)
      max_scaled = (std::max)(max_scaled, a * scale);
    if(max_scaled > pi * (1. + 1e-9))
      return mean_value_ring_weights(center, ring, weights);

    // polar map q_k = r_k (cos theta_k, sin theta_k), theta increasing from 0
    m_theta.resize(d);
    m_q.resize(d);
    double theta = 0.;
    for(std::size_t k = 0; k < d; ++k) {
      m_theta[k] = theta;
      m_q[k] = {m_radius[k] * std::cos(theta), m_radius[k] * std::sin(theta)};
      theta += m_angle[k] * scale;
    }

    for(std::size_t k = 0; k < d; ++k) {
      double phi = m_theta[k] + pi;
      if(phi >= 2. * pi)
        phi -= 2. * pi;
      // r: last ring point whose angle does not exceed phi (theta is sorted)
      std::size_t r = std::size_t(std::upper_bound(m_theta.begin(), m_theta.end(), phi) - m_theta.begin()) - 1;
      // rounding may pick an edge incident to q_k when an angle is exactly pi
      if(r == k)
        r = (k + 1) % d;
      else if((r + 1) % d == k)
        r = (k + d - 2) % d;
      const std::size_t s = (r + 1) % d;
      add_barycentric(k, r, s, weights);
    }
    for(double& w : weights)
      w /= double(d);
    return true;
  }

private:
  static double cross2(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

  // Adds the barycentric coordinates of the origin in (q_k, q_r, q_s).
  void add_barycentric(std::size_t k, std::size_t r, std::size_t s, std::vector<double>& weights) const
  {
    const Vec2 &a = m_q[k], &b = m_q[r], &c = m_q[s];
    const double det = cross2({b[0] - a[0], b[1] - a[1]}, {c[0] - a[0], c[1] - a[1]});
    const double scale = m_radius[k] + m_radius[r] + m_radius[s];
    if(std::abs(det) <= 1e-14 * scale * scale) {
      // q_r, q_s on one ray through the origin: the origin lies on segment (q_k, q_r)
      const double ra = m_radius[k], rb = m_radius[r];
      weights[k] += rb / (ra + rb);
      weights[r] += ra / (ra + rb);
      return;
    }
    double la = cross2(b, c) / det, lb = cross2(c, a) / det, lc = cross2(a, b) / det;
    // tiny negative values come from rounding only: clamp, then restore the partition of unity
    la = (std::max)(la, 0.);
    lb = (std::max)(lb, 0.);
    lc = (std::max)(lc, 0.);
    const double sum = la + lb + lc;
    weights[k] += la / sum;
    weights[r] += lb / sum;
    weights[s] += lc / sum;
  }

  std::vector<double> m_radius, m_angle, m_theta;
  std::vector<Vec2> m_q;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SHAPE_PRESERVING_WEIGHTS_H

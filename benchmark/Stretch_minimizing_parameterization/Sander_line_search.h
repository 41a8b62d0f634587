// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Row (d) of the paper's tables: the stretch minimization of Sander, Snyder, Gortler and Hoppe
// ("Texture mapping progressive meshes", SIGGRAPH 2001), border fixed. Sweeps over the interior
// vertices, the ones of highest stretch first; each vertex moves along a random direction to
// the minimum, found by a golden-section line search, of the L2 stretch energy of its
// triangles (sum of 3D area times squared L2 stretch), within the kernel of its ring, so no
// triangle flips. Sander et al. optimize coarse to fine on a progressive mesh; this version
// optimizes all vertices from the start (the benchmark's meshes are not progressive meshes).
// It stops when a sweep lowers the energy by less than a relative 1e-4, or at a time cap.

#ifndef SMP_BENCHMARK_SANDER_LINE_SEARCH_H
#define SMP_BENCHMARK_SANDER_LINE_SEARCH_H

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace SMP_benchmark {

namespace SMPI = CGAL::Surface_mesh_parameterization::internal;

struct Sander_line_search_result
{
  int sweeps = 0;
  bool capped = false; // stopped by the time cap
};

// Minimizes the L2 stretch of `uv` (a flip-free map of `m`) over the vertices not `fixed`.
inline Sander_line_search_result sander_line_search(const SMPI::Flat_triangles& m, std::vector<SMPI::Vec2>& uv,
                                                    const std::vector<char>& fixed, double seconds_cap)
{
  using SMPI::Vec2;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = uv.size();
  // the triangles of each vertex
  std::vector<std::size_t> first(n + 1, 0), ring;
  for(const SMPI::Triangle& t : m.tri)
    for(int v : t) ++first[std::size_t(v) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  ring.resize(first[n]);
  {
    std::vector<std::size_t> at(first.begin(), first.end() - 1);
    for(std::size_t f = 0; f < m.tri.size(); ++f)
      for(int v : m.tri[f]) ring[at[std::size_t(v)]++] = f;
  }
  double orientation = 0.;
  for(const SMPI::Triangle& t : m.tri)
    orientation += SMPI::twice_signed_area(uv[std::size_t(t[0])], uv[std::size_t(t[1])], uv[std::size_t(t[2])]);
  const double sign = orientation < 0. ? -1. : 1.;
  const auto face_energy = [&](std::size_t f) {
    const SMPI::Triangle& t = m.tri[f];
    const Vec2 &a = uv[std::size_t(t[0])], &b = uv[std::size_t(t[1])], &c = uv[std::size_t(t[2])];
    if(!(sign * SMPI::twice_signed_area(a, b, c) > 0.))
      return HUGE_VAL;
    // (the L2 stretch does not depend on the orientation)
    const auto s = SMPI::triangle_stretch(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])], a, b, c);
    return s.area_3d * s.l2 * s.l2;
  };
  const auto ring_energy = [&](std::size_t v) {
    double e = 0.;
    for(std::size_t k = first[v]; k < first[v + 1]; ++k) e += face_energy(ring[k]);
    return e;
  };
  std::vector<std::size_t> order;
  for(std::size_t v = 0; v < n; ++v)
    if(!fixed[v] && first[v + 1] > first[v]) order.push_back(v);
  std::mt19937 random(0);
  std::uniform_real_distribution<double> angle(0., 2. * CGAL_PI);
  // the energy that can change: of the triangles with a free vertex (a triangle of three border
  // vertices, flat on a side of the square, has none)
  const auto movable_energy = [&]() {
    double e = 0.;
    for(std::size_t f = 0; f < m.tri.size(); ++f)
      if(!fixed[std::size_t(m.tri[f][0])] || !fixed[std::size_t(m.tri[f][1])] || !fixed[std::size_t(m.tri[f][2])])
        e += face_energy(f);
    return e;
  };
  double total = movable_energy();
  Sander_line_search_result r;
  std::vector<double> area(n, 0.), key(n, 0.);
  for(std::size_t f = 0; f < m.tri.size(); ++f) {
    const SMPI::Triangle& t = m.tri[f];
    const double a = SMPI::triangle_area(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])]);
    for(int v : t) area[std::size_t(v)] += a;
  }
  for(;;) {
    if(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds_cap) {
      r.capped = true;
      break;
    }
    // highest stretch first
    for(std::size_t v : order) key[v] = area[v] > 0. ? ring_energy(v) / area[v] : 0.;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] > key[b] || (key[a] == key[b] && a < b); });
    for(std::size_t v : order) {
      const double theta = angle(random);
      const Vec2 d = {{std::cos(theta), std::sin(theta)}}, p = uv[v];
      // the kernel along d: each triangle's signed area is linear in the step
      double lo = -HUGE_VAL, hi = HUGE_VAL, reach = 0.;
      for(std::size_t k = first[v]; k < first[v + 1]; ++k) {
        const SMPI::Triangle& t = m.tri[ring[k]];
        const auto area_at = [&](const Vec2& q) {
          uv[v] = q;
          const double a = sign * SMPI::twice_signed_area(uv[std::size_t(t[0])], uv[std::size_t(t[1])], uv[std::size_t(t[2])]);
          uv[v] = p;
          return a;
        };
        const double f0 = area_at(p), slope = area_at({{p[0] + d[0], p[1] + d[1]}}) - f0;
        if(slope > 0.) lo = (std::max)(lo, -f0 / slope);
        if(slope < 0.) hi = (std::min)(hi, -f0 / slope);
        for(int w : t)
          reach = (std::max)(reach, std::hypot(uv[std::size_t(w)][0] - p[0], uv[std::size_t(w)][1] - p[1]));
      }
      lo = (std::max)(lo, -reach) * 0.999;
      hi = (std::min)(hi, reach) * 0.999;
      if(!(lo < 0.) || !(hi > 0.))
        continue;
      const auto energy_at = [&](double t) {
        uv[v] = {{p[0] + t * d[0], p[1] + t * d[1]}};
        const double e = ring_energy(v);
        uv[v] = p;
        return e;
      };
      const double golden = 0.5 * (std::sqrt(5.) - 1.);
      double a = lo, b = hi, x1 = b - golden * (b - a), x2 = a + golden * (b - a);
      double e1 = energy_at(x1), e2 = energy_at(x2);
      for(int i = 0; i < 30; ++i) {
        if(e1 < e2) { b = x2; x2 = x1; e2 = e1; x1 = b - golden * (b - a); e1 = energy_at(x1); }
        else { a = x1; x1 = x2; e1 = e2; x2 = a + golden * (b - a); e2 = energy_at(x2); }
      }
      const double best = e1 < e2 ? x1 : x2;
      if((std::min)(e1, e2) < energy_at(0.))
        uv[v] = {{p[0] + best * d[0], p[1] + best * d[1]}};
    }
    ++r.sweeps;
    const double now = movable_energy();
    const bool done = !(total - now > 1e-4 * total);
    total = now;
    if(done)
      break;
  }
  return r;
}

} // namespace SMP_benchmark

#endif // SMP_BENCHMARK_SANDER_LINE_SEARCH_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A planar grid as flat arrays, for the tests of the polish and of the remeshing.

#ifndef SMP_TEST_FLAT_GRID_H
#define SMP_TEST_FLAT_GRID_H

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <random>
#include <vector>

namespace smp_test {

// A planar grid of (k+1) x (k+1) vertices on [0,1]^2 in the plane z = 0, interior vertices
// jittered by `jitter` cells; border loop counter-clockwise.
struct Flat_grid
{
  CGAL::Surface_mesh_parameterization::internal::Flat_triangles m;
  std::vector<int> border;
  std::vector<char> fixed;
};

inline Flat_grid make_flat_grid(int k, double jitter, std::mt19937& rng)
{
  Flat_grid g;
  std::uniform_real_distribution<double> u(-1., 1.);
  const double h = 1. / k;
  auto id = [k](int i, int j) { return j * (k + 1) + i; };
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) {
      const bool inner = i > 0 && j > 0 && i < k && j < k;
      g.m.xyz.push_back({i * h + (inner ? jitter * h * u(rng) : 0.), j * h + (inner ? jitter * h * u(rng) : 0.), 0.});
      g.fixed.push_back(inner ? 0 : 1);
    }
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      g.m.tri.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      g.m.tri.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for(int i = 0; i < k; ++i) g.border.push_back(id(i, 0));
  for(int j = 0; j < k; ++j) g.border.push_back(id(k, j));
  for(int i = k; i > 0; --i) g.border.push_back(id(i, k));
  for(int j = k; j > 0; --j) g.border.push_back(id(0, j));
  return g;
}

} // namespace smp_test

#endif // SMP_TEST_FLAT_GRID_H

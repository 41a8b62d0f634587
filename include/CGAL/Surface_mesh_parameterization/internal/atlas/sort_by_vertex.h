// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_SORT_BY_VERTEX_H
#define CGAL_SMP_INTERNAL_ATLAS_SORT_BY_VERTEX_H

// The sides of a chart's triangles are sorted by their vertices again and again (outlines for
// the packing, the sides two triangles share, the area terms of the conformal map): a counting
// sort on the first vertex, then the few sides at each vertex, gives std::sort's order in time
// linear in the sides and the vertices.

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Sorts `items` by their operator<, whose first compared field is `first(item)`, a vertex
// index (at least 0): the order of std::sort.
template <typename T, typename First>
void sort_by_vertex(std::vector<T>& items, const First& first)
{
  std::size_t n = 0;
  for(const T& x : items)
    n = (std::max)(n, std::size_t(first(x)) + 1);
  std::vector<std::size_t> begin(n + 1, 0);
  for(const T& x : items)
    ++begin[std::size_t(first(x)) + 1];
  for(std::size_t v = 0; v < n; ++v)
    begin[v + 1] += begin[v];
  std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
  std::vector<T> sorted(items.size());
  for(const T& x : items)
    sorted[next[std::size_t(first(x))]++] = x;
  for(std::size_t v = 0; v < n; ++v)
    std::sort(sorted.begin() + std::ptrdiff_t(begin[v]), sorted.begin() + std::ptrdiff_t(begin[v + 1]));
  items.swap(sorted);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_SORT_BY_VERTEX_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_VERTEX_ORDER_H
#define CGAL_SMP_INTERNAL_VERTEX_ORDER_H

// One fill-reducing order of the vertices of a mesh, shared by all its sparse systems of one row
// per vertex (the symmetric weighted Laplacians of the stretch minimizer, the polisher's proxy
// and split Newton systems): they have the pattern of the mesh's edges, or a part of it. On
// large meshes METIS's nested dissection (through CHOLMOD) gives factors of markedly fewer flops
// than the minimum degree order Eigen's Cholesky finds by itself, but it costs a few
// factorizations to compute: once per mesh, not once per system. The order of a subset of the
// vertices (a system whose border is fixed) is this order restricted to them.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <Eigen/SparseCore>
#if defined(CGAL_SMP_USE_CHOLMOD)
#include <Eigen/CholmodSupport>
#endif

#include <algorithm>
#include <cstddef>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// METIS draws from one random number generator of the whole process (GKlib's, seeded anew at
// the start of each call), which is not made for threads: two calls at once draw from each
// other's sequence, and their orders, and the rounding of the factorizations in them, would
// follow the timing (charts of the atlas polished side by side). One call at a time, in every
// configuration of the solvers.
inline std::mutex& metis_mutex()
{
  static std::mutex m;
  return m;
}

CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// Below this many vertices the minimum degree order is as good (measured: no faster
// factorization at 13k rows, a third faster at 52k, half at 207k) and METIS's cost not repaid.
constexpr std::size_t nested_dissection_threshold = 30000;

// rank[v]: the place of vertex v (of `vertices`) in a nested-dissection order of the graph of
// the edges of `triangles` and `more_triangles`; empty if the mesh is small or METIS is not
// there (CHOLMOD is not used) or fails: each system then orders itself.
inline std::vector<int> fill_reducing_vertex_rank(std::size_t vertices, const std::vector<Triangle>& triangles,
                                                  const std::vector<Triangle>& more_triangles)
{
#if defined(CGAL_SMP_USE_CHOLMOD)
  if(vertices < nested_dissection_threshold)
    return {};
  // the lower triangle of the pattern, with the diagonal (which CHOLMOD's ordering ignores)
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(vertices + 3 * (triangles.size() + more_triangles.size()));
  for(std::size_t v = 0; v < vertices; ++v)
    entries.emplace_back(int(v), int(v), 1.);
  for(const std::vector<Triangle>* tri : {&triangles, &more_triangles})
    for(const Triangle& t : *tri)
      for(int k = 0; k < 3; ++k)
        entries.emplace_back((std::max)(t[k], t[(k + 1) % 3]), (std::min)(t[k], t[(k + 1) % 3]), 1.);
  const Eigen::Index n = static_cast<Eigen::Index>(vertices);
  Eigen::SparseMatrix<double> lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());
  std::vector<Eigen::Triplet<double> >().swap(entries);

  cholmod_common common;
  cholmod_start(&common);
  common.print = 0; // a failure is handled here
  cholmod_sparse A = Eigen::viewAsCholmod(lower);
  A.stype = -1; // symmetric, lower triangle stored
  std::vector<int> order(vertices);
  bool ordered = false;
  {
    std::lock_guard<std::mutex> one_at_a_time(metis_mutex());
    ordered = cholmod_metis(&A, nullptr, 0, 1, order.data(), &common) != 0;
  }
  cholmod_finish(&common);
  if(!ordered)
    return {};
  std::vector<int> rank(vertices);
  for(std::size_t k = 0; k < vertices; ++k)
    rank[std::size_t(order[k])] = int(k);
  return rank;
#else
  static_cast<void>(vertices);
  static_cast<void>(triangles);
  static_cast<void>(more_triangles);
  return {};
#endif
}

// The rows of a system in the order of `rank`, row r standing for vertex `vertex_of_row[r]`
// (rows of the elimination order, first to last); empty if `rank` is.
inline std::vector<int> rows_in_order(const std::vector<int>& rank, const std::vector<int>& vertex_of_row)
{
  std::vector<int> rows;
  if(rank.empty())
    return rows;
  rows.resize(vertex_of_row.size());
  for(std::size_t r = 0; r < rows.size(); ++r)
    rows[r] = int(r);
  std::sort(rows.begin(), rows.end(), [&](int a, int b) {
    return rank[std::size_t(vertex_of_row[std::size_t(a)])] < rank[std::size_t(vertex_of_row[std::size_t(b)])];
  });
  return rows;
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_VERTEX_ORDER_H

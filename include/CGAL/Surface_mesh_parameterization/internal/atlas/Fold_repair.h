// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_FOLD_REPAIR_H
#define CGAL_SMP_INTERNAL_ATLAS_FOLD_REPAIR_H

// LSCM's free-border map of a chart can be a bijection but for a few triangles folded over
// inside the chart (mostly slivers, whose cotangent weights are negative). Such folds are
// undone where they are: the inner vertices of the folded triangles, with their inner
// neighbours ring by ring while a fold stays, are moved to the convex combination of their
// neighbours given by mean-value weights (Floater 2003), the other vertices held. Tutte's theorem
// would need the held vertices around them to be in convex position, which they only nearly
// are: the result is checked, not assumed. (Moving border vertices too, to undo a border laid
// over itself, was tried: drawn inwards by their neighbours, they fold other triangles.)

#include <CGAL/Surface_mesh_parameterization/internal/shape_preserving_weights.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Undoes the folds of `uv` (one point per vertex of `tm`, by the vertex's index) away from the
// border of `tm`, a triangle mesh whose face i is `triangles[i]` and vertex i is at `xyz[i]`,
// moving as few vertices as it can (rings around the folds up to `max_rings`). True if every
// triangle then has a positive signed area in `uv`; `uv` is changed only then.
template <typename TriangleMesh>
bool repair_interior_folds(const TriangleMesh& tm, const std::vector<Vec3>& xyz,
                           const std::vector<std::array<int, 3> >& triangles, std::vector<Vec2>& uv,
                           int max_rings = 3)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const auto vim = get(CGAL::vertex_index, tm);
  const std::size_t nv = uv.size();
  std::vector<vertex_descriptor> vd(nv);
  std::vector<char> on_border(nv, 0);
  for(vertex_descriptor v : vertices(tm)) {
    vd[std::size_t(get(vim, v))] = v;
    on_border[std::size_t(get(vim, v))] = CGAL::is_border(v, tm) ? 1 : 0;
  }
  auto positive = [](const std::vector<Vec2>& x, const std::array<int, 3>& t) {
    return twice_signed_area(x[std::size_t(t[0])], x[std::size_t(t[1])], x[std::size_t(t[2])]) > 0.;
  };
  std::vector<char> moved(nv, 0);
  bool folded = false;
  for(const auto& t : triangles)
    if(!positive(uv, t)) {
      folded = true;
      bool inner = false;
      for(int v : t)
        if(!on_border[std::size_t(v)]) moved[std::size_t(v)] = inner = true;
      if(!inner) // a fold of border vertices only: nothing inside to move
        return false;
    }
  if(!folded)
    return true;

  std::vector<Vec2> trial;
  std::vector<Vec3> ring;
  std::vector<std::size_t> ring_index;
  std::vector<double> w;
  for(int r = 0; r <= max_rings; ++r) {
    if(r > 0) { // one ring more, of inner vertices (none left: the same solve again)
      const std::vector<char> before = moved;
      for(std::size_t v = 0; v < nv; ++v)
        if(before[v])
          for(halfedge_descriptor h : halfedges_around_target(halfedge(vd[v], tm), tm)) {
            const std::size_t s = std::size_t(get(vim, source(h, tm)));
            if(!on_border[s]) moved[s] = 1;
          }
      if(moved == before)
        return false;
    }
    std::vector<int> unknown(nv, -1);
    int n = 0;
    for(std::size_t v = 0; v < nv; ++v)
      if(moved[v]) unknown[v] = n++;
    std::vector<Eigen::Triplet<double> > entries;
    Eigen::VectorXd bu = Eigen::VectorXd::Zero(n), bv = Eigen::VectorXd::Zero(n);
    for(std::size_t v = 0; v < nv; ++v) {
      if(!moved[v]) continue;
      ring.clear();
      ring_index.clear();
      for(halfedge_descriptor h : halfedges_around_target(halfedge(vd[v], tm), tm)) {
        const std::size_t s = std::size_t(get(vim, source(h, tm)));
        ring_index.push_back(s);
        ring.push_back(xyz[s]);
      }
      if(!mean_value_ring_weights(xyz[v], ring, w)) // a zero-length spoke: the centroid
        w.assign(ring.size(), 1. / double(ring.size()));
      const int i = unknown[v];
      entries.emplace_back(i, i, 1.);
      for(std::size_t k = 0; k < ring.size(); ++k) {
        const std::size_t s = ring_index[k];
        if(unknown[s] >= 0)
          entries.emplace_back(i, unknown[s], -w[k]);
        else {
          bu[i] += w[k] * uv[s][0];
          bv[i] += w[k] * uv[s][1];
        }
      }
    }
    // every connected set of moved vertices meets a held one (the border is held): the matrix
    // is an irreducibly diagonally dominant M-matrix, so invertible
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double> > lu(a);
    if(lu.info() != Eigen::Success)
      return false;
    const Eigen::VectorXd xu = lu.solve(bu), xv = lu.solve(bv);
    trial = uv;
    for(std::size_t v = 0; v < nv; ++v)
      if(unknown[v] >= 0)
        trial[v] = Vec2{xu[unknown[v]], xv[unknown[v]]};
    bool ok = true;
    for(const auto& t : triangles)
      ok = ok && positive(trial, t);
    if(ok) {
      uv.swap(trial);
      return true;
    }
  }
  return false;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_FOLD_REPAIR_H

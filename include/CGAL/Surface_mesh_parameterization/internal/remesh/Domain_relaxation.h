// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_DOMAIN_RELAXATION_H
#define CGAL_SMP_INTERNAL_REMESH_DOMAIN_RELAXATION_H

// Lloyd-like relaxation of a lifted triangulation: each interior vertex moves, in the
// parameter domain, to the centroid of its triangles there weighted by their surface areas
// (the centroid of its dual cell on the surface, approximately), which evens out the areas
// and widens the angles; a move that would turn a triangle in the domain is halved, then
// left out, so the mesh stays an embedding of the domain.

#include <CGAL/Surface_mesh_parameterization/internal/remesh/Surface_delaunay_flips.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// `lift(v, q)` puts vertex `v` at the surface point of the domain point `q` (and returns
// false if it cannot). `sign` is the orientation of the triangles in the domain (1 or -1).
template <typename Lift>
void relax_in_domain(Lifted_mesh& mesh, std::vector<Vec2>& uv, int steps, double sign, Lift lift)
{
  typedef Lifted_mesh::Vertex_index vertex_descriptor;
  const auto at = [&](vertex_descriptor v) -> Vec3 {
    const auto& p = mesh.point(v);
    return {{p.x(), p.y(), p.z()}};
  };
  std::vector<Vec2> target(uv.size());
  for(int step = 0; step < steps; ++step) {
    for(const vertex_descriptor v : mesh.vertices()) {
      target[std::size_t(v)] = uv[std::size_t(v)];
      if(mesh.is_border(v))
        continue;
      Vec2 sum = {{0., 0.}};
      double weight = 0.;
      for(const auto f : faces_around_target(mesh.halfedge(v), mesh)) {
        const auto h = mesh.halfedge(f);
        const vertex_descriptor a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h));
        const double w = triangle_area(at(a), at(b), at(c));
        for(int i = 0; i < 2; ++i)
          sum[i] += w * (uv[std::size_t(a)][i] + uv[std::size_t(b)][i] + uv[std::size_t(c)][i]) / 3.;
        weight += w;
      }
      if(weight > 0.)
        target[std::size_t(v)] = {{sum[0] / weight, sum[1] / weight}};
    }
    for(const vertex_descriptor v : mesh.vertices()) {
      const Vec2 from = uv[std::size_t(v)];
      Vec2 to = target[std::size_t(v)];
      for(int attempt = 0; attempt < 3 && to != from; ++attempt) {
        uv[std::size_t(v)] = to;
        bool valid = true;
        for(const auto f : faces_around_target(mesh.halfedge(v), mesh)) {
          const auto h = mesh.halfedge(f);
          valid = valid && sign * twice_signed_area(uv[std::size_t(mesh.source(h))], uv[std::size_t(mesh.target(h))],
                                                    uv[std::size_t(mesh.target(mesh.next(h)))]) > 0.;
        }
        if(valid && lift(v, to))
          break;
        uv[std::size_t(v)] = from;
        to = {{0.5 * (from[0] + to[0]), 0.5 * (from[1] + to[1])}};
      }
    }
    flip_to_surface_delaunay(mesh, uv, 16);
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_DOMAIN_RELAXATION_H

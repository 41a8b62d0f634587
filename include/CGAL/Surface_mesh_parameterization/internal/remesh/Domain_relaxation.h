// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_DOMAIN_RELAXATION_H
#define CGAL_SMP_INTERNAL_REMESH_DOMAIN_RELAXATION_H

// Lloyd-like relaxation of a lifted triangulation: each interior vertex moves to the centroid
// of its triangles on the surface (each triangle's centroid weighted by its area times the
// sampling density there: the centroid of its dual cell, approximately), carried to the
// parameter domain through the triangle of its fan that holds it (if any); the lift puts it
// back on the surface. This evens out the surface areas and widens the angles wherever the
// domain is squeezed or stretched. (The same centroid
// taken in the domain, with the same weights, does not: its fixed point leaves the triangles
// larger where the domain is squeezed, and the more steps, the more so.) A move that would turn
// a triangle in the domain or over on the surface is halved, then left out, so the mesh stays
// an embedding of the domain and keeps its orientation on the surface.

#include <CGAL/Surface_mesh_parameterization/internal/remesh/Surface_delaunay_flips.h>

#include <CGAL/Polygon_mesh_processing/locate.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// `lift(v, q)` puts vertex `v` at the surface point of the domain point `q` and updates its
// `density` (the relative sampling density per vertex; none: 1), or returns false if it cannot.
// `sign` is the orientation of the triangles in the domain (1 or -1).
template <typename Lift>
void relax_in_domain(Lifted_mesh& mesh, std::vector<Vec2>& uv, const std::vector<double>& density, int steps, double sign,
                     Lift lift)
{
  typedef Lifted_mesh::Vertex_index vertex_descriptor;
  typedef Lifted_mesh::Point Point_3;
  const auto at = [&](vertex_descriptor v) { return lifted_point(mesh, v); };
  // the normals of the triangles around `v` on the surface (not normalized)
  std::vector<Vec3> before, after;
  std::vector<double> fan_area; // the surface areas of the triangles around a vertex, in turn
  const auto fan_normals = [&](vertex_descriptor v, std::vector<Vec3>& normals) {
    normals.clear();
    for(const auto f : faces_around_target(mesh.halfedge(v), mesh)) {
      const auto h = mesh.halfedge(f);
      const Vec3 a = at(mesh.source(h));
      normals.push_back(cross3(sub3(at(mesh.target(h)), a), sub3(at(mesh.target(mesh.next(h))), a)));
    }
  };
  std::vector<Vec2> target(uv.size());
  for(int step = 0; step < steps; ++step) {
    for(const vertex_descriptor v : mesh.vertices()) {
      target[std::size_t(v)] = uv[std::size_t(v)];
      if(mesh.is_border(v))
        continue;
      Vec3 sum = {{0., 0., 0.}};
      double weight = 0.;
      fan_area.clear();
      for(const auto f : faces_around_target(mesh.halfedge(v), mesh)) {
        const auto h = mesh.halfedge(f);
        const Vec3 a = at(mesh.source(h)), b = at(mesh.target(h)), c = at(mesh.target(mesh.next(h)));
        fan_area.push_back(triangle_area(a, b, c));
        const double w = density.empty() ? fan_area.back()
                                         : fan_area.back() * (density[std::size_t(mesh.source(h))] + density[std::size_t(mesh.target(h))] +
                                                              density[std::size_t(mesh.target(mesh.next(h)))]) / 3.;
        for(int i = 0; i < 3; ++i)
          sum[i] += w * (a[i] + b[i] + c[i]) / 3.;
        weight += w;
      }
      if(!(weight > 0.))
        continue;
      const Point_3 centroid(sum[0] / weight, sum[1] / weight, sum[2] / weight);
      // its barycentric coordinates in the fan triangle it is the most inside of (projected on
      // the triangle's plane), applied to that triangle's corners in the domain; a centroid in
      // none of them (a fan folded sharply, as at the tip of a horn) leaves the vertex where it is
      double inside = -HUGE_VAL;
      std::size_t n = 0;
      for(const auto f : faces_around_target(mesh.halfedge(v), mesh)) {
        const auto h = mesh.halfedge(f);
        const vertex_descriptor k[3] = {mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))};
        if(!(fan_area[n++] > 0.))
          continue;
        const std::array<double, 3> w =
            Polygon_mesh_processing::barycentric_coordinates(mesh.point(k[0]), mesh.point(k[1]), mesh.point(k[2]), centroid);
        const double least = (std::min)({w[0], w[1], w[2]});
        if(!(least > inside))
          continue;
        inside = least;
        for(int i = 0; i < 2; ++i)
          target[std::size_t(v)][i] = w[0] * uv[std::size_t(k[0])][i] + w[1] * uv[std::size_t(k[1])][i] + w[2] * uv[std::size_t(k[2])][i];
      }
      if(inside < 0.)
        target[std::size_t(v)] = uv[std::size_t(v)];
    }
    for(const vertex_descriptor v : mesh.vertices()) {
      const Vec2 from = uv[std::size_t(v)];
      Vec2 to = target[std::size_t(v)];
      if(to == from)
        continue;
      fan_normals(v, before);
      for(int attempt = 0; attempt < 3; ++attempt) {
        uv[std::size_t(v)] = to;
        bool valid = true;
        for(const auto f : faces_around_target(mesh.halfedge(v), mesh))
          valid = valid && sign * twice_domain_area(mesh, uv, f) > 0.;
        if(valid && lift(v, to)) {
          fan_normals(v, after);
          bool kept = true; // no triangle turned over on the surface either
          for(std::size_t i = 0; i < before.size() && kept; ++i)
            kept = dot3(before[i], after[i]) > 0. || dot3(before[i], before[i]) == 0.;
          if(kept)
            break;
          lift(v, from);
        }
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

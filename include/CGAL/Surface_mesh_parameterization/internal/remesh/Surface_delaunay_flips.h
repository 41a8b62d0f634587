// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_SURFACE_DELAUNAY_FLIPS_H
#define CGAL_SMP_INTERNAL_REMESH_SURFACE_DELAUNAY_FLIPS_H

// A triangulation made Delaunay in a parameter domain is not Delaunay on the surface where
// the map is not conformal; edge flips on the surface's angles mend it, each flip kept valid
// in the parameter domain (the new triangles keep the domain's orientation), so the lifted
// mesh stays an embedding of the domain.

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Flips edges of `tri` (vertices by index, positions `xyz` on the surface and `uv` in the
// domain) whose two opposite surface angles sum above pi, in at most `passes` passes over the
// edges; a flip is left out if a new triangle would be flat or turned in the domain, or if
// the two new triangles would fold onto each other on the surface.
inline void flip_to_surface_delaunay(const std::vector<Vec3>& xyz, const std::vector<Vec2>& uv,
                                     std::vector<Triangle>& tri, int passes)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  typedef Mesh::Vertex_index vertex_descriptor;
  typedef Mesh::Halfedge_index halfedge_descriptor;
  Mesh mesh;
  {
    std::vector<K::Point_3> points;
    points.reserve(xyz.size());
    for(const Vec3& p : xyz)
      points.emplace_back(p[0], p[1], p[2]);
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, tri, mesh);
  }
  if(mesh.number_of_vertices() != xyz.size()) // a vertex in no triangle: the numbers differ
    return;
  const auto at = [&](vertex_descriptor v) -> const Vec3& { return xyz[std::size_t(v)]; };
  const auto in_domain = [&](vertex_descriptor v) -> const Vec2& { return uv[std::size_t(v)]; };
  for(int pass = 0; pass < passes; ++pass) {
    std::size_t flips = 0;
    for(const auto e : mesh.edges()) {
      const halfedge_descriptor h = mesh.halfedge(e), o = mesh.opposite(h);
      if(mesh.is_border(e))
        continue;
      const vertex_descriptor a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h)),
                              d = mesh.target(mesh.next(o));
      if(angle3(sub3(at(a), at(c)), sub3(at(b), at(c))) + angle3(sub3(at(a), at(d)), sub3(at(b), at(d))) <= CGAL_PI + 1e-9)
        continue;
      // the quad (a, d, b, c) splits into (a, d, c) and (d, b, c), turning as (a, b, c) does
      const double before = twice_signed_area(in_domain(a), in_domain(b), in_domain(c));
      const double t1 = twice_signed_area(in_domain(a), in_domain(d), in_domain(c)) * before,
                   t2 = twice_signed_area(in_domain(d), in_domain(b), in_domain(c)) * before;
      const double floor = 1e-12 * before * before;
      if(!(t1 > floor) || !(t2 > floor) || CGAL::halfedge(c, d, mesh).second)
        continue;
      const Vec3 n1 = cross3(sub3(at(d), at(a)), sub3(at(c), at(a))), n2 = cross3(sub3(at(b), at(d)), sub3(at(c), at(d)));
      if(!(dot3(n1, n2) > 0.))
        continue;
      CGAL::Euler::flip_edge(h, mesh);
      ++flips;
    }
    if(flips == 0)
      break;
  }
  tri.clear();
  for(const auto f : mesh.faces()) {
    const halfedge_descriptor h = mesh.halfedge(f);
    tri.push_back({int(mesh.source(h)), int(mesh.target(h)), int(mesh.target(mesh.next(h)))});
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_SURFACE_DELAUNAY_FLIPS_H

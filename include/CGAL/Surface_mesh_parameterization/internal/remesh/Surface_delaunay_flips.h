// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_SURFACE_DELAUNAY_FLIPS_H
#define CGAL_SMP_INTERNAL_REMESH_SURFACE_DELAUNAY_FLIPS_H

// Edge flips of a triangulation lifted from a parameter domain to the surface, each kept valid
// in the domain (the new triangles keep the domain's orientation), so the lifted mesh stays an
// embedding of the domain: a triangulation made Delaunay in the domain is not Delaunay on the
// surface where the map is not conformal, and flips on the surface's angles mend it; a
// triangle turned over on the surface (spanning a fold) is mended by a flip where one leaves
// both new triangles turned as the surface.

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Lifted_mesh;

// Twice the signed area of face `f` of `mesh` in the domain `uv`.
inline double twice_domain_area(const Lifted_mesh& mesh, const std::vector<Vec2>& uv, Lifted_mesh::Face_index f)
{
  const auto h = mesh.halfedge(f);
  return twice_signed_area(uv[std::size_t(mesh.source(h))], uv[std::size_t(mesh.target(h))],
                           uv[std::size_t(mesh.target(mesh.next(h)))]);
}

// The position of vertex `v` of `mesh`.
inline Vec3 lifted_point(const Lifted_mesh& mesh, Lifted_mesh::Vertex_index v)
{
  const auto& p = mesh.point(v);
  return {{p.x(), p.y(), p.z()}};
}

// True if flipping the edge of halfedge `h` (not on the border) keeps `mesh` an embedding of
// the domain `uv`: the quad (a, d, b, c) around it, with (a, b, c) the face of `h`, splits into
// (a, d, c) and (d, b, c), both turning as (a, b, c) does and not nearly flat, and c and d are
// not joined already.
inline bool flip_keeps_domain(const Lifted_mesh& mesh, const std::vector<Vec2>& uv, Lifted_mesh::Halfedge_index h)
{
  const auto a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h)),
             d = mesh.target(mesh.next(mesh.opposite(h)));
  const auto in_domain = [&](Lifted_mesh::Vertex_index v) -> const Vec2& { return uv[std::size_t(v)]; };
  const double before = twice_signed_area(in_domain(a), in_domain(b), in_domain(c));
  const double t1 = twice_signed_area(in_domain(a), in_domain(d), in_domain(c)) * before,
               t2 = twice_signed_area(in_domain(d), in_domain(b), in_domain(c)) * before;
  const double floor = 1e-12 * before * before;
  return t1 > floor && t2 > floor && !CGAL::halfedge(c, d, mesh).second;
}

// Flips edges of `mesh` (its vertex i at `uv[i]` in the domain) whose two opposite surface
// angles sum above pi, in at most `passes` passes over the edges; a flip is left out if a new
// triangle would be flat or turned in the domain, or if the two new triangles would fold onto
// each other on the surface.
inline void flip_to_surface_delaunay(Lifted_mesh& mesh, const std::vector<Vec2>& uv, int passes)
{
  typedef Lifted_mesh::Vertex_index vertex_descriptor;
  typedef Lifted_mesh::Halfedge_index halfedge_descriptor;
  const auto at = [&](vertex_descriptor v) { return lifted_point(mesh, v); };
  for(int pass = 0; pass < passes; ++pass) {
    std::size_t flips = 0;
    for(const auto e : mesh.edges()) {
      const halfedge_descriptor h = mesh.halfedge(e), o = mesh.opposite(h);
      if(mesh.is_border(e))
        continue;
      const vertex_descriptor a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h)),
                              d = mesh.target(mesh.next(o));
      const Vec3 pa = at(a), pb = at(b), pc = at(c), pd = at(d);
      if(angle3(sub3(pa, pc), sub3(pb, pc)) + angle3(sub3(pa, pd), sub3(pb, pd)) <= CGAL_PI + 1e-9)
        continue;
      // (the new triangles are (a, d, c) and (d, b, c))
      if(!flip_keeps_domain(mesh, uv, h))
        continue;
      if(!(dot3(cross3(sub3(pd, pa), sub3(pc, pa)), cross3(sub3(pb, pd), sub3(pc, pd))) > 0.))
        continue;
      CGAL::Euler::flip_edge(h, mesh);
      ++flips;
    }
    if(flips == 0)
      break;
  }
}

// True if the triangle (a, b, c) of `mesh` is turned against the surface: against the sum of
// the input surface's normals where its corners are (`normal[v]` for vertex v).
inline bool turned_against(const Lifted_mesh& mesh, const std::vector<Vec3>& normal, Lifted_mesh::Vertex_index a,
                           Lifted_mesh::Vertex_index b, Lifted_mesh::Vertex_index c)
{
  const Vec3 sum = add3(add3(normal[std::size_t(a)], normal[std::size_t(b)]), normal[std::size_t(c)]);
  const Vec3 p = lifted_point(mesh, a);
  return dot3(cross3(sub3(lifted_point(mesh, b), p), sub3(lifted_point(mesh, c), p)), sum) < 0.;
}

// Flips an edge of each triangle of `mesh` turned against the surface (`normal[v]`: the input
// surface's unit normal where vertex v is, 0 if unknown) where the flip keeps the domain `uv`
// (flip_keeps_domain()) and neither new triangle is turned (a fan that spans a fold narrower
// than its edges can often follow it with the same vertices).
inline void flip_turned_triangles(Lifted_mesh& mesh, const std::vector<Vec2>& uv, const std::vector<Vec3>& normal)
{
  typedef Lifted_mesh::Vertex_index vertex_descriptor;
  for(const auto f : mesh.faces()) {
    auto h = mesh.halfedge(f);
    if(!turned_against(mesh, normal, mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))))
      continue;
    for(int k = 0; k < 3; ++k, h = mesh.next(h)) {
      if(mesh.is_border(mesh.edge(h)))
        continue;
      const vertex_descriptor a = mesh.source(h), b = mesh.target(h), c = mesh.target(mesh.next(h)),
                              d = mesh.target(mesh.next(mesh.opposite(h)));
      if(!flip_keeps_domain(mesh, uv, h) || turned_against(mesh, normal, a, d, c) ||
         turned_against(mesh, normal, d, b, c))
        continue;
      CGAL::Euler::flip_edge(h, mesh);
      break;
    }
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_SURFACE_DELAUNAY_FLIPS_H

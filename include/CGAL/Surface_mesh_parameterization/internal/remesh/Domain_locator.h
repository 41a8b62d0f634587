// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_DOMAIN_LOCATOR_H
#define CGAL_SMP_INTERNAL_REMESH_DOMAIN_LOCATOR_H

// Where a point of a parameter domain is on the surface: CGAL's AABB tree of the domain's
// triangles (in the plane z = 0) finds the nearest one.

#include <CGAL/Surface_mesh_parameterization/internal/remesh/Density_sampling.h>

#include <CGAL/Surface_mesh_parameterization/internal/aabb_tree_compatibility.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Domain_locator
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef Aabb_tree<K, Aabb_triangle_primitive<K, Iterator> > Tree;

public:
  // The triangles `tri` laid out by `uv` (both kept by reference); the ones flat in the plane
  // are left out.
  Domain_locator(const std::vector<Triangle>& tri, const std::vector<Vec2>& uv) : m_tri(tri), m_uv(uv)
  {
    for(std::size_t f = 0; f < tri.size(); ++f) {
      const Vec2 &a = uv[std::size_t(tri[f][0])], &b = uv[std::size_t(tri[f][1])], &c = uv[std::size_t(tri[f][2])];
      if(twice_signed_area(a, b, c) != 0.) {
        m_triangles.emplace_back(K::Point_3(a[0], a[1], 0.), K::Point_3(b[0], b[1], 0.), K::Point_3(c[0], c[1], 0.));
        m_face.push_back(int(f));
      }
    }
    m_tree.insert(m_triangles.cbegin(), m_triangles.cend());
    m_tree.accelerate_distance_queries();
    for(const Vec2& q : uv)
      m_size = (std::max)({m_size, std::abs(q[0]), std::abs(q[1])});
  }

  // The surface location of `p` if `p` is in the domain (not outside it, not in a hole, up to
  // a rounding of its size).
  bool locate_inside(const Vec2& p, Surface_location& s) const
  {
    if(!locate(p, s))
      return false;
    const Vec2 found = locate_in(s, m_tri, m_uv);
    return std::abs(found[0] - p[0]) + std::abs(found[1] - p[1]) <= 1e-9 * m_size;
  }

  // The surface location of the point of the domain nearest to `p`; false if the domain has no triangle.
  bool locate(const Vec2& p, Surface_location& s) const
  {
    if(m_triangles.empty())
      return false;
    const auto nearest = m_tree.closest_point_and_primitive(K::Point_3(p[0], p[1], 0.));
    s.face = m_face[std::size_t(nearest.second - m_triangles.cbegin())];
    const Triangle& t = m_tri[std::size_t(s.face)];
    const Vec2 q = {{nearest.first.x(), nearest.first.y()}};
    barycentric_inside(q, m_uv[std::size_t(t[0])], m_uv[std::size_t(t[1])], m_uv[std::size_t(t[2])], s.weight);
    // the nearest point is in the triangle: only rounding puts a weight below 0
    double sum = 0.;
    for(double& w : s.weight) {
      w = (std::max)(0., w);
      sum += w;
    }
    for(double& w : s.weight)
      w = sum > 0. ? w / sum : 1. / 3.;
    return true;
  }

private:
  const std::vector<Triangle>& m_tri;
  const std::vector<Vec2>& m_uv;
  std::vector<K::Triangle_3> m_triangles;
  std::vector<int> m_face;
  Tree m_tree;
  double m_size = 0.; // the largest coordinate of the domain, for a tolerance
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_DOMAIN_LOCATOR_H

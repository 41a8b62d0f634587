// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far a new mesh is from its input, as smp-remesh reports it and the remeshing comparison
// (benchmark/) measures it: one definition for both.

#ifndef SMP_TOOLS_SMP_SURFACE_DISTANCE_H
#define SMP_TOOLS_SMP_SURFACE_DISTANCE_H

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Surface_mesh_parameterization/internal/aabb_tree_compatibility.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace smp_tools {

template <typename Mesh>
double bounding_box_diagonal(const Mesh& mesh)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

// The symmetric Hausdorff distance between `a` and `b` to within a hundred-thousandth of
// `diagonal` (CGAL's bounded-error algorithm, which culls the triangles that cannot hold the
// farthest point: points sampled on the meshes only approach it from below, and cost more).
template <typename Mesh>
double symmetric_hausdorff_distance(const Mesh& a, const Mesh& b, double diagonal)
{
  return CGAL::Polygon_mesh_processing::bounded_error_symmetric_Hausdorff_distance<CGAL::Parallel_if_available_tag>(
      a, b, 1e-5 * diagonal);
}

// The mean distance from the points of `a` to `b` and from those of `b` to `a` (the mean of the
// two), over 2 10^5 points drawn evenly by area on each, always the same ones (an area mean, and
// a mean needs fewer points than a maximum). The Hausdorff distance is one point's:
// where a part of the input is thinner than the new mesh's edges (a horn's tip), it is decided
// by how near a vertex happens to fall, which the rounding of a different machine changes; the
// mean tells how closely the new mesh follows the surface everywhere else.
template <typename Mesh>
double symmetric_mean_distance(const Mesh& a, const Mesh& b)
{
  typedef typename CGAL::Kernel_traits<typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel K;
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef CGAL::Surface_mesh_parameterization::internal::Aabb_tree<K, Primitive> Tree;
  const auto one_way = [](const Mesh& from, const Mesh& to) {
    // (CGAL's sampler places each point in its triangle with the process-wide default generator,
    // whatever seed it is given, so that what drew from it before moves the points: the same
    // points every time are drawn here)
    std::vector<typename K::Triangle_3> triangles;
    std::vector<double> below; // the area of the triangles before each, and of all at the end
    below.push_back(0.);
    for(const auto f : faces(from)) {
      const auto h = halfedge(f, from);
      triangles.emplace_back(get(CGAL::vertex_point, from, source(h, from)), get(CGAL::vertex_point, from, target(h, from)),
                             get(CGAL::vertex_point, from, target(next(h, from), from)));
      below.push_back(below.back() + std::sqrt(CGAL::to_double(triangles.back().squared_area())));
    }
    std::mt19937 random(1);
    std::uniform_real_distribution<double> unit(0., 1.);
    std::vector<typename K::Point_3> points;
    for(int i = 0; i < 200000 && below.back() > 0.; ++i) {
      const double at = unit(random) * below.back();
      const std::size_t t = std::size_t(std::upper_bound(below.begin() + 1, below.end() - 1, at) - (below.begin() + 1));
      double r = unit(random), s = unit(random);
      if(r + s > 1.) {
        r = 1. - r;
        s = 1. - s;
      }
      const auto& tri = triangles[t];
      points.push_back(tri[0] + r * (tri[1] - tri[0]) + s * (tri[2] - tri[0]));
    }
    if(points.empty() || num_faces(to) == 0)
      return 0.;
    Tree tree(faces(to).first, faces(to).second, to);
    tree.accelerate_distance_queries();
    double sum = 0.;
    for(const auto& p : points)
      sum += std::sqrt(tree.squared_distance(p));
    return sum / double(points.size());
  };
  return 0.5 * (one_way(a, b) + one_way(b, a));
}

} // namespace smp_tools

#endif // SMP_TOOLS_SMP_SURFACE_DISTANCE_H

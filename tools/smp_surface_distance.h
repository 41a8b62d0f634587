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
#include <iterator>
#include <vector>

namespace smp_tools {

template <typename Mesh>
double bounding_box_diagonal(const Mesh& mesh)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(mesh);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

// CGAL's symmetric Hausdorff distance between `a` and `b`, on a grid of points on each spaced
// by a thousandth of `diagonal` (random points made it vary by a third between identical meshes).
template <typename Mesh>
double symmetric_hausdorff_distance(const Mesh& a, const Mesh& b, double diagonal)
{
  const auto samples = CGAL::parameters::use_grid_sampling(true).grid_spacing(diagonal / 1000.);
  return CGAL::Polygon_mesh_processing::approximate_symmetric_Hausdorff_distance<CGAL::Parallel_if_available_tag>(
      a, b, samples, samples);
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
    std::vector<typename K::Point_3> points;
    CGAL::Polygon_mesh_processing::sample_triangle_mesh(
        from, std::back_inserter(points),
        CGAL::parameters::use_random_uniform_sampling(true).number_of_points_on_faces(200000)
          .do_sample_vertices(false).do_sample_edges(false).random_seed(1u));
    Tree tree(faces(to).first, faces(to).second, to);
    tree.accelerate_distance_queries();
    double sum = 0.;
    for(const auto& p : points)
      sum += std::sqrt(tree.squared_distance(p));
    return points.empty() ? 0. : sum / double(points.size());
  };
  return 0.5 * (one_way(a, b) + one_way(b, a));
}

} // namespace smp_tools

#endif // SMP_TOOLS_SMP_SURFACE_DISTANCE_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far a new mesh is from its input, as smp-remesh reports it and the remeshing comparison
// (benchmark/) measures it: one definition for both.

#ifndef SMP_TOOLS_SMP_SURFACE_DISTANCE_H
#define SMP_TOOLS_SMP_SURFACE_DISTANCE_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/distance.h>

#include <cmath>

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

} // namespace smp_tools

#endif // SMP_TOOLS_SMP_SURFACE_DISTANCE_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_HOLE_FILLING_COMPATIBILITY_H
#define CGAL_SMP_INTERNAL_HOLE_FILLING_COMPATIBILITY_H

// CGAL 5.6 gives triangulate_hole() its new faces through the named parameter
// `face_output_iterator` and deprecates the output iterator argument, which CGAL 5.5 alone
// has: the package calls this, right on both.

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/version.h>

#include <boost/graph/graph_traits.hpp>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Fills the hole of `border` by CGAL's search over all its triangulations (cubic in the hole's
// size), which adds no edge the mesh already has and, unlike CGAL's default search through a 3D
// Delaunay triangulation, depends on the hole alone; writes the new faces to `out` (none if no
// triangulation is found).
template <typename PolygonMesh, typename OutputIterator>
void fill_hole_exhaustively(PolygonMesh& mesh, typename boost::graph_traits<PolygonMesh>::halfedge_descriptor border,
                            OutputIterator out)
{
  const auto np = CGAL::parameters::use_2d_constrained_delaunay_triangulation(false).use_delaunay_triangulation(false);
#if CGAL_VERSION_NR >= 1050601000
  CGAL::Polygon_mesh_processing::triangulate_hole(mesh, border, np.face_output_iterator(out));
#else
  CGAL::Polygon_mesh_processing::triangulate_hole(mesh, border, out, np);
#endif
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_HOLE_FILLING_COMPATIBILITY_H

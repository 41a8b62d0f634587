// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_COMPONENT_FACES_H
#define CGAL_SMP_INTERNAL_COMPONENT_FACES_H

// The faces of one connected component, by a walk over faces that share an edge, marked in a
// face property map: PMP::connected_component() keeps a std::set of the faces, whose
// allocations and look-ups cost more than the walk itself.

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The faces of the component of `f0` in `tm`, `f0` first, then in the order the walk meets them.
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
component_faces(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor f0)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<typename GT::face_descriptor> found;
  auto seen = get(CGAL::dynamic_face_property_t<bool>(), tm);
  for(typename GT::face_descriptor f : faces(tm))
    put(seen, f, false);
  put(seen, f0, true);
  found.push_back(f0);
  for(std::size_t k = 0; k < found.size(); ++k)
    for(typename GT::halfedge_descriptor h : halfedges_around_face(halfedge(found[k], tm), tm)) {
      const typename GT::face_descriptor g = face(opposite(h, tm), tm);
      if(g != GT::null_face() && !get(seen, g)) {
        put(seen, g, true);
        found.push_back(g);
      }
    }
  return found;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_COMPONENT_FACES_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_COMPONENT_VERTEX_INDEX_H
#define CGAL_SMP_INTERNAL_COMPONENT_VERTEX_INDEX_H

// The vertex numbering that CGAL's free function parameterize() hands to a parameterizer (the
// vertices of one connected component numbered from 0, the others -1), made from the faces of
// component_faces(): CGAL's own (internal::fill_index_map_of_cc()) finds the component by
// PMP::connected_component(), whose std::set of faces is a sizeable share of a call's time on
// meshes of millions of faces (the benchmark's method uopt_cgal_body measures it).

#include <CGAL/Surface_mesh_parameterization/internal/component_faces.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Numbers in `vimap` the vertices of the component of the face opposite `bhd`, as CGAL's
// fill_index_map_of_cc() does: in the order of vertices(tm) if the component is the whole
// mesh, else in the order its faces are met, and -1 for the vertices of other components.
// A null or an inner `bhd` numbers nothing: the parameterizer reports it.
template <typename TriangleMesh, typename VertexIndexMap>
void number_component_vertices(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                               const TriangleMesh& tm, VertexIndexMap vimap)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  if(bhd == GT::null_halfedge() || face(opposite(bhd, tm), tm) == GT::null_face())
    return;
  const std::vector<typename GT::face_descriptor> cc = component_faces(tm, face(opposite(bhd, tm), tm));
  int index = 0;
  if(cc.size() == num_faces(tm)) {
    for(typename GT::vertex_descriptor v : vertices(tm))
      put(vimap, v, index++);
    return;
  }
  for(typename GT::vertex_descriptor v : vertices(tm))
    put(vimap, v, -1);
  for(typename GT::face_descriptor f : cc)
    for(typename GT::vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      if(get(vimap, v) < 0)
        put(vimap, v, index++);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_COMPONENT_VERTEX_INDEX_H

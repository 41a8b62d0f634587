// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_DISK_COMPONENT_H
#define CGAL_SMP_INTERNAL_DISK_COMPONENT_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The connected component of a border halfedge, checked to be a triangulated topological
// disk and copied once into flat arrays: positions and triangles by local vertex index, the
// border loop, the interior vertices (the unknowns of the linear system) and their rings in
// the order of `Vertex_around_target_circulator` from `halfedge(v, tm)`.
struct Disk_component_base
{
  Flat_triangles flat;
  std::vector<int> row;                    // local index -> row of the system, -1 on the border
  std::vector<int> interior;               // row -> local index
  std::vector<int> ring_begin;             // row -> first entry in `ring` (size rows + 1)
  std::vector<int> ring;                   // local indices of the neighbours of each row
  std::vector<int> border;                 // local indices along the border loop of `bhd`
  std::string message;                     // why `build()` failed

  std::size_t number_of_rows() const { return interior.size(); }
};

template <typename TriangleMesh>
class Disk_component : public Disk_component_base
{
  typedef boost::graph_traits<TriangleMesh>                  GT;

public:
  typedef typename GT::vertex_descriptor                     vertex_descriptor;
  typedef typename GT::halfedge_descriptor                   halfedge_descriptor;
  typedef typename GT::face_descriptor                       face_descriptor;

  std::vector<vertex_descriptor> vertices; // local index -> vertex

  // Fills the arrays; on failure returns the error and explains it in `message`.
  // `Mesh` is `TriangleMesh` or `const TriangleMesh`: a mutable mesh gets a temporary vertex
  // property sized for its whole storage, which stays valid on a `Surface_mesh` with garbage.
  template <typename Mesh, typename VertexPointMap>
  Error_code build(Mesh& tm, halfedge_descriptor bhd, VertexPointMap vpm)
  {
    if(bhd == GT::null_halfedge()) {
      for(halfedge_descriptor h : halfedges(tm))
        if(is_border(h, tm))
          return fail(ERROR_WRONG_PARAMETER, "the given border halfedge is null");
      return fail(faces(tm).empty() ? ERROR_EMPTY_MESH : ERROR_NO_TOPOLOGICAL_DISC,
                  "the mesh has no border: cut it into a disk first (e.g. with a Seam_mesh)");
    }
    if(!is_border(bhd, tm))
      return fail(ERROR_WRONG_PARAMETER, "the given halfedge is not a border halfedge");

    std::vector<face_descriptor> cc_faces;
    Polygon_mesh_processing::connected_component(face(opposite(bhd, tm), tm), tm,
                                                 std::back_inserter(cc_faces));

    auto local = get(CGAL::dynamic_vertex_property_t<int>(), tm); // local index + 1; 0: unseen
    for(face_descriptor f : cc_faces)
      for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
        put(local, v, 0);

    std::size_t border_halfedges = 0;
    flat.tri.reserve(cc_faces.size());
    for(face_descriptor f : cc_faces) {
      Triangle t;
      int k = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) {
        if(k == 3)
          return fail(ERROR_NON_TRIANGULAR_MESH, "the component has a face with more than three sides");
        if(is_border(opposite(h, tm), tm))
          ++border_halfedges;
        const vertex_descriptor v = target(h, tm);
        if(get(local, v) == 0) {
          const auto& p = get(vpm, v);
          const Vec3 x = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
          if(!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
            return fail(ERROR_WRONG_PARAMETER, "a vertex has a non-finite coordinate (NaN or infinity)");
          vertices.push_back(v);
          flat.xyz.push_back(x);
          put(local, v, int(vertices.size()));
        }
        t[k++] = get(local, v) - 1;
      }
      if(k != 3)
        return fail(ERROR_NON_TRIANGULAR_MESH, "the component has a face with fewer than three sides");
      flat.tri.push_back(t);
    }

    row.assign(vertices.size(), 0);
    for(halfedge_descriptor h : halfedges_around_face(bhd, tm)) {
      const int v = get(local, target(h, tm)) - 1;
      if(row[v] == -1)
        return fail(ERROR_NO_TOPOLOGICAL_DISC, "the border passes twice through a vertex");
      row[v] = -1;
      border.push_back(v);
    }
    if(border_halfedges != border.size())
      return fail(ERROR_NO_TOPOLOGICAL_DISC,
                  "the component has several boundaries (holes): only disks are supported");
    // Euler characteristic of a disk: V - E + F = 1, with 2E = 3F + (border edges)
    const long long nv = (long long)vertices.size(), nf = (long long)flat.tri.size();
    const long long ne = (3 * nf + (long long)border_halfedges) / 2;
    if(nv - ne + nf != 1)
      return fail(ERROR_NO_TOPOLOGICAL_DISC, "the component is not a topological disk (it has handles)");

    for(std::size_t v = 0; v < vertices.size(); ++v)
      if(row[v] == 0) {
        row[v] = int(interior.size());
        interior.push_back(int(v));
      }

    ring_begin.assign(1, 0);
    for(int v : interior) {
      int degree = 0;
      for(vertex_descriptor w : vertices_around_target(halfedge(vertices[v], tm), tm)) {
        ring.push_back(get(local, w) - 1);
        ++degree;
      }
      if(degree < 3)
        return fail(ERROR_NON_TRIANGULAR_MESH, "an interior vertex has fewer than three neighbours");
      ring_begin.push_back(int(ring.size()));
    }
    return OK;
  }

private:
  Error_code fail(Error_code e, const char* why)
  {
    message = why;
    return e;
  }
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_DISK_COMPONENT_H

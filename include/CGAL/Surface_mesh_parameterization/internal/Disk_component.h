// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_DISK_COMPONENT_H
#define CGAL_SMP_INTERNAL_DISK_COMPONENT_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/component_faces.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The connected component of a border halfedge, checked to be a triangulated topological
// disk, possibly with holes, and copied once into flat arrays: positions and triangles by local
// vertex index, the border loop of the halfedge, the interior vertices (the unknowns of the
// linear system) and their rings. Each inner hole is closed by a virtual vertex at the centroid
// of its boundary (after the real vertices) and a fan of virtual faces. A ring is in the order
// of `Vertex_around_target_circulator` from `halfedge(v, tm)`, or, around a hole, in the order
// of the flat faces (`flat_ring`).
struct Disk_component_base
{
  Flat_triangles flat;
  std::vector<int> row;                    // local index -> row of the system, -1 on the border
  std::vector<int> interior;               // row -> local index
  std::vector<int> ring_begin;             // row -> first entry in `ring` (size rows + 1)
  std::vector<int> ring;                   // local indices of the neighbours of each row
  std::vector<int> border;                 // local indices along the border loop of `bhd`
  std::vector<Triangle> virtual_tri;       // faces closing the inner holes (not measured)
  std::vector<char> flat_ring;             // row -> ring taken from the flat faces (around a hole)
  std::size_t holes = 0;                   // inner boundaries closed by a virtual fan
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

    const std::vector<face_descriptor> cc_faces = component_faces(tm, face(opposite(bhd, tm), tm));

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

    // the border loops: the one of `bhd` is fixed, every other one is an inner hole
    const int real_vertices = int(vertices.size());
    std::vector<int> loop_of(real_vertices, -1);
    std::vector<std::vector<halfedge_descriptor> > loops;
    std::size_t loop_halfedges = 0;
    auto walk = [&](halfedge_descriptor start) {
      const int id = int(loops.size());
      loops.emplace_back();
      for(halfedge_descriptor h : halfedges_around_face(start, tm)) {
        const int v = get(local, target(h, tm)) - 1;
        // a vertex where the border touches itself, or one of another component (the loop
        // goes on there through a vertex the two share): not a manifold surface
        if(v < 0 || loop_of[v] != -1)
          return false;
        loop_of[v] = id;
        loops.back().push_back(h);
        ++loop_halfedges;
      }
      return true;
    };
    if(!walk(bhd))
      return fail(ERROR_NO_TOPOLOGICAL_DISC, "the border passes twice through a vertex, or through another component");
    for(face_descriptor f : cc_faces)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
        if(is_border(opposite(h, tm), tm) && loop_of[get(local, source(h, tm)) - 1] == -1)
          if(!walk(opposite(h, tm)))
            return fail(ERROR_NO_TOPOLOGICAL_DISC, "two boundaries meet at a vertex");
    if(loop_halfedges != border_halfedges)
      return fail(ERROR_NO_TOPOLOGICAL_DISC, "a boundary passes twice through a vertex");

    // Each hole is closed by a virtual fan around its centroid, in the linear system only:
    // its vertices become interior vertices with positive weights, so that Tutte's theorem
    // still holds for the disk made of the real and the virtual faces.
    for(std::size_t k = 1; k < loops.size(); ++k) {
      const int center = int(flat.xyz.size());
      Vec3 c{0., 0., 0.};
      for(halfedge_descriptor h : loops[k]) {
        const Vec3& x = flat.xyz[get(local, target(h, tm)) - 1];
        for(int i = 0; i < 3; ++i) c[i] += x[i] / double(loops[k].size());
      }
      flat.xyz.push_back(c);
      for(halfedge_descriptor h : loops[k]) // a border halfedge runs around the hole like a face's
        virtual_tri.push_back({get(local, source(h, tm)) - 1, get(local, target(h, tm)) - 1, center});
    }
    holes = loops.size() - 1;

    // Euler characteristic of a disk once the holes are closed: V - E + F = 1,
    // with 2E = 3F + (border edges), and each closed hole adding one vertex
    const long long nv = (long long)real_vertices, nf = (long long)flat.tri.size();
    const long long ne = (3 * nf + (long long)border_halfedges) / 2;
    if(nv - ne + nf + (long long)holes != 1)
      return fail(ERROR_NO_TOPOLOGICAL_DISC, "the component is not a topological disk with holes (it has handles)");

    const int all_vertices = int(flat.xyz.size());
    row.assign(all_vertices, 0);
    for(halfedge_descriptor h : loops[0]) {
      const int v = get(local, target(h, tm)) - 1;
      row[v] = -1;
      border.push_back(v);
    }
    for(int v = 0; v < all_vertices; ++v)
      if(row[v] == 0) {
        row[v] = int(interior.size());
        interior.push_back(v);
      }

    // rings: from the mesh where it is whole, from the flat faces around the closed holes
    std::vector<std::vector<std::pair<int, int> > > fans;
    std::vector<int> fan_of(all_vertices, -1);
    for(int v = 0; v < all_vertices; ++v)
      if(v >= real_vertices || loop_of[v] > 0) {
        fan_of[v] = int(fans.size());
        fans.emplace_back();
      }
    auto collect = [&](const Triangle& t) {
      for(int k = 0; k < 3; ++k)
        if(fan_of[t[k]] >= 0)
          fans[fan_of[t[k]]].emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
    };
    for(const Triangle& t : flat.tri) collect(t);
    for(const Triangle& t : virtual_tri) collect(t);

    ring_begin.assign(1, 0);
    flat_ring.assign(interior.size(), 0);
    for(std::size_t r = 0; r < interior.size(); ++r) {
      const int v = interior[r];
      const std::size_t first = ring.size();
      if(fan_of[v] < 0) {
        for(vertex_descriptor w : vertices_around_target(halfedge(vertices[v], tm), tm))
          ring.push_back(get(local, w) - 1);
      } else if(!chain(fans[fan_of[v]])) {
        return fail(ERROR_NO_TOPOLOGICAL_DISC, "the faces around a hole do not close up");
      } else {
        flat_ring[r] = 1;
      }
      if(ring.size() - first < 3)
        return fail(ERROR_NON_TRIANGULAR_MESH, "an interior vertex has fewer than three neighbours");
      ring_begin.push_back(int(ring.size()));
    }
    return OK;
  }

private:
  // Appends to `ring` the neighbours of a vertex given by the (previous, next) pairs of its
  // faces, in order around it; false unless they close up into one cycle.
  bool chain(std::vector<std::pair<int, int> >& fan)
  {
    const std::size_t d = fan.size();
    if(d == 0)
      return false;
    int current = fan[0].first;
    for(std::size_t k = 0; k < d; ++k) {
      auto it = std::find_if(fan.begin(), fan.end(), [current](const std::pair<int, int>& e) { return e.first == current; });
      if(it == fan.end())
        return false;
      ring.push_back(current);
      current = it->second;
      it->first = -1; // used
    }
    return current == ring[ring.size() - d];
  }

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

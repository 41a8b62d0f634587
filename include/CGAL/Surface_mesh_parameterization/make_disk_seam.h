// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MAKE_DISK_SEAM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MAKE_DISK_SEAM_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {

// Shortest edge paths (Dijkstra on edge lengths) from `source` over a vertex-indexed graph.
template <typename TriangleMesh, typename VertexIndex, typename VertexPointMap>
void shortest_paths(const TriangleMesh& tm, VertexIndex index, VertexPointMap vpm,
                    const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertices,
                    int source, std::vector<double>& dist, std::vector<int>& previous)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  dist.assign(vertices.size(), std::numeric_limits<double>::infinity());
  previous.assign(vertices.size(), -1);
  typedef std::pair<double, int> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  dist[source] = 0.;
  queue.emplace(0., source);
  while(!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    if(top.first > dist[top.second])
      continue;
    const auto& p = get(vpm, vertices[top.second]);
    for(halfedge_descriptor h : halfedges_around_source(vertices[top.second], tm)) {
      const int w = get(index, target(h, tm));
      const auto& q = get(vpm, target(h, tm));
      const double dx = CGAL::to_double(q.x()) - CGAL::to_double(p.x());
      const double dy = CGAL::to_double(q.y()) - CGAL::to_double(p.y());
      const double dz = CGAL::to_double(q.z()) - CGAL::to_double(p.z());
      const double d = top.first + std::sqrt(dx * dx + dy * dy + dz * dz);
      if(d < dist[w]) {
        dist[w] = d;
        previous[w] = top.second;
        queue.emplace(d, w);
      }
    }
  }
}

} // namespace internal

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Cuts a closed surface of genus 0 into a topological disk: marks as seam of `mesh` the
/// shortest edge path between two vertices far apart (the ends of a double Dijkstra sweep,
/// an approximate diameter), and returns in `bhd` a border halfedge of the cut mesh, ready for
/// `parameterize()`. The underlying mesh is not modified.
///
/// A closed surface with handles (genus > 0) cannot be opened into a disk by one path: the
/// function then returns an error, and the seams must be given by the caller
/// (`Seam_mesh::add_seams()`), so that they cut every handle.
///
/// \tparam TriangleMesh a model of `FaceGraph`, with an internal vertex point map
/// \tparam SeamEdgeMap,SeamVertexMap the property maps of the `Seam_mesh`
///
/// \param mesh a seam mesh over a closed, connected triangle mesh, with no seam yet
/// \param bhd receives a border halfedge of `mesh` (on the new seam)
/// \param why if not null, receives the reason of a failure
///
/// \returns `OK`, or `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
/// `ERROR_NO_TOPOLOGICAL_BALL` (a border, several components, or a genus above 0), with the
/// reason in `why` if given.
template <typename TriangleMesh, typename SeamEdgeMap, typename SeamVertexMap>
Error_code make_disk_seam(Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap>& mesh,
                          typename boost::graph_traits<Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> >::halfedge_descriptor& bhd,
                          std::string* why = nullptr)
{
  typedef boost::graph_traits<TriangleMesh>                          GT;
  typedef typename GT::vertex_descriptor                             vertex_descriptor;
  typedef typename GT::halfedge_descriptor                           halfedge_descriptor;
  typedef typename GT::face_descriptor                               face_descriptor;
  typedef boost::graph_traits<Seam_mesh<TriangleMesh, SeamEdgeMap, SeamVertexMap> > SGT;

  auto fail = [why](Error_code e, const char* reason) {
    if(why != nullptr) *why = reason;
    return e;
  };
  const TriangleMesh& tm = mesh.mesh();
  if(faces(tm).empty())
    return fail(ERROR_EMPTY_MESH, "the mesh has no face");

  std::vector<vertex_descriptor> vertices;
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  for(vertex_descriptor v : CGAL::vertices(tm)) {
    put(index, v, int(vertices.size()));
    vertices.push_back(v);
  }
  std::size_t nf = 0, ne = 0;
  for(face_descriptor f : faces(tm)) {
    if(CGAL::halfedges_around_face(halfedge(f, tm), tm).size() != 3)
      return fail(ERROR_NON_TRIANGULAR_MESH, "a face is not a triangle");
    ++nf;
  }
  for(halfedge_descriptor h : halfedges(tm)) {
    if(is_border(h, tm))
      return fail(ERROR_NO_TOPOLOGICAL_BALL, "the mesh has a border: it is not closed");
    ++ne;
  }
  ne /= 2;
  // Euler characteristic of a sphere
  if((long long)vertices.size() - (long long)ne + (long long)nf != 2)
    return fail(ERROR_NO_TOPOLOGICAL_BALL,
                "the mesh is not one closed surface of genus 0 (several components, isolated vertices or handles): give the seams");

  const auto vpm = get(CGAL::vertex_point, tm);
  std::vector<double> dist;
  std::vector<int> previous;
  auto farthest = [&](int source) {
    internal::shortest_paths(tm, index, vpm, vertices, source, dist, previous);
    int far = source;
    for(int v = 0; v < int(vertices.size()); ++v)
      if(dist[v] > dist[far])
        far = v;
    return far;
  };
  const int a = farthest(0);
  for(double d : dist)
    if(!std::isfinite(d))
      return fail(ERROR_NO_TOPOLOGICAL_BALL, "the mesh has several connected components");
  const int b = farthest(a); // leaves the paths from a in `previous`
  if(!std::isfinite(dist[b]) || b == a || previous[b] == a)
    return fail(ERROR_NO_TOPOLOGICAL_BALL, "no seam of two edges or more could be found");

  for(int v = b; v != a; v = previous[v])
    mesh.add_seam(vertices[previous[v]], vertices[v]);
  // a halfedge of the seam mesh on the new border
  for(typename SGT::halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh)) {
      bhd = h;
      return OK;
    }
  return fail(ERROR_NO_TOPOLOGICAL_BALL, "the seam did not open the mesh");
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MAKE_DISK_SEAM_H

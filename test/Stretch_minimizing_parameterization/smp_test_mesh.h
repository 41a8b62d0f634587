// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tests on CGAL::Surface_mesh share: its types, the bundled meshes, uv maps, and a
// planar grid.

#ifndef SMP_TEST_MESH_H
#define SMP_TEST_MESH_H

#include "smp_test_util.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace smp_test {

typedef CGAL::Simple_cartesian<double>                  Kernel;
typedef Kernel::Point_2                                 Point_2;
typedef Kernel::Point_3                                 Point_3;
typedef Kernel::Vector_3                                Vector_3;
typedef CGAL::Surface_mesh<Point_3>                     Mesh;
typedef Mesh::Vertex_index                              vertex_descriptor;
typedef Mesh::Halfedge_index                            halfedge_descriptor;
typedef Mesh::Face_index                                face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>  UV_map;

// The bundled mesh `name` (a failed check if it cannot be read).
inline Mesh read_mesh(const std::string& name)
{
  Mesh m;
  const bool ok = CGAL::IO::read_polygon_mesh(data_file(name), m);
  SMP_CHECK(ok && !faces(m).empty(), "cannot read " << name);
  return m;
}

// A bundled mesh and a halfedge of its longest border.
struct Loaded
{
  Mesh mesh;
  halfedge_descriptor bhd;
};

inline Loaded load(const std::string& name)
{
  Loaded l{read_mesh(name), halfedge_descriptor()};
  l.bhd = CGAL::Polygon_mesh_processing::longest_border(l.mesh).first;
  return l;
}

// Where a new uv map puts every vertex: a vertex left unwritten shows.
const Point_2 unwritten_uv(-7., -7.);

inline UV_map new_uv(Mesh& m, const std::string& name)
{
  return m.add_property_map<vertex_descriptor, Point_2>(name, unwritten_uv).first;
}

// The maps that a parameterizer's member parameterize() takes: uv at `unwritten_uv`, vimap
// numbering every vertex 0..n-1, vpmap false.
struct Maps
{
  UV_map uv;
  Mesh::Property_map<vertex_descriptor, int> vi;
  Mesh::Property_map<vertex_descriptor, bool> vp;
};

inline Maps make_maps(Mesh& m)
{
  Maps maps;
  maps.uv = m.add_property_map<vertex_descriptor, Point_2>("v:test_uv", unwritten_uv).first;
  maps.vi = m.add_property_map<vertex_descriptor, int>("v:test_index", -1).first;
  maps.vp = m.add_property_map<vertex_descriptor, bool>("v:test_parameterized", false).first;
  int i = 0;
  for(vertex_descriptor v : vertices(m)) {
    put(maps.uv, v, unwritten_uv);
    put(maps.vi, v, i++);
    put(maps.vp, v, false);
  }
  return maps;
}

// The border halfedge whose source is `s` (null if none).
inline halfedge_descriptor border_halfedge_from(const Mesh& m, vertex_descriptor s)
{
  for(halfedge_descriptor h : halfedges(m))
    if(is_border(h, m) && source(h, m) == s)
      return h;
  return boost::graph_traits<Mesh>::null_halfedge();
}

// The largest distance between the uv of a vertex in `a` and in `b`.
inline double max_distance(const Mesh& m, UV_map a, UV_map b)
{
  double d = 0.;
  for(vertex_descriptor v : vertices(m))
    d = (std::max)(d, std::hypot(a[v].x() - b[v].x(), a[v].y() - b[v].y()));
  return d;
}

// A planar (nx x ny)-cell grid at z = 0, cell (i, j) split along (i, j)-(i+1, j+1) (or a quad),
// faces counterclockwise seen from +z; vertex (i, j) is at (i, j, 0).
struct Grid
{
  Mesh mesh;
  std::vector<vertex_descriptor> v;
  int nx = 0;
  vertex_descriptor at(int i, int j) const { return v[std::size_t(j * (nx + 1) + i)]; }
};

inline Grid make_grid(int nx, int ny, bool quads = false)
{
  Grid g;
  g.nx = nx;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      g.v.push_back(g.mesh.add_vertex(Point_3(i, j, 0)));
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i) {
      if(quads) {
        g.mesh.add_face(g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1), g.at(i, j + 1));
      } else {
        g.mesh.add_face(g.at(i, j), g.at(i + 1, j), g.at(i + 1, j + 1));
        g.mesh.add_face(g.at(i, j), g.at(i + 1, j + 1), g.at(i, j + 1));
      }
    }
  return g;
}

} // namespace smp_test

#endif // SMP_TEST_MESH_H

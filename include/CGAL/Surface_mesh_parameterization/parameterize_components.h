// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZE_COMPONENTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZE_COMPONENTS_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// One chart of `parameterize_components()`: a connected component and where it went.
struct Chart
{
  std::size_t faces = 0;        ///< faces of the component
  Error_code status = OK;       ///< what its parameterization returned
  double area_3d = 0.;          ///< its surface area
  /// abscissa of the lower left corner of its box in the final uv map (`y`: its ordinate)
  double x = 0., y = 0.;        ///< lower left corner of its box in the final uv map
  /// width of its box in the final uv map, 0 if not parameterized (`height`: its height)
  double width = 0., height = 0.; ///< size of its box in the final uv map (0 if not parameterized)
};

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Parameterizes every connected component of `mesh` that has a border into its own chart,
/// with `parameterizer` (a copy of it per component, on the longest border of the component),
/// and lays the charts side by side in one uv map without overlap: each chart is scaled so that
/// uv area is proportional to surface area (one texel density for all), then the charts are
/// packed in rows by decreasing height, with a gap, and the whole is scaled into the unit square.
///
/// A closed component has no border to fix: it is left unwritten with
/// `ERROR_NO_TOPOLOGICAL_DISC` (cut it first, e.g. with `make_disk_seam()` on a `Seam_mesh`).
/// A component whose parameterization fails is left unwritten too; the others are laid out.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam Parameterizer a model of `Parameterizer_3` for `TriangleMesh`
/// \tparam VertexUVmap a model of `ReadWritePropertyMap` from `vertex_descriptor` to a 2D point
///
/// \param mesh the mesh; its components are parameterized, the mesh itself is not modified
/// \param parameterizer the parameterizer, copied for each component
/// \param uvmap receives the position in the plane of every vertex of the parameterized components
/// \param charts if not null, receives one `Chart` per component, in the order of
///        `Polygon_mesh_processing::connected_components()`
/// \param gap the space left around each chart, as a fraction of the square root of the total
///        uv area of the charts
/// \returns `OK` if every component was parameterized, else the first error met; `ERROR_EMPTY_MESH`
/// for a mesh without faces.
template <typename TriangleMesh, typename Parameterizer, typename VertexUVmap>
Error_code parameterize_components(TriangleMesh& mesh, const Parameterizer& parameterizer, VertexUVmap uvmap,
                                   std::vector<Chart>* charts = nullptr, double gap = 0.01)
{
  typedef boost::graph_traits<TriangleMesh>                        GT;
  typedef typename GT::vertex_descriptor                           vertex_descriptor;
  typedef typename GT::halfedge_descriptor                         halfedge_descriptor;
  typedef typename GT::face_descriptor                             face_descriptor;
  typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;

  if(faces(mesh).empty())
    return ERROR_EMPTY_MESH;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t n = Polygon_mesh_processing::connected_components(mesh, component);
  std::vector<std::vector<face_descriptor> > cc(n);
  for(face_descriptor f : faces(mesh))
    cc[get(component, f)].push_back(f);

  std::vector<Chart> out(n);
  Error_code result = OK;
  std::vector<std::vector<vertex_descriptor> > chart_vertices(n);
  std::vector<std::array<double, 4> > box(n); // xmin, ymin, xmax, ymax of each chart's uv
  const auto vpm = get(CGAL::vertex_point, mesh);
  auto seen = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  auto on_visited_loop = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(std::size_t c = 0; c < n; ++c) {
    out[c].faces = cc[c].size();
    // the longest border loop of the component, and its area
    halfedge_descriptor bhd = GT::null_halfedge();
    double longest = -1.;
    for(face_descriptor f : cc[c]) {
      const halfedge_descriptor h0 = halfedge(f, mesh);
      const auto& p = get(vpm, source(h0, mesh));
      const auto& q = get(vpm, target(h0, mesh));
      const auto& r = get(vpm, target(next(h0, mesh), mesh));
      out[c].area_3d += std::sqrt(CGAL::to_double(CGAL::squared_area(p, q, r)));
      for(vertex_descriptor v : vertices_around_face(h0, mesh))
        if(!get(seen, v)) {
          put(seen, v, true);
          chart_vertices[c].push_back(v);
        }
    }
    for(face_descriptor f : cc[c])
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh)) {
        const halfedge_descriptor b = opposite(h, mesh);
        if(!is_border(b, mesh) || get(on_visited_loop, target(b, mesh)))
          continue;
        double length = 0.;
        for(halfedge_descriptor e : halfedges_around_face(b, mesh)) {
          put(on_visited_loop, target(e, mesh), true);
          length += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(e, mesh)), get(vpm, target(e, mesh)))));
        }
        if(length > longest) {
          longest = length;
          bhd = b;
        }
      }
    if(bhd == GT::null_halfedge()) {
      out[c].status = ERROR_NO_TOPOLOGICAL_DISC;
    } else {
      int index = 0; // the component's vertices numbered from 0, as fixed-border methods expect
      for(vertex_descriptor v : chart_vertices[c]) {
        put(vimap, v, index++);
        put(vpmap, v, false);
      }
      Parameterizer p = parameterizer;
      out[c].status = p.parameterize(mesh, bhd, uvmap, vimap, vpmap);
    }
    if(out[c].status != OK) {
      if(result == OK)
        result = out[c].status;
      continue;
    }
    // scale to the surface area: one texel density for every chart
    double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL, area_uv = 0.;
    for(face_descriptor f : cc[c]) {
      const halfedge_descriptor h0 = halfedge(f, mesh);
      const Point_2 a = get(uvmap, source(h0, mesh)), b = get(uvmap, target(h0, mesh)),
                    d = get(uvmap, target(next(h0, mesh), mesh));
      area_uv += std::abs(CGAL::to_double((b.x() - a.x()) * (d.y() - a.y()) - (d.x() - a.x()) * (b.y() - a.y()))) / 2.;
    }
    const double s = area_uv > 0. ? std::sqrt(out[c].area_3d / area_uv) : 1.;
    for(vertex_descriptor v : chart_vertices[c]) {
      const Point_2 q = get(uvmap, v);
      const double x = s * CGAL::to_double(q.x()), y = s * CGAL::to_double(q.y());
      put(uvmap, v, Point_2(x, y));
      xmin = (std::min)(xmin, x); ymin = (std::min)(ymin, y);
      xmax = (std::max)(xmax, x); ymax = (std::max)(ymax, y);
    }
    box[c] = {xmin, ymin, xmax, ymax};
    out[c].width = xmax - xmin;
    out[c].height = ymax - ymin;
  }

  // shelf packing by decreasing height, rows about as wide as the square root of the total area
  std::vector<std::size_t> order;
  double total = 0.;
  for(std::size_t c = 0; c < n; ++c)
    if(out[c].status == OK) {
      order.push_back(c);
      total += out[c].width * out[c].height;
    }
  if(order.empty()) {
    if(charts != nullptr)
      *charts = out;
    return result;
  }
  std::sort(order.begin(), order.end(), [&out](std::size_t a, std::size_t b) { return out[a].height > out[b].height; });
  const double margin = gap * std::sqrt(total);
  double row_width = std::sqrt(total) * 1.2;
  for(std::size_t c : order)
    row_width = (std::max)(row_width, out[c].width + 2. * margin);
  double x = 0., y = 0., row_height = 0., extent = 0.;
  for(std::size_t c : order) {
    if(x > 0. && x + out[c].width + 2. * margin > row_width) {
      x = 0.;
      y += row_height;
      row_height = 0.;
    }
    out[c].x = x + margin;
    out[c].y = y + margin;
    x += out[c].width + 2. * margin;
    row_height = (std::max)(row_height, out[c].height + 2. * margin);
    extent = (std::max)(extent, (std::max)(x, y + row_height));
  }
  // into the unit square
  for(std::size_t c : order) {
    for(vertex_descriptor v : chart_vertices[c]) {
      const Point_2 q = get(uvmap, v);
      put(uvmap, v, Point_2((CGAL::to_double(q.x()) - box[c][0] + out[c].x) / extent,
                            (CGAL::to_double(q.y()) - box[c][1] + out[c].y) / extent));
    }
    out[c].x /= extent;
    out[c].y /= extent;
    out[c].width /= extent;
    out[c].height /= extent;
  }
  if(charts != nullptr)
    *charts = out;
  return result;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZE_COMPONENTS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_NATURAL_BORDER_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_NATURAL_BORDER_PARAMETERIZER_3_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/component_faces.h>

#include <CGAL/Default.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// A "natural" border (Yoshizawa et al. 2004 \cgalCite{cgal:ybs-fssmm-04}, figure 12): the
/// border of a free-border conformal map (by default CGAL's `LSCM_parameterizer_3`, Lévy et
/// al. 2002 \cgalCite{cgal:lprm-lscm-02}), scaled into the unit square and then fixed. A
/// fixed-border method started from it keeps the border shape of the conformal map, which
/// suits a surface far from a square much better than a square does.
///
/// Such a border is generally not convex, so Tutte's theorem no longer rules out flipped
/// faces: `Stretch_minimizing_parameterizer_3` then checks every step and never returns a
/// flipped map (it keeps the best flip-free step, or fails with `ERROR_NO_1_TO_1_MAPPING`).
/// When the conformal map folds the border over itself (its border polygon is not simple),
/// this class returns `ERROR_NO_1_TO_1_MAPPING`, and `why()` says so.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (a triangle mesh)
/// \tparam FreeBorderParameterizer_ a model of `Parameterizer_3` that maps the whole component
///         (border included) to the plane and writes every vertex of it.
///         <b>%Default:</b> `LSCM_parameterizer_3<TriangleMesh_>`
///
/// It is used as the border parameterizer of a fixed-border method, e.g.
/// \code
///   typedef SMP::Natural_border_parameterizer_3<Mesh>                 Border;
///   typedef SMP::Shape_preserving_parameterizer_3<Mesh, Border>       Initializer;
///   SMP::Stretch_minimizing_parameterizer_3<Mesh, Initializer>         parameterizer;
/// \endcode
template <class TriangleMesh_, class FreeBorderParameterizer_ = Default>
class Natural_border_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                    Triangle_mesh;
  /// Triangle mesh type (the spelling of CGAL's parameterizers)
  typedef TriangleMesh_                                                    TriangleMesh;
  /// Free-border parameterizer type
  typedef typename Default::Get<FreeBorderParameterizer_, LSCM_parameterizer_3<TriangleMesh_> >::type
                                                                           Free_border_parameterizer;
  /// Mesh vertex type
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor   vertex_descriptor;
  /// Mesh halfedge type
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor halfedge_descriptor;

private:
  typedef typename boost::graph_traits<Triangle_mesh>::face_descriptor     face_descriptor;
  typedef CGAL::Simple_cartesian<double>                                   K;

public:
  /// Constructor.
  /// \param free the free-border parameterizer whose border is used
  explicit Natural_border_parameterizer_3(const Free_border_parameterizer& free = Free_border_parameterizer())
    : m_free(free)
  { }

  /// Runs the free-border parameterizer on the component of `bhd` (with its own maps: the
  /// caller's maps get only the border) and places the border of `bhd` where it put it, scaled
  /// so that its bounding box fits the unit square.
  ///
  /// \tparam VertexUVMap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and a 2D point as value
  /// \tparam VertexIndexMap ignored: the free-border parameterizer gets a numbering of its own
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key and `bool` as value
  ///
  /// \param mesh the triangle mesh
  /// \param bhd a halfedge on the border to parameterize
  /// \param uvmap receives the position in the plane of every vertex of the border
  /// \param vpmap receives `true` for every vertex of the border
  ///
  /// \returns `OK`, `ERROR_WRONG_PARAMETER` if `bhd` is not a border halfedge, the error of the
  /// free-border parameterizer, or `ERROR_NO_1_TO_1_MAPPING` if
  /// the border it gives is not a simple polygon (`why()` tells which).
  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVMap uvmap,
                          VertexIndexMap, VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVMap>::value_type Point_2;
    m_why.clear();
    m_free_flips = 0;
    if(bhd == halfedge_descriptor() || !is_border(bhd, mesh)) {
      m_why = "no border halfedge";
      return ERROR_WRONG_PARAMETER;
    }
    // the free-border method numbers the vertices of the component from 0: give it a
    // numbering of its own (the caller's may cover other components or isolated vertices)
    auto index = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
    auto free_uv = get(CGAL::dynamic_vertex_property_t<K::Point_2>(), mesh);
    auto free_vp = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
    const std::vector<face_descriptor> cc = internal::component_faces(mesh, face(opposite(bhd, mesh), mesh));
    for(face_descriptor f : cc)
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
        put(index, v, -1);
    int n = 0;
    for(face_descriptor f : cc)
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
        if(get(index, v) < 0) {
          put(index, v, n++);
          put(free_uv, v, K::Point_2(0, 0));
          put(free_vp, v, false);
        }
    const Error_code status = m_free.parameterize(mesh, bhd, free_uv, index, free_vp);
    if(status != OK) {
      m_why = "the free-border parameterization failed";
      return status;
    }

    // how much the free-border map itself folds over (its interior is not used)
    std::size_t positive = 0, negative = 0;
    for(face_descriptor f : cc) {
      std::vector<K::Point_2> q;
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
        q.push_back(get(free_uv, v));
      const double area = CGAL::area(q[0], q[1], q[2]);
      if(area > 0.) ++positive;
      else if(area < 0.) ++negative;
    }
    m_free_flips = (std::min)(positive, negative);

    CGAL::Polygon_2<K> polygon;
    for(halfedge_descriptor h : halfedges_around_face(bhd, mesh))
      polygon.push_back(get(free_uv, target(h, mesh)));
    for(const K::Point_2& p : polygon.container())
      if(!std::isfinite(p.x()) || !std::isfinite(p.y())) {
        m_why = "the free-border parameterization gave non-finite positions";
        return ERROR_NO_1_TO_1_MAPPING;
      }
    if(polygon.size() < 3 || !polygon.is_simple()) {
      m_why = "the free-border map folds its border over itself (the border is not a simple polygon)";
      return ERROR_NO_1_TO_1_MAPPING;
    }
    const CGAL::Bbox_2 box = polygon.bbox();
    const double scale = (std::max)(box.xmax() - box.xmin(), box.ymax() - box.ymin());
    if(!(scale > 0.)) {
      m_why = "the border collapsed to a point";
      return ERROR_NO_1_TO_1_MAPPING;
    }
    for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) {
      const K::Point_2 p = get(free_uv, target(h, mesh));
      put(uvmap, target(h, mesh), Point_2((p.x() - box.xmin()) / scale, (p.y() - box.ymin()) / scale));
      put(vpmap, target(h, mesh), true);
    }
    return OK;
  }

  /// A natural border is in general not convex.
  bool is_border_convex() const { return false; }

  /// Why the last call failed (empty after a success).
  const std::string& why() const { return m_why; }

  /// Faces that the free-border map of the last call flipped (its interior is discarded; a
  /// large number warns that its border may be a poor start).
  std::size_t number_of_free_border_flipped_faces() const { return m_free_flips; }

private:
  Free_border_parameterizer m_free;
  std::string m_why;
  std::size_t m_free_flips = 0;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_NATURAL_BORDER_PARAMETERIZER_3_H

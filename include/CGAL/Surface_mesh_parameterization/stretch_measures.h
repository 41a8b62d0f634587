// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MEASURES_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MEASURES_H

#include <CGAL/Surface_mesh_parameterization/Face_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Measures of a whole parameterization, as in the tables of Yoshizawa et al. (2004).
/// Stretches are normalized by \f$ \sqrt{\sum A_{uv} / \sum A_{3D}} \f$, so that 1 is an
/// isometry up to scale, and leave out the degenerate faces (zero area in 3D or in uv).
struct Stretch_statistics
{
  double l2_stretch = 0.;             ///< \f$ \sqrt{\sum A_{3D} (L^2)^2 / \sum A_{3D}} \f$, normalized
  double linf_stretch = 0.;           ///< \f$ \max L^\infty \f$, normalized
  double edge_distortion = 0.;        ///< \f$ \sum_{edges} | \ell_{3D} / \sum \ell_{3D} - \ell_{uv} / \sum \ell_{uv} | \f$
  double angle_distortion = 0.;       ///< mean \f$ |\theta_{3D} - \theta_{uv}| \f$ over the corners of the non-degenerate faces (radians)
  double area_distortion = 0.;        ///< \f$ \sum_{faces} | A_{3D} / \sum A_{3D} - |A_{uv}| / \sum |A_{uv}| | \f$
  std::size_t number_of_faces = 0;    ///< faces measured
  std::size_t flipped_faces = 0;      ///< non-degenerate faces oriented against the total signed uv area
  std::size_t degenerate_uv_faces = 0;///< faces of zero uv area (and non-zero 3D area)
  std::size_t degenerate_3d_faces = 0;///< faces of zero 3D area
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Returns the stretch of the map from the parameter triangle `(q1, q2, q3)` to the 3D
/// triangle `(p1, p2, p3)`.
/// \tparam Point_3 a 3D point type with `x()`, `y()`, `z()`
/// \tparam Point_2 a 2D point type with `x()`, `y()`
/// \param p1,p2,p3 the corners of the 3D triangle
/// \param q1,q2,q3 the corners of the parameter triangle, in the same order
template <typename Point_3, typename Point_2>
Face_stretch face_stretch(const Point_3& p1, const Point_3& p2, const Point_3& p3,
                          const Point_2& q1, const Point_2& q2, const Point_2& q3)
{
  auto p = [](const Point_3& x) {
    return internal::Vec3{CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z())};
  };
  auto q = [](const Point_2& x) { return internal::Vec2{CGAL::to_double(x.x()), CGAL::to_double(x.y())}; };
  return internal::triangle_stretch(p(p1), p(p2), p(p3), q(q1), q(q2), q(q3));
}

namespace internal {

// Copies the triangles of `face_range` into flat arrays, with the points of the
// `vertex_point_map` of `np`; `vertices` receives the local numbering.
template <typename FaceRange, typename TriangleMesh, typename VertexUVMap, typename NamedParameters>
void flatten(const FaceRange& face_range, const TriangleMesh& tm, VertexUVMap uvmap, const NamedParameters& np,
             Flat_triangles& flat, std::vector<Vec2>& uv,
             std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vertices)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto local = get(CGAL::dynamic_vertex_property_t<int>(), tm); // index + 1; 0: unseen
  for(face_descriptor f : face_range)
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      put(local, v, 0);
  for(face_descriptor f : face_range) {
    Triangle t{{0, 0, 0}};
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm)) {
      if(k == 3)
        break; // precondition: triangles
      if(get(local, v) == 0) {
        const auto& p = get(vpm, v);
        const auto& q = get(uvmap, v);
        vertices.push_back(v);
        flat.xyz.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
        uv.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y())});
        put(local, v, int(vertices.size()));
      }
      t[k++] = get(local, v) - 1;
    }
    flat.tri.push_back(t);
  }
}

// The faces of `face_range` flattened and their stretch evaluated: what every measure starts from.
template <typename TriangleMesh>
struct Measured_faces
{
  Flat_triangles flat;
  std::vector<Vec2> uv;
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertices; // by local index
  Flat_stretch stretch;
  Flat_stretch_summary summary;

  template <typename FaceRange, typename VertexUVMap, typename NamedParameters>
  Measured_faces(const FaceRange& face_range, const TriangleMesh& tm, VertexUVMap uvmap, const NamedParameters& np)
  {
    flatten(face_range, tm, uvmap, np, flat, uv, vertices);
    summary = stretch.evaluate(flat, uv);
  }
};

} // namespace internal

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Measures the parameterization `uvmap` over the faces of `face_range`.
///
/// \tparam FaceRange a range of `face_descriptor`
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from `vertex_descriptor` to a 2D point
/// \tparam T,Tag,Base the types of the named parameters `np` (deduced)
///
/// \param face_range the faces to measure
/// \param tm the mesh of these faces
/// \param uvmap the parameterization to measure
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and a 3D point as value}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the measures, in a `Stretch_statistics`
///
/// \pre every face of `face_range` is a triangle and every vertex of it has a uv position
template <typename FaceRange, typename TriangleMesh, typename VertexUVMap,
          typename T = bool, typename Tag = CGAL::internal_np::all_default_t,
          typename Base = CGAL::internal_np::No_property>
Stretch_statistics compute_stretch_statistics(const FaceRange& face_range, const TriangleMesh& tm,
                                              VertexUVMap uvmap,
                                              const Named_function_parameters<T, Tag, Base>& np = parameters::default_values())
{
  const internal::Measured_faces<TriangleMesh> m(face_range, tm, uvmap, np);
  const internal::Flat_stretch_summary& s = m.summary;
  const internal::Flat_distortions d = internal::flat_distortions(m.flat, m.uv, m.stretch);
  Stretch_statistics r;
  r.l2_stretch = s.l2;
  r.linf_stretch = s.linf;
  r.edge_distortion = d.edge;
  r.angle_distortion = d.angle;
  r.area_distortion = d.area;
  r.number_of_faces = m.flat.tri.size();
  r.flipped_faces = s.flipped;
  r.degenerate_uv_faces = s.degenerate_uv;
  r.degenerate_3d_faces = s.degenerate_3d;
  return r;
}

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Measures the parameterization `uvmap` over all faces of `tm`
/// (see the overload taking a face range).
/// \param tm the mesh
/// \param uvmap the parameterization to measure
/// \pre every face of `tm` is a triangle and every vertex has a uv position
template <typename TriangleMesh, typename VertexUVMap>
Stretch_statistics compute_stretch_statistics(const TriangleMesh& tm, VertexUVMap uvmap)
{
  return compute_stretch_statistics(faces(tm), tm, uvmap, parameters::default_values());
}

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Measures the parameterization `uvmap` over all faces of `tm`, with named parameters
/// (see the overload taking a face range).
/// \param tm the mesh
/// \param uvmap the parameterization to measure
/// \param np named parameters: `vertex_point_map`, as for the overload taking a face range
/// \pre every face of `tm` is a triangle and every vertex has a uv position
template <typename TriangleMesh, typename VertexUVMap, typename T, typename Tag, typename Base>
Stretch_statistics compute_stretch_statistics(const TriangleMesh& tm, VertexUVMap uvmap,
                                              const Named_function_parameters<T, Tag, Base>& np)
{
  return compute_stretch_statistics(faces(tm), tm, uvmap, np);
}

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Writes the normalized L2 stretch of every vertex of the faces of `face_range` into
/// `vertex_stretch_map`: the area-weighted RMS of the stretch of the non-degenerate faces
/// around it (Yoshizawa et al. 2004, eq. 1), times the normalization of
/// `Stretch_statistics::l2_stretch`. A vertex with no such face gets 0.
///
/// \tparam FaceRange a range of `face_descriptor`
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from `vertex_descriptor` to a 2D point
/// \tparam VertexStretchMap a model of `WritablePropertyMap` from `vertex_descriptor` to `double`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param face_range the faces to measure
/// \param tm the mesh of these faces
/// \param uvmap the parameterization to measure
/// \param vertex_stretch_map receives the stretch of every vertex of the faces of `face_range`
/// \param np an optional sequence of named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key and a 3D point as value}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \pre every face of `face_range` is a triangle and every vertex of it has a uv position
template <typename FaceRange, typename TriangleMesh, typename VertexUVMap, typename VertexStretchMap,
          typename NamedParameters = parameters::Default_named_parameters>
void compute_vertex_stretch(const FaceRange& face_range, const TriangleMesh& tm, VertexUVMap uvmap,
                            VertexStretchMap vertex_stretch_map,
                            const NamedParameters& np = parameters::default_values())
{
  const internal::Measured_faces<TriangleMesh> m(face_range, tm, uvmap, np);
  std::vector<double> sigma;
  m.stretch.vertex_stretch(m.flat, 0., sigma);
  const double normalization = m.summary.rms > 0. ? m.summary.l2 / m.summary.rms : 0.;
  for(std::size_t v = 0; v < m.vertices.size(); ++v)
    put(vertex_stretch_map, m.vertices[v], sigma[v] * normalization);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MEASURES_H

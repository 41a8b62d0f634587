// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_REMESH_WITH_PARAMETERIZATIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_REMESH_WITH_PARAMETERIZATIONS_H

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/Remeshing_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Remeshing_pipeline.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Remeshes a disk-like triangle mesh (holes allowed) with two of its parameterizations, as
/// Yoshizawa, Belyaev and Seidel (2004) do with the interactive geometry remeshing of Alliez,
/// Meyer and Desbrun (2002): the vertices of the new mesh are sampled in U'' by error
/// diffusion of a density that compensates the area distortion of U'' (so that they are
/// spread evenly over the surface), carried to U' (\f$ U^0 \f$, Floater's shape-preserving
/// parameterization with the border on a circle), triangulated there by CGAL's constrained
/// Delaunay triangulation, lifted to the surface, flipped toward the surface's Delaunay
/// triangulation and relaxed. The closer U'' is to area-preserving, the less the sampling leans
/// on the density, and the more evenly the surface is sampled. The manual's section on
/// remeshing gives the stages and what they guarantee.
///
/// The surface is sampled evenly unless a density asks otherwise: a user's density per vertex,
/// the curvature's, or both (multiplied). The curvature's is \f$ 1 + a\, k / \bar k \f$, with
/// \f$ a \f$ the curvature adaptation, \f$ k \f$ the largest absolute principal curvature at a
/// vertex (CGAL's jet fitting on its rings) and \f$ \bar k \f$ its mean over the surface by
/// area (the ratio capped at 16): the edges shorten as \f$ 1/\sqrt{k} \f$ where the curvature
/// dominates, which keeps the distance between the triangles and the surface even. A density
/// is relative: the number of vertices stays the one asked for, and the local spacing goes as
/// the inverse square root of the density, on the border loops as inside.
///
/// Each border loop of the input is kept: the new border vertices are on it, evenly spaced,
/// and a first row of vertices runs along it inside, so that the triangles along the border
/// are as even as the others.
/// The new mesh has the input's orientation and about `number_of_vertices` vertices (within a
/// few in a thousand from a thousand vertices on, within a few vertices at a hundred or two,
/// unless the border loops alone take more).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, all faces triangles
/// \tparam PolygonMesh a model of `MutableFaceGraph`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tmesh the input: one connected component with at least one border loop
/// \param number_of_vertices the number of vertices of the new mesh
/// \param out receives the new mesh (replaced on success only)
/// \param np an optional sequence of named parameters among the ones below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{parameterization_pair}
///     \cgalParamDescription{the parameterizations {U', U''}}
///     \cgalParamType{`Remeshing_pair`}
///     \cgalParamDefault{`Remeshing_pair::U0_UOPT`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_relaxation_steps}
///     \cgalParamDescription{steps moving each interior vertex to the centroid of its triangles
///       on the surface, carried to U' (evens out the areas, widens the angles)}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_density_map}
///     \cgalParamDescription{a relative sampling density per vertex of `tmesh`, linear over each
///       face: the number of vertices per unit area of the new mesh goes as it}
///     \cgalParamType{a model of `ReadablePropertyMap` from vertices to a number type convertible
///       to `double`; each value finite and \f$ > 0 \f$}
///     \cgalParamDefault{1 everywhere}
///   \cgalParamNEnd
///   \cgalParamNBegin{curvature_adaptation}
///     \cgalParamDescription{\f$ a \f$: how much the sampling density follows the curvature
///       (0: not at all); from about \f$ 1/(1+a) \f$ times the mean density where the surface is
///       flat to \f$ (1+16a)/(1+a) \f$ times where the curvature is 16 times its mean or more}
///     \cgalParamType{`double`, finite and \f$ \ge 0 \f$}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the points of `tmesh`}
///     \cgalParamType{a model of `ReadablePropertyMap` from vertices to a 3D point type}
///     \cgalParamDefault{the internal property map for `CGAL::vertex_point_t`}
///   \cgalParamNEnd
///   \cgalParamNBegin{eta, number_of_iterations, start_weights, number_of_threads}
///     \cgalParamDescription{passed to `Stretch_minimizing_parameterizer_3` to compute U''}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the report; its `status` is `OK`, or `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
/// `ERROR_NO_TOPOLOGICAL_DISC` (no border, several components, handles),
/// `ERROR_WRONG_PARAMETER` (fewer vertices asked for than the border loops take, a coordinate
/// that is not finite, a density or curvature adaptation out of its range), an error of the
/// parameterization, or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` when memory runs out
/// (`std::bad_alloc`, caught); `message` says more.
template <typename TriangleMesh, typename PolygonMesh, typename NamedParameters = parameters::Default_named_parameters>
Remeshing_report remesh_with_parameterizations(const TriangleMesh& tmesh, std::size_t number_of_vertices, PolygonMesh& out,
                                               const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<internal::Remeshing_input::Mesh>::face_descriptor face_descriptor;
  typedef typename GetVertexPointMap<PolygonMesh>::type Output_point_map;
  typedef typename boost::property_traits<Output_point_map>::value_type Output_point;
  using parameters::choose_parameter;
  using parameters::get_parameter;

  Remeshing_report r;
  internal::Remeshing_settings settings;
  settings.start = std::chrono::steady_clock::now();
  settings.vertices = number_of_vertices;
  settings.pair = choose_parameter(get_parameter(np, internal_np::parameterization_pair), Remeshing_pair::U0_UOPT);
  settings.relaxation_steps = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_relaxation_steps),
                                               settings.relaxation_steps);
  const auto fail = [&](Error_code e, const std::string& why) {
    r.status = e;
    r.message = why;
    r.seconds = internal::seconds_since(settings.start);
    return r;
  };
  if(number_of_vertices < 3 || number_of_vertices > std::size_t((std::numeric_limits<int>::max)() / 4))
    return fail(ERROR_WRONG_PARAMETER, "the number of vertices must be at least 3 and below 2^29");
  const double adaptation = choose_parameter(get_parameter(np, internal_np::curvature_adaptation), 0.);
  if(!(adaptation >= 0.) || !std::isfinite(adaptation))
    return fail(ERROR_WRONG_PARAMETER, "the curvature adaptation must be a finite number >= 0");

  try {
    // the input copied into flat arrays and a Surface_mesh, vertices and faces from 0
    internal::Remeshing_input in;
    std::vector<typename internal::Remeshing_input::K::Point_3> points;
    std::vector<std::array<std::size_t, 3> > triangles;
    {
      typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type Input_point_map;
      std::vector<typename boost::property_traits<Input_point_map>::value_type> input_points;
      std::vector<std::vector<std::size_t> > polygons;
      Polygon_mesh_processing::polygon_mesh_to_polygon_soup(tmesh, input_points, polygons, np);
      if(polygons.empty())
        return fail(ERROR_EMPTY_MESH, "the mesh has no face");
      for(const auto& p : input_points) {
        const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
        if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
          return fail(ERROR_WRONG_PARAMETER, "a vertex coordinate is not finite");
        points.emplace_back(x, y, z);
      }
      for(const auto& p : polygons) {
        if(p.size() != 3)
          return fail(ERROR_NON_TRIANGULAR_MESH, "a face is not a triangle: triangulate the mesh first");
        triangles.push_back({p[0], p[1], p[2]});
      }
    }
    // (the soup has the vertices of `tmesh` in their order, and so has the copy)
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::vertex_density_map_t>::value) {
      const auto density = get_parameter(np, internal_np::vertex_density_map);
      for(auto v : vertices(tmesh)) {
        const double d = CGAL::to_double(get(density, v));
        if(!(d > 0.) || !std::isfinite(d))
          return fail(ERROR_WRONG_PARAMETER, "a vertex density is not a finite number > 0");
        in.density.push_back(d);
      }
    }
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, triangles, in.mesh);
    for(auto v : vertices(in.mesh)) {
      const auto& p = in.mesh.point(v);
      in.flat.xyz.push_back({p.x(), p.y(), p.z()});
    }
    for(face_descriptor f : faces(in.mesh)) {
      const auto h = halfedge(f, in.mesh);
      in.flat.tri.push_back({int(source(h, in.mesh)), int(target(h, in.mesh)), int(target(next(h, in.mesh), in.mesh))});
    }
    {
      auto component = in.mesh.add_property_map<face_descriptor, std::size_t>("f:smp_remesh_component").first;
      const std::size_t parts = Polygon_mesh_processing::connected_components(in.mesh, component);
      in.mesh.remove_property_map(component);
      if(parts != 1)
        return fail(ERROR_NO_TOPOLOGICAL_DISC, "the mesh has " + std::to_string(parts) +
                    " connected components: remeshing takes one disk (with holes)");
    }
    in.loops = internal::border_loops(in.mesh);
    if(adaptation > 0.) {
      const std::vector<double> curvature = internal::curvature_density(in.mesh, in.flat, adaptation);
      if(in.density.empty())
        in.density = curvature;
      else
        for(std::size_t i = 0; i < in.density.size(); ++i)
          in.density[i] *= curvature[i];
    }
    internal::weld_density_on_borders(in.flat, in.loops, in.density);
    if(!internal::normalize_density(in.flat, in.density))
      return fail(ERROR_WRONG_PARAMETER, "the density has no integral over the surface");
    if(!internal::parameterize_for_remeshing(in, settings.pair, np, r)) {
      r.seconds = internal::seconds_since(settings.start);
      return r;
    }
    r.seconds_parameterization = internal::seconds_since(settings.start);

    std::vector<internal::Vec3> xyz;
    std::vector<internal::Triangle> tri;
    if(!internal::remesh_flat(in, settings, xyz, tri, r)) {
      r.seconds = internal::seconds_since(settings.start);
      return r;
    }
    std::vector<Output_point> out_points;
    out_points.reserve(xyz.size());
    for(const internal::Vec3& p : xyz)
      out_points.emplace_back(p[0], p[1], p[2]);
    // built aside, so that memory running out here leaves `out` as it was
    PolygonMesh result;
    Polygon_mesh_processing::polygon_soup_to_polygon_mesh(out_points, tri, result);
    out = std::move(result);
  } catch(const std::bad_alloc&) {
    return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "out of memory (std::bad_alloc): the mesh is too large for the memory available");
  }
  r.seconds = internal::seconds_since(settings.start);
  return r;
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_REMESH_WITH_PARAMETERIZATIONS_H

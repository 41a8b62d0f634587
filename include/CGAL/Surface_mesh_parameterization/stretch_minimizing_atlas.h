// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_ATLAS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_ATLAS_H

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Atlas.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/build_atlas.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_named_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <new>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Makes a texture atlas of a polygon soup: any polygons (triangulated inside), any number of
/// parts, any genus, boundaries, non-manifold edges and vertices, vertices repeated at one
/// position (welded). The soup is cut into charts that are topological disks; each chart is
/// flattened by this package (`Stretch_minimizing_parameterizer_3` with
/// `Stretch_minimizing_preset::LOWEST_STRETCH`, then Newton steps on Sander's stretch with a free
/// border: no face flips, the border never crosses itself); a chart whose normalized L2 stretch
/// is above `max_stretch` is cut further, and neighbouring charts are joined where their union
/// still flattens within `max_stretch` (shorter seams). The charts are then scaled to one texel density,
/// turned to their smallest bounding rectangle and packed into the unit square with a gutter,
/// without overlap.
///
/// Every polygon gets a uv for each of its corners and a chart, the polygons of fewer than
/// three distinct positions too (with zero uv area). The triangles of one polygon stay in one
/// chart. The atlas depends on the soup and the options only: another call, in this process
/// or another, on any number of threads, gives the same one, bit for bit.
///
/// \tparam PointRange a range of 3D points (`x()`, `y()`, `z()`)
/// \tparam PolygonRange a range of ranges of vertex indices
/// \tparam NamedParameters a sequence of named parameters
///
/// \param points the vertex positions
/// \param polygons the polygons, as indices into `points`
/// \param np an optional sequence of named parameters among the ones below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{max_stretch}
///     \cgalParamDescription{a chart whose normalized L2 stretch is above this bound is cut further}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1.05`}
///   \cgalParamNEnd
///   \cgalParamNBegin{resolution}
///     \cgalParamDescription{texels along a side of the square texture the gutter is measured in}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`1024`}
///   \cgalParamNEnd
///   \cgalParamNBegin{gutter}
///     \cgalParamDescription{texels left between two charts (half of it along the sides of the square)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{threads flattening the charts (0: one per core); the atlas does not depend on it}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{polish_iterations}
///     \cgalParamDescription{free-border Newton steps per chart}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`10`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{called on the calling thread with an `Atlas_progress` at the end of
///       each stage and as charts are flattened and packing rounds end (progress bars, logs)}
///     \cgalParamType{a callable with a `const Atlas_progress&` (its result is ignored)}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the atlas; its `report.status` is `OK`, `ERROR_EMPTY_MESH` (no polygon),
/// `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` (memory ran out: `std::bad_alloc`, caught) or
/// `ERROR_WRONG_PARAMETER` (a coordinate that is not finite, an index out of range, a bad
/// option: `report.message` says which); on an error `uv` and `chart` are empty.
template <typename PointRange, typename PolygonRange, typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          , typename = std::enable_if_t<internal::Is_named_parameters<NamedParameters>::value>
#endif
          >
Atlas make_atlas(const PointRange& points, const PolygonRange& polygons,
                 const NamedParameters& np = parameters::default_values())
{
  const auto start = std::chrono::steady_clock::now();
  Atlas atlas;
  Atlas_report& r = atlas.report;
  internal::Atlas_settings settings = internal::read_atlas_settings(np);
  settings.start = start;
  auto fail = [&](Error_code e, const std::string& why) {
    Atlas a;
    a.report.status = e;
    a.report.message = why;
    a.report.seconds = internal::seconds_since(start);
    return a;
  };
  if(!(settings.max_stretch >= 1.) || !std::isfinite(settings.max_stretch))
    return fail(ERROR_WRONG_PARAMETER, "max_stretch must be a finite number of at least 1");
  if(settings.packing.resolution < 1 || !(settings.packing.gutter >= 0.) || !std::isfinite(settings.packing.gutter) ||
     settings.packing.gutter * 4. >= double(settings.packing.resolution))
    return fail(ERROR_WRONG_PARAMETER, "the resolution must be positive and the gutter at least 0 and well below the resolution");
  if(polygons.size() == 0)
    return fail(ERROR_EMPTY_MESH, "the soup has no polygon");

  // memory running out anywhere below is reported, not thrown
  try {
    internal::Atlas_triangles m;
    const std::string why = internal::make_atlas_triangles(points, polygons, m);
    if(!why.empty())
      return fail(ERROR_WRONG_PARAMETER, why);
    r.triangles = m.vertex.size();
    r.welded_vertices = m.welded_vertices;
    r.flat_polygons = m.flat_polygons.size();
    atlas.uv.resize(polygons.size());
    std::size_t p = 0;
    for(const auto& polygon : polygons)
      atlas.uv[p++].assign(polygon.size(), std::array<double, 2>{0., 0.});
    r.seconds_input = internal::seconds_since(start);
    settings.tell(Atlas_stage::INPUT, 1, 1);

    std::vector<std::vector<char> > written;
    std::unordered_map<int, internal::Vec2> vertex_uv;
    internal::build_atlas(m, polygons.size(), settings, atlas, written, vertex_uv);
    // corners left out of the triangles (repeated, or of polygons without area): the uv of their
    // position elsewhere in the polygon, else of that position in some chart, else the origin
    p = 0;
    for(const auto& polygon : polygons) {
      std::size_t k = 0;
      for(const auto corner : polygon) {
        if(!written[p][k]) {
          const int v = m.weld[std::size_t(corner)];
          bool found = false;
          std::size_t j = 0;
          for(const auto other : polygon) {
            if(written[p][j] && m.weld[std::size_t(other)] == v) {
              atlas.uv[p][k] = atlas.uv[p][j];
              found = true;
              break;
            }
            ++j;
          }
          if(!found) {
            const auto it = vertex_uv.find(v);
            if(it != vertex_uv.end())
              atlas.uv[p][k] = it->second;
          }
        }
        ++k;
      }
      ++p;
    }
    r.seconds = internal::seconds_since(start);
    settings.tell(Atlas_stage::DONE, 1, 1);
    return atlas;
  } catch(const std::bad_alloc&) {
    atlas = Atlas();
    return fail(ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "out of memory (std::bad_alloc): the soup is too large for the memory available");
  }
}

/// \ingroup PkgStretchMinimizingParameterizationRef
///
/// Makes a texture atlas of a polygon mesh (`Surface_mesh`, `Polyhedron_3`, any model of
/// `FaceListGraph`): the same atlas as the polygon soup version of `make_atlas()` on the mesh's
/// vertices and faces, written as a uv per halfedge (the uv of its target in its face: a vertex
/// on a seam has one uv per chart) and a chart per face. The mesh may have any genus, several
/// components, boundaries and faces of any size; it is not modified.
///
/// \tparam PolygonMesh a model of `FaceListGraph`
/// \tparam HalfedgeUVMap a model of `WritablePropertyMap` from halfedges to a 2D point type
///         constructible from two `double`s
/// \tparam FaceChartMap a model of `WritablePropertyMap` from faces to an integer type
/// \tparam NamedParameters a sequence of named parameters
///
/// \param pmesh the mesh
/// \param uv_map receives the uv of every halfedge that has a face, in \f$ [0,1]^2 \f$
/// \param chart_map receives the chart of every face, from 0
/// \param np the named parameters of the soup version, and `vertex_point_map` (the points of
///        `pmesh`, by default the internal property map for `CGAL::vertex_point_t`)
///
/// \returns the report; the maps are written only if its `status` is `OK`.
template <typename PolygonMesh, typename HalfedgeUVMap, typename FaceChartMap,
          typename NamedParameters = parameters::Default_named_parameters
#ifndef DOXYGEN_RUNNING
          , typename = std::enable_if_t<!internal::Is_named_parameters<FaceChartMap>::value>
#endif
          >
Atlas_report make_atlas(const PolygonMesh& pmesh, HalfedgeUVMap uv_map, FaceChartMap chart_map,
                        const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;
  typedef typename boost::property_traits<FaceChartMap>::value_type Chart_index;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::const_type Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;

  // the faces in the order of faces(pmesh), each from the target of halfedge(f, pmesh) on
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(pmesh, points, polygons, np);
  const Atlas atlas = make_atlas(points, polygons, np);
  if(atlas.report.status != OK)
    return atlas.report;
  std::size_t i = 0;
  for(face_descriptor f : faces(pmesh)) {
    put(chart_map, f, Chart_index(atlas.chart[i]));
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, pmesh), pmesh)) {
      put(uv_map, h, Point_2(atlas.uv[i][k][0], atlas.uv[i][k][1]));
      ++k;
    }
    ++i;
  }
  return atlas.report;
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_ATLAS_H

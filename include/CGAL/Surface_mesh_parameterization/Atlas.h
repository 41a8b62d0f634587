// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_H

// What make_atlas() returns and tells its visitor.

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// What `make_atlas()` did.
struct Atlas_report
{
  Error_code status = OK;            ///< `OK`, `ERROR_EMPTY_MESH`, `ERROR_WRONG_PARAMETER` or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` (out of memory; see `message`)
  std::string message;               ///< why, when `status` is not `OK`
  std::size_t charts = 0;            ///< charts in the atlas
  std::size_t triangles = 0;         ///< triangles the polygons were split into
  std::size_t welded_vertices = 0;   ///< input vertices at the position of an earlier one
  std::size_t flat_polygons = 0;     ///< polygons with fewer than three distinct positions (zero uv area)
  double l2_stretch = 0.;            ///< normalized L2 stretch of the whole atlas (Sander et al. 2001)
  double linf_stretch = 0.;          ///< normalized Linf stretch of the whole atlas
  std::size_t flipped_faces = 0;     ///< triangles whose uv orientation is not the input's, among those with an area in 3D and in uv (above \f$ 10^{-12} \f$ of the mean, as in `compute_stretch_statistics()`); 0 unless a chart failed
  double seam_length = 0.;           ///< surface length of the cut edges (edges of two or more faces whose sides are not glued)
  double edge_length = 0.;           ///< surface length of all edges
  double utilization = 0.;           ///< area of the charts / area of the unit square
  double seconds_input = 0.;         ///< checking, welding and triangulating the polygons
  double seconds_cutting = 0.;       ///< growing the charts, and splitting the ones above the stretch bound
  double seconds_parameterization = 0.; ///< flattening the charts
  double seconds_packing = 0.;       ///< packing them into the unit square
  double seconds = 0.;               ///< the whole call
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// The stages of `make_atlas()`, in order.
enum class Atlas_stage
{
  INPUT,      ///< the polygons checked, welded and triangulated
  FLATTENING, ///< charts grown, flattened, and cut while above the stretch bound
  PACKING,    ///< the charts packed; the longest cut across while the square is poorly filled
  DONE        ///< the atlas written
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// What the `visitor` of `make_atlas()` is told, on the calling thread, as the work goes on.
struct Atlas_progress
{
  Atlas_stage stage = Atlas_stage::INPUT; ///< the stage under way
  std::size_t done = 0;                   ///< its parts done: charts flattened, or packings (the last one full)
  std::size_t total = 0;                  ///< its parts known so far (cuts add charts; the packings stop when the square is full enough)
  double seconds = 0.;                    ///< since the call started
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// A texture atlas: a uv per polygon corner and a chart per polygon, in the input's order.
struct Atlas
{
  std::vector<std::vector<std::array<double, 2> > > uv; ///< per polygon, per corner: in \f$ [0,1]^2 \f$
  std::vector<std::size_t> chart;                       ///< per polygon
  Atlas_report report;                                  ///< what the call did
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_H

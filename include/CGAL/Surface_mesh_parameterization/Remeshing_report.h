// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_REMESHING_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_REMESHING_REPORT_H

// What remesh_with_parameterizations() is asked for and what it returns.

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// The two parameterizations of `remesh_with_parameterizations()`, written {U', U''} in the
/// paper: the new mesh is triangulated in U' (always \f$ U^0 \f$, close to conformal) and its
/// vertices are placed by sampling U'' (close to area-preserving when it is \f$ U^{opt} \f$).
enum class Remeshing_pair
{
  U0,      ///< {\f$ U^0 \f$}: sampled and triangulated in \f$ U^0 \f$
  U0_U1,   ///< {\f$ U^0, U^1 \f$}: sampled in \f$ U^1 \f$, one reweighting step
  U0_UOPT  ///< {\f$ U^0, U^{opt} \f$}: sampled in \f$ U^{opt} \f$ (the paper's choice)
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// What `remesh_with_parameterizations()` did, and the quality of the mesh it made.
struct Remeshing_report
{
  Error_code status = OK;             ///< `OK` or the error (see `message`)
  std::string message;                ///< why, when `status` is not `OK`
  std::size_t vertices = 0;           ///< vertices of the new mesh
  std::size_t border_vertices = 0;    ///< of which on the border loops of the input
  std::size_t faces = 0;              ///< triangles of the new mesh
  std::size_t border_loops = 0;       ///< border loops of the input, each kept
  double triangulation_l2_stretch = 0.; ///< normalized L2 stretch of U' (\f$ U^0 \f$)
  double sampling_l2_stretch = 0.;    ///< normalized L2 stretch of U''
  double min_angle = 0.;              ///< smallest angle of the new triangles, in degrees
  std::array<std::size_t, 18> angle_histogram{}; ///< angles of the new triangles in bins of 10 degrees
  double angles_at_least_30 = 0.;     ///< fraction of the angles of 30 degrees or more
  double area_variation = 0.;         ///< coefficient of variation of the 3D areas of the new triangles
  std::size_t wrong_faces = 0;        ///< new triangles that cross another or are turned against the input where they lie: 0 unless their repair gave up (see the manual)
  double seconds_parameterization = 0.; ///< computing U' and U''
  double seconds_sampling = 0.;       ///< the border and the interior samples
  double seconds_triangulation = 0.;  ///< the triangulation in U' and the lift to 3D
  double seconds = 0.;                ///< the whole call
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_REMESHING_REPORT_H

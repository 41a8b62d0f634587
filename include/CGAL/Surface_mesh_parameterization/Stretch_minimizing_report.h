// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_REPORT_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// What is known of one parameterization \f$ U^h \f$ of the iteration; a visitor receives it
/// after each solve. Stretches are normalized (1 is an isometry up to scale) and leave out the
/// faces that are degenerate in 3D or in the parameter domain.
struct Stretch_minimizing_step
{
  std::size_t step = 0;                ///< h: 0 for the initial parameterization U^0
  double l2_stretch = 0.;              ///< normalized L2 stretch of U^h
  double linf_stretch = 0.;            ///< normalized Linf stretch of U^h
  std::size_t flipped_faces = 0;       ///< faces oriented against the others
  std::size_t degenerate_uv_faces = 0; ///< faces of zero parameter area (e.g. border ears)
  double seconds = 0.;                 ///< wall time since the start of the call
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Why the iteration ended.
enum class Stretch_minimizing_stop
{
  NOT_RUN,            ///< no parameterization computed (see `Stretch_minimizing_report::status`)
  STRETCH_INCREASED,  ///< the paper's rule: \f$ E(U^{h+1}) \ge E(U^h) \f$
  ITERATION_CAP,      ///< `number_of_iterations` steps were taken
  VISITOR,            ///< the visitor asked to stop
  FLIPPED_FACES       ///< a step produced flipped faces (possible with a non-convex border only)
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// The outcome of one call of `Stretch_minimizing_parameterizer_3::parameterize()`, returned
/// by `Stretch_minimizing_parameterizer_3::report()`.
struct Stretch_minimizing_report
{
  Error_code status = OK;                           ///< the value that the call returned
  std::string message;                              ///< why, when `status != OK`
  std::vector<Stretch_minimizing_step> history;     ///< U^0, U^1, ... in order
  std::size_t kept_step = 0;                        ///< h of the parameterization written (U^opt)
  Stretch_minimizing_stop stop = Stretch_minimizing_stop::NOT_RUN; ///< why the iteration ended
  std::size_t degenerate_3d_faces = 0;              ///< faces of zero 3D area, left out of the measures
  std::size_t interior_vertices = 0;                ///< unknowns of the linear system
  std::size_t border_vertices = 0;                  ///< vertices fixed by the border parameterizer
  std::size_t faces = 0;                            ///< faces of the parameterized component
  std::size_t holes_closed = 0;                     ///< inner boundaries closed virtually

  /// Number of reweighting steps computed (the size of the history less U^0).
  std::size_t steps_taken() const { return history.empty() ? 0 : history.size() - 1; }

  /// The step that was written to the uv map.
  const Stretch_minimizing_step& kept() const { return history.at(kept_step); }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_REPORT_H

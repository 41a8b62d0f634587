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
  double eta = 0.;                     ///< the exponent of the update that gave U^h (0 for U^0)
  double l2_stretch = 0.;              ///< normalized L2 stretch of U^h
  double linf_stretch = 0.;            ///< normalized Linf stretch of U^h
  std::size_t flipped_faces = 0;       ///< faces oriented against the others
  std::size_t degenerate_uv_faces = 0; ///< faces of zero parameter area (e.g. border ears)
  double seconds = 0.;                 ///< wall time since the start of the call
  std::size_t solver_iterations = 0;   ///< iterations of the package's iterative (multigrid) solver for \f$ U^h \f$, the most of the u and v columns; 0 when the system was factored (or the previous map already solved it)
  bool screened = false;               ///< \f$ U^h \f$ was solved by the multigrid solver only far enough to show that it raises the stretch of the kept step by more than 1% (to a residual of \f$ 10^{-6} \f$ times the right-hand side's): the figures of this step are those of that approximate map, its stretch within \f$ 3 \cdot 10^{-5} \f$ (relative) of the full solve's on the meshes measured (the paper's rejected last step, on large meshes)
  bool polish = false;                 ///< a step of the polish stage (`step` counts from 1 there)
  bool descent = false;                ///< a descent step of the polish stage, before its Newton steps
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Why the iteration ended.
enum class Stretch_minimizing_stop
{
  NOT_RUN,            ///< no parameterization computed (see `Stretch_minimizing_report::status`)
  STRETCH_INCREASED,  ///< the paper's rule: \f$ E(U^{h+1}) \ge E(U^h) \f$ (with `Step_rule::HALVE_ETA`: even with the smallest \f$ \eta \f$)
  ITERATION_CAP,      ///< `number_of_iterations` steps were taken
  VISITOR,            ///< the visitor asked to stop
  FLIPPED_FACES,      ///< a step produced flipped faces (possible with a non-convex border only)
  SOLVER_FAILED       ///< the sparse solver failed after \f$ U^0 \f$: the best map so far is kept (`message` says at which step)
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Why the polish stage ended (its Newton steps if any ran, else its descent steps).
enum class Polish_stop
{
  NOT_RUN,        ///< no polish was asked for, or it could not start (see `Stretch_minimizing_polish::message`)
  CONVERGED,      ///< a step lowered the energy by less than a relative \f$ 10^{-6} \f$
  ITERATION_CAP,  ///< `polish_iterations` Newton steps (or, without them, `descent_iterations` descent steps) were taken
  TIME_BUDGET,    ///< `polish_time_budget` ran out
  VISITOR,        ///< the visitor asked to stop
  NO_PROGRESS     ///< the line search found no step that lowers the energy
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// What the polish stage did to lower Sander's L2 stretch energy from \f$ U^{opt} \f$, with the
/// border fixed or free: descent steps along the gradient preconditioned by the cotangent
/// Laplacian of the mesh (factored once, cheap steps), then projected Newton steps.
struct Stretch_minimizing_polish
{
  Polish_stop stop = Polish_stop::NOT_RUN;       ///< why it ended
  std::string message;                           ///< why it could not start or could not go on, if so
  bool free_border = false;                      ///< the border moved
  std::size_t descent_iterations = 0;            ///< descent steps taken
  std::size_t iterations = 0;                    ///< Newton steps taken
  double l2_before = 0.;                         ///< normalized L2 stretch of \f$ U^{opt} \f$
  double l2_after = 0.;                          ///< normalized L2 stretch of the map written
  double seconds = 0.;                           ///< wall time of the polish
  std::vector<Stretch_minimizing_step> history;  ///< one entry per step (`step` counts them from 1)

  /// Whether the polish ran and its result was written.
  bool ran() const { return stop != Polish_stop::NOT_RUN; }
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
  Stretch_minimizing_polish polish;                 ///< the polish stage, if asked for

  /// Number of reweighting steps computed (the size of the history less U^0).
  std::size_t steps_taken() const { return history.empty() ? 0 : history.size() - 1; }

  /// The step \f$ U^{opt} \f$ of the reweighting; it is the map written unless the polish ran.
  const Stretch_minimizing_step& kept() const { return history.at(kept_step); }

  /// The normalized L2 stretch of the map written.
  double l2_stretch() const { return polish.ran() ? polish.l2_after : kept().l2_stretch; }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_REPORT_H

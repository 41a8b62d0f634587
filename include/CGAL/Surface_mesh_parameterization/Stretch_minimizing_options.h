// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_OPTIONS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_OPTIONS_H

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// The weights \f$ w^0_{ij} \f$ of \f$ U^0 \f$ (named parameter `start_weights`). The
/// reweighting is cumulative, so they matter beyond \f$ U^0 \f$: on the bundled meshes,
/// clamped cotangent weights lead to a lower final stretch than Floater's.
/// All of them are positive, so \f$ U^0 \f$ has no flipped face with a convex border.
enum class Start_weights
{
  INITIALIZER,       ///< the weights of the initial parameterizer (Floater's by default)
  SHAPE_PRESERVING,  ///< Floater's (1997) shape-preserving weights, whatever the initializer
  MEAN_VALUE,        ///< Floater's (2003) mean-value weights
  CLAMPED_COTANGENT  ///< cotangent weights raised to at least 1% of the mean absolute weight of their ring
                     ///< (or of the neighbour's ring, if larger): symmetric, \f$ w_{ij} = w_{ji} \f$
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// The stretch that divides a weight \f$ w_{ij} \f$ at each step (named parameter `stretch_update`).
enum class Stretch_update
{
  VERTEX,    ///< \f$ \sigma_j \f$, the stretch of the neighbour (the paper's rule)
  SYMMETRIC, ///< \f$ (\sigma_i + \sigma_j) / 2 \f$
  EDGE       ///< the stretch of the edge \f$ ij \f$: area-weighted RMS over its two faces (over
             ///< \f$ \sigma_i \f$ and \f$ \sigma_j \f$ for an edge without a measured face,
             ///< e.g. one closing a hole)
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// What to do when a step does not decrease the stretch (named parameter `step_rule`).
enum class Step_rule
{
  STOP_AT_INCREASE, ///< stop and keep the best step (the paper's rule)
  HALVE_ETA         ///< drop the step, halve \f$ \eta \f$ and step again from the best parameterization;
                    ///< stop when \f$ \eta \f$ would fall below 1/4 of its initial value
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Sets of options with a name (named parameter `preset`); options given beside a preset
/// override it.
enum class Stretch_minimizing_preset
{
  /// The paper's method: `Start_weights::INITIALIZER` (Floater's by default),
  /// `Stretch_update::VERTEX`, `Step_rule::STOP_AT_INCREASE`, \f$ \eta = 1 \f$. The default.
  PAPER,
  /// `Start_weights::CLAMPED_COTANGENT`, `Stretch_update::EDGE`, `Step_rule::STOP_AT_INCREASE`,
  /// \f$ \eta = 1 \f$, then at most `lowest_stretch_descent_iterations` descent steps of the
  /// polish stage (`descent_iterations`): a stretch close to the lowest the border allows, for
  /// one to three times the time of `PAPER` up to a few hundred thousand vertices and more above
  /// (the manual's benchmark), still no flipped face with a convex border.
  LOWEST_STRETCH
};

/// \ingroup PkgStretchMinimizingParameterizationRef
/// The cap on the descent steps of `Stretch_minimizing_preset::LOWEST_STRETCH`
/// (see `descent_iterations`), which also stop when the last steps gain little: past that point the
/// Newton steps of the polish (`polish_iterations`) go on to the optimum.
constexpr unsigned int lowest_stretch_descent_iterations = 30;

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRETCH_MINIMIZING_OPTIONS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_NAMED_PARAMETERS_H
#define CGAL_SMP_INTERNAL_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

// The package's own tags live here, never in CGAL::internal_np.
namespace internal_np {
enum eta_t { eta };
enum start_weights_t { start_weights };
enum stretch_update_t { stretch_update };
enum step_rule_t { step_rule };
enum preset_t { preset };
enum descent_iterations_t { descent_iterations };
enum polish_iterations_t { polish_iterations };
enum polish_time_budget_t { polish_time_budget };
enum free_border_t { free_border };
enum number_of_threads_t { number_of_threads };
enum max_stretch_t { max_stretch };
enum resolution_t { resolution };
enum gutter_t { gutter };
} // namespace internal_np

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Named parameters of this package. CGAL's own named parameters are re-exported. CGAL's chain
/// syntax `a(x).b(y)` only knows CGAL's names, so a package name takes the rest of the chain as
/// its second argument: `SMP::parameters::eta(0.5, SMP::parameters::step_rule(SMP::Step_rule::HALVE_ETA,
/// CGAL::parameters::number_of_iterations(10)))`, or starts a chain of CGAL names:
/// `SMP::parameters::eta(0.5).number_of_iterations(10)`.
namespace parameters {

using namespace CGAL::parameters;

#ifndef DOXYGEN_RUNNING
#define CGAL_SMP_ADD_NAMED_PARAMETER(NAME)                                                        \
  template <typename T>                                                                           \
  Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& value)                        \
  {                                                                                               \
    return Named_function_parameters<T, internal_np::NAME##_t>(value);                            \
  }                                                                                               \
  template <typename T, typename T2, typename Tag2, typename Base2>                               \
  Named_function_parameters<T, internal_np::NAME##_t, Named_function_parameters<T2, Tag2, Base2> > \
  NAME(const T& value, const Named_function_parameters<T2, Tag2, Base2>& np)                      \
  {                                                                                               \
    return Named_function_parameters<T, internal_np::NAME##_t,                                    \
                                     Named_function_parameters<T2, Tag2, Base2> >(value, np);     \
  }

CGAL_SMP_ADD_NAMED_PARAMETER(eta)
CGAL_SMP_ADD_NAMED_PARAMETER(start_weights)
CGAL_SMP_ADD_NAMED_PARAMETER(stretch_update)
CGAL_SMP_ADD_NAMED_PARAMETER(step_rule)
CGAL_SMP_ADD_NAMED_PARAMETER(preset)
CGAL_SMP_ADD_NAMED_PARAMETER(descent_iterations)
CGAL_SMP_ADD_NAMED_PARAMETER(polish_iterations)
CGAL_SMP_ADD_NAMED_PARAMETER(polish_time_budget)
CGAL_SMP_ADD_NAMED_PARAMETER(free_border)
CGAL_SMP_ADD_NAMED_PARAMETER(number_of_threads)
CGAL_SMP_ADD_NAMED_PARAMETER(max_stretch)
CGAL_SMP_ADD_NAMED_PARAMETER(resolution)
CGAL_SMP_ADD_NAMED_PARAMETER(gutter)
#undef CGAL_SMP_ADD_NAMED_PARAMETER
#else
/// Exponent \f$ \eta \f$ of the weight update \f$ w_{ij} \leftarrow w_{ij} / \sigma_j^{\eta} \f$, in \f$ (0, 1] \f$.
template <typename T> unspecified_type eta(const T& value);
/// The weights of \f$ U^0 \f$: a `Start_weights`.
template <typename T> unspecified_type start_weights(const T& value);
/// The stretch that divides the weights: a `Stretch_update`.
template <typename T> unspecified_type stretch_update(const T& value);
/// What to do when a step does not decrease the stretch: a `Step_rule`.
template <typename T> unspecified_type step_rule(const T& value);
/// A set of options: a `Stretch_minimizing_preset`.
template <typename T> unspecified_type preset(const T& value);
/// Cap on the descent steps of the polish stage, before its Newton steps (0: none).
template <typename T> unspecified_type descent_iterations(const T& value);
/// Cap on the Newton steps of the polish stage (0: none).
template <typename T> unspecified_type polish_iterations(const T& value);
/// Time budget of the polish stage in seconds (0: none).
template <typename T> unspecified_type polish_time_budget(const T& value);
/// If `true`, the polish stage frees the border.
template <typename T> unspecified_type free_border(const T& value);
/// Number of threads of the per-face, per-vertex and per-column loops (0: all cores, the default;
/// 1: none started). The result does not depend on it.
template <typename T> unspecified_type number_of_threads(const T& value);
/// `make_atlas()`: a chart whose normalized L2 stretch is above this bound is cut further.
template <typename T> unspecified_type max_stretch(const T& value);
/// `make_atlas()`: texels along a side of the square texture.
template <typename T> unspecified_type resolution(const T& value);
/// `make_atlas()`: texels left between two charts.
template <typename T> unspecified_type gutter(const T& value);
/// Each function above also takes named parameters as a second argument and puts itself in front of them.
#endif

} // namespace parameters
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_NAMED_PARAMETERS_H

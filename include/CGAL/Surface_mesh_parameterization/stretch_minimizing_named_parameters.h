// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_STRETCH_MINIMIZING_NAMED_PARAMETERS_H
#define CGAL_SMP_STRETCH_MINIMIZING_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <functional>

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
enum parameterization_pair_t { parameterization_pair };
enum vertex_density_map_t { vertex_density_map };
enum curvature_adaptation_t { curvature_adaptation };
} // namespace internal_np

#ifndef DOXYGEN_RUNNING
// Every name of a chain: the package's, then CGAL's from CGAL's own list (CGAL 6 adds the kinds
// of names below the first; the two that hold references are stored as CGAL stores them). Each
// calls CGAL_SMP_LINK(tag, name, stored type, argument type, wrapper of the argument), defined
// below once for the members of a chain and once for the functions that start one.
#define CGAL_SMP_PACKAGE_LINK(NAME) CGAL_SMP_LINK(internal_np::NAME##_t, NAME, K, const K&, )
#define CGAL_SMP_PACKAGE_LINKS                                                                    \
  CGAL_SMP_PACKAGE_LINK(eta) CGAL_SMP_PACKAGE_LINK(start_weights) CGAL_SMP_PACKAGE_LINK(stretch_update) \
  CGAL_SMP_PACKAGE_LINK(step_rule) CGAL_SMP_PACKAGE_LINK(preset) CGAL_SMP_PACKAGE_LINK(descent_iterations) \
  CGAL_SMP_PACKAGE_LINK(polish_iterations) CGAL_SMP_PACKAGE_LINK(polish_time_budget)          \
  CGAL_SMP_PACKAGE_LINK(free_border) CGAL_SMP_PACKAGE_LINK(number_of_threads)                 \
  CGAL_SMP_PACKAGE_LINK(max_stretch) CGAL_SMP_PACKAGE_LINK(resolution) CGAL_SMP_PACKAGE_LINK(gutter) \
  CGAL_SMP_PACKAGE_LINK(parameterization_pair) CGAL_SMP_PACKAGE_LINK(vertex_density_map)        \
  CGAL_SMP_PACKAGE_LINK(curvature_adaptation)
#define CGAL_add_named_parameter(X, Y, Z) CGAL_SMP_LINK(CGAL::internal_np::X, Z, K, const K&, )
#define CGAL_add_named_parameter_with_compatibility(X, Y, Z) CGAL_SMP_LINK(CGAL::internal_np::X, Z, K, const K&, )
#define CGAL_add_extra_named_parameter_with_compatibility(X, Y, Z) CGAL_SMP_LINK(CGAL::internal_np::X, Z, K, const K&, )
#define CGAL_add_named_parameter_with_compatibility_cref_only(X, Y, Z)                            \
  CGAL_SMP_LINK(CGAL::internal_np::X, Z, std::reference_wrapper<const K>, const K&, std::cref)
#define CGAL_add_named_parameter_with_compatibility_ref_only(X, Y, Z)                             \
  CGAL_SMP_LINK(CGAL::internal_np::X, Z, std::reference_wrapper<K>, K&, std::ref)

namespace internal {

// CGAL's parameter object, whose chain also knows the package's names: every link, CGAL's or
// the package's, returns this type again, so that a chain started by a name of
// `SMP::parameters` takes CGAL's and the package's names in any order. CGAL reads it as its own
// (it derives from CGAL::Named_function_parameters and keeps its `base`).
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_parameters;
  typedef Named_parameters<T, Tag, Base> self;

  Named_parameters() = default;
  Named_parameters(const T& v) : Cgal_parameters(v) {}
  Named_parameters(const T& v, const Base& b) : Cgal_parameters(v, b) {}

#define CGAL_SMP_LINK(TAG, NAME, STORED, ARGUMENT, WRAP)                                          \
  template <typename K>                                                                           \
  Named_parameters<STORED, TAG, self> NAME(ARGUMENT k) const                                      \
  {                                                                                               \
    return Named_parameters<STORED, TAG, self>(WRAP(k), *this);                                   \
  }
  CGAL_SMP_PACKAGE_LINKS
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_SMP_LINK
};

} // namespace internal
#endif

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Named parameters of this package, and CGAL's. A chain that starts with a function of this
/// namespace takes the package's and CGAL's names in any order:
/// `SMP::parameters::eta(0.5).number_of_iterations(10).descent_iterations(3)`. A function of
/// the package's also takes other named parameters as a second argument and puts itself in
/// front of them: `SMP::parameters::eta(0.5, CGAL::parameters::number_of_iterations(10))`.
///
/// The package's names (each `name(value)`; which functions read them is said where they are
/// documented):
///
/// | name | value |
/// |---|---|
/// | `eta` | exponent \f$ \eta \f$ of the weight update \f$ w_{ij} \leftarrow w_{ij} / \sigma_j^{\eta} \f$, in \f$ (0, 1] \f$ |
/// | `start_weights` | the weights of \f$ U^0 \f$: a `Start_weights` |
/// | `stretch_update` | the stretch that divides the weights: a `Stretch_update` |
/// | `step_rule` | what to do when a step does not decrease the stretch: a `Step_rule` |
/// | `preset` | a set of options: a `Stretch_minimizing_preset` |
/// | `descent_iterations` | cap on the descent steps of the polish stage (Newton steps on u and v apart with a fixed border, along a proxy with a free one), before its Newton steps (0: none) |
/// | `polish_iterations` | cap on the Newton steps of the polish stage (0: none) |
/// | `polish_time_budget` | time budget of the polish stage in seconds (0: none) |
/// | `free_border` | if `true`, the polish stage frees the border |
/// | `number_of_threads` | threads of the per-face, per-vertex, per-column and per-chart loops (0: all cores, the default; 1: none started); the result does not depend on it |
/// | `max_stretch` | `make_atlas()`: a chart whose normalized L2 stretch is above this bound is cut further |
/// | `resolution` | `make_atlas()`: texels along a side of the square texture |
/// | `gutter` | `make_atlas()`: texels left between two charts |
/// | `parameterization_pair` | `remesh_with_parameterizations()`: the parameterizations {U', U''} (a `Remeshing_pair`) |
/// | `vertex_density_map` | `remesh_with_parameterizations()`: a relative sampling density per vertex (a property map to numbers > 0) |
/// | `curvature_adaptation` | `remesh_with_parameterizations()`: how much the sampling follows the curvature (a number >= 0; 0: not at all) |
namespace parameters {

using namespace CGAL::parameters;

#ifndef DOXYGEN_RUNNING
// CGAL's names start a chain of the package's type too (they hide CGAL's functions here, which
// stay reachable as CGAL::parameters::...)
#define CGAL_SMP_LINK(TAG, NAME, STORED, ARGUMENT, WRAP)                                          \
  template <typename K>                                                                           \
  internal::Named_parameters<STORED, TAG> NAME(ARGUMENT k)                                        \
  {                                                                                               \
    return internal::Named_parameters<STORED, TAG>(WRAP(k));                                      \
  }
CGAL_SMP_PACKAGE_LINKS
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_SMP_LINK

// a package name in front of other named parameters
#define CGAL_SMP_LINK(TAG, NAME, STORED, ARGUMENT, WRAP)                                          \
  template <typename K, typename T2, typename Tag2, typename Base2>                               \
  internal::Named_parameters<STORED, TAG, Named_function_parameters<T2, Tag2, Base2> >            \
  NAME(ARGUMENT k, const Named_function_parameters<T2, Tag2, Base2>& np)                          \
  {                                                                                               \
    return internal::Named_parameters<STORED, TAG, Named_function_parameters<T2, Tag2, Base2> >(WRAP(k), np); \
  }
CGAL_SMP_PACKAGE_LINKS
#undef CGAL_SMP_LINK

#undef CGAL_SMP_PACKAGE_LINK
#undef CGAL_SMP_PACKAGE_LINKS
#undef CGAL_add_named_parameter
#undef CGAL_add_named_parameter_with_compatibility
#undef CGAL_add_extra_named_parameter_with_compatibility
#undef CGAL_add_named_parameter_with_compatibility_cref_only
#undef CGAL_add_named_parameter_with_compatibility_ref_only
#endif

} // namespace parameters
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_STRETCH_MINIMIZING_NAMED_PARAMETERS_H

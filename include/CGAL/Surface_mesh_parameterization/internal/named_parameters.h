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
} // namespace internal_np

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Named parameters of this package. CGAL's own named parameters are re-exported, so that a
/// chain may start with a package name and go on with CGAL's:
/// `SMP::parameters::eta(0.5).number_of_iterations(10)`.
namespace parameters {

using namespace CGAL::parameters;

/// Exponent \f$ \eta \f$ of the weight update \f$ w_{ij} \leftarrow w_{ij} / \sigma_j^{\eta} \f$,
/// in \f$ (0, 1] \f$.
template <typename T>
Named_function_parameters<T, internal_np::eta_t> eta(const T& value)
{
  return Named_function_parameters<T, internal_np::eta_t>(value);
}

/// Chains `eta` onto existing named parameters, e.g. CGAL's:
/// `SMP::parameters::eta(0.5, CGAL::parameters::number_of_iterations(10))`.
template <typename T, typename T2, typename Tag2, typename Base2>
Named_function_parameters<T, internal_np::eta_t, Named_function_parameters<T2, Tag2, Base2> >
eta(const T& value, const Named_function_parameters<T2, Tag2, Base2>& np)
{
  return Named_function_parameters<T, internal_np::eta_t, Named_function_parameters<T2, Tag2, Base2> >(value, np);
}

} // namespace parameters
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_NAMED_PARAMETERS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_ERROR_MESSAGE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_ERROR_MESSAGE_H

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Returns a short English description of `code`. Unlike CGAL 5.5.1's `get_error_message()`,
/// whose table is one entry out of step with the enum, it matches every `Error_code` by name.
/// \param code a value returned by a parameterizer
/// \returns a static string, never null
inline const char* error_message(Error_code code)
{
  switch(code) {
    case OK: return "Success";
    case ERROR_EMPTY_MESH: return "Input mesh is empty";
    case ERROR_NON_TRIANGULAR_MESH: return "Input mesh is not triangular";
    case ERROR_NO_TOPOLOGICAL_DISC: return "Input mesh is not a topological disc";
    case ERROR_NO_TOPOLOGICAL_BALL: return "Input mesh is not a topological ball";
    case ERROR_BORDER_TOO_SHORT: return "This border parameterization requires a longer border";
    case ERROR_NON_CONVEX_BORDER: return "This parameterization method requires a convex border";
    case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "Cannot solve linear system";
    case ERROR_NO_1_TO_1_MAPPING: return "Parameterization failed: no one-to-one mapping";
    case ERROR_WRONG_PARAMETER: return "A method received an unexpected parameter";
  }
  return "Unknown error";
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_ERROR_MESSAGE_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_FACE_STRETCH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_FACE_STRETCH_H

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgStretchMinimizingParameterizationRef
/// Stretch of the affine map \f$ S \f$ from a parameter triangle to its 3D triangle
/// (Sander, Snyder, Gortler, Hoppe 2001 \cgalCite{cgal:ssgh-tmpm-01}). With \f$ a = S_s \cdot S_s \f$,
/// \f$ b = S_s \cdot S_t \f$, \f$ c = S_t \cdot S_t \f$:
/// \f$ L^2 = \sqrt{(a + c) / 2} \f$ and \f$ L^\infty = \sqrt{((a + c) + \sqrt{(a - c)^2 + 4 b^2}) / 2} \f$.
/// Both are infinite when the parameter triangle has zero area.
struct Face_stretch
{
  double l2 = 0.;      ///< root mean square of the singular values of \f$ S \f$
  double linf = 0.;    ///< largest singular value of \f$ S \f$
  double area_3d = 0.; ///< area of the 3D triangle
  double area_uv = 0.; ///< signed area of the parameter triangle (positive if counterclockwise)
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_FACE_STRETCH_H

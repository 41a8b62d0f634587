// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SMALL_VECTORS_H
#define CGAL_SMP_INTERNAL_SMALL_VECTORS_H

// The package's vocabulary of points and vectors in the plane and in space, and the few
// operations every part of it needs (the weights, the stretch, the polish, the atlas).

#include <array>
#include <cmath>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

inline Vec3 sub3(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add3(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross3(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm3(const Vec3& a) { return std::sqrt(dot3(a, a)); }

// Angle between a and b in [0, pi]; atan2 stays accurate near 0 and pi, where acos does not.
inline double angle3(const Vec3& a, const Vec3& b) { return std::atan2(norm3(cross3(a, b)), dot3(a, b)); }

// Twice the signed area of the triangle (a, b, c) of the plane: positive when it turns
// counterclockwise.
inline double twice_signed_area(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SMALL_VECTORS_H

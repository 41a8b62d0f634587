// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_WALL_CLOCK_H
#define CGAL_SMP_INTERNAL_WALL_CLOCK_H

// The time of the stages the reports give.

#include <chrono>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_WALL_CLOCK_H

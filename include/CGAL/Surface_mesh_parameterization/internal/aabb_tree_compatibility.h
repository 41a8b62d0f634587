// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_AABB_TREE_COMPATIBILITY_H
#define CGAL_SMP_INTERNAL_AABB_TREE_COMPATIBILITY_H

// CGAL 6 names the AABB tree's traits and primitives with a _3 and deprecates the old names,
// which CGAL 5.5 alone has: the package and its tests use these aliases, right on both.

#include <CGAL/AABB_tree.h>
#include <CGAL/version.h>

#if CGAL_VERSION_NR >= 1060000000
#include <CGAL/AABB_segment_primitive_3.h>
#include <CGAL/AABB_traits_3.h>
#include <CGAL/AABB_triangle_primitive_3.h>
#else
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

#if CGAL_VERSION_NR >= 1060000000
template <typename K, typename Primitive>
using Aabb_tree = CGAL::AABB_tree<CGAL::AABB_traits_3<K, Primitive> >;
template <typename K, typename Iterator>
using Aabb_segment_primitive = CGAL::AABB_segment_primitive_3<K, Iterator>;
template <typename K, typename Iterator>
using Aabb_triangle_primitive = CGAL::AABB_triangle_primitive_3<K, Iterator>;
#else
template <typename K, typename Primitive>
using Aabb_tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> >;
template <typename K, typename Iterator>
using Aabb_segment_primitive = CGAL::AABB_segment_primitive<K, Iterator>;
template <typename K, typename Iterator>
using Aabb_triangle_primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
#endif

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_AABB_TREE_COMPATIBILITY_H

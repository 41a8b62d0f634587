// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SOLVER_CONFIGURATION_H
#define CGAL_SMP_INTERNAL_SOLVER_CONFIGURATION_H

// Two macros choose the package's sparse solvers:
// - CGAL_SMP_USE_SPARSESUITE_SOLVERS (CGAL's own, as in its ARAP and Orbifold Tutte
//   parameterizers): the default solver is UMFPACK's LU (link UMFPACK);
// - CGAL_SMP_USE_CHOLMOD: the Cholesky factorizations of the systems of one row per vertex
//   take METIS's order (vertex_order.h), the largest definite ones CHOLMOD's LL^T (link CHOLMOD).
// The package's CMake target defines each when it finds the library.
//
// A macro that changes what a class or function template is would let two translation units,
// built with and without it, define one entity in two ways (an ODR violation: the linker keeps
// one of them, silently). So what depends on the macros is declared in an inline namespace named
// after them (as libstdc++ does for its string ABI): each configuration gets entities of its
// own, names in the source stay the same, and mixing configurations across a function's
// signature is a link error, never a silent mismatch.

#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS) && defined(CGAL_SMP_USE_CHOLMOD)
#define CGAL_SMP_SOLVER_NAMESPACE with_umfpack_cholmod
#elif defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
#define CGAL_SMP_SOLVER_NAMESPACE with_umfpack
#elif defined(CGAL_SMP_USE_CHOLMOD)
#define CGAL_SMP_SOLVER_NAMESPACE with_cholmod
#else
#define CGAL_SMP_SOLVER_NAMESPACE with_eigen
#endif

#define CGAL_SMP_BEGIN_SOLVER_NAMESPACE inline namespace CGAL_SMP_SOLVER_NAMESPACE {
#define CGAL_SMP_END_SOLVER_NAMESPACE }

#endif // CGAL_SMP_INTERNAL_SOLVER_CONFIGURATION_H

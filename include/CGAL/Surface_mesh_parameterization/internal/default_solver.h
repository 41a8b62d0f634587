// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_DEFAULT_SOLVER_H
#define CGAL_SMP_INTERNAL_DEFAULT_SOLVER_H

// The default sparse solver of the package. With CGAL_SMP_USE_UMFPACK defined (the CMake target
// defines it when SuiteSparse's UMFPACK is found), UMFPACK's LU; else Eigen's SparseLU with
// COLAMD ordering. On the mannequin head and its Loop refinement, UMFPACK without iterative
// refinement took about 0.6 times the time of SparseLU (benchmark/).

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/SparseLU>
#if defined(CGAL_SMP_USE_UMFPACK)
#include <Eigen/UmfPackSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

#if defined(CGAL_SMP_USE_UMFPACK)
typedef CGAL::Eigen_solver_traits<Eigen::UmfPackLU<Eigen_sparse_matrix<double>::EigenType> > Default_solver_traits;
#else
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<Eigen_sparse_matrix<double>::EigenType,
                                                  Eigen::COLAMDOrdering<int> > >           Default_solver_traits;
#endif

// Analyses the pattern of `A`. UMFPACK is told to skip its iterative refinement, which Eigen
// leaves on and which made each solve several times slower for no gain in accuracy here, and
// to order with METIS on large systems: METIS needs far fewer flops and less memory than AMD at
// 200k unknowns and more, but its own cost outweighs that below (at 13k and 52k unknowns AMD
// made the whole U^opt 1.3-1.5 times faster; AMD also if this UMFPACK has no METIS).
template <typename Solver, typename Matrix>
void analyze_pattern(Solver& solver, const Matrix& A)
{
  solver.analyzePattern(A);
}

#if defined(CGAL_SMP_USE_UMFPACK)
constexpr long metis_threshold = 150000; // unknowns

template <typename Matrix, typename Eigen_matrix>
void analyze_pattern(Eigen::UmfPackLU<Eigen_matrix>& solver, const Matrix& A)
{
  solver.umfpackControl()(UMFPACK_IRSTEP) = 0;
  solver.umfpackControl()(UMFPACK_ORDERING) =
    A.rows() < metis_threshold ? UMFPACK_ORDERING_AMD : UMFPACK_ORDERING_METIS;
  solver.analyzePattern(A);
  if(solver.info() != Eigen::Success) {
    solver.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_AMD;
    solver.analyzePattern(A);
  }
}
#endif

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_DEFAULT_SOLVER_H

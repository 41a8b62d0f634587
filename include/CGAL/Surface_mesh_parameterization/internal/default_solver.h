// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_DEFAULT_SOLVER_H
#define CGAL_SMP_INTERNAL_DEFAULT_SOLVER_H

// The default direct sparse solver of the package (the multigrid solver takes its place on large
// systems). With CGAL's own macro CGAL_SMP_USE_SPARSESUITE_SOLVERS defined (the package's CMake
// target defines it when SuiteSparse's UMFPACK is found), UMFPACK's LU (`Umfpack_lu`); else
// Eigen's SparseLU in a minimum degree order of the pattern (`Ordered_sparse_lu`). UMFPACK
// without iterative refinement is the faster of the two on the benchmark's large meshes
// (benchmark/ measures by how much). The type depends on the macro: it is declared in the
// solver configuration's namespace (solver_configuration.h says why).

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/Ordered_sparse_lu.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_vertex_solver.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>

#include <type_traits>
#include <utility>

#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
#include <CGAL/Surface_mesh_parameterization/internal/Umfpack_lu.h>
#include <Eigen/UmfPackSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// Whether `Solver` is UMFPACK's LU (the package's wrapper or Eigen's).
template <typename Solver>
struct Is_umfpack : std::false_type { };
#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
template <typename Matrix>
struct Is_umfpack<Umfpack_lu<Matrix> > : std::true_type { };
template <typename Matrix>
struct Is_umfpack<Eigen::UmfPackLU<Matrix> > : std::true_type { };
#endif

#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
typedef Umfpack_lu<Eigen_sparse_matrix<double>::EigenType> Default_direct_solver;
#else
typedef Ordered_sparse_lu Default_direct_solver;
#endif

// The traits of the default solver: the direct solver's, as a type of their own, so that the
// multigrid solver takes its place on large systems (Weighted_laplacian_system.h) only where
// the user chose no solver.
struct Default_solver_traits : CGAL::Eigen_solver_traits<Default_direct_solver>
{ };

// What the package knows of solver traits `Traits`: a `CGAL::Eigen_solver_traits` (a `Solver`
// reached by `solver()`) has its pattern analysed once and its factorization reused, the
// columns solved together; other traits are used through CGAL's concept
// `SparseLinearAlgebraWithFactorTraits_d` (`factor()`, then `linear_solver()` per column).
template <typename Traits, typename = void>
struct Solver_kind
{
  static constexpr bool eigen = false;
  static constexpr bool iterative = false;
  typedef Eigen::SparseMatrix<double> Matrix; // the package's copy of the system
};

template <typename Traits>
struct Solver_kind<Traits, std::void_t<typename Traits::Solver::MatrixType, decltype(std::declval<Traits&>().solver())> >
{
  typedef typename Traits::Solver Solver;
  static constexpr bool eigen = true;
  static constexpr bool iterative = std::is_base_of<Eigen::IterativeSolverBase<Solver>, Solver>::value;
  typedef typename Solver::MatrixType Matrix;
};

// Whether a symmetric system of `n` unknowns is better factored by the package's sparse
// Cholesky (`Sander_vertex_solver`) than by the direct Eigen solver `Solver`: yes, but for
// UMFPACK's LU on a large system when CHOLMOD is not there (no METIS order for the Cholesky:
// Eigen's simplicial LDL^T then factors in its minimum degree order, with more fill than
// UMFPACK's METIS order gives; measured at 207k rows: 0.85 s against 0.50 s).
template <typename Solver>
bool cholesky_pays(Eigen::Index n)
{
#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS) && !defined(CGAL_SMP_USE_CHOLMOD)
  if constexpr(Is_umfpack<Solver>::value)
    return n < 100000;
#endif
  static_cast<void>(n);
  return true;
}

// Analyses the pattern of `A`. A `UmfPackLU` given by the user is told to skip its iterative
// refinement and ordered as `Umfpack_lu` orders (see there why).
template <typename Solver, typename Matrix>
void analyze_pattern(Solver& solver, const Matrix& A)
{
  solver.analyzePattern(A);
}

// X = A^{-1} B with the factorization of a direct solver; `Umfpack_lu` solves the columns in
// parallel. False if the solve fails.
template <typename Solver>
bool solve_columns(const Solver& solver, const Eigen::MatrixXd& B, Eigen::MatrixXd& X, unsigned int /* threads */)
{
  X = solver.solve(B);
  return solver.info() == Eigen::Success;
}

// Frees the numeric factorization of a direct solver once it has served, where the solver
// allows it: it is the bulk of the memory, and the next step factorizes again.
template <typename Solver>
void release_numeric(Solver&)
{ }

// Frees what the solver keeps of the last system, where the solver allows it: the factors of
// a large mesh should not outlive the call.
template <typename Solver>
void release_factors(Solver&)
{ }

// the Eigen-only default's factors
inline void release_factors(Ordered_sparse_lu& solver)
{
  solver.release();
}

// `release_factors()` of the Eigen solver of `traits`, if it has one.
template <typename Traits>
void release_factors_of(Traits& traits)
{
  if constexpr(Solver_kind<Traits>::eigen)
    release_factors(traits.solver());
}

#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
template <typename Matrix, typename Eigen_matrix>
void analyze_pattern(Eigen::UmfPackLU<Eigen_matrix>& solver, const Matrix& A)
{
  solver.umfpackControl()(UMFPACK_IRSTEP) = 0;
  const bool metis = A.rows() >= Umfpack_lu<Eigen_matrix>::metis_threshold;
  solver.umfpackControl()(UMFPACK_ORDERING) = metis ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
  solver.analyzePattern(A);
  if(metis && solver.info() != Eigen::Success) {
    solver.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_AMD;
    solver.analyzePattern(A);
  }
}

template <typename Matrix, typename Eigen_matrix>
void analyze_pattern(Umfpack_lu<Eigen_matrix>& solver, const Matrix& A)
{
  solver.analyzePattern(A);
}

template <typename Eigen_matrix>
bool solve_columns(const Umfpack_lu<Eigen_matrix>& solver, const Eigen::MatrixXd& B, Eigen::MatrixXd& X,
                   unsigned int threads)
{
  return solver.solve_columns(B, X, threads);
}

template <typename Eigen_matrix>
void release_numeric(Umfpack_lu<Eigen_matrix>& solver)
{
  solver.release_numeric();
}

template <typename Eigen_matrix>
void release_factors(Umfpack_lu<Eigen_matrix>& solver)
{
  solver.release();
}
#endif

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_DEFAULT_SOLVER_H

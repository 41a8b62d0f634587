// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SANDER_VERTEX_SOLVER_H
#define CGAL_SMP_INTERNAL_SANDER_VERTEX_SOLVER_H

// The solver of the systems with one row per moving vertex, symmetric and positive
// (semi)definite: the polisher's proxy (factored once) and its two split Newton systems, and the
// stretch minimizer's systems of symmetric weights (the pattern analysed once, the values
// factored at every step).

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#if defined(CGAL_SMP_USE_CHOLMOD)
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// Eigen's SimplicialLDLT, or, when SuiteSparse is used and the system is large, CHOLMOD's with a
// nested-dissection ordering (METIS), whose factor takes fewer flops than the minimum degree
// ordering's on large meshes (the benchmark measures where).
class Sander_vertex_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  static constexpr Eigen::Index large_threshold = 100000;

  // `definite`: the systems are positive definite, so CHOLMOD may take its supernodal LL^T (much
  // faster than its LDL^T on the largest systems, through BLAS).
  explicit Sander_vertex_solver(bool definite = false)
#if defined(CGAL_SMP_USE_CHOLMOD)
    : m_definite(definite)
#endif
  {
    static_cast<void>(definite);
  }

  void analyzePattern(const Matrix& lower)
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    m_large = lower.rows() >= large_threshold;
    if(m_large) {
      m_cholmod.cholmod().print = 0; // its failure is handled here, not printed
      m_cholmod.cholmod().nmethods = 1;
      m_cholmod.cholmod().method[0].ordering = CHOLMOD_METIS;
      // else LDL^T, as Eigen's: a supernodal LL^T refuses the systems whose smallest
      // eigenvalues are at the floor of the projected Hessians, where the LDL^T factors them
      m_cholmod.cholmod().supernodal = m_definite ? CHOLMOD_SUPERNODAL : CHOLMOD_SIMPLICIAL;
      m_cholmod.cholmod().final_ll = m_definite ? 1 : 0;
      m_cholmod.analyzePattern(lower);
      if(m_cholmod.info() == Eigen::Success)
        return;
      m_large = false;
    }
#endif
    m_small.analyzePattern(lower);
  }

  void factorize(const Matrix& lower)
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_large) {
      m_cholmod.factorize(lower);
      if(m_cholmod.info() == Eigen::Success)
        return;
      // a free border leaves the proxy singular (translations): CHOLMOD stops at its zero
      // pivot, where Eigen's LDLT goes on (the line search copes with the free translation)
      m_large = false;
      m_small.analyzePattern(lower);
    }
#endif
    m_small.factorize(lower);
  }

  void compute(const Matrix& lower)
  {
    analyzePattern(lower);
    factorize(lower);
  }

  Eigen::ComputationInfo info() const
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_large) return m_cholmod.info();
#endif
    return m_small.info();
  }

  // one column or several
  template <typename Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Rhs& b) const
  {
    typedef Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> Dense;
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_large) return m_cholmod.solve(Dense(b)); // CHOLMOD reads a plain matrix
#endif
    return m_small.solve(b);
  }

private:
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower> m_small;
#if defined(CGAL_SMP_USE_CHOLMOD)
  Eigen::CholmodDecomposition<Matrix, Eigen::Lower> m_cholmod;
  bool m_large = false;
  bool m_definite = false;
#endif
};

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SANDER_VERTEX_SOLVER_H

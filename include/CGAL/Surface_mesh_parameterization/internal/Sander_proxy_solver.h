// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SANDER_PROXY_SOLVER_H
#define CGAL_SMP_INTERNAL_SANDER_PROXY_SOLVER_H

// The solver of the polisher's fixed quadratic proxy (the cotangent Laplacian of the 3D mesh),
// factored once per polish and solved at every descent step.

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

// Factors the proxy once and solves it at every descent step: with Eigen's SimplicialLDLT, or,
// when SuiteSparse is used and the proxy is large, with CHOLMOD's supernodal Cholesky (its
// default ordering: AMD, and METIS too when AMD fills in much), whose dense fronts only pay off
// on large systems (the benchmark measures where).
class Sander_proxy_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  static constexpr Eigen::Index supernodal_threshold = 100000;

  void compute(const Matrix& lower)
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    // a free border leaves the proxy singular (translations): CHOLMOD's LLT refuses it, where
    // the LDLT factors it (the line search copes with the free translation)
    m_supernodal = lower.rows() >= supernodal_threshold;
    if(m_supernodal) {
      m_large.cholmod().print = 0; // its failure is handled here, not printed
      m_large.compute(lower);
      if(m_large.info() == Eigen::Success)
        return;
      m_supernodal = false;
    }
#endif
    m_small.compute(lower);
  }

  Eigen::ComputationInfo info() const
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_supernodal) return m_large.info();
#endif
    return m_small.info();
  }

  Eigen::Matrix<double, Eigen::Dynamic, 2> solve(const Eigen::Matrix<double, Eigen::Dynamic, 2>& b) const
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_supernodal) return m_large.solve(b);
#endif
    return m_small.solve(b);
  }

private:
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower> m_small;
#if defined(CGAL_SMP_USE_CHOLMOD)
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> m_large;
  bool m_supernodal = false;
#endif
};

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SANDER_PROXY_SOLVER_H

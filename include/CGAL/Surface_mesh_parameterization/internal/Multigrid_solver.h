// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_MULTIGRID_SOLVER_H
#define CGAL_SMP_INTERNAL_MULTIGRID_SOLVER_H

#include <CGAL/Surface_mesh_parameterization/internal/Aggregation_multigrid.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Solves A X = B column by column by BiCGSTAB (van der Vorst 1992) preconditioned by one V-cycle
// of `Aggregation_multigrid`, from a given guess (the previous step's solution, in the
// reweighting loop). Columns run on threads of their own and each is computed alike whatever
// the thread count. A column has converged when its residual is below `tolerance` times the
// norm of its right-hand side; a column that does not converge in `max_iterations`, or whose
// iteration breaks down, fails the solve, and the caller then falls back to a direct solver.
// `iterations()` tells how many iterations the last solve took (the most of its columns).
class Multigrid_solver
{
public:
  // small enough that the stretch of every step is the direct solver's to 1e-6
  // (test_stretch_minimizing checks it on a large mesh)
  static constexpr double tolerance = 1e-12;
  static constexpr int max_iterations = 200;

  // Builds the multigrid hierarchy of `A`. False if it cannot be built.
  template <typename Matrix>
  bool compute(const Matrix& A)
  {
    return m_multigrid.compute(A);
  }

  // X: the guess on entry, the solution on return (B's size). False if a column fails.
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X, unsigned int threads)
  {
    if(X.rows() != B.rows() || X.cols() != B.cols())
      X.setZero(B.rows(), B.cols());
    std::vector<int> converged(std::size_t(B.cols()), 0);
    std::vector<std::size_t> iterations(std::size_t(B.cols()), 0);
    parallel_for_each(std::size_t(B.cols()), threads, [&](std::size_t c) {
      Eigen::VectorXd x = X.col(Eigen::Index(c));
      converged[c] = bicgstab(B.col(Eigen::Index(c)), x, iterations[c]) ? 1 : 0;
      X.col(Eigen::Index(c)) = x;
    });
    m_iterations = iterations.empty() ? 0 : *std::max_element(iterations.begin(), iterations.end());
    for(int ok : converged)
      if(!ok)
        return false;
    return X.allFinite();
  }

  std::size_t iterations() const { return m_iterations; }

  void release() { m_multigrid.release(); }

private:
  // `iterations`: how many were taken, on return
  bool bicgstab(const Eigen::VectorXd& b, Eigen::VectorXd& x, std::size_t& iterations) const
  {
    iterations = 0;
    const Aggregation_multigrid::Row_matrix& A = m_multigrid.matrix();
    const double target = tolerance * b.norm();
    Eigen::VectorXd r = b - A * x;
    if(r.norm() <= target)
      return true;
    Aggregation_multigrid::Workspace w = m_multigrid.workspace();
    Eigen::VectorXd r0 = r, p = Eigen::VectorXd::Zero(b.size()), v = p, y, z, s, t;
    double rho = 1., alpha = 1., omega = 1.;
    for(int k = 0; k < max_iterations; ++k) {
      iterations = std::size_t(k) + 1;
      const double rho_next = r0.dot(r);
      if(!(std::abs(rho_next) > 0.))
        return false;
      p = r + (rho_next / rho) * (alpha / omega) * (p - omega * v);
      rho = rho_next;
      m_multigrid.apply(p, y, w);
      v.noalias() = A * y;
      alpha = rho / r0.dot(v);
      s = r - alpha * v;
      m_multigrid.apply(s, z, w);
      t.noalias() = A * z;
      const double tt = t.squaredNorm();
      omega = tt > 0. ? t.dot(s) / tt : 0.;
      x += alpha * y + omega * z;
      r = s - omega * t;
      if(!std::isfinite(alpha) || !std::isfinite(omega))
        return false;
      if(r.norm() <= target)
        return true;
      if(!(std::abs(omega) > 0.))
        return false;
    }
    return false;
  }

  Aggregation_multigrid m_multigrid;
  std::size_t m_iterations = 0;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_MULTIGRID_SOLVER_H

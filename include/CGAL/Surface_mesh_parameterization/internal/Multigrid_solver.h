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
// the thread count. A column has converged when its residual is below a tolerance (`tolerance`
// unless the caller asks for less) times the norm of its right-hand side; a column that does not
// converge in `max_iterations`, or whose iteration breaks down, fails the solve, and the caller
// then falls back to a direct solver. A solve can be resumed to a smaller tolerance.
// `iterations()` tells how many iterations the last solve took (the most of its columns).
class Multigrid_solver
{
public:
  // small enough that the stretch of every step is the direct solver's to 1e-6
  // (test_stretch_minimizing checks it on a large mesh)
  static constexpr double tolerance = 1e-12;
  // enough to tell a step that raises the stretch (test_stretch_minimizing measures the error
  // of the stretch of such a solution)
  static constexpr double screening_tolerance = 1e-6;
  static constexpr int max_iterations = 200;

  // Builds the multigrid hierarchy of `A` on up to `threads` threads. False if it cannot be built.
  template <typename Matrix>
  bool compute(const Matrix& A, unsigned int threads = 1)
  {
    m_columns.clear();
    return m_multigrid.compute(A, threads);
  }

  // X: the guess on entry, the solution on return (B's size), to a residual of `relative_tolerance`
  // times B's column norms. With `resume`, the iteration of the last solve goes on where it
  // stopped (same B and X, a smaller tolerance): the iterates are those of one solve to that
  // tolerance. False if a column fails. The iterations of the solve (the most of its columns,
  // counted from the solve that `resume` continues) are in `iterations()`.
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X, unsigned int threads,
             double relative_tolerance = tolerance, bool resume = false)
  {
    if(X.rows() != B.rows() || X.cols() != B.cols())
      X.setZero(B.rows(), B.cols());
    if(!resume || m_columns.size() != std::size_t(B.cols()))
      m_columns.assign(std::size_t(B.cols()), Bicgstab_state());
    std::vector<int> converged(std::size_t(B.cols()), 0);
    parallel_for_each(std::size_t(B.cols()), threads, [&](std::size_t c) {
      Eigen::VectorXd x = X.col(Eigen::Index(c));
      converged[c] = bicgstab(B.col(Eigen::Index(c)), relative_tolerance, x, m_columns[c]) ? 1 : 0;
      X.col(Eigen::Index(c)) = x;
    });
    m_iterations = 0;
    for(const Bicgstab_state& column : m_columns)
      m_iterations = (std::max)(m_iterations, column.iterations);
    for(int ok : converged)
      if(!ok)
        return false;
    return X.allFinite();
  }

  std::size_t iterations() const { return m_iterations; }

  void release()
  {
    m_multigrid.release();
    m_columns.clear();
  }

private:
  // where the iteration of one column stands
  struct Bicgstab_state
  {
    Eigen::VectorXd r0, r, p, v; // shadow residual, residual, search directions
    double rho = 1., alpha = 1., omega = 1.;
    std::size_t iterations = 0;
    bool started = false;
  };

  // From the state `it` (a new one: from x), until the residual is below `relative_tolerance`
  // times b's norm.
  bool bicgstab(const Eigen::VectorXd& b, double relative_tolerance, Eigen::VectorXd& x, Bicgstab_state& it) const
  {
    const Aggregation_multigrid::Row_matrix& A = m_multigrid.matrix();
    const double target = relative_tolerance * b.norm();
    if(!it.started) {
      it.r = b - A * x;
      it.r0 = it.r;
      it.p = Eigen::VectorXd::Zero(b.size());
      it.v = it.p;
      it.started = true;
    }
    Eigen::VectorXd& r = it.r;
    Eigen::VectorXd& p = it.p;
    Eigen::VectorXd& v = it.v;
    if(r.norm() <= target)
      return true;
    Aggregation_multigrid::Workspace w = m_multigrid.workspace();
    Eigen::VectorXd y, z, s, t;
    while(it.iterations < std::size_t(max_iterations)) {
      ++it.iterations;
      const double rho_next = it.r0.dot(r);
      if(!(std::abs(rho_next) > 0.))
        return false;
      p = r + (rho_next / it.rho) * (it.alpha / it.omega) * (p - it.omega * v);
      it.rho = rho_next;
      m_multigrid.apply(p, y, w);
      v.noalias() = A * y;
      it.alpha = it.rho / it.r0.dot(v);
      s = r - it.alpha * v;
      m_multigrid.apply(s, z, w);
      t.noalias() = A * z;
      const double tt = t.squaredNorm();
      it.omega = tt > 0. ? t.dot(s) / tt : 0.;
      x += it.alpha * y + it.omega * z;
      r = s - it.omega * t;
      if(!std::isfinite(it.alpha) || !std::isfinite(it.omega))
        return false;
      if(r.norm() <= target)
        return true;
      if(!(std::abs(it.omega) > 0.))
        return false;
    }
    return false;
  }

  Aggregation_multigrid m_multigrid;
  std::vector<Bicgstab_state> m_columns;
  std::size_t m_iterations = 0;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_MULTIGRID_SOLVER_H

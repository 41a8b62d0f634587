// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_WEIGHTED_LAPLACIAN_SYSTEM_H
#define CGAL_SMP_INTERNAL_WEIGHTED_LAPLACIAN_SYSTEM_H

#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/default_solver.h>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <algorithm>
#include <utility>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The system sum_j w_ij (u_i - u_j) = 0 over the interior vertices, border vertices moved to
// the right-hand side, each row divided by its weight sum (same solution, better scaled).
//
// Only the weights change between steps, so the sparsity pattern is built once and analysed
// once by direct solvers, values are rewritten in place, and one factorization serves the u and
// v columns together. Iterative solvers start from the previous solution.
template <typename SolverTraits>
class Weighted_laplacian_system
{
  typedef typename SolverTraits::Solver                      Eigen_solver;
  typedef typename Eigen_solver::MatrixType                  Matrix;
  static constexpr bool iterative =
    std::is_base_of<Eigen::IterativeSolverBase<Eigen_solver>, Eigen_solver>::value;

public:
  explicit Weighted_laplacian_system(const Disk_component_base& dc) : m_dc(dc)
  {
    const Eigen::Index n = Eigen::Index(dc.number_of_rows());
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(dc.ring.size() + dc.interior.size());
    for(Eigen::Index i = 0; i < n; ++i) {
      entries.emplace_back(i, i, 1.);
      for(int e = dc.ring_begin[i]; e < dc.ring_begin[i + 1]; ++e)
        if(dc.row[dc.ring[e]] >= 0)
          entries.emplace_back(i, dc.row[dc.ring[e]], 0.);
    }
    m_A.resize(n, n);
    m_A.setFromTriplets(entries.begin(), entries.end());
    m_A.makeCompressed();

    m_diag.resize(std::size_t(n));
    m_slot.assign(dc.ring.size(), -1);
    for(Eigen::Index i = 0; i < n; ++i) {
      m_diag[std::size_t(i)] = slot(i, i);
      for(int e = dc.ring_begin[i]; e < dc.ring_begin[i + 1]; ++e)
        if(dc.row[dc.ring[e]] >= 0)
          m_slot[e] = slot(i, dc.row[dc.ring[e]]);
    }
    m_B.resize(n, 2);
    m_X.setZero(n, 2);
  }

  // Solves with the weights `w` (one per ring entry) and writes the interior rows of `uv`;
  // the border entries of `uv` are read. Returns false if the solver fails.
  bool solve(const std::vector<double>& w, std::vector<Vec2>& uv, SolverTraits& traits)
  {
    const Eigen::Index n = m_A.rows();
    if(n == 0)
      return true;
    double* values = m_A.valuePtr();
    std::fill(values, values + m_A.nonZeros(), 0.);
    m_B.setZero();
    for(Eigen::Index i = 0; i < n; ++i) {
      const int begin = m_dc.ring_begin[i], end = m_dc.ring_begin[i + 1];
      double sum = 0.;
      for(int e = begin; e < end; ++e)
        sum += w[e];
      values[m_diag[std::size_t(i)]] = 1.;
      for(int e = begin; e < end; ++e) {
        const double c = w[e] / sum;
        if(m_slot[e] >= 0)
          values[m_slot[e]] -= c; // += keeps a repeated neighbour correct
        else {
          m_B(i, 0) += c * uv[m_dc.ring[e]][0];
          m_B(i, 1) += c * uv[m_dc.ring[e]][1];
        }
      }
    }

    Eigen_solver& solver = traits.solver();
    if constexpr(iterative) {
      // the preconditioner is rebuilt whole: Eigen 3.4's IncompleteLUT leaves its status
      // unset after analyzePattern() alone
      solver.compute(m_A);
      if(solver.info() != Eigen::Success)
        return false;
      m_X = solver.solveWithGuess(m_B, m_X);
    } else {
      if(!m_analysed) {
        analyze_pattern(solver, m_A);
        m_analysed = true;
      }
      solver.factorize(m_A);
      if(solver.info() != Eigen::Success)
        return false;
      m_X = solver.solve(m_B);
    }
    if(solver.info() != Eigen::Success || !m_X.allFinite())
      return false;
    for(Eigen::Index i = 0; i < n; ++i)
      uv[m_dc.interior[i]] = {m_X(i, 0), m_X(i, 1)};
    return true;
  }

private:
  // position of entry (i, j) in the value array of the compressed matrix
  int slot(Eigen::Index i, Eigen::Index j) const
  {
    if(Matrix::IsRowMajor)
      std::swap(i, j);
    const auto* first = m_A.innerIndexPtr() + m_A.outerIndexPtr()[j];
    const auto* last = m_A.innerIndexPtr() + m_A.outerIndexPtr()[j + 1];
    return int(std::lower_bound(first, last, i) - m_A.innerIndexPtr());
  }

  const Disk_component_base& m_dc;
  Matrix m_A;
  std::vector<int> m_diag, m_slot; // positions in the value array (nonzeros fit an int, as Eigen's indices)
  Eigen::MatrixXd m_B, m_X;
  bool m_analysed = false;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_WEIGHTED_LAPLACIAN_SYSTEM_H

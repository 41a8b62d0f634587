// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ORDERED_SPARSE_LU_H
#define CGAL_SMP_INTERNAL_ORDERED_SPARSE_LU_H

// Eigen's SparseLU on a system with a symmetric pattern (a mesh's vertex adjacency), its rows
// and columns first permuted alike into a minimum degree order of the pattern: the default
// solver when SuiteSparse is not used. Eigen's SparseLU orders the columns alone (COLAMD),
// which fills more on such systems; handed Eigen's AMD order as its own ordering method, it is
// far slower still, while the same order applied to the matrix beforehand factors faster than
// COLAMD's on large meshes (benchmark/results/solver_paths measures by how much).
// The diagonal is preferred as pivot, which keeps the order's fill: the package's systems are
// diagonally dominant, where elimination on the diagonal is stable.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <Eigen/Core>
#include <Eigen/OrderingMethods>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <memory>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

class Ordered_sparse_lu
{
public:
  typedef double Scalar;
  typedef Eigen::SparseMatrix<double> MatrixType;

  // A pivot is kept on the diagonal while it is at least this fraction of its column's largest
  // entry, as UMFPACK's symmetric strategy does.
  static constexpr double diagonal_pivot_threshold = 1e-3;

  // The order, and the analysis of the permuted pattern.
  void analyzePattern(const MatrixType& A)
  {
    order(A);
    permute(A);
    analyze();
  }

  // `A`: the pattern last analysed
  void factorize(const MatrixType& A)
  {
    permute(A);
    m_lu->factorize(m_permuted);
  }

  void compute(const MatrixType& A)
  {
    analyzePattern(A);
    m_lu->factorize(m_permuted); // permuted by the analysis
  }

  // The same for a symmetric matrix given by its lower triangle (the upper one is not read),
  // permuted into both triangles in one pass.
  void analyze_lower(const MatrixType& lower)
  {
    order(lower);
    permute_lower(lower);
    analyze();
  }

  void factorize_lower(const MatrixType& lower)
  {
    permute_lower(lower);
    m_lu->factorize(m_permuted);
  }

  Eigen::ComputationInfo info() const { return m_lu ? m_lu->info() : Eigen::InvalidInput; }

  // one column or several
  template <typename Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Rhs& b) const
  {
    typedef Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> Dense;
    const Dense permuted_b = m_pinv * b;
    const Dense y = m_lu->solve(permuted_b);
    return m_p * y;
  }

  // The factors, freed (they are the bulk of the memory of a large system).
  void release()
  {
    m_lu.reset();
    m_permuted = MatrixType();
  }

private:
  // the minimum degree order of the pattern of A + A^T
  void order(const MatrixType& A)
  {
    Eigen::AMDOrdering<int> amd;
    amd(A, m_p);
    m_pinv = m_p.inverse();
  }

  void analyze()
  {
    m_lu.reset(new Lu);
    m_lu->isSymmetric(true);
    m_lu->setPivotThreshold(diagonal_pivot_threshold);
    m_lu->analyzePattern(m_permuted);
  }

  void permute(const MatrixType& A)
  {
    m_permuted = m_pinv * A * m_p;
    m_permuted.makeCompressed();
  }

  void permute_lower(const MatrixType& lower)
  {
    m_permuted = lower.selfadjointView<Eigen::Lower>().twistedBy(m_pinv);
    m_permuted.makeCompressed();
  }

  typedef Eigen::SparseLU<MatrixType, Eigen::NaturalOrdering<int> > Lu; // not copyable: held by pointer

  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> m_p, m_pinv;
  MatrixType m_permuted;
  std::unique_ptr<Lu> m_lu;
};

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ORDERED_SPARSE_LU_H

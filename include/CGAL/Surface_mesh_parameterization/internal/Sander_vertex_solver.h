// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SANDER_VERTEX_SOLVER_H
#define CGAL_SMP_INTERNAL_SANDER_VERTEX_SOLVER_H

// The solver of the symmetric positive (semi)definite systems over the moving vertices: the
// polisher's Newton system (two rows per vertex), its proxy (factored once) and its two split
// Newton systems, and the stretch minimizer's systems of symmetric weights (the pattern analysed
// once, the values factored at every step).

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/Ordered_sparse_lu.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#if defined(CGAL_SMP_USE_CHOLMOD)
#include <Eigen/CholmodSupport>
#endif

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// The rows of a system whose unknown k has the rows 2k and 2k + 1 (u and v of a vertex), in the
// order `order` of the unknowns (first eliminated first), each pair of rows together.
inline std::vector<int> paired_rows(const std::vector<int>& order)
{
  std::vector<int> rows(2 * order.size());
  for(std::size_t k = 0; k < order.size(); ++k) {
    rows[2 * k] = 2 * order[k];
    rows[2 * k + 1] = 2 * order[k] + 1;
  }
  return rows;
}

// The minimum degree order in which Eigen's simplicial LDL^T of `lower` (a lower triangle)
// would eliminate the rows, first eliminated first: given to several systems of one pattern, it
// is computed once and the factorizations are the same. With `paired`, rows 2k and 2k + 1 are
// the u and v of one vertex (an even number of rows): the order is that of the vertices, found
// on their pattern (a quarter of the system's entries), each pair of rows eliminated together,
// as the minimum degree order of the whole system would mostly eliminate them too.
inline std::vector<int> minimum_degree_order(const Eigen::SparseMatrix<double>& lower, bool paired = false)
{
  typedef Eigen::SparseMatrix<double> Matrix;
  // assigned, not constructed: Eigen's constructor from a view leaks its column array when an
  // allocation that follows throws (no destructor runs for an object whose constructor threw)
  Matrix full;
  paired = paired && lower.rows() % 2 == 0;
  if(paired) {
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(2 * std::size_t(lower.nonZeros()));
    for(Eigen::Index j = 0; j < lower.outerSize(); ++j)
      for(Matrix::InnerIterator it(lower, j); it; ++it) {
        entries.emplace_back(int(it.row() / 2), int(j / 2), 1.);
        entries.emplace_back(int(j / 2), int(it.row() / 2), 1.);
      }
    full.resize(lower.rows() / 2, lower.cols() / 2);
    full.setFromTriplets(entries.begin(), entries.end());
  } else {
    full = lower.selfadjointView<Eigen::Lower>();
  }
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int>()(full, order);
  const std::vector<int> first_eliminated(order.indices().data(), order.indices().data() + order.indices().size());
  return paired ? paired_rows(first_eliminated) : first_eliminated;
}

// Eigen's simplicial LDL^T, in its own minimum degree order or in an order given by rows
// (vertex_order.h: one nested-dissection order for all the systems of a mesh). The factorization
// of each set of values scatters them into the permuted pattern made by the analysis, where
// Eigen's own permutes the whole matrix anew (counting its columns and allocating a copy) at
// every factorization.
class Ordered_ldlt : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>
{
  typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> Base;

public:
  typedef Eigen::SparseMatrix<double> Matrix;

  // `order`: the rows, first eliminated first; empty: the minimum degree order (`paired`: see
  // minimum_degree_order())
  void analyze(const Matrix& lower, const std::vector<int>& order, bool paired = false)
  {
    const std::vector<int> own = order.empty() ? minimum_degree_order(lower, paired) : std::vector<int>();
    const std::vector<int>& rows = order.empty() ? own : order;
    const Eigen::Index n = lower.rows();
    m_P.resize(n);
    for(Eigen::Index k = 0; k < n; ++k)
      m_P.indices()[rows[std::size_t(k)]] = int(k); // row -> place
    m_Pinv = m_P.inverse();
    permute_pattern(lower);
    analyzePattern_preordered(m_permuted, true); // the pattern alone counts
  }

  // The factorization of `lower`, of the pattern analysed.
  void factorize(const Matrix& lower)
  {
    if(m_source.empty() || !lower.isCompressed() || lower.nonZeros() != m_lower_entries) {
      Base::factorize(lower); // permuted anew
      return;
    }
    const double* from = lower.valuePtr();
    double* to = m_permuted.valuePtr();
    for(std::size_t k = 0; k < m_source.size(); ++k)
      to[k] = from[m_source[k]];
    factorize_preordered<true>(m_permuted);
  }

private:
  // The permuted pattern of `lower`, and, if `lower` is compressed, where each of its values
  // comes from in `lower`: the positions of `lower`'s values permuted as values (integers,
  // exact in doubles).
  void permute_pattern(const Matrix& lower)
  {
    Matrix position; // assigned, not constructed: see minimum_degree_order()
    position = lower;
    position.makeCompressed();
    for(Eigen::Index k = 0; k < position.nonZeros(); ++k)
      position.valuePtr()[k] = double(k);
    m_permuted.resize(lower.rows(), lower.cols());
    m_permuted.selfadjointView<Eigen::Upper>() = position.selfadjointView<Eigen::Lower>().twistedBy(m_P);
    m_lower_entries = lower.nonZeros();
    m_source.clear();
    if(!lower.isCompressed())
      return;
    m_source.resize(std::size_t(m_permuted.nonZeros()));
    for(std::size_t k = 0; k < m_source.size(); ++k)
      m_source[k] = Matrix::StorageIndex(m_permuted.valuePtr()[k]);
  }

  CholMatrixType m_permuted;           // the pattern in elimination order (upper triangle)
  std::vector<Matrix::StorageIndex> m_source; // per value of m_permuted: its position in `lower`
  Eigen::Index m_lower_entries = 0;
};

#if defined(CGAL_SMP_USE_CHOLMOD)
// CHOLMOD's supernodal LL^T in an order given by rows, else in its minimum degree order.
class Ordered_cholmod : public Eigen::CholmodBase<Eigen::SparseMatrix<double>, Eigen::Lower, Ordered_cholmod>
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  // `order`: the rows, first eliminated first; empty: CHOLMOD's minimum degree order (AMD)
  void analyze(const Matrix& lower, std::vector<int>& order)
  {
    if(m_cholmodFactor != nullptr) {
      cholmod_free_factor(&m_cholmodFactor, &m_cholmod);
      m_cholmodFactor = nullptr;
    }
    m_cholmod.print = 0; // its failure is handled by the caller, not printed
    m_cholmod.nmethods = 1;
    m_cholmod.method[0].ordering = order.empty() ? CHOLMOD_AMD : CHOLMOD_GIVEN;
    m_cholmod.postorder = 1;
    m_cholmod.supernodal = CHOLMOD_SUPERNODAL;
    m_cholmod.final_ll = 1;
    cholmod_sparse A = Eigen::viewAsCholmod(lower.selfadjointView<Eigen::Lower>());
    m_cholmodFactor = cholmod_analyze_p(&A, order.empty() ? nullptr : order.data(), nullptr, 0, &m_cholmod);
    m_isInitialized = true;
    m_info = m_cholmodFactor != nullptr ? Eigen::Success : Eigen::NumericalIssue;
    m_analysisIsOk = m_cholmodFactor != nullptr;
    m_factorizationIsOk = false;
  }
};
#endif

// The factorization of one system, analysed once (`analyzePattern`) and factored for each set of
// values (`factorize`): Eigen's simplicial LDL^T, or, for the positive definite systems of many
// rows, a supernodal factorization, which the simplicial one falls far behind as the systems
// grow: CHOLMOD's LL^T (through BLAS) in the same order when SuiteSparse's CHOLMOD is used and
// BLAS is allowed, else Eigen's SparseLU in a minimum degree order (Ordered_sparse_lu).
class Sander_vertex_solver
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  // measured on the clamped cotangent system in a METIS order: Eigen's LDL^T is faster at 207k
  // rows, CHOLMOD's supernodal LL^T at 829k
  static constexpr Eigen::Index default_supernodal_rows = 500000;
  // The systems of 2 x 2 blocks, u and v of each vertex coupled (LSCM's, the polisher's Newton
  // system), fill more: the supernodal factorizations overtake the simplicial one at far fewer
  // rows, and leave it ever further behind above (the benchmark's blocked_solvers measures it).
  static constexpr Eigen::Index blocked_supernodal_rows = 60000;
  // whether the supernodal factorization of the definite systems is CHOLMOD's (else Eigen's SparseLU)
#if defined(CGAL_SMP_USE_CHOLMOD)
  static constexpr bool cholmod = true;
#else
  static constexpr bool cholmod = false;
#endif

  // `definite`: the systems are positive definite, so a supernodal method may factor those of
  // `supernodal_rows` rows or more (an LL^T refuses the semidefinite systems whose smallest
  // eigenvalues are at the floor of the projected Hessians, where the LDL^T factors them)
  explicit Sander_vertex_solver(bool definite = false, Eigen::Index supernodal_rows = default_supernodal_rows)
    : m_definite(definite), m_supernodal_rows(supernodal_rows)
  {}

  // from the next analysis on; `blas`: CHOLMOD's LL^T (through BLAS) may be the supernodal
  // factorization, else Eigen's SparseLU (no BLAS: for systems factored on several threads at
  // once, where a multithreaded BLAS would take more threads than there are cores)
  void set_supernodal_rows(Eigen::Index rows, bool blas = true)
  {
    m_supernodal_rows = rows;
    m_blas = blas;
  }

  // whether rows 2k and 2k + 1 are the u and v of one vertex, so that a minimum degree order
  // is found on the vertices (see minimum_degree_order()); from the next analysis on
  void set_paired_rows(bool paired) { m_paired = paired; }

  // `order`: the rows, first eliminated first (see vertex_order.h); empty: a minimum degree order
  void analyzePattern(const Matrix& lower, const std::vector<int>& order = std::vector<int>())
  {
    m_order = order;
    m_method = m_definite && lower.rows() >= m_supernodal_rows ? Method::LU : Method::SIMPLICIAL;
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_method == Method::LU && m_blas) {
      m_cholmod.analyze(lower, m_order);
      m_method = m_cholmod.info() == Eigen::Success ? Method::CHOLMOD : Method::SIMPLICIAL;
    }
#endif
    if(m_method == Method::LU)
      m_lu.analyze_lower(lower);
    else if(m_method == Method::SIMPLICIAL)
      m_ldlt.analyze(lower, order, m_paired);
  }

  void factorize(const Matrix& lower)
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_method == Method::CHOLMOD) {
      m_cholmod.factorize(lower);
      if(m_cholmod.info() == Eigen::Success)
        return;
    }
#endif
    if(m_method == Method::LU) {
      m_lu.factorize_lower(lower);
      if(m_lu.info() == Eigen::Success)
        return;
      m_lu.release();
    }
    if(m_method != Method::SIMPLICIAL) {
      // not definite to working precision after all: the LDL^T, in the same order
      m_method = Method::SIMPLICIAL;
      m_ldlt.analyze(lower, m_order, m_paired);
    }
    m_ldlt.factorize(lower);
  }

  void compute(const Matrix& lower, const std::vector<int>& order = std::vector<int>())
  {
    analyzePattern(lower, order);
    factorize(lower);
  }

  Eigen::ComputationInfo info() const
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    if(m_method == Method::CHOLMOD) return m_cholmod.info();
#endif
    return m_method == Method::LU ? m_lu.info() : m_ldlt.info();
  }

  // one column or several
  template <typename Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> solve(const Rhs& b) const
  {
#if defined(CGAL_SMP_USE_CHOLMOD)
    typedef Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> Dense;
    if(m_method == Method::CHOLMOD) return m_cholmod.solve(Dense(b)); // CHOLMOD reads a plain matrix
#endif
    if(m_method == Method::LU) return m_lu.solve(b);
    return m_ldlt.solve(b);
  }

  // whether the last factorization was a supernodal one
  bool supernodal() const { return m_method != Method::SIMPLICIAL; }

private:
  enum class Method { SIMPLICIAL, CHOLMOD, LU };

  Ordered_ldlt m_ldlt;
#if defined(CGAL_SMP_USE_CHOLMOD)
  Ordered_cholmod m_cholmod;
#endif
  Ordered_sparse_lu m_lu;
  std::vector<int> m_order; // kept for an LDL^T in the place of the supernodal factorization
  bool m_definite = false;
  Eigen::Index m_supernodal_rows = default_supernodal_rows;
  bool m_blas = true;
  bool m_paired = false;
  Method m_method = Method::SIMPLICIAL; // of the last analysis
};

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SANDER_VERTEX_SOLVER_H

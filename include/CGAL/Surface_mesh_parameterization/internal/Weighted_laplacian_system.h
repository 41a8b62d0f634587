// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_WEIGHTED_LAPLACIAN_SYSTEM_H
#define CGAL_SMP_INTERNAL_WEIGHTED_LAPLACIAN_SYSTEM_H

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Multigrid_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_vertex_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/default_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/vertex_order.h>

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
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// The system sum_j w_ij (u_i - u_j) = 0 over the interior vertices, border vertices moved to
// the right-hand side, each row divided by its weight sum (same solution, better scaled).
//
// Symmetric weights (w_ij = w_ji between interior vertices) make the system without that
// division symmetric positive definite: it is then factored by a sparse Cholesky (LDL^T) from
// its lower triangle, a fraction of the cost of an LU, in place of the direct Eigen solver of
// the traits (which still serves where it is the faster, see `cholesky_pays()`), in the
// elimination order of the mesh's vertices when there is one (vertex_order.h).
//
// Large systems with the package's default solver are solved by the multigrid solver
// (Multigrid_solver.h) from the previous step's solution, in place of a factorization: its time
// and memory grow with the mesh, where those of a sparse LU grow faster. It gives way to the
// direct solver for the rest of the call if it fails, or on the caller's request
// (`use_direct_solver()`: a solution with a flipped face, which may be the multigrid's error).
//
// Only the weights change between steps, so the sparsity pattern is built once and analysed
// once by direct solvers, values are rewritten in place, and one factorization serves the u and
// v columns together. Iterative solvers start from the previous solution. Solver traits that
// only model CGAL's concept (no Eigen solver inside) factor a copy of the matrix at every step.
//
// Memory: the factorization is the peak (the factors are the largest arrays of a call), so
// what is not needed then is not held then. With a direct solver, the caller's weights are
// freed during the factorization and given back divided by their row sum (which changes no
// solution): the matrix holds them meanwhile, and the few weights of border neighbours are
// kept aside, to make the right-hand side after the factorization.
template <typename SolverTraits>
class Weighted_laplacian_system
{
  typedef Solver_kind<SolverTraits>                          Kind;
  typedef typename Kind::Matrix                              Matrix;

public:
  // the Cholesky takes the place of direct Eigen solvers on the same matrix type
  static constexpr bool cholesky_possible =
    Kind::eigen && !Kind::iterative && std::is_same<Matrix, Sander_vertex_solver::Matrix>::value;

  // the multigrid solver takes the place of the package's default solver
  static constexpr bool multigrid_possible = std::is_same<SolverTraits, Default_solver_traits>::value;
  // from this many rows on, the multigrid solver is the faster (benchmark/ measures by how much)
  static constexpr Eigen::Index multigrid_rows = 30000;

  // `symmetric`: the weights given to `solve()` are symmetric; `vertex_rank`: the elimination
  // order of the vertices of `dc` (empty: the Cholesky's own); `multigrid_from`: the number
  // of rows from which the multigrid solver serves, where it can.
  Weighted_laplacian_system(const Disk_component_base& dc, bool symmetric, const std::vector<int>& vertex_rank,
                            Eigen::Index multigrid_from = multigrid_rows)
    : m_dc(dc)
  {
    const Eigen::Index n = Eigen::Index(dc.number_of_rows());
    if constexpr(cholesky_possible)
      m_cholesky = symmetric && cholesky_pays<typename Kind::Solver>(n);
    if constexpr(multigrid_possible)
      m_multigrid = !m_cholesky && n >= multigrid_from;
    if(m_cholesky)
      m_order = rows_in_order(vertex_rank, dc.interior);
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(dc.ring.size() + dc.interior.size());
    for(Eigen::Index i = 0; i < n; ++i) {
      entries.emplace_back(i, i, 1.);
      for(int e = dc.ring_begin[i]; e < dc.ring_begin[i + 1]; ++e) {
        const int j = dc.row[dc.ring[e]];
        if(j >= 0 && !(m_cholesky && j > i)) // the lower triangle of a symmetric system
          entries.emplace_back(i, j, 0.);
      }
    }
    m_A.resize(n, n);
    m_A.setFromTriplets(entries.begin(), entries.end());
    m_A.makeCompressed();

    m_diag.resize(std::size_t(n));
    m_slot.assign(dc.ring.size(), -1);
    std::vector<int> seen(std::size_t(n), -1);
    for(Eigen::Index i = 0; i < n; ++i) {
      m_diag[std::size_t(i)] = slot(i, i);
      for(int e = dc.ring_begin[i]; e < dc.ring_begin[i + 1]; ++e) {
        const int j = dc.row[dc.ring[e]];
        if(j < 0) {
          m_border_entries.push_back(e);
          continue;
        }
        m_slot[e] = m_cholesky ? slot((std::max)(i, Eigen::Index(j)), (std::min)(i, Eigen::Index(j))) : slot(i, j);
        if(seen[std::size_t(j)] == int(i))
          m_repeated_neighbour = true; // its entry sums two weights: they cannot be told apart
        seen[std::size_t(j)] = int(i);
      }
    }
    m_border_weight.resize(m_border_entries.size());
    m_X.setZero(n, 2);
  }

  // Whether the system is factored by the sparse Cholesky.
  bool cholesky() const { return m_cholesky; }

  // Whether the next solve is by the multigrid solver.
  bool multigrid() const { return m_multigrid; }

  // The multigrid iterations of the last solve and its refinement if any, 0 after a factorization.
  std::size_t solver_iterations() const { return m_multigrid ? m_iterations : 0; }

  // Whether the last solve stopped at the multigrid solver's screening tolerance (see `solve()`).
  bool screened() const { return m_screened; }

  // The next solves are by the direct solver.
  void use_direct_solver()
  {
    m_multigrid = false;
    m_built = m_screened = false;
    m_multigrid_solver.release();
  }

  // Solves with the weights `w` (one per ring entry) and writes the interior rows of `uv`;
  // the border entries of `uv` are read. Unless the system is factored by the Cholesky, `w`
  // comes back divided by the weight sums of the rows. The rows are filled, and the u and v
  // columns solved, on up to `threads` threads. Returns false if the solver fails.
  // With `screen`, the multigrid solver stops at its screening tolerance (a map good enough to
  // tell whether it raises the stretch), and `refine()` then takes it to the full tolerance;
  // direct solvers solve fully either way.
  bool solve(std::vector<double>& w, std::vector<Vec2>& uv, SolverTraits& traits, unsigned int threads = 1,
             bool screen = false)
  {
    m_iterations = 0;
    m_screened = m_built = false;
    const Eigen::Index n = m_A.rows();
    if(n == 0)
      return true;
    double* values = m_A.valuePtr();
    // each row writes its own entries of the matrix (a neighbour repeated in a ring is in the
    // same row; of a symmetric pair, the row below the diagonal): no two threads write the
    // same value
    parallel_for(std::size_t(n), threads, parallel_grain, [&](std::size_t first, std::size_t last) {
      for(std::size_t i = first; i < last; ++i) {
        const int begin = m_dc.ring_begin[i], end = m_dc.ring_begin[i + 1];
        double sum = 0.;
        for(int e = begin; e < end; ++e)
          sum += w[e];
        values[m_diag[i]] = m_cholesky ? sum : 1.;
        for(int e = begin; e < end; ++e)
          if(writes(i, e))
            values[m_slot[e]] = 0.;
        for(int e = begin; e < end; ++e) {
          if(!m_cholesky)
            w[e] /= sum;
          if(writes(i, e))
            values[m_slot[e]] -= w[e]; // -= keeps a repeated neighbour correct
        }
      }
    });
    for(std::size_t k = 0; k < m_border_entries.size(); ++k)
      m_border_weight[k] = w[m_border_entries[k]];

    return solve_system(w, uv, traits, threads, screen);
  }

  // Takes a screened solution (see `solve()`) to the full tolerance, with the weights `w` as
  // `solve()` gave them back, and writes it into `uv`; does nothing after a full solve.
  bool refine(std::vector<double>& w, std::vector<Vec2>& uv, SolverTraits& traits, unsigned int threads = 1)
  {
    if(!m_screened)
      return true;
    m_screened = false;
    return solve_system(w, uv, traits, threads, false);
  }

private:
  // the solution of the system as filled into m_X and the interior rows of `uv`, by the solver
  // this system uses now (with `screen`, see `solve()`)
  bool solve_system(std::vector<double>& w, std::vector<Vec2>& uv, SolverTraits& traits, unsigned int threads,
                    bool screen)
  {
    if(!solve_by_current_solver(w, uv, traits, threads, screen) || !m_X.allFinite())
      return false;
    for(Eigen::Index i = 0; i < m_A.rows(); ++i)
      uv[m_dc.interior[i]] = {m_X(i, 0), m_X(i, 1)};
    return true;
  }

  bool solve_by_current_solver(std::vector<double>& w, const std::vector<Vec2>& uv, SolverTraits& traits,
                               unsigned int threads, bool screen)
  {
    if(m_multigrid) {
      // a refinement goes on with the hierarchy and the iteration of the screening solve
      const bool resume = m_built;
      m_built = m_built || m_multigrid_solver.compute(m_A, threads);
      const double tolerance = screen ? Multigrid_solver::screening_tolerance : Multigrid_solver::tolerance;
      if(m_built && m_multigrid_solver.solve(right_hand_side(uv), m_X, threads, tolerance, resume)) {
        m_iterations = m_multigrid_solver.iterations();
        m_screened = screen;
        return true;
      }
      use_direct_solver(); // and for the rest of the call: this system is hard for it
    }
    if(m_cholesky)
      return factor_and_solve(m_cholesky_solver, w, uv, threads);
    if constexpr(!Kind::eigen) {
      return solve_by_concept(traits, right_hand_side(uv));
    } else if constexpr(Kind::iterative) {
      // the preconditioner is rebuilt whole: Eigen 3.4's IncompleteLUT leaves its status
      // unset after analyzePattern() alone
      auto& solver = traits.solver();
      solver.compute(m_A);
      if(solver.info() != Eigen::Success)
        return false;
      m_X = solver.solveWithGuess(right_hand_side(uv), m_X);
      return solver.info() == Eigen::Success;
    } else {
      return factor_and_solve(traits.solver(), w, uv, threads);
    }
  }

  // With a direct solver (the traits' or the Cholesky): the pattern analysed once, then a
  // factorization and the u and v columns; the weights are freed meanwhile and restored after.
  template <typename Solver>
  bool factor_and_solve(Solver& solver, std::vector<double>& w, const std::vector<Vec2>& uv, unsigned int threads)
  {
    if(!m_analysed) {
      if constexpr(std::is_same<Solver, Sander_vertex_solver>::value)
        solver.analyzePattern(m_A, m_order);
      else
        analyze_pattern(solver, m_A);
      m_analysed = true;
    }
    const bool hand_back = !m_repeated_neighbour;
    if(hand_back)
      std::vector<double>().swap(w);
    m_X.resize(0, 0);
    solver.factorize(m_A);
    const bool ok = solver.info() == Eigen::Success && solve_columns(solver, right_hand_side(uv), m_X, threads);
    release_numeric(solver);
    if(hand_back)
      restore(w, threads);
    return ok;
  }

  // With solver traits that model CGAL's `SparseLinearAlgebraWithFactorTraits_d`: one
  // factorization, then the u and v columns (the solution of a column is X / D).
  bool solve_by_concept(SolverTraits& traits, const Eigen::MatrixXd& B)
  {
    typedef typename SolverTraits::NT NT;
    const Eigen::Index n = m_A.rows();
    const std::size_t size = static_cast<std::size_t>(n); // the concept's constructors take a dimension
    typename SolverTraits::Matrix A(size);
    for(Eigen::Index k = 0; k < m_A.outerSize(); ++k)
      for(typename Matrix::InnerIterator it(m_A, k); it; ++it)
        A.set_coef(it.row(), it.col(), NT(it.value()), true);
    NT D = NT(1);
    if(!traits.factor(A, D))
      return false;
    m_X.resize(n, 2);
    for(Eigen::Index c = 0; c < 2; ++c) {
      typename SolverTraits::Vector b(size), x(size);
      for(Eigen::Index i = 0; i < n; ++i)
        b[i] = NT(B(i, c));
      if(!traits.linear_solver(b, x))
        return false;
      for(Eigen::Index i = 0; i < n; ++i)
        m_X(i, c) = CGAL::to_double(x[i] / D);
    }
    return true;
  }

  // the border neighbours' share of every row
  Eigen::MatrixXd right_hand_side(const std::vector<Vec2>& uv) const
  {
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(m_A.rows(), 2);
    for(std::size_t k = 0; k < m_border_entries.size(); ++k) {
      const int e = m_border_entries[k];
      const Eigen::Index i = row_of(e);
      B(i, 0) += m_border_weight[k] * uv[m_dc.ring[e]][0];
      B(i, 1) += m_border_weight[k] * uv[m_dc.ring[e]][1];
    }
    return B;
  }

  // whether row `i` writes the matrix entry of its ring entry `e`
  bool writes(std::size_t i, int e) const
  {
    return m_slot[e] >= 0 && !(m_cholesky && m_dc.row[m_dc.ring[e]] > int(i));
  }

  // the weights (normalized, but for the Cholesky), from the matrix and the border weights
  void restore(std::vector<double>& w, unsigned int threads) const
  {
    w.resize(m_dc.ring.size());
    const double* values = m_A.valuePtr();
    parallel_for(w.size(), threads, parallel_grain, [&](std::size_t begin, std::size_t end) {
      for(std::size_t e = begin; e < end; ++e)
        if(m_slot[e] >= 0)
          w[e] = -values[m_slot[e]];
    });
    for(std::size_t k = 0; k < m_border_entries.size(); ++k)
      w[m_border_entries[k]] = m_border_weight[k];
  }

  Eigen::Index row_of(int e) const
  {
    return Eigen::Index(std::upper_bound(m_dc.ring_begin.begin(), m_dc.ring_begin.end(), e) - m_dc.ring_begin.begin()) - 1;
  }

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
  bool m_cholesky = false;
  Sander_vertex_solver m_cholesky_solver{true}; // positive definite: the border holds it
  bool m_multigrid = false;
  Multigrid_solver m_multigrid_solver;
  std::vector<int> m_order; // the Cholesky's rows in elimination order, empty for its own
  Matrix m_A;
  std::vector<int> m_diag, m_slot; // positions in the value array (nonzeros fit an int, as Eigen's indices)
  std::vector<int> m_border_entries; // ring entries whose neighbour is on the border
  std::vector<double> m_border_weight; // their normalized weights
  Eigen::MatrixXd m_X;
  std::size_t m_iterations = 0; // of the multigrid solver since the matrix was filled
  bool m_screened = false;      // m_X is a screening solution
  bool m_built = false;         // the multigrid hierarchy is that of the matrix as filled
  bool m_repeated_neighbour = false;
  bool m_analysed = false;
};

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_WEIGHTED_LAPLACIAN_SYSTEM_H

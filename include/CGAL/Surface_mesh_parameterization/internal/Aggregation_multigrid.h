// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_AGGREGATION_MULTIGRID_H
#define CGAL_SMP_INTERNAL_AGGREGATION_MULTIGRID_H

#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Smoothed aggregation algebraic multigrid (Vanek, Mandel and Brezina 1996) for the systems of
// the package: rows of a mesh Laplacian with positive weights, nonzero diagonal, not necessarily
// symmetric. One V-cycle approximates A^{-1} b; it serves as the preconditioner of a Krylov
// solver (Multigrid_solver.h). Its setup is a few passes over the matrix, and its memory a small
// multiple of the matrix's, where the factors of a sparse LU grow faster than the mesh: that is
// why it takes over from the direct solvers on large meshes.
//
// Setup, level by level: vertices are grouped into aggregates of strongly coupled neighbours;
// the constant on each aggregate, smoothed by one damped Jacobi step, gives the prolongation P
// (fine x coarse); the coarse matrix is P^T A P. The smallest level is factored by Eigen's
// SparseLU. The cycle smooths by Gauss-Seidel (forward before the coarse correction, backward
// after), sequential and so deterministic.
class Aggregation_multigrid
{
public:
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;

  // Work vectors of one cycle; one per thread that runs cycles at once.
  struct Workspace
  {
    std::vector<Eigen::VectorXd> x, b; // solution and right-hand side per coarse level (from 1)
  };

  // Builds the hierarchy of `A` (square, nonzero diagonal), its products on up to `threads`
  // threads (the hierarchy is the same on any number). False if a level cannot be built (a zero
  // or non-finite diagonal entry, a coarsest matrix SparseLU cannot factor).
  template <typename Matrix>
  bool compute(const Matrix& A, unsigned int threads = 1)
  {
    release();
    Row_matrix level = A;
    double threshold = strength_threshold;
    while(level.rows() > coarsest_rows) {
      Level l;
      l.A = std::move(level);
      if(!inverse_diagonal(l.A, l.inv_diag))
        return false;
      std::vector<Eigen::Index> aggregate;
      const Eigen::Index n_coarse = aggregates(l.A, l.inv_diag, threshold, aggregate);
      if(n_coarse == 0 || double(n_coarse) > max_coarse_ratio * double(l.A.rows())) {
        level = std::move(l.A); // it does not coarsen: factor it as it is
        break;
      }
      l.P = smoothed_prolongation(l.A, l.inv_diag, aggregate, n_coarse);
      l.R = l.P.transpose();
      const Row_matrix AP = product(l.A, l.P, threads);
      level = product(l.R, AP, threads);
      level.prune(0.);
      m_levels.push_back(std::move(l));
      threshold *= 0.5; // coarse levels are denser and more evenly coupled
    }
    m_coarsest = std::move(level);
    const Eigen::SparseMatrix<double> coarsest = m_coarsest; // SparseLU takes column-major matrices
    m_coarse_lu = std::make_unique<Coarse_lu>();
    m_coarse_lu->compute(coarsest);
    return m_coarse_lu->info() == Eigen::Success;
  }

  // X Y, with the entries of each row summed in the order of X's row. Row by row (Gustavson):
  // a row of X gathers the rows of Y it names into a dense accumulator. Eigen's sparse product
  // (for these row-major operands) took most of the setup; this one also runs on threads, each
  // on its own range of rows, and gives the same matrix on any number of them.
  static Row_matrix product(const Row_matrix& X, const Row_matrix& Y, unsigned int threads)
  {
    typedef Row_matrix::StorageIndex Index;
    struct Rows
    {
      std::vector<Index> end, inner; // end of each row in inner
      std::vector<double> values;
    };
    const std::size_t n = std::size_t(X.rows());
    const std::size_t chunks = (std::max)(std::size_t(1), (std::min)(std::size_t(threads), n / parallel_grain));
    std::vector<Rows> part(chunks);
    parallel_for_each(chunks, threads, [&](std::size_t c) {
      Rows& out = part[c];
      std::vector<double> sum(std::size_t(Y.cols()), 0.);
      std::vector<std::size_t> last_row(std::size_t(Y.cols()), n); // the row that last wrote sum[j]
      const std::size_t begin = n * c / chunks, end = n * (c + 1) / chunks;
      // the products of the hierarchy (A P, R A P) have fewer entries than X
      out.inner.reserve(std::size_t(X.nonZeros()) / chunks);
      out.values.reserve(out.inner.capacity());
      out.end.reserve(end - begin);
      for(std::size_t i = begin; i < end; ++i) {
        const std::size_t first = out.inner.size();
        for(Row_matrix::InnerIterator x(X, Eigen::Index(i)); x; ++x)
          for(Row_matrix::InnerIterator y(Y, x.col()); y; ++y) {
            const std::size_t j = std::size_t(y.col());
            if(last_row[j] != i) {
              last_row[j] = i;
              sum[j] = 0.;
              out.inner.push_back(Index(j));
            }
            sum[j] += x.value() * y.value();
          }
        std::sort(out.inner.begin() + std::ptrdiff_t(first), out.inner.end());
        for(std::size_t k = first; k < out.inner.size(); ++k)
          out.values.push_back(sum[std::size_t(out.inner[k])]);
        out.end.push_back(Index(out.inner.size()));
      }
    });
    std::size_t nonzeros = 0;
    for(const Rows& r : part)
      nonzeros += r.inner.size();
    Row_matrix result(X.rows(), Y.cols());
    result.resizeNonZeros(Eigen::Index(nonzeros));
    Index* outer = result.outerIndexPtr();
    std::size_t row = 0, at = 0;
    outer[0] = 0;
    for(const Rows& r : part) {
      for(Index e : r.end)
        outer[++row] = Index(at) + e;
      std::copy(r.inner.begin(), r.inner.end(), result.innerIndexPtr() + at);
      std::copy(r.values.begin(), r.values.end(), result.valuePtr() + at);
      at += r.inner.size();
    }
    return result;
  }

  // the matrix given to `compute()`
  const Row_matrix& matrix() const { return m_levels.empty() ? m_coarsest : m_levels.front().A; }

  std::size_t number_of_levels() const { return m_levels.size() + 1; }

  Workspace workspace() const
  {
    Workspace w;
    w.x.resize(number_of_levels());
    w.b.resize(number_of_levels());
    return w;
  }

  // x = one V-cycle applied to b, from x = 0.
  void apply(const Eigen::VectorXd& b, Eigen::VectorXd& x, Workspace& w) const
  {
    cycle(0, b, x, w);
  }

  void release()
  {
    m_levels.clear();
    m_coarsest = Row_matrix();
    m_coarse_lu.reset();
  }

  // levels stop coarsening at this size: SparseLU factors it at once
  static constexpr Eigen::Index coarsest_rows = 1500;
  // a level whose aggregates keep more than this share of its rows is the last one
  static constexpr double max_coarse_ratio = 0.9;
  // a_ij couples i and j strongly if |a_ij| >= threshold sqrt(|a_ii a_jj|) (on the finest level)
  static constexpr double strength_threshold = 0.08;
  // damping of the Jacobi step that smooths the prolongation: 4/3 over the spectral radius of
  // D^{-1} A (Vanek et al.). Gershgorin bounds that radius by 2 (the finest rows are weakly
  // diagonally dominant), but on a triangle mesh it is nearer 3/2, its value on a regular one
  // with equal weights (the mean over the six neighbours has -1/2 as its lowest eigenvalue):
  // the damping of the bound, 2/3, left the prolongation under-smoothed and cost more
  // iterations (benchmark/results/multigrid_damping.md).
  static constexpr double prolongation_damping = 8. / 9.;

private:
  typedef Eigen::SparseLU<Eigen::SparseMatrix<double> > Coarse_lu;

  struct Level
  {
    Row_matrix A, P, R; // the level's matrix, prolongation from the next level, P^T
    Eigen::VectorXd inv_diag;
  };

  static bool inverse_diagonal(const Row_matrix& A, Eigen::VectorXd& inv_diag)
  {
    inv_diag = A.diagonal();
    for(Eigen::Index i = 0; i < inv_diag.size(); ++i) {
      if(!(std::abs(inv_diag[i]) > 0.) || !std::isfinite(inv_diag[i]))
        return false;
      inv_diag[i] = 1. / inv_diag[i];
    }
    return true;
  }

  // Groups the rows of `A` into aggregates (`aggregate[i]`: the aggregate of row i); returns
  // their number. First, a row none of whose strong neighbours is taken makes an aggregate with
  // them; then the rows left join the aggregate of their strongest taken neighbour; the rows
  // still left (no taken neighbour) make aggregates with their free neighbours.
  static Eigen::Index aggregates(const Row_matrix& A, const Eigen::VectorXd& inv_diag, double threshold,
                                 std::vector<Eigen::Index>& aggregate)
  {
    const Eigen::Index n = A.rows();
    auto strong = [&](Eigen::Index i, Eigen::Index j, double a) {
      return i != j && std::abs(a) * std::sqrt(std::abs(inv_diag[i] * inv_diag[j])) >= threshold;
    };
    aggregate.assign(std::size_t(n), -1);
    Eigen::Index count = 0;
    for(Eigen::Index i = 0; i < n; ++i) {
      if(aggregate[std::size_t(i)] >= 0)
        continue;
      bool free = true, coupled = false;
      for(Row_matrix::InnerIterator it(A, i); it && free; ++it)
        if(strong(i, it.col(), it.value())) {
          coupled = true;
          free = aggregate[std::size_t(it.col())] < 0;
        }
      if(!free || !coupled)
        continue;
      aggregate[std::size_t(i)] = count;
      for(Row_matrix::InnerIterator it(A, i); it; ++it)
        if(strong(i, it.col(), it.value()))
          aggregate[std::size_t(it.col())] = count;
      ++count;
    }
    std::vector<Eigen::Index> joined = aggregate;
    for(Eigen::Index i = 0; i < n; ++i) {
      if(aggregate[std::size_t(i)] >= 0)
        continue;
      double strongest = 0.;
      for(Row_matrix::InnerIterator it(A, i); it; ++it)
        if(it.col() != i && aggregate[std::size_t(it.col())] >= 0 && std::abs(it.value()) > strongest) {
          strongest = std::abs(it.value());
          joined[std::size_t(i)] = aggregate[std::size_t(it.col())];
        }
    }
    aggregate.swap(joined);
    for(Eigen::Index i = 0; i < n; ++i) {
      if(aggregate[std::size_t(i)] >= 0)
        continue;
      for(Row_matrix::InnerIterator it(A, i); it; ++it)
        if(aggregate[std::size_t(it.col())] < 0)
          aggregate[std::size_t(it.col())] = count;
      aggregate[std::size_t(i)] = count++;
    }
    return count;
  }

  // P = (I - omega D^{-1} A) T, T the constant on each aggregate. Row i of P is row i of A
  // gathered by aggregate, written in place: a row has a few entries, where building P from
  // triplets sorts and copies all of them twice. The entries of one aggregate are summed in the
  // order of the row (as the triplets summed them), exact zeros are left out.
  static Row_matrix smoothed_prolongation(const Row_matrix& A, const Eigen::VectorXd& inv_diag,
                                          const std::vector<Eigen::Index>& aggregate, Eigen::Index n_coarse)
  {
    typedef Row_matrix::StorageIndex Index;
    std::vector<Index> outer(std::size_t(A.rows()) + 1, 0), inner;
    std::vector<double> values;
    inner.reserve(std::size_t(A.nonZeros()));
    values.reserve(std::size_t(A.nonZeros()));
    std::vector<std::pair<Index, double> > row; // (aggregate, entry) of one row
    for(Eigen::Index i = 0; i < A.rows(); ++i) {
      row.clear();
      for(Row_matrix::InnerIterator it(A, i); it; ++it) {
        double p = -prolongation_damping * inv_diag[i] * it.value();
        if(it.col() == i)
          p += 1.;
        row.emplace_back(Index(aggregate[std::size_t(it.col())]), p);
      }
      for(std::size_t k = 1; k < row.size(); ++k) // insertion sort: stable, and rows are short
        for(std::size_t l = k; l > 0 && row[l - 1].first > row[l].first; --l)
          std::swap(row[l - 1], row[l]);
      for(std::size_t k = 0; k < row.size();) {
        double sum = row[k].second;
        std::size_t l = k + 1;
        for(; l < row.size() && row[l].first == row[k].first; ++l)
          sum += row[l].second;
        if(sum != 0.) {
          inner.push_back(row[k].first);
          values.push_back(sum);
        }
        k = l;
      }
      outer[std::size_t(i) + 1] = Index(inner.size());
    }
    return Eigen::Map<const Row_matrix>(A.rows(), n_coarse, Eigen::Index(inner.size()), outer.data(), inner.data(),
                                        values.data());
  }

  // one Gauss-Seidel sweep on A x = b, rows in increasing or decreasing order
  static void gauss_seidel(const Row_matrix& A, const Eigen::VectorXd& inv_diag, const Eigen::VectorXd& b,
                           Eigen::VectorXd& x, bool forward)
  {
    const Eigen::Index n = A.rows();
    for(Eigen::Index k = 0; k < n; ++k) {
      const Eigen::Index i = forward ? k : n - 1 - k;
      double r = b[i];
      for(Row_matrix::InnerIterator it(A, i); it; ++it)
        if(it.col() != i)
          r -= it.value() * x[it.col()];
      x[i] = r * inv_diag[i];
    }
  }

  // x = the V-cycle from level k down applied to b; the coarser levels' vectors in `w`
  void cycle(std::size_t k, const Eigen::VectorXd& b, Eigen::VectorXd& x, Workspace& w) const
  {
    if(k == m_levels.size()) {
      x = m_coarse_lu->solve(b);
      return;
    }
    const Level& l = m_levels[k];
    x.setZero(l.A.rows());
    gauss_seidel(l.A, l.inv_diag, b, x, true);
    w.b[k + 1].noalias() = l.R * (b - l.A * x);
    cycle(k + 1, w.b[k + 1], w.x[k + 1], w);
    x.noalias() += l.P * w.x[k + 1];
    gauss_seidel(l.A, l.inv_diag, b, x, false);
  }

  std::vector<Level> m_levels;
  Row_matrix m_coarsest;
  std::unique_ptr<Coarse_lu> m_coarse_lu;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_AGGREGATION_MULTIGRID_H

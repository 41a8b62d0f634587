// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_UMFPACK_LU_H
#define CGAL_SMP_INTERNAL_UMFPACK_LU_H

// Eigen's UmfPackLU, set up for a sequence of factorizations of one pattern, with an eye on
// the peak memory (measured by the benchmark on the Loop refinements of the mannequin head):
// - UMFPACK's iterative refinement is off (Eigen leaves it on; it made each solve several times
//   slower for no gain in accuracy here);
// - METIS orders large systems (far fewer flops and less memory than AMD on large meshes; on
//   small ones its own cost outweighs that: see metis_threshold), AMD the others or if this
//   UMFPACK has no METIS;
// - the work area of the numeric factorization is allocated once at the size it needs: UMFPACK
//   starts from a fraction of an upper bound and grows by 1.2 at a time, which left the peak
//   well above the need. The first factorization is sized from the symbolic estimate of
//   the factors, the next ones from the peak of the previous one (same pattern, same pivots);
// - on large systems, the memory freed since the last factorization (by METIS, by the
//   stretch evaluation) is handed back to the system before the next one: glibc keeps freed
//   blocks below 32 MB in its heap, which raised the peak;
// - the factors are freed as soon as they have served (`release_numeric()` after the solve: the
//   stretch evaluation and the weight update that follow would otherwise add to them), and
//   `release()` frees the analysis once the iteration is over.

#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <Eigen/Dense>
#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <type_traits>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <typename Matrix_>
class Umfpack_lu : public Eigen::UmfPackLU<Matrix_>
{
  typedef Eigen::UmfPackLU<Matrix_>                          Base;

public:
  // unknowns from which METIS orders the system
  static constexpr long metis_threshold = 150000;

  template <typename Matrix>
  void analyzePattern(const Matrix& A)
  {
    this->umfpackControl()(UMFPACK_IRSTEP) = 0;
    const bool metis = A.rows() >= metis_threshold;
    this->umfpackControl()(UMFPACK_ORDERING) = metis ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
    Base::analyzePattern(A);
    if(metis && this->info() != Eigen::Success) {
      this->umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_AMD;
      Base::analyzePattern(A);
    }
    m_large = metis;
    m_work_units = 0.;
    // With the symmetric strategy (diagonal pivots, as on these diagonally dominant systems),
    // the estimate of the factors is close; otherwise UMFPACK's default applies.
    if(this->info() == Eigen::Success &&
       this->m_umfpackInfo(UMFPACK_STRATEGY_USED) == UMFPACK_STRATEGY_SYMMETRIC) {
      // 5% above the factors: the frontal matrices share the area (2% on top, measured)
      m_work_units = (std::max)(1.05 * this->m_umfpackInfo(UMFPACK_SYMMETRIC_LUNZ),
                                this->m_umfpackInfo(UMFPACK_VARIABLE_INIT_ESTIMATE));
    }
  }

  template <typename Matrix>
  void factorize(const Matrix& A)
  {
    // a negative value is an absolute size, in UMFPACK's units
    this->umfpackControl()(UMFPACK_ALLOC_INIT) = m_work_units > 0. ? -m_work_units : 0.7;
    release_numeric(); // before the new one is made, not while
#if defined(__GLIBC__)
    if(m_large)
      malloc_trim(0); // cheap next to the factorization
#endif
    Base::factorize(A);
    if(this->info() == Eigen::Success && this->m_umfpackInfo(UMFPACK_VARIABLE_PEAK) > 0.)
      m_work_units = this->m_umfpackInfo(UMFPACK_VARIABLE_PEAK);
  }

  // X = A^{-1} B after `factorize()`, the columns on up to `threads` threads: UMFPACK's solve
  // only reads the factors, and each column gets its own workspace and report. False if a
  // solve fails.
  bool solve_columns(const Eigen::MatrixXd& B, Eigen::MatrixXd& X, unsigned int threads) const
  {
    typedef typename Base::StorageIndex Index;
    if constexpr(!std::is_same<typename Base::Scalar, double>::value || !std::is_same<Index, int>::value) {
      X = this->solve(B);
      return this->info() == Eigen::Success;
    } else {
      const Eigen::Index n = B.rows(), columns = B.cols();
      X.resize(n, columns);
      if(!this->m_numeric || this->mp_matrix.rows() != n)
        return false;
      // W holds n values without iterative refinement, 5n with it
      const Eigen::Index w_size = this->m_control(UMFPACK_IRSTEP) > 0. ? 5 * n : n;
      // workspaces allocated here: the threads must not throw
      std::vector<char> ok(std::size_t(columns), 0);
      std::vector<std::vector<int> > wi(std::size_t(columns), std::vector<int>(static_cast<std::size_t>(n)));
      std::vector<std::vector<double> > w(std::size_t(columns), std::vector<double>(static_cast<std::size_t>(w_size)));
      parallel_for(std::size_t(columns), n >= Eigen::Index(parallel_grain) ? threads : 1u, 1,
                   [&](std::size_t begin, std::size_t end) {
        double info[UMFPACK_INFO];
        for(std::size_t j = begin; j < end; ++j)
          ok[j] = umfpack_di_wsolve(UMFPACK_A, this->mp_matrix.outerIndexPtr(), this->mp_matrix.innerIndexPtr(),
                                    this->mp_matrix.valuePtr(), X.col(Eigen::Index(j)).data(),
                                    B.col(Eigen::Index(j)).data(), this->m_numeric, this->m_control.data(),
                                    info, wi[j].data(), w[j].data()) == UMFPACK_OK;
      });
      return std::find(ok.begin(), ok.end(), 0) == ok.end();
    }
  }

  // Frees the numeric factorization; the next use starts with `factorize()`.
  void release_numeric()
  {
    if(this->m_numeric)
      Eigen::umfpack_free_numeric(&this->m_numeric, typename Base::Scalar(), typename Base::StorageIndex());
    this->m_factorizationIsOk = false;
  }

  // Frees the symbolic and numeric factorizations; the next use starts with `analyzePattern()`.
  void release()
  {
    release_numeric();
    if(this->m_symbolic)
      Eigen::umfpack_free_symbolic(&this->m_symbolic, typename Base::Scalar(), typename Base::StorageIndex());
    this->m_isInitialized = false;
    this->m_analysisIsOk = false;
    m_work_units = 0.;
  }

private:
  double m_work_units = 0.; // size of the work area of the next factorization (0: UMFPACK's default)
  bool m_large = false;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_UMFPACK_LU_H

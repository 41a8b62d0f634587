// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_UMFPACK_LU_H
#define CGAL_SMP_INTERNAL_UMFPACK_LU_H

// SuiteSparse's UMFPACK LU behind the interface of an Eigen sparse solver (what
// `CGAL::Eigen_solver_traits` calls: compute, analyzePattern, factorize, solve, info), set up
// for a sequence of factorizations of one pattern, with an eye on the peak memory (the
// benchmark measures it on the Loop refinements of the mannequin head). It calls UMFPACK's C
// interface itself, where Eigen's `UmfPackLU` keeps what this needs in protected members:
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
//   `release()` frees the analysis once the iteration is over;
// - the columns of a right-hand side are solved in parallel (`solve_columns()`);
// - the 32-bit interface (`di`) is used while the work area is well under 2 GB, which it cannot
//   exceed (UMFPACK then fails as out of memory), the 64-bit one (`dl`) beyond: a mesh of a few
//   million vertices needs more, and the 64-bit indices take more memory on smaller ones. The
//   64-bit analysis then takes the column order of the 32-bit one, where it would order the
//   system again (METIS on a large system is much of the cost of the analysis).

#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <umfpack.h>

#include <algorithm>
#include <climits>
#include <new>
#include <type_traits>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// UMFPACK's 64-bit index type (SuiteSparse_long before SuiteSparse 6, int64_t since), read off
// its own declaration.
template <typename R, typename I, typename... A>
I first_parameter(R (*)(I, A...));
typedef decltype(first_parameter(&umfpack_dl_symbolic)) Umfpack_index;

// UMFPACK's real-valued functions for 32-bit (`di`) or 64-bit (`dl`) indices.
template <typename Index>
struct Umfpack_interface;

template <>
struct Umfpack_interface<int>
{
  static long symbolic(long n, const int* p, const int* i, const double* x, void** s, const double* c, double* r)
  { return umfpack_di_symbolic(int(n), int(n), p, i, x, s, c, r); }
  static long numeric(const int* p, const int* i, const double* x, void* s, void** f, const double* c, double* r)
  { return umfpack_di_numeric(p, i, x, s, f, c, r); }
  static long solve(const int* p, const int* i, const double* x, double* X, const double* B, void* f, const double* c,
                    double* r, std::vector<int>& wi, std::vector<double>& w)
  { return umfpack_di_wsolve(UMFPACK_A, p, i, x, X, B, f, c, r, wi.data(), w.data()); }
  static void free_symbolic(void** s) { umfpack_di_free_symbolic(s); }
  static void free_numeric(void** f) { umfpack_di_free_numeric(f); }
};

template <>
struct Umfpack_interface<Umfpack_index>
{
  typedef Umfpack_index I;
  static long symbolic(long n, const I* p, const I* i, const double* x, void** s, const double* c, double* r)
  { return long(umfpack_dl_symbolic(I(n), I(n), p, i, x, s, c, r)); }
  static long ordered_symbolic(long n, const I* p, const I* i, const double* x, const I* q, void** s, const double* c,
                               double* r)
  { return long(umfpack_dl_qsymbolic(I(n), I(n), p, i, x, q, s, c, r)); }
  static long numeric(const I* p, const I* i, const double* x, void* s, void** f, const double* c, double* r)
  { return long(umfpack_dl_numeric(p, i, x, s, f, c, r)); }
  static long solve(const I* p, const I* i, const double* x, double* X, const double* B, void* f, const double* c,
                    double* r, std::vector<I>& wi, std::vector<double>& w)
  { return long(umfpack_dl_wsolve(UMFPACK_A, p, i, x, X, B, f, c, r, wi.data(), w.data())); }
  static void free_symbolic(void** s) { umfpack_dl_free_symbolic(s); }
  static void free_numeric(void** f) { umfpack_dl_free_numeric(f); }
};

// `Matrix` is `Eigen::SparseMatrix<double>` (column-major, int indices, copied to 64-bit ones
// for the `dl` interface). The matrix given to `factorize()` must outlive the solves that follow it.
template <typename Matrix>
class Umfpack_lu
{
  static_assert(std::is_same<typename Matrix::Scalar, double>::value &&
                std::is_same<typename Matrix::StorageIndex, int>::value && !Matrix::IsRowMajor,
                "Umfpack_lu takes a column-major Eigen::SparseMatrix<double> with int indices");

public:
  typedef Matrix                                             MatrixType;
  typedef double                                             Scalar;
  typedef int                                                StorageIndex;

  // unknowns from which METIS orders the system
  static constexpr long metis_threshold = 150000;

  Umfpack_lu()
  {
    umfpack_di_defaults(m_control);
    m_control[UMFPACK_IRSTEP] = 0;
  }
  // the factors are UMFPACK's: one owner (Eigen_solver_traits holds its solver by pointer)
  Umfpack_lu(const Umfpack_lu&) = delete;
  Umfpack_lu& operator=(const Umfpack_lu&) = delete;
  ~Umfpack_lu() { release(); }

  Eigen::ComputationInfo info() const { return m_info; }
  Eigen::Index rows() const { return m_n; }
  Eigen::Index cols() const { return m_n; }

  // The 64-bit interface, from the next `analyzePattern()` on, for work areas above `bytes` (for
  // tests; the default is half of what 32-bit indices allow): 0 takes it whatever the size,
  // after a 32-bit analysis whose column order it takes.
  void limit_32_bit_work_area(double bytes) { m_limit_32_bits = bytes; }

  // How the last analysis ordered the columns: UMFPACK_ORDERING_METIS, _AMD or _GIVEN (the
  // order of an earlier analysis).
  int ordering_used() const { return int(m_report[UMFPACK_ORDERING_USED]); }

  // The strategy of the last analysis: UMFPACK_STRATEGY_SYMMETRIC or _UNSYMMETRIC.
  int strategy_used() const { return int(m_report[UMFPACK_STRATEGY_USED]); }

  void compute(const Matrix& A)
  {
    analyzePattern(A);
    if(m_info == Eigen::Success)
      factorize(A);
  }

  void analyzePattern(const Matrix& A)
  {
    release();
    const Matrix& C = compressed(A);
    m_n = C.rows();
    if(C.rows() != C.cols()) {
      m_info = Eigen::InvalidInput;
      return;
    }
    m_wide = false;
    analyze(C);
    if(m_info == Eigen::Success && !fits_32_bits())
      widen(C);
  }

  void factorize(const Matrix& A)
  {
    release_numeric(); // before the new one is made, not while
    if(m_symbolic == nullptr || A.rows() != m_n || A.cols() != m_n) {
      m_info = Eigen::InvalidInput;
      return;
    }
    m_matrix = &compressed(A);
    if(m_wide)
      copy_pattern(*m_matrix);
#if defined(__GLIBC__)
    if(m_large)
      malloc_trim(0); // cheap next to the factorization
#endif
    long status = numeric();
    if(status == UMFPACK_ERROR_out_of_memory && !m_wide) { // the estimate was short: the 64-bit interface
      widen(*m_matrix); // its analysis copies the pattern to 64-bit indices
      status = m_info == Eigen::Success ? numeric() : long(UMFPACK_ERROR_internal_error);
    }
    if(status == UMFPACK_ERROR_out_of_memory) { // told as such by the parameterizers
      release_numeric();
      m_info = Eigen::NumericalIssue;
      throw std::bad_alloc();
    }
    if(status != UMFPACK_OK) { // a singular matrix gets factors too: they are not used
      release_numeric();
      m_info = Eigen::NumericalIssue;
      return;
    }
    m_info = Eigen::Success;
    if(m_report[UMFPACK_VARIABLE_PEAK] > 0.)
      m_work_units = m_report[UMFPACK_VARIABLE_PEAK];
  }

  // A^{-1} b after `factorize()`, one column after the other.
  template <typename Rhs>
  Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime>
  solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    Eigen::Matrix<double, Eigen::Dynamic, Rhs::ColsAtCompileTime> X(b.rows(), b.cols());
    const Eigen::MatrixXd B = b;
    if(!solve_columns(B, X, 1u))
      m_info = Eigen::NumericalIssue;
    return X;
  }

  // X = A^{-1} B after `factorize()`, the columns on up to `threads` threads: UMFPACK's solve
  // only reads the factors, and each column gets its own workspace and report. False if a
  // solve fails.
  template <typename Result>
  bool solve_columns(const Eigen::MatrixXd& B, Result& X, unsigned int threads) const
  {
    const Eigen::Index columns = B.cols();
    X.resize(m_n, columns);
    if(m_numeric == nullptr || B.rows() != m_n)
      return false;
    return m_wide ? solve_columns(Umfpack_interface<Umfpack_index>(), m_columns.data(), m_rows.data(), B, X, threads)
                  : solve_columns(Umfpack_interface<int>(), m_matrix->outerIndexPtr(), m_matrix->innerIndexPtr(),
                                  B, X, threads);
  }

  // Frees the numeric factorization; the next use starts with `factorize()`.
  void release_numeric()
  {
    if(m_numeric != nullptr)
      m_wide ? Umfpack_interface<Umfpack_index>::free_numeric(&m_numeric) : Umfpack_interface<int>::free_numeric(&m_numeric);
    m_numeric = nullptr;
  }

  // Frees the symbolic and numeric factorizations; the next use starts with `analyzePattern()`.
  void release()
  {
    release_numeric();
    free_symbolic();
    m_matrix = nullptr;
    m_own = Matrix();
    std::vector<Umfpack_index>().swap(m_columns);
    std::vector<Umfpack_index>().swap(m_rows);
    m_work_units = 0.;
  }

private:
  // `A` itself when compressed, else a compressed copy (UMFPACK reads compressed columns)
  const Matrix& compressed(const Matrix& A)
  {
    if(A.isCompressed())
      return A;
    m_own = A;
    m_own.makeCompressed();
    return m_own;
  }

  // the column starts and row indices of `C` in 64-bit indices
  void copy_pattern(const Matrix& C)
  {
    m_columns.assign(C.outerIndexPtr(), C.outerIndexPtr() + C.outerSize() + 1);
    m_rows.assign(C.innerIndexPtr(), C.innerIndexPtr() + C.nonZeros());
  }

  // frees what the 32-bit interface made and analyses `C` again with the 64-bit one, in the
  // column order and with the strategy of the 32-bit analysis (or ordering anew if the order
  // cannot be read; a given order alone would get the unsymmetric strategy and its pivoting),
  // and its estimate of the factors (an analysis with a given order makes none)
  void widen(const Matrix& C)
  {
    const double strategy = m_report[UMFPACK_STRATEGY_USED], entries = m_report[UMFPACK_SYMMETRIC_LUNZ];
    std::vector<int> order(static_cast<std::size_t>(m_n));
    int n_row, n_col, n1, nz, fronts, chains;
    const bool ordered = umfpack_di_get_symbolic(&n_row, &n_col, &n1, &nz, &fronts, &chains, nullptr, order.data(),
                                                 nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, nullptr,
#if UMFPACK_MAIN_VERSION >= 6
                                                 nullptr, // Dmap, since UMFPACK 6
#endif
                                                 m_symbolic) == UMFPACK_OK;
    release_numeric();
    free_symbolic();
    m_wide = true;
    if(ordered) {
      const std::vector<Umfpack_index> q(order.begin(), order.end());
      std::vector<int>().swap(order);
      m_control[UMFPACK_STRATEGY] = strategy;
      analyze(C, q.data());
      m_control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_AUTO;
      if(m_info == Eigen::Success && strategy == UMFPACK_STRATEGY_SYMMETRIC) // the same order, the same factors
        m_work_units = (std::max)(work_units(entries), m_report[UMFPACK_VARIABLE_INIT_ESTIMATE]);
    }
    if(!ordered || m_info != Eigen::Success)
      analyze(C);
  }

  void free_symbolic()
  {
    if(m_symbolic != nullptr)
      m_wide ? Umfpack_interface<Umfpack_index>::free_symbolic(&m_symbolic) : Umfpack_interface<int>::free_symbolic(&m_symbolic);
    m_symbolic = nullptr;
  }

  // The symbolic analysis of `C` with the interface of `m_wide`, in the column order `given`
  // (64-bit interface only) or else METIS's on large systems (AMD's if METIS fails) or AMD's,
  // and the size of the work area it predicts.
  void analyze(const Matrix& C, const Umfpack_index* given = nullptr)
  {
    const bool metis = m_n >= metis_threshold;
    m_control[UMFPACK_ORDERING] = metis ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
    long status = symbolic(C, given);
    if(given == nullptr && metis && status != UMFPACK_OK) {
      m_control[UMFPACK_ORDERING] = UMFPACK_ORDERING_AMD;
      status = symbolic(C);
    }
    m_info = status == UMFPACK_OK ? Eigen::Success : Eigen::NumericalIssue;
    m_large = metis;
    m_work_units = 0.;
    // With the symmetric strategy (diagonal pivots, as on these diagonally dominant systems),
    // the estimate of the factors is close; otherwise UMFPACK's default applies.
    if(m_info == Eigen::Success && m_report[UMFPACK_STRATEGY_USED] == UMFPACK_STRATEGY_SYMMETRIC)
      m_work_units = (std::max)(work_units(m_report[UMFPACK_SYMMETRIC_LUNZ]), m_report[UMFPACK_VARIABLE_INIT_ESTIMATE]);
  }

  // The work area, in UMFPACK's units, for factors of `entries` entries: a unit holds a double in
  // the 32-bit interface and two 64-bit indices (two doubles) in the 64-bit one. The margin is for
  // the frontal matrices, which share the area, and for the indices of the factors, which take
  // twice the room in the 64-bit interface.
  double work_units(double entries) const
  {
    return m_wide ? 1.10 * entries / 2. : 1.05 * entries;
  }

  // whether the work area the analysis predicts (or, without one, UMFPACK's upper bound) is
  // under the limit (by default half of what 32-bit indices allow: a margin for the estimate;
  // factorize() switches interfaces if it is still short)
  bool fits_32_bits() const
  {
    const double units = m_work_units > 0. ? m_work_units : m_report[UMFPACK_VARIABLE_PEAK_ESTIMATE];
    return units * double(sizeof(double)) < m_limit_32_bits;
  }

  long symbolic(const Matrix& C, const Umfpack_index* given = nullptr)
  {
    free_symbolic();
    if(!m_wide)
      return Umfpack_interface<int>::symbolic(long(m_n), C.outerIndexPtr(), C.innerIndexPtr(), C.valuePtr(),
                                              &m_symbolic, m_control, m_report);
    copy_pattern(C);
    typedef Umfpack_interface<Umfpack_index> Wide;
    return given != nullptr
             ? Wide::ordered_symbolic(long(m_n), m_columns.data(), m_rows.data(), C.valuePtr(), given, &m_symbolic,
                                      m_control, m_report)
             : Wide::symbolic(long(m_n), m_columns.data(), m_rows.data(), C.valuePtr(), &m_symbolic, m_control,
                              m_report);
  }

  long numeric()
  {
    // a negative value is an absolute size, in UMFPACK's units
    m_control[UMFPACK_ALLOC_INIT] = m_work_units > 0. ? -m_work_units : 0.7;
    return m_wide ? Umfpack_interface<Umfpack_index>::numeric(m_columns.data(), m_rows.data(), m_matrix->valuePtr(),
                                                              m_symbolic, &m_numeric, m_control, m_report)
                  : Umfpack_interface<int>::numeric(m_matrix->outerIndexPtr(), m_matrix->innerIndexPtr(),
                                                    m_matrix->valuePtr(), m_symbolic, &m_numeric, m_control, m_report);
  }

  template <typename Interface, typename Index, typename Result>
  bool solve_columns(Interface, const Index* columns, const Index* rows, const Eigen::MatrixXd& B, Result& X,
                     unsigned int threads) const
  {
    // one workspace per column: the columns are solved at the same time
    const std::size_t c = static_cast<std::size_t>(B.cols()), n = static_cast<std::size_t>(m_n);
    std::vector<char> ok(c, 0);
    std::vector<std::vector<Index> > wi(c, std::vector<Index>(n));
    std::vector<std::vector<double> > w(c, std::vector<double>(n));
    parallel_for(c, m_n >= Eigen::Index(parallel_grain) ? threads : 1u, 1, [&](std::size_t begin, std::size_t end) {
      double report[UMFPACK_INFO];
      for(std::size_t j = begin; j < end; ++j)
        ok[j] = Interface::solve(columns, rows, m_matrix->valuePtr(), X.col(Eigen::Index(j)).data(),
                                 B.col(Eigen::Index(j)).data(), m_numeric, m_control, report, wi[j], w[j]) == UMFPACK_OK;
    });
    return std::find(ok.begin(), ok.end(), 0) == ok.end();
  }

  double m_control[UMFPACK_CONTROL];
  double m_report[UMFPACK_INFO];
  void* m_symbolic = nullptr;
  void* m_numeric = nullptr;
  const Matrix* m_matrix = nullptr; // the factorized matrix (read again by the solves)
  Matrix m_own;                     // its compressed copy when it was not compressed
  Eigen::Index m_n = 0;
  mutable Eigen::ComputationInfo m_info = Eigen::InvalidInput;
  double m_work_units = 0.;         // size of the work area of the next factorization (0: UMFPACK's default)
  bool m_large = false;
  bool m_wide = false;              // the 64-bit interface, on m_columns and m_rows
  double m_limit_32_bits = 0.5 * double(INT_MAX); // bytes of work area
  std::vector<Umfpack_index> m_columns, m_rows; // the pattern in 64-bit indices, when m_wide
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_UMFPACK_LU_H

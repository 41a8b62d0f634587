// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_PARALLEL_FOR_H
#define CGAL_SMP_INTERNAL_PARALLEL_FOR_H

// The loops of the iteration over faces, ring entries and columns, on several cores with
// std::thread (no dependency beyond the standard library). Each item writes only its own
// outputs and every sum is taken afterwards in a fixed order, so that the result does not
// depend on the number of threads, bit for bit.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Fewest items (faces, ring entries, rows) a thread takes in the loops of the iteration.
constexpr std::size_t parallel_grain = 16384;

// Number of threads for `requested` (0: one per core).
inline unsigned int thread_count(unsigned int requested)
{
  if(requested > 0)
    return requested;
  const unsigned int cores = std::thread::hardware_concurrency();
  return cores > 0 ? cores : 1;
}

// The first exception thrown by the calls that `run()` makes, from any thread (an exception
// left in a std::thread would terminate the program); `rethrow()` throws it on the calling thread.
class First_exception
{
public:
  // Calls `f()`; if it throws, keeps the exception (the first one) and returns false.
  template <typename Function>
  bool run(const Function& f)
  {
    try {
      f();
      return true;
    } catch(...) {
      std::lock_guard<std::mutex> lock(m_mutex);
      if(!m_error)
        m_error = std::current_exception();
      return false;
    }
  }

  void rethrow() const
  {
    if(m_error)
      std::rethrow_exception(m_error);
  }

private:
  std::exception_ptr m_error;
  std::mutex m_mutex;
};

// Calls `f(begin, end)` on contiguous chunks covering [0, n), on at most `threads` threads,
// with at least `min_chunk` items a chunk (starting a thread costs tens of microseconds).
// If a thread cannot be started, its chunk runs on the calling thread. The first exception
// thrown by `f` is rethrown here once every thread has stopped.
template <typename Function>
void parallel_for(std::size_t n, unsigned int threads, std::size_t min_chunk, const Function& f)
{
  const std::size_t chunks = (std::min)(std::size_t(threads), n / (std::max)(min_chunk, std::size_t(1)));
  if(chunks <= 1) {
    f(std::size_t(0), n);
    return;
  }
  First_exception error;
  auto chunk = [&](std::size_t k) { error.run([&] { f(n * k / chunks, n * (k + 1) / chunks); }); };
  std::vector<std::thread> pool;
  pool.reserve(chunks - 1); // before any thread runs: a joinable thread must not be left behind
  std::size_t k = 1;
  try {
    for(; k < chunks; ++k)
      pool.emplace_back(chunk, k);
  } catch(const std::exception&) {
    // no more threads (or no memory for one): the remaining chunks run here
  }
  chunk(0);
  for(std::size_t j = k; j < chunks; ++j)
    chunk(j);
  for(std::thread& t : pool)
    t.join();
  error.rethrow();
}

// Calls `f(i)` for every i in [0, n) on at most `threads` threads, each taking the next item
// when it is done with one (for items of very different costs, such as the charts of an
// atlas). The first exception thrown by `f` is rethrown here once every thread has stopped.
template <typename Function>
void parallel_for_each(std::size_t n, unsigned int threads, const Function& f)
{
  std::atomic<std::size_t> next(0);
  First_exception error;
  auto work = [&]() {
    for(std::size_t i = next++; i < n; i = next++)
      if(!error.run([&] { f(i); }))
        next = n; // the others stop after their current item
  };
  std::vector<std::thread> pool;
  const std::size_t helpers = (std::min)(std::size_t(threads), n) - (n > 0 && threads > 0 ? 1 : 0);
  pool.reserve(helpers); // before any thread runs: a joinable thread must not be left behind
  try {
    for(std::size_t k = 0; k < helpers; ++k)
      pool.emplace_back(work);
  } catch(const std::exception&) {
    // no more threads (or no memory for one): the calling thread and the ones started take every item
  }
  work();
  for(std::thread& t : pool)
    t.join();
  error.rethrow();
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_PARALLEL_FOR_H

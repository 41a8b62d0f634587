// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_SECOND_THREAD_H
#define CGAL_SMP_INTERNAL_ATLAS_SECOND_THREAD_H

// A second thread for tasks too short to start a thread each: the caller hands a task over,
// does work of its own, then withdraws the task if the thread has not started it (and does it
// itself), so that it never waits for a thread that the system has not scheduled yet. On a
// machine busy with other processes, such a wait lasts a time slice of theirs, far longer than
// a short task. Either side checks for a while before it sleeps on a condition variable (waking
// a sleeping thread takes longer than many tasks): the caller without giving its core away, the
// thread yielding its core between checks to the program's other threads.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Second_thread
{
public:
  typedef std::chrono::steady_clock Clock;

  // Starts the thread; if the system gives none, every task is left to be withdrawn.
  Second_thread()
  {
    try {
      m_thread = std::thread([this] { serve(); });
    } catch(const std::system_error&) {
    }
  }

  // Withdraws the task handed over or waits for it (the caller may be leaving on an exception,
  // the task's data with it), then stops the thread.
  ~Second_thread()
  {
    if(!m_thread.joinable()) return;
    int pending = PENDING;
    m_state.compare_exchange_strong(pending, IDLE, std::memory_order_acq_rel);
    {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_done.wait(lock, [this] { return m_state.load(std::memory_order_acquire) == IDLE; });
      m_stop = true;
    }
    m_wake.notify_one();
    m_thread.join();
  }

  Second_thread(const Second_thread&) = delete;
  Second_thread& operator=(const Second_thread&) = delete;

  // Hands `task` over (the task before it withdrawn or run).
  void hand_over(std::function<void()> task)
  {
    m_task = std::move(task);
    {
      std::lock_guard<std::mutex> lock(m_mutex);
      m_state.store(PENDING, std::memory_order_release);
    }
    m_wake.notify_one();
  }

  // Takes the task handed over back if the thread has not started it within `grace` (true: it
  // will not run), else waits until it has run (false); an exception the task threw is thrown here.
  bool withdraw(Clock::duration grace = Clock::duration::zero())
  {
    if(m_thread.joinable())
      spin([this] { return m_state.load(std::memory_order_acquire) != PENDING; }, grace);
    int pending = PENDING;
    if(m_state.compare_exchange_strong(pending, IDLE, std::memory_order_acq_rel)) {
      m_task = nullptr;
      return true;
    }
    const auto idle = [this] { return m_state.load(std::memory_order_acquire) == IDLE; };
    if(!spin(idle, caller_spin())) {
      std::unique_lock<std::mutex> lock(m_mutex);
      m_done.wait(lock, idle);
    }
    if(m_error)
      std::rethrow_exception(std::exchange(m_error, nullptr));
    return false;
  }

private:
  enum : int { IDLE, PENDING, RUNNING };
  std::thread m_thread;
  std::atomic<int> m_state{IDLE};
  std::function<void()> m_task; // set by the caller while IDLE, taken by the thread once RUNNING
  std::exception_ptr m_error;   // set by the thread before IDLE
  std::mutex m_mutex;           // for sleeping on the state and on m_stop
  std::condition_variable m_wake, m_done;
  bool m_stop = false;

  static Clock::duration caller_spin() { return std::chrono::microseconds(500); }
  static Clock::duration thread_spin() { return std::chrono::milliseconds(1); }

  // Whether `done()` became true within `time`, checked without sleeping (yielding the core
  // to other threads between checks if `yield`).
  template <typename Predicate>
  static bool spin(const Predicate& done, Clock::duration time, bool yield = false)
  {
    const auto start = Clock::now();
    for(int i = 1; !done(); ++i) {
      if(yield)
        std::this_thread::yield();
      if((yield || i % 64 == 0) && Clock::now() - start > time)
        return done();
    }
    return true;
  }

  void serve()
  {
    const auto pending = [this] { return m_state.load(std::memory_order_acquire) == PENDING; };
    for(;;) {
      if(!spin(pending, thread_spin(), true)) {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_wake.wait(lock, [&] { return m_stop || pending(); });
        if(m_stop) return;
      }
      int expected = PENDING;
      if(!m_state.compare_exchange_strong(expected, RUNNING, std::memory_order_acq_rel))
        continue; // withdrawn meanwhile
      const std::function<void()> task = std::move(m_task);
      try {
        task();
      } catch(...) {
        m_error = std::current_exception();
      }
      {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_state.store(IDLE, std::memory_order_release);
      }
      m_done.notify_one();
    }
  }
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_SECOND_THREAD_H

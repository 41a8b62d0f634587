// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SHARED_REPORT_H
#define CGAL_SMP_INTERNAL_SHARED_REPORT_H

// The report of the last call, shared by the copies of a parameterizer: CGAL's free
// parameterize() works on a copy, and the caller reads the report from the original. A call
// fills a report of its own and publishes it when it ends, so copies that work at the same time
// (on several threads) never write one report at once: the last call to end is the one read.

#include <mutex>
#include <utility>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <typename Report>
class Shared_report
{
public:
  void publish(Report&& report)
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    m_report = std::move(report);
  }

  Report read() const
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_report;
  }

private:
  mutable std::mutex m_mutex;
  Report m_report;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SHARED_REPORT_H

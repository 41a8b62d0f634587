// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Faults that are not in the input: memory running out at any allocation of a call (a global
// operator new that fails the N-th allocation, for every N), and a sparse solver that fails at
// some step. Each must give an error code with a message, or the best map so far: never an
// exception out of the package, a crash, or a half-written map.

#include "smp_test_mesh.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

// ---- an operator new that fails the N-th allocation (counted from arm()), once
namespace {
std::atomic<long> allocations(0);
std::atomic<long> fail_at(-1); // -1: none fails
std::atomic<bool> failed(false);

void arm(long n)
{
  allocations = 0;
  failed = false;
  fail_at = n;
}

void disarm() { fail_at = -1; }
} // namespace

void* operator new(std::size_t size)
{
  if(allocations++ == fail_at) {
    failed = true;
    throw std::bad_alloc();
  }
  if(void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
// every other form goes through the two above (with a sanitizer, a block must be freed by the
// allocator that made it)
void* operator new[](std::size_t size) { return ::operator new(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept
{
  try {
    return ::operator new(size);
  } catch(const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return ::operator new(size, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

// LeakSanitizer: CGAL leaks a block it has just allocated when the allocation that follows
// fails: Surface_mesh's property container the array it is adding (CGAL 6.1.1,
// Property_container::add), and Compact_container (under the triangulations that
// triangulate_hole() builds) a new block of items, when recording the block fails
// (push_back_new_block()). Only this test makes allocations fail.
extern "C" const char* __lsan_default_suppressions()
{
  return "leak:Property_container\n"
         "leak:push_back_new_block\n";
}

namespace {

using namespace smp_test;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = SMP::parameters;

bool says_out_of_memory(const std::string& message) { return message.find("out of memory") != std::string::npos; }

// Every allocation of a parameterizer call fails once in turn (at most `runs` of them, evenly
// spread): the call returns an out-of-memory error (or OK, where a fallback absorbed the
// failure), never throws, and on an error no interior vertex is written.
template <typename Parameterizer>
void check_out_of_memory(const std::string& what, Parameterizer p, const std::string& file, long runs)
{
  Mesh m = read_mesh(file);
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  Maps maps = make_maps(m);
  std::vector<bool> on_border(m.number_of_vertices(), false);
  for(halfedge_descriptor h : halfedges_around_face(bhd, m))
    on_border[std::size_t(target(h, m))] = true;

  // the allocations of one call
  arm(-1);
  SMP_CHECK(p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp) == SMP::OK, what << ": fails without a fault");
  const long total = allocations;
  SMP_CHECK(total > 0, what << ": no allocation counted");
  const long stride = (std::max)(1L, total / runs);
  long errors = 0, escaped = 0;
  for(long n = 0; n < total; n += stride) {
    for(vertex_descriptor v : vertices(m))
      put(maps.uv, v, unwritten_uv);
    SMP::Error_code status = SMP::OK;
    arm(n);
    try {
      status = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    } catch(...) {
      ++escaped;
    }
    disarm();
    if(!failed)
      continue; // the call took another path with fewer allocations
    if(status == SMP::OK)
      continue; // what failed had a fallback (e.g. one thread fewer)
    ++errors;
    SMP_CHECK(status == SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM && says_out_of_memory(p.report().message),
              what << ": allocation " << n << ": " << SMP::error_message(status) << ", " << p.report().message);
    bool written = false;
    for(vertex_descriptor v : vertices(m))
      written = written || (!on_border[std::size_t(v)] && get(maps.uv, v) != unwritten_uv);
    SMP_CHECK(!written, what << ": allocation " << n << ": an interior vertex written on an error");
  }
  SMP_CHECK(escaped == 0, what << ": std::bad_alloc escaped from " << escaped << " calls");
  SMP_CHECK(errors > 0, what << ": no failed allocation gave an error");
  std::cout << what << ": " << total << " allocations, every " << stride << "th failed in turn: " << errors
            << " out-of-memory errors, " << escaped << " exceptions out" << std::endl;
}

// The same for the atlas of a closed mesh (cut, charts flattened on two threads, packed).
void check_atlas_out_of_memory(const std::string& file, long runs)
{
  Mesh m = read_mesh(file);
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(m, points, polygons);
  arm(-1);
  SMP_CHECK(SMP::make_atlas(points, polygons, P::number_of_threads(2u)).report.status == SMP::OK, "atlas without a fault");
  const long total = allocations;
  const long stride = (std::max)(1L, total / runs);
  long errors = 0, escaped = 0;
  for(long n = 0; n < total; n += stride) {
    SMP::Atlas atlas;
    arm(n);
    try {
      atlas = SMP::make_atlas(points, polygons, P::number_of_threads(2u));
    } catch(...) {
      ++escaped;
    }
    disarm();
    if(!failed || atlas.report.status == SMP::OK)
      continue;
    ++errors;
    SMP_CHECK(says_out_of_memory(atlas.report.message) && atlas.uv.empty() && atlas.chart.empty(),
              "atlas: allocation " << n << ": " << atlas.report.message);
  }
  SMP_CHECK(escaped == 0, "atlas: std::bad_alloc escaped from " << escaped << " calls");
  SMP_CHECK(errors > 0, "atlas: no failed allocation gave an error");
  std::cout << "atlas of " << file << ": " << total << " allocations, every " << stride << "th failed in turn: "
            << errors << " out-of-memory errors, " << escaped << " exceptions out" << std::endl;
}

// Eigen's SparseLU whose factorizations fail from the `fail_from`-th one (counted from 0).
struct Failing_lu : Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> >
{
  typedef Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > Base;
  static int fail_from;
  int factorizations = 0;
  bool failing = false;

  void factorize(const MatrixType& A)
  {
    Base::factorize(A);
    failing = factorizations++ >= fail_from;
  }
  Eigen::ComputationInfo info() const { return failing ? Eigen::NumericalIssue : Base::info(); }
};
int Failing_lu::fail_from = 0;

// A solver that fails on U^0 gives an error; one that fails later keeps the best map so far.
void check_solver_failure()
{
  typedef CGAL::Eigen_solver_traits<Failing_lu> Traits;
  typedef SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Traits> Failing;
  Mesh m = read_mesh("nefertiti.off");
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  UV_map uv = new_uv(m, "v:uv"), uv0 = new_uv(m, "v:uv0");

  Failing_lu::fail_from = 0;
  Failing first;
  SMP_CHECK(SMP::parameterize(m, first, bhd, uv) == SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM &&
            !first.report().message.empty(), "a failure on U^0: " << first.report().message);

  Failing_lu::fail_from = 1;
  Failing later;
  SMP_CHECK(SMP::parameterize(m, later, bhd, uv) == SMP::OK, "a failure at step 1: " << later.report().message);
  const SMP::Stretch_minimizing_report r = later.report();
  SMP_CHECK(r.stop == SMP::Stretch_minimizing_stop::SOLVER_FAILED && r.kept_step == 0 && r.history.size() == 1 &&
            r.message.find("step 1") != std::string::npos, "stop " << int(r.stop) << ", " << r.message);
  SMP::Stretch_minimizing_parameterizer_3<Mesh> u0(P::number_of_iterations(0));
  SMP_CHECK(SMP::parameterize(m, u0, bhd, uv0) == SMP::OK, "U^0");
  const double d = max_distance(m, uv, uv0);
  SMP_CHECK(d < 1e-9, "the map kept is not U^0: " << d);
}

} // namespace

int main()
{
  check_solver_failure();
  check_out_of_memory("paper", SMP::Stretch_minimizing_parameterizer_3<Mesh>(), "nefertiti.off", 400);
  check_out_of_memory("lowest stretch, free border",
                      SMP::Stretch_minimizing_parameterizer_3<Mesh>(
                        P::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH).free_border(true)),
                      "nefertiti.off", 400);
  check_atlas_out_of_memory("pig.off", 120);
  return smp_test::summary();
}

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The iteration on every bundled disk mesh: no flipped face at any step, the kept step is the
// minimum of the history, U^1 below U^0, the package's overload of CGAL's free function
// parameterize(), the iteration cap, the options and the visitor, the
// initializers and solvers, symmetric weights and their Cholesky, the default solver on a large
// system, the multigrid solver, the result on several threads, and the quality bar of the
// paper's Mannequin head.

#include "smp_test_mesh.h"
#include "solver_configuration_eigen.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Natural_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_ear_aware_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>
#include <CGAL/Surface_mesh_parameterization/internal/Multigrid_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/Ordered_sparse_lu.h>
#include <CGAL/Surface_mesh_parameterization/internal/ring_weights.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/subdivision_method_3.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseLU>

#include <algorithm>
#include <atomic>
#include <limits>
#include <random>
#include <cctype>
#include <cmath>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <typeinfo>
#include <vector>

namespace test_stretch_minimizing {

using namespace smp_test;
namespace SMP = CGAL::Surface_mesh_parameterization;

typedef SMP::Stretch_minimizing_parameterizer_3<Mesh> Default_smp;

// The properties every run on a disk with a convex border must have.
template <typename Parameterizer>
void check_run(const std::string& what, Mesh& m, halfedge_descriptor bhd, Parameterizer& p, UV_map uv,
               SMP::Error_code status)
{
  const SMP::Stretch_minimizing_report& r = p.report();
  SMP_CHECK(status == SMP::OK && r.status == SMP::OK, what << ": " << SMP::error_message(status) << " " << r.message);
  if(status != SMP::OK)
    return;
  double best = r.history.at(0).l2_stretch;
  std::size_t argmin = 0;
  for(const SMP::Stretch_minimizing_step& s : r.history) {
    SMP_CHECK(s.flipped_faces == 0, what << ": U^" << s.step << " has " << s.flipped_faces << " flipped faces");
    SMP_CHECK(std::isfinite(s.l2_stretch) && s.l2_stretch >= 1. - 1e-12, what << ": U^" << s.step << " L2 " << s.l2_stretch);
    if(s.l2_stretch < best) { best = s.l2_stretch; argmin = s.step; }
  }
  SMP_CHECK(r.kept_step == argmin, what << ": kept U^" << r.kept_step << " but the minimum is U^" << argmin);

  // what was written is what the report says
  const SMP::Stretch_statistics st = SMP::compute_stretch_statistics(m, uv);
  SMP_CHECK(std::abs(st.l2_stretch - r.l2_stretch()) < 1e-9 * st.l2_stretch,
            what << ": written map has L2 " << st.l2_stretch << ", report says " << r.l2_stretch());
  SMP_CHECK(st.flipped_faces == 0, what << ": written map has " << st.flipped_faces << " flipped faces");
  SMP_CHECK(st.degenerate_uv_faces == r.kept().degenerate_uv_faces, what << ": degenerate faces differ");
  for(vertex_descriptor v : vertices(m))
    if(!(uv[v].x() >= -1e-12 && uv[v].x() <= 1. + 1e-12 && uv[v].y() >= -1e-12 && uv[v].y() <= 1. + 1e-12)) {
      SMP_CHECK(false, what << ": a vertex is outside the unit square (or not written)");
      break;
    }
  (void)bhd;
}

void check_disk_mesh(const std::string& name)
{
  Loaded l = load(name);
  Mesh& m = l.mesh;

  // the paper's method, through CGAL's free function
  UV_map uv = new_uv(m, "v:uv");
  Default_smp p;
  SMP::Error_code status = SMP::parameterize(m, p, l.bhd, uv);
  check_run(name + " default", m, l.bhd, p, uv, status);
  const SMP::Stretch_minimizing_report r = p.report();
  SMP_CHECK(r.history.size() >= 3, name << ": U^1 already rejected");
  if(r.history.size() < 2)
    return; // what follows compares with U^1
  SMP_CHECK(r.history[1].l2_stretch < r.history[0].l2_stretch, name << ": U^1 not below U^0");
  SMP_CHECK(r.stop == SMP::Stretch_minimizing_stop::STRETCH_INCREASED, name << ": stopped for another reason");
  SMP_CHECK(r.interior_vertices + r.border_vertices == num_vertices(m), name << ": vertex counts");
  std::cout << name << ": U^0 " << r.history[0].l2_stretch << "  U^1 " << r.history[1].l2_stretch
            << "  U^opt " << r.kept().l2_stretch << " (h = " << r.kept_step << ")  degenerate uv faces "
            << r.kept().degenerate_uv_faces << std::endl;

  // cap 0: U^0, which is Floater's shape-preserving parameterization itself
  UV_map uv0 = new_uv(m, "v:uv0"), floater = new_uv(m, "v:floater");
  Default_smp p0(SMP::parameters::number_of_iterations(0));
  check_run(name + " cap 0", m, l.bhd, p0, uv0, SMP::parameterize(m, p0, l.bhd, uv0));
  SMP_CHECK(p0.report().history.size() == 1 && p0.report().kept_step == 0
              && p0.report().stop == SMP::Stretch_minimizing_stop::ITERATION_CAP, name << ": cap 0");
  SMP_CHECK(SMP::parameterize(m, SMP::Shape_preserving_parameterizer_3<Mesh>(), l.bhd, floater) == SMP::OK,
            name << ": Shape_preserving_parameterizer_3 failed");
  SMP_CHECK(max_distance(m, uv0, floater) < 1e-8, name << ": U^0 differs from Floater's map by " << max_distance(m, uv0, floater));

  // cap 1: U^1
  UV_map uv1 = new_uv(m, "v:uv1");
  Default_smp p1(SMP::parameters::number_of_iterations(1));
  check_run(name + " cap 1", m, l.bhd, p1, uv1, SMP::parameterize(m, p1, l.bhd, uv1));
  SMP_CHECK(p1.report().history.size() == 2 && p1.report().kept_step == 1, name << ": cap 1 kept U^" << p1.report().kept_step);
  SMP_CHECK(std::abs(p1.report().kept().l2_stretch - r.history[1].l2_stretch) < 1e-12, name << ": U^1 differs between runs");

  // mean-value start on a circle
  typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh> > MVC;
  UV_map uvm = new_uv(m, "v:uvm");
  SMP::Stretch_minimizing_parameterizer_3<Mesh, MVC> pm(MVC(), SMP::parameters::eta(0.8));
  status = SMP::parameterize(m, pm, l.bhd, uvm);
  SMP_CHECK(status == SMP::OK, name << " MVC: " << pm.report().message);
  if(status == SMP::OK) {
    SMP_CHECK(pm.report().kept().l2_stretch < pm.report().history[0].l2_stretch, name << " MVC: no gain");
    for(const auto& s : pm.report().history)
      SMP_CHECK(s.flipped_faces == 0, name << " MVC: flipped faces at U^" << s.step);
  }
}

void check_mannequin_bar()
{
  Loaded l = load("mannequin-devil.off");
  UV_map uv = new_uv(l.mesh, "v:uv");
  Default_smp p;
  check_run("mannequin eta 1", l.mesh, l.bhd, p, uv, SMP::parameterize(l.mesh, p, l.bhd, uv));
  const SMP::Stretch_minimizing_report& r = p.report();
  SMP_CHECK(r.history.size() > 1 && r.history[1].l2_stretch <= 1.95, "mannequin U^1 " << r.history.at(1).l2_stretch);
  SMP_CHECK(r.kept().l2_stretch <= 1.50, "mannequin U^opt (eta 1) " << r.kept().l2_stretch);

  Default_smp half(SMP::parameters::eta(0.5));
  check_run("mannequin eta 0.5", l.mesh, l.bhd, half, uv, SMP::parameterize(l.mesh, half, l.bhd, uv));
  SMP_CHECK(half.report().kept().l2_stretch <= 1.47, "mannequin U^opt (eta 0.5) " << half.report().kept().l2_stretch);
  std::cout << "mannequin: eta 0.5 U^opt " << half.report().kept().l2_stretch << " (h = "
            << half.report().kept_step << ")" << std::endl;
}

void check_options_and_visitor()
{
  Loaded l = load("mushroom.off");
  Mesh& m = l.mesh;
  UV_map uv = new_uv(m, "v:uv");

  // both ways of chaining the package's name with CGAL's give the same options
  Default_smp a(SMP::parameters::eta(0.5).number_of_iterations(7).verbose(false));
  Default_smp b(SMP::parameters::eta(0.5, CGAL::parameters::number_of_iterations(7)));
  SMP_CHECK(a.eta() == 0.5 && b.eta() == 0.5 && a.number_of_iterations() == 7 && b.number_of_iterations() == 7,
            "named parameters not taken");

  // the visitor sees every step in order and can stop the iteration
  std::vector<double> seen;
  auto record = [&seen](const SMP::Stretch_minimizing_step& s) { seen.push_back(s.l2_stretch); };
  Default_smp v(SMP::parameters::visitor(record));
  SMP_CHECK(SMP::parameterize(m, v, l.bhd, uv) == SMP::OK, "visited run failed");
  SMP_CHECK(seen.size() == v.report().history.size(), "visitor saw " << seen.size() << " steps");
  for(std::size_t h = 0; h < seen.size() && h < v.report().history.size(); ++h)
    SMP_CHECK(seen[h] == v.report().history[h].l2_stretch, "visitor saw another stretch at step " << h);

  std::size_t calls = 0;
  auto stop_at_1 = [&calls](const SMP::Stretch_minimizing_step& s) { ++calls; return s.step < 1; };
  Default_smp stopper;
  SMP_CHECK(stopper.parameterize(m, l.bhd, uv, get(CGAL::vertex_index, m),
                                 m.add_property_map<vertex_descriptor, bool>("v:done", false).first,
                                 SMP::parameters::visitor(stop_at_1)) == SMP::OK, "stopped run failed");
  SMP_CHECK(calls == 2 && stopper.report().history.size() == 2
              && stopper.report().stop == SMP::Stretch_minimizing_stop::VISITOR,
            "visitor stop: " << calls << " calls, " << stopper.report().history.size() << " steps");

  // per-call options override the constructor's: eta 0.25 needs more steps than eta 1
  Default_smp slow;
  SMP_CHECK(slow.parameterize(m, l.bhd, uv, get(CGAL::vertex_index, m),
                              m.add_property_map<vertex_descriptor, bool>("v:done2", false).first,
                              SMP::parameters::eta(0.25).number_of_iterations(50)) == SMP::OK, "eta 0.25 failed");
  SMP_CHECK(slow.report().history.size() > v.report().history.size(),
            "eta 0.25 took " << slow.report().history.size() << " steps, eta 1 " << v.report().history.size());

  // an iterative solver (warm-started from the last step) gives the same map as the LU default
  typedef CGAL::Eigen_solver_traits<Eigen::BiCGSTAB<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                                    Eigen::IncompleteLUT<double> > > Iterative;
  Iterative iterative;
  iterative.solver().setTolerance(1e-12);
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Iterative>
    pi(SMP::Shape_preserving_parameterizer_3<Mesh>(), iterative);
  UV_map uvi = new_uv(m, "v:uvi"), uvd = new_uv(m, "v:uvd");
  Default_smp pd;
  SMP_CHECK(SMP::parameterize(m, pi, l.bhd, uvi) == SMP::OK && SMP::parameterize(m, pd, l.bhd, uvd) == SMP::OK,
            "iterative or direct run failed");
  SMP_CHECK(pi.report().kept_step == pd.report().kept_step, "iterative kept another step");
  SMP_CHECK(max_distance(m, uvi, uvd) < 1e-7, "iterative and direct differ by " << max_distance(m, uvi, uvd));
}

// parallel_for covers [0, n) once, in chunks of at least the grain, whatever the thread count
void check_parallel_for()
{
  for(std::size_t n : {0, 1, 5, 100, 1001})
    for(unsigned int threads : {1u, 2u, 3u, 8u})
      for(std::size_t grain : {1, 7, 400}) {
        std::vector<int> hits(n, 0); // each index is written by one chunk only
        std::vector<std::pair<std::size_t, std::size_t> > chunks(threads + 1, {0, 0});
        std::atomic<unsigned int> calls(0);
        SMP::internal::parallel_for(n, threads, grain, [&](std::size_t begin, std::size_t end) {
          const unsigned int k = calls++;
          if(k < chunks.size())
            chunks[k] = {begin, end};
          for(std::size_t i = begin; i < end; ++i)
            ++hits[i];
        });
        SMP_CHECK(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }),
                  "parallel_for missed or repeated an index (n " << n << ", threads " << threads << ")");
        SMP_CHECK(calls >= 1 && calls <= threads, "parallel_for made " << calls << " chunks for " << threads << " threads");
        for(unsigned int k = 0; calls > 1 && k < calls; ++k)
          SMP_CHECK(chunks[k].second - chunks[k].first >= grain, "a chunk below the grain (n " << n << ")");
      }
}

// The loops over faces, ring entries and rows, and the two solves, run on several threads on a
// mesh this large (103k faces): the maps and the histories must be those of one thread, bit for
// bit, with the paper's rule and with the preset that updates the weights per edge.
void check_threads()
{
  Loaded l = load("mannequin-devil.off");
  CGAL::Subdivision_method_3::Loop_subdivision(l.mesh, CGAL::parameters::number_of_iterations(1));
  Mesh& m = l.mesh;
  l.bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  for(bool lowest : {false, true}) {
    const auto preset = lowest ? SMP::Stretch_minimizing_preset::LOWEST_STRETCH : SMP::Stretch_minimizing_preset::PAPER;
    // under the sanitizers, two descent steps: the same parallel code, run fewer times
    const unsigned int descent = !lowest ? 0u : smp_test::sanitized ? 2u : SMP::lowest_stretch_descent_iterations;
    Default_smp one(SMP::parameters::number_of_threads(1, SMP::parameters::preset(preset))
                      .number_of_iterations(3).descent_iterations(descent));
    Default_smp three(SMP::parameters::number_of_threads(3, SMP::parameters::preset(preset))
                        .number_of_iterations(3).descent_iterations(descent));
    UV_map uv1 = new_uv(m, "v:uv_one"), uv3 = new_uv(m, "v:uv_three");
    check_run("52k vertices, 1 thread", m, l.bhd, one, uv1, SMP::parameterize(m, one, l.bhd, uv1));
    check_run("52k vertices, 3 threads", m, l.bhd, three, uv3, SMP::parameterize(m, three, l.bhd, uv3));
    SMP_CHECK(max_distance(m, uv1, uv3) == 0., "3 threads differ from 1 by " << max_distance(m, uv1, uv3));
    const SMP::Stretch_minimizing_report r1 = one.report(), r3 = three.report();
    const auto& h1 = r1.history;
    const auto& h3 = r3.history;
    SMP_CHECK(h1.size() == h3.size(), "3 threads made " << h3.size() << " steps, 1 thread " << h1.size());
    for(std::size_t h = 0; h < h1.size() && h < h3.size(); ++h)
      SMP_CHECK(h1[h].l2_stretch == h3[h].l2_stretch && h1[h].eta == h3[h].eta, "step " << h << " differs");
    SMP_CHECK(one.report().l2_stretch() == three.report().l2_stretch() &&
              one.report().polish.descent_iterations == three.report().polish.descent_iterations,
              "the polish differs: " << one.report().l2_stretch() << " vs " << three.report().l2_stretch());
    m.remove_property_map(uv1);
    m.remove_property_map(uv3);
  }
}

// Copies of one parameterizer called on two threads at once (CGAL's free parameterize() copies
// it, and the copies share the solver): each call gives its own map, and the report they share
// is the whole report of one of the two calls. (With the solver shared unguarded, UMFPACK
// crashed here.)
void check_concurrent_copies()
{
  Loaded a = load("mushroom.off"), b = load("three_peaks.off");
  Default_smp p(SMP::parameters::number_of_threads(1));
  UV_map uva = new_uv(a.mesh, "v:uv"), uvb = new_uv(b.mesh, "v:uv");
  SMP_CHECK(SMP::parameterize(a.mesh, p, a.bhd, uva) == SMP::OK, "mushroom alone");
  const SMP::Stretch_minimizing_report ra = p.report();
  SMP_CHECK(SMP::parameterize(b.mesh, p, b.bhd, uvb) == SMP::OK, "three_peaks alone");
  const SMP::Stretch_minimizing_report rb = p.report();
  auto same = [](const SMP::Stretch_minimizing_report& x, const SMP::Stretch_minimizing_report& y) {
    return x.status == y.status && x.faces == y.faces && x.history.size() == y.history.size() &&
           x.kept_step == y.kept_step && x.l2_stretch() == y.l2_stretch();
  };
  SMP_CHECK(!same(ra, rb), "the two meshes should give two reports");
  for(int run = 0; run < 4; ++run) {
    SMP::Error_code ea = SMP::ERROR_EMPTY_MESH, eb = SMP::ERROR_EMPTY_MESH;
    std::thread ta([&] { ea = SMP::parameterize(a.mesh, p, a.bhd, uva); });
    std::thread tb([&] { eb = SMP::parameterize(b.mesh, p, b.bhd, uvb); });
    ta.join();
    tb.join();
    const SMP::Stretch_minimizing_report r = p.report();
    SMP_CHECK(ea == SMP::OK && eb == SMP::OK, "concurrent copies failed");
    SMP_CHECK(same(r, ra) || same(r, rb), "the shared report mixes two calls");
    SMP_CHECK(std::abs(SMP::compute_stretch_statistics(a.mesh, uva).l2_stretch - ra.l2_stretch()) < 1e-9 &&
              std::abs(SMP::compute_stretch_statistics(b.mesh, uvb).l2_stretch - rb.l2_stretch()) < 1e-9,
              "a map differs from its call alone");
  }
}

// A translation unit built without SuiteSparse (solver_configuration_eigen.cpp) and this one
// are linked together: when their solver macros differ, the package's types must differ too
// (else one definition would silently replace the other), and the maps must agree.
void check_solver_configurations()
{
  const std::string here = typeid(Default_smp).name(), there = eigen_configuration_type_name();
  SMP_CHECK(there.find("with_eigen") != std::string::npos, there);
#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS) || defined(CGAL_SMP_USE_CHOLMOD)
  SMP_CHECK(here != there, "one type for two solver configurations: " << here);
#else
  SMP_CHECK(here == there, here << " vs " << there);
#endif
  Loaded l = load("mannequin-devil.off");
  UV_map uv = new_uv(l.mesh, "v:uv_configuration");
  Default_smp p;
  SMP_CHECK(SMP::parameterize(l.mesh, p, l.bhd, uv) == SMP::OK, "the parameterization failed");
  const double other = eigen_configuration_stretch(smp_test::data_file("mannequin-devil.off"));
  SMP_CHECK(std::abs(p.report().l2_stretch() - other) < 1e-9 * other,
            p.report().l2_stretch() << " here, " << other << " without SuiteSparse");
}

// Solver traits that only model CGAL's concept SparseLinearAlgebraWithFactorTraits_d (no
// `solver()`): the same map as with the Eigen solver inside them.
struct Concept_only_traits
{
  typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                                    Eigen::COLAMDOrdering<int> > > Inside;
  typedef Inside::Matrix Matrix;
  typedef Inside::Vector Vector;
  typedef Inside::NT NT;

  bool factor(const Matrix& A, NT& D) { return inside.factor(A, D); }
  bool linear_solver(const Vector& B, Vector& X) { return inside.linear_solver(B, X); }
  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D) { return inside.linear_solver(A, B, X, D); }

  Inside inside;
};

void check_solver_concept()
{
  Loaded l = load("mannequin-devil.off");
  UV_map a = new_uv(l.mesh, "v:uv_concept"), b = new_uv(l.mesh, "v:uv_eigen");
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Concept_only_traits> pc;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Concept_only_traits::Inside> pe;
  check_run("concept-only solver traits", l.mesh, l.bhd, pc, a, SMP::parameterize(l.mesh, pc, l.bhd, a));
  SMP_CHECK(SMP::parameterize(l.mesh, pe, l.bhd, b) == SMP::OK, "Eigen_solver_traits");
  SMP_CHECK(pc.report().history.size() == pe.report().history.size() && max_distance(l.mesh, a, b) < 1e-9,
            "concept-only traits and Eigen_solver_traits differ by " << max_distance(l.mesh, a, b));
}

// A bundled mesh as the linear systems see it: its disk component, its clamped cotangent
// weights and its border on the unit circle.
struct System_input
{
  Loaded l;
  SMP::internal::Disk_component<Mesh> dc;
  std::vector<double> w;
  bool symmetric = false;
  std::vector<SMP::internal::Vec2> uv;
};

void load_system_input(const std::string& name, System_input& in)
{
  in.l = load(name);
  SMP_CHECK(in.dc.build(in.l.mesh, in.l.bhd, get(CGAL::vertex_point, in.l.mesh)) == SMP::OK, name << ": " << in.dc.message);
  SMP_CHECK(SMP::internal::clamped_cotangent_weights(in.dc, in.w, in.symmetric), name << ": no weights");
  in.uv.assign(in.dc.flat.xyz.size(), {0., 0.});
  for(std::size_t k = 0; k < in.dc.border.size(); ++k) {
    const double t = 6.283185307179586 * double(k) / double(in.dc.border.size());
    in.uv[std::size_t(in.dc.border[k])] = {std::cos(t), std::sin(t)};
  }
}

// Symmetric weights and their Cholesky. The clamped cotangent start gives w_ij = w_ji between
// interior vertices, bit for bit, around the closed holes too and where the floor raised a
// weight; a system of symmetric weights is factored by the Cholesky and solves as the LU of the
// normalized rows does; and the LOWEST_STRETCH iteration (edge update: the weights stay
// symmetric) takes the same steps as with traits that keep to the LU.
void check_symmetric_weights(const std::string& name)
{
  System_input in;
  load_system_input(name, in);
  Loaded& l = in.l;
  const SMP::internal::Disk_component<Mesh>& dc = in.dc;
  const std::vector<double>& w = in.w;
  SMP_CHECK(in.symmetric, name << ": not symmetric");
  std::size_t pairs = 0, asymmetric = 0, raised = 0;
  std::vector<SMP::internal::Vec3> ring;
  std::vector<double> raw;
  double mean = 0.;
  for(std::size_t r = 0; r < dc.number_of_rows(); ++r) {
    ring.clear();
    for(int e = dc.ring_begin[r]; e < dc.ring_begin[r + 1]; ++e)
      ring.push_back(dc.flat.xyz[dc.ring[e]]);
    SMP::internal::cotangent_ring_weights(dc.flat.xyz[dc.interior[r]], ring, raw, mean);
    for(int e = dc.ring_begin[r]; e < dc.ring_begin[r + 1]; ++e) {
      SMP_CHECK(w[e] > 0., name << ": a weight is not positive");
      raised += w[e] > raw[std::size_t(e - dc.ring_begin[r])];
      const int j = dc.row[dc.ring[e]];
      if(j < 0)
        continue;
      const int* first = &dc.ring[dc.ring_begin[j]];
      const int* last = &dc.ring[dc.ring_begin[j + 1]];
      const int* back = std::find(first, last, dc.interior[r]);
      ++pairs;
      asymmetric += back == last || w[std::size_t(back - &dc.ring[0])] != w[e];
    }
  }
  SMP_CHECK(pairs > 0 && asymmetric == 0, name << ": " << asymmetric << " of " << pairs << " pairs differ");
  std::cout << name << ": clamped cotangent weights, " << pairs << " symmetric pairs, " << raised
            << " raised to the floor" << std::endl;

  // the Cholesky of the symmetric system against the LU of the normalized one
  typedef SMP::internal::Default_solver_traits Traits;
  std::vector<SMP::internal::Vec2> uv_lu = in.uv, uv_ch = in.uv;
  std::vector<SMP::internal::Vec2> uv_ordered = uv_lu;
  std::vector<double> w_lu = w, w_ch = w, w_ordered = w;
  Traits lu_traits, ch_traits, ordered_traits;
  // any elimination order gives the same solution: the vertices backwards
  std::vector<int> rank(dc.flat.xyz.size());
  for(std::size_t v = 0; v < rank.size(); ++v)
    rank[v] = int(rank.size() - 1 - v);
  SMP::internal::Weighted_laplacian_system<Traits> lu(dc, false, {}), ch(dc, true, {}), ordered(dc, true, rank);
  SMP_CHECK(!lu.cholesky() && ch.cholesky() && ordered.cholesky(), name << ": the Cholesky is not taken where it should be");
  SMP_CHECK(lu.solve(w_lu, uv_lu, lu_traits) && ch.solve(w_ch, uv_ch, ch_traits) &&
            ordered.solve(w_ordered, uv_ordered, ordered_traits), name << ": a solve failed");
  double distance = 0., distance_ordered = 0.;
  for(std::size_t v = 0; v < uv_lu.size(); ++v) {
    distance = (std::max)(distance, std::hypot(uv_lu[v][0] - uv_ch[v][0], uv_lu[v][1] - uv_ch[v][1]));
    distance_ordered = (std::max)(distance_ordered, std::hypot(uv_lu[v][0] - uv_ordered[v][0], uv_lu[v][1] - uv_ordered[v][1]));
  }
  SMP_CHECK(distance < 1e-10, name << ": the Cholesky and the LU differ by " << distance);
  SMP_CHECK(distance_ordered < 1e-10, name << ": the Cholesky in a given order and the LU differ by " << distance_ordered);
  SMP_CHECK(w_ch == w && w_ordered == w, name << ": the Cholesky did not give the weights back as they were");

  // the whole LOWEST_STRETCH iteration, against concept-only traits (always the LU)
  namespace P = SMP::parameters;
  SMP::Stretch_minimizing_parameterizer_3<Mesh> pd(P::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH).descent_iterations(0u));
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Concept_only_traits> pc(
    SMP::Shape_preserving_parameterizer_3<Mesh>(), P::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH).descent_iterations(0u));
  UV_map a = new_uv(l.mesh, "v:uv_cholesky"), b = new_uv(l.mesh, "v:uv_lu");
  check_run(name + " LOWEST_STRETCH, Cholesky", l.mesh, l.bhd, pd, a, SMP::parameterize(l.mesh, pd, l.bhd, a));
  SMP_CHECK(SMP::parameterize(l.mesh, pc, l.bhd, b) == SMP::OK, name << ": LOWEST_STRETCH with the LU failed");
  const auto& hd = pd.report().history;
  const auto& hc = pc.report().history;
  bool same = hd.size() == hc.size();
  for(std::size_t h = 0; same && h < hd.size(); ++h)
    same = std::abs(hd[h].l2_stretch - hc[h].l2_stretch) <= 1e-9 * hc[h].l2_stretch;
  SMP_CHECK(same && max_distance(l.mesh, a, b) < 1e-9,
            name << ": LOWEST_STRETCH steps differ between the Cholesky and the LU (" << hd.size() << " and "
                 << hc.size() << " steps, maps " << max_distance(l.mesh, a, b) << " apart)");
}

// The Cholesky factorizations of Sander_vertex_solver in a given order (Eigen's LDL^T, and
// CHOLMOD's supernodal LL^T, which it takes for the definite systems of the largest meshes)
// against Eigen's LDL^T in its own order, on a grid Laplacian with its border fixed; the LL^T
// refuses a semidefinite system (which the solver then gives to the LDL^T).
void check_ordered_solvers()
{
  typedef Eigen::SparseMatrix<double> Matrix;
  const int side = 40, n = side * side;
  std::vector<Eigen::Triplet<double> > entries;
  for(int i = 0; i < side; ++i)
    for(int j = 0; j < side; ++j) {
      const int r = i * side + j;
      entries.emplace_back(r, r, 4. + 0.01 * double((i * 7 + j * 3) % 5));
      if(i > 0) entries.emplace_back(r, r - side, -1.);
      if(j > 0) entries.emplace_back(r, r - 1, -1.);
    }
  Matrix lower(n, n);
  lower.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd b(n);
  for(int r = 0; r < n; ++r)
    b(r) = std::sin(0.1 * r);
  std::vector<int> order(static_cast<std::size_t>(n)); // every other row, then the rest
  for(int k = 0; k < n; ++k)
    order[std::size_t(k)] = k < n / 2 ? 2 * k : 2 * (k - n / 2) + 1;
  Eigen::SimplicialLDLT<Matrix, Eigen::Lower> reference(lower);
  const Eigen::VectorXd x = reference.solve(b);
  SMP::internal::Ordered_ldlt ldlt;
  ldlt.analyze(lower, order);
  ldlt.factorize(lower);
  SMP_CHECK(ldlt.info() == Eigen::Success && (ldlt.solve(b) - x).norm() < 1e-10 * x.norm(),
            "Eigen's LDL^T in a given order solves otherwise");
  // new values on the pattern analysed (scattered into the permuted pattern of the analysis),
  // in the given order and in the minimum degree one, and a matrix not compressed (permuted anew)
  Matrix other = lower;
  for(int k = 0; k < other.nonZeros(); ++k)
    other.valuePtr()[k] *= 1. + 0.3 * std::cos(double(k));
  const Eigen::VectorXd y = Eigen::SimplicialLDLT<Matrix, Eigen::Lower>(other).solve(b);
  SMP::internal::Ordered_ldlt own, paired;
  own.analyze(lower, std::vector<int>());
  // the rows taken as pairs (2k, 2k + 1), as the u and v of a vertex: the minimum degree order
  // of the pairs keeps each pair together and is a permutation of the rows
  const std::vector<int> pairs = SMP::internal::minimum_degree_order(lower, true);
  std::vector<char> seen(std::size_t(n), 0);
  bool together = pairs.size() == std::size_t(n);
  for(std::size_t k = 0; together && k < pairs.size(); ++k) {
    const int r = pairs[k];
    together = r >= 0 && r < n && !seen[std::size_t(r)] && (k % 2 == 0 ? r % 2 == 0 : r == pairs[k - 1] + 1);
    if(together) seen[std::size_t(r)] = 1;
  }
  SMP_CHECK(together, "the minimum degree order of the pairs of rows splits a pair or is no permutation");
  paired.analyze(lower, std::vector<int>(), true);
  for(SMP::internal::Ordered_ldlt* solver : {&ldlt, &own, &paired}) {
    solver->factorize(other);
    SMP_CHECK(solver->info() == Eigen::Success && (solver->solve(b) - y).norm() < 1e-10 * y.norm(),
              "Eigen's LDL^T solves otherwise with new values on the pattern analysed");
    Matrix loose = other;
    loose.uncompress();
    solver->factorize(loose);
    SMP_CHECK(solver->info() == Eigen::Success && (solver->solve(b) - y).norm() < 1e-10 * y.norm(),
              "Eigen's LDL^T solves otherwise on a matrix not compressed");
  }
#if defined(CGAL_SMP_USE_CHOLMOD)
  SMP::internal::Ordered_cholmod llt;
  llt.analyze(lower, order);
  llt.factorize(lower);
  SMP_CHECK(llt.info() == Eigen::Success && (llt.solve(b) - x).norm() < 1e-10 * x.norm(),
            "CHOLMOD's LL^T in a given order solves otherwise");
  Matrix singular = lower;
  for(int r = 0; r < n; ++r)
    singular.coeffRef(r, r) = r == n / 3 ? -1. : singular.coeff(r, r);
  llt.factorize(singular);
  SMP_CHECK(llt.info() != Eigen::Success, "CHOLMOD's LL^T factored an indefinite matrix");
#endif

  // Eigen's SparseLU in the minimum degree order of the pattern, on a nonsymmetric matrix of
  // that pattern (rows weighted unevenly, as the weights of a vertex's neighbours are): the
  // solution of COLAMD's order, for one column and two, with the values changed after the
  // analysis, and again after the factors are freed
  Matrix general = lower.selfadjointView<Eigen::Lower>();
  for(int k = 0; k < general.outerSize(); ++k)
    for(Matrix::InnerIterator it(general, k); it; ++it)
      if(it.row() != it.col())
        it.valueRef() *= 1. + 0.5 * std::sin(double(3 * it.row() + it.col()));
  Eigen::SparseLU<Matrix, Eigen::COLAMDOrdering<int> > colamd(general);
  Eigen::MatrixXd B(n, 2);
  B << b, b.reverse();
  const Eigen::MatrixXd X = colamd.solve(B);
  SMP::internal::Ordered_sparse_lu lu;
  lu.analyzePattern(lower.selfadjointView<Eigen::Lower>());
  lu.factorize(general);
  SMP_CHECK(lu.info() == Eigen::Success && (lu.solve(B) - X).norm() < 1e-10 * X.norm() &&
            (lu.solve(b) - X.col(0)).norm() < 1e-10 * X.norm(), "Eigen's SparseLU in a minimum degree order solves otherwise");
  lu.release();
  SMP_CHECK(lu.info() != Eigen::Success, "the LU has factors after release()");
  lu.compute(general);
  SMP_CHECK(lu.info() == Eigen::Success && (lu.solve(B) - X).norm() < 1e-10 * X.norm(),
            "Eigen's SparseLU in a minimum degree order solves otherwise after release()");
}

// The multigrid solver. On systems of nonsymmetric positive weights (the clamped cotangent
// weights scaled at random, so that w_ij != w_ji), its solution is the LU's to 1e-9 (its
// tolerance is on the residual, 1e-12 of the right-hand side's norm), whatever the thread
// count; the direct solver it gives way to solves as the LU does, bit for bit. A hierarchy
// that cannot be built (a zero diagonal) and an iteration that cannot converge (a singular
// system with no solution) are reported as failures.
void check_multigrid(const std::string& name)
{
  System_input in;
  load_system_input(name, in);
  const SMP::internal::Disk_component<Mesh>& dc = in.dc;
  std::vector<double>& w = in.w;
  const std::vector<SMP::internal::Vec2>& uv = in.uv;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> scale(0.2, 5.);
  for(double& x : w)
    x *= scale(rng);
  typedef SMP::internal::Default_solver_traits Traits;
  typedef SMP::internal::Weighted_laplacian_system<Traits> System;
  Traits lu_traits, mg_traits, mg1_traits;
  System lu(dc, false, {}, std::numeric_limits<Eigen::Index>::max()), mg(dc, false, {}, 0), mg1(dc, false, {}, 0);
  std::vector<double> w_lu = w, w_mg = w, w_mg1 = w;
  std::vector<SMP::internal::Vec2> uv_lu = uv, uv_mg = uv, uv_mg1 = uv;
  SMP_CHECK(!lu.multigrid() && mg.multigrid(), name << ": the multigrid solver is not taken where it should be");
  SMP_CHECK(lu.solve(w_lu, uv_lu, lu_traits, 2) && mg.solve(w_mg, uv_mg, mg_traits, 2) &&
            mg1.solve(w_mg1, uv_mg1, mg1_traits, 1), name << ": a solve failed");
  SMP_CHECK(mg.multigrid() && mg1.multigrid(), name << ": the multigrid solver gave way to the direct solver");
  SMP_CHECK(lu.solver_iterations() == 0 && mg.solver_iterations() > 0 && mg.solver_iterations() == mg1.solver_iterations(),
            name << ": solver iterations " << lu.solver_iterations() << " (LU), " << mg.solver_iterations() << " and "
            << mg1.solver_iterations() << " (multigrid on two threads and on one)");
  double distance = 0.;
  for(std::size_t v = 0; v < uv.size(); ++v)
    distance = (std::max)(distance, std::hypot(uv_lu[v][0] - uv_mg[v][0], uv_lu[v][1] - uv_mg[v][1]));
  SMP_CHECK(distance < 1e-9, name << ": the multigrid solver and the LU differ by " << distance);
  SMP_CHECK(uv_mg == uv_mg1, name << ": the multigrid solution depends on the number of threads");

  // a screening solve stops early, and its refinement goes on with the same iteration: the map
  // and the iteration count of one full solve, bit for bit; a full solve needs no refinement
  {
    System screened(dc, false, {}, 0);
    std::vector<double> w_s = w;
    std::vector<SMP::internal::Vec2> uv_s = uv;
    SMP_CHECK(screened.solve(w_s, uv_s, mg1_traits, 2, true) && screened.screened() &&
              screened.solver_iterations() > 0 && screened.solver_iterations() < mg.solver_iterations(),
              name << ": the screening solve took " << screened.solver_iterations() << " iterations, the full one "
                   << mg.solver_iterations());
    SMP_CHECK(uv_s != uv_mg, name << ": the screening solve gave the full solution");
    SMP_CHECK(screened.refine(w_s, uv_s, mg1_traits, 2) && !screened.screened() && uv_s == uv_mg &&
              screened.solver_iterations() == mg.solver_iterations(),
              name << ": the refined screening solve differs from a full solve (" << screened.solver_iterations()
                   << " iterations against " << mg.solver_iterations() << ")");
    const std::vector<SMP::internal::Vec2> before = uv_s;
    SMP_CHECK(screened.refine(w_s, uv_s, mg1_traits, 2) && uv_s == before, name << ": a full solve was refined");
  }

  // the products of the hierarchy: Eigen's, on any number of threads
  {
    typedef SMP::internal::Aggregation_multigrid::Row_matrix Row_matrix;
    Row_matrix X(40000, 30000), Y(30000, 5000);
    std::vector<Eigen::Triplet<double> > x_entries, y_entries;
    std::uniform_int_distribution<int> x_col(0, 29999), y_col(0, 4999);
    for(int i = 0; i < 40000; ++i)
      for(int k = 0; k < 7; ++k)
        x_entries.emplace_back(i, x_col(rng), scale(rng) - 2.);
    for(int i = 0; i < 30000; ++i)
      for(int k = 0; k < 4; ++k)
        y_entries.emplace_back(i, y_col(rng), scale(rng));
    X.setFromTriplets(x_entries.begin(), x_entries.end());
    Y.setFromTriplets(y_entries.begin(), y_entries.end());
    const Row_matrix by_eigen = X * Y;
    const Row_matrix one = SMP::internal::Aggregation_multigrid::product(X, Y, 1);
    const Row_matrix two = SMP::internal::Aggregation_multigrid::product(X, Y, 2);
    const bool same_pattern = one.nonZeros() == by_eigen.nonZeros() && two.nonZeros() == one.nonZeros() &&
      std::equal(one.outerIndexPtr(), one.outerIndexPtr() + one.rows() + 1, by_eigen.outerIndexPtr()) &&
      std::equal(one.innerIndexPtr(), one.innerIndexPtr() + one.nonZeros(), by_eigen.innerIndexPtr()) &&
      std::equal(two.outerIndexPtr(), two.outerIndexPtr() + two.rows() + 1, one.outerIndexPtr()) &&
      std::equal(two.innerIndexPtr(), two.innerIndexPtr() + two.nonZeros(), one.innerIndexPtr());
    SMP_CHECK(same_pattern && (one - by_eigen).norm() <= 1e-14 * by_eigen.norm() &&
              std::equal(two.valuePtr(), two.valuePtr() + two.nonZeros(), one.valuePtr()),
              "the hierarchy's product differs from Eigen's or between one thread and two ("
                << one.nonZeros() << ", " << two.nonZeros() << " and " << by_eigen.nonZeros() << " entries)");
  }

  // the direct solver in its place: the LU's map again (the weights, normalized by the first
  // solves, are normalized alike in both)
  mg.use_direct_solver();
  SMP_CHECK(!mg.multigrid() && lu.solve(w_lu, uv_lu, lu_traits, 2) && mg.solve(w_mg, uv_mg, mg_traits, 2),
            name << ": a solve failed");
  SMP_CHECK(uv_mg == uv_lu, name << ": the direct solver after the multigrid one differs from the LU");
  std::cout << name << ": multigrid against LU " << distance << std::endl;

  // failures; the zero diagonal on a matrix larger than the coarsest level (which SparseLU
  // factors, with pivoting)
  const Eigen::Index size = 2 * SMP::internal::Aggregation_multigrid::coarsest_rows;
  Eigen::SparseMatrix<double> A(size, size);
  for(Eigen::Index i = 0; i < size; ++i)
    A.insert(i, i ^ 1) = 1.;
  SMP::internal::Aggregation_multigrid zero_diagonal;
  SMP_CHECK(!zero_diagonal.compute(A), "a zero diagonal entry is not reported");
  const int k = 60; // a ring of k vertices, its graph Laplacian: singular
  std::vector<Eigen::Triplet<double> > entries;
  for(int i = 0; i < k; ++i) {
    entries.emplace_back(i, i, 2.);
    entries.emplace_back(i, (i + 1) % k, -1.);
    entries.emplace_back(i, (i + k - 1) % k, -1.);
  }
  Eigen::SparseMatrix<double> ring(k, k);
  ring.setFromTriplets(entries.begin(), entries.end());
  SMP::internal::Multigrid_solver singular;
  Eigen::MatrixXd B = Eigen::MatrixXd::Ones(k, 1), X; // no x has A x = B: the rows of A sum to 0
  SMP_CHECK(singular.compute(ring) && !singular.solve(B, X, 1), "a system without solution is not reported");
}

#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
// The package's UMFPACK wrapper through CGAL's solver traits, as a user would call it: an
// uncompressed matrix, a solve checked against Eigen's SparseLU, and a singular matrix refused.
void check_umfpack_lu()
{
  typedef CGAL::Eigen_solver_traits<SMP::internal::Umfpack_lu<CGAL::Eigen_sparse_matrix<double>::EigenType> > Umfpack;
  typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > Sparse_lu;
  const int n = 50;
  Umfpack::Matrix A(n, n);
  Sparse_lu::Matrix A2(n, n);
  Umfpack::Vector B(n), X(n), X2(n);
  for(int i = 0; i < n; ++i) {
    A.set_coef(i, i, 4. + i, true);
    A2.set_coef(i, i, 4. + i, true);
    if(i + 1 < n) {
      A.set_coef(i, i + 1, -1., true);
      A2.set_coef(i, i + 1, -1., true);
      A.set_coef(i + 1, i, -2., true);
      A2.set_coef(i + 1, i, -2., true);
    }
    B.set(i, std::sin(double(i)));
  }
  Umfpack umfpack;
  Sparse_lu sparse_lu;
  double D = 0., D2 = 0.;
  SMP_CHECK(umfpack.linear_solver(A, B, X, D) && sparse_lu.linear_solver(A2, B, X2, D2), "a solve failed");
  double error = 0.;
  for(int i = 0; i < n; ++i)
    error = (std::max)(error, std::abs(X(i) - X2(i)));
  SMP_CHECK(error < 1e-12, "UMFPACK and SparseLU differ by " << error);

  Umfpack::Matrix S(2, 2); // rank 1
  S.set_coef(0, 0, 1., true);
  S.set_coef(0, 1, 1., true);
  S.set_coef(1, 0, 1., true);
  S.set_coef(1, 1, 1., true);
  Umfpack::Vector b(2), x(2);
  b.set(0, 1.);
  b.set(1, 2.);
  SMP_CHECK(!umfpack.linear_solver(S, b, x, D), "a singular matrix was solved");

  // the 64-bit interface (taken for work areas near 2 GB, here for any) analyses in the column
  // order of the 32-bit analysis, gives the same solutions, one or two columns at a time, and
  // refuses the singular matrix too
  typedef CGAL::Eigen_sparse_matrix<double>::EigenType Eigen_matrix;
  SMP::internal::Umfpack_lu<Eigen_matrix> narrow, wide;
  wide.limit_32_bit_work_area(0.);
  const Eigen_matrix& E = A.eigen_object();
  Eigen::MatrixXd rhs(n, 2), x32, x64;
  for(int i = 0; i < n; ++i)
    rhs.row(i) << std::sin(double(i)), std::cos(3. * i);
  narrow.compute(E);
  wide.compute(E);
  SMP_CHECK(narrow.ordering_used() == UMFPACK_ORDERING_AMD && wide.ordering_used() == UMFPACK_ORDERING_GIVEN,
            "the 64-bit analysis ordered the system again (ordering " << wide.ordering_used() << ")");
  SMP_CHECK(narrow.strategy_used() == UMFPACK_STRATEGY_SYMMETRIC && wide.strategy_used() == UMFPACK_STRATEGY_SYMMETRIC,
            "the 64-bit analysis took another strategy (" << wide.strategy_used() << ")");
  const bool solved = narrow.info() == Eigen::Success && wide.info() == Eigen::Success &&
                      narrow.solve_columns(rhs, x32, 2u) && wide.solve_columns(rhs, x64, 2u);
  SMP_CHECK(solved && (x32 - x64).cwiseAbs().maxCoeff() < 1e-14 && (E * x64 - rhs).cwiseAbs().maxCoeff() < 1e-12,
            "UMFPACK's 64-bit interface solves otherwise");
  const Eigen::VectorXd one = wide.solve(rhs.col(0));
  SMP_CHECK(wide.info() == Eigen::Success && (one - x32.col(0)).cwiseAbs().maxCoeff() < 1e-14,
            "UMFPACK's 64-bit interface solves one column otherwise");
  wide.compute(S.eigen_object());
  SMP_CHECK(wide.info() != Eigen::Success, "a singular matrix was factored by the 64-bit interface");
}

// Above 150,000 unknowns the package's UMFPACK solver orders with METIS, sizes its work area from
// the symbolic estimate and then from the last factorization, hands memory back between steps
// and frees its factors after each solve and after the call: the maps must be those of Eigen's
// SparseLU, and a second call of the same object (which analyses again) must repeat the first.
// The default solver there is the multigrid solver: the paper's whole iteration takes the
// steps the LU takes, to 1e-6 in the stretch of each.
void check_large_system()
{
  Loaded l = load("mannequin-devil.off");
  CGAL::Subdivision_method_3::Loop_subdivision(l.mesh, CGAL::parameters::number_of_iterations(2));
  Mesh& m = l.mesh;
  l.bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType,
                                                    Eigen::COLAMDOrdering<int> > > Sparse_lu;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Sparse_lu>
    reference(SMP::Shape_preserving_parameterizer_3<Mesh>(), SMP::parameters::number_of_iterations(1));
  typedef CGAL::Eigen_solver_traits<SMP::internal::Umfpack_lu<CGAL::Eigen_sparse_matrix<double>::EigenType> > Umfpack_traits;
  typedef SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Umfpack_traits> Umfpack_smp;
  Umfpack_smp p(SMP::Shape_preserving_parameterizer_3<Mesh>(), SMP::parameters::number_of_iterations(1));
  UV_map uvr = new_uv(m, "v:uv_ref"), uv1 = new_uv(m, "v:uv1"), uv2 = new_uv(m, "v:uv2");
  check_run("207k vertices, SparseLU", m, l.bhd, reference, uvr, SMP::parameterize(m, reference, l.bhd, uvr));
  check_run("207k vertices, UMFPACK", m, l.bhd, p, uv1, SMP::parameterize(m, p, l.bhd, uv1));
  SMP_CHECK(p.report().interior_vertices >= 150000, "only " << p.report().interior_vertices << " unknowns");
  SMP_CHECK(max_distance(m, uv1, uvr) < 1e-9, "UMFPACK and SparseLU differ by " << max_distance(m, uv1, uvr));
  check_run("207k vertices, UMFPACK again", m, l.bhd, p, uv2, SMP::parameterize(m, p, l.bhd, uv2));
  SMP_CHECK(max_distance(m, uv1, uv2) == 0., "a second call differs by " << max_distance(m, uv1, uv2));
  std::cout << "207k vertices: U^1 " << p.report().kept().l2_stretch << ", SparseLU " << reference.report().kept().l2_stretch
            << ", max distance " << max_distance(m, uv1, uvr) << std::endl;

  // the default (multigrid) solver, the paper's whole iteration, against UMFPACK's
  Umfpack_smp direct;
  Default_smp multigrid;
  UV_map uvd = new_uv(m, "v:uv_direct"), uvm = new_uv(m, "v:uv_multigrid");
  check_run("207k vertices, UMFPACK, U^opt", m, l.bhd, direct, uvd, SMP::parameterize(m, direct, l.bhd, uvd));
  check_run("207k vertices, multigrid, U^opt", m, l.bhd, multigrid, uvm, SMP::parameterize(m, multigrid, l.bhd, uvm));
  const auto& hd = direct.report().history;
  const auto& hm = multigrid.report().history;
  SMP_CHECK(hd.size() == hm.size() && direct.report().kept_step == multigrid.report().kept_step,
            "multigrid: " << hm.size() << " steps, U^" << multigrid.report().kept_step << " kept; UMFPACK: "
            << hd.size() << ", U^" << direct.report().kept_step);
  for(std::size_t h = 0; h < (std::min)(hd.size(), hm.size()); ++h) {
    // the rejected last step is only screened: its stretch is that of an approximate map
    const double error = hm[h].screened ? 1e-5 : 1e-6;
    SMP_CHECK(std::abs(hd[h].l2_stretch - hm[h].l2_stretch) < error * hd[h].l2_stretch,
              "U^" << h << ": L2 " << hm[h].l2_stretch << " by the multigrid solver" << (hm[h].screened ? " (screened)" : "")
                   << ", " << hd[h].l2_stretch << " by UMFPACK");
    SMP_CHECK(!hd[h].screened && hm[h].screened == (h + 1 == hm.size() && h > multigrid.report().kept_step),
              "U^" << h << (hm[h].screened ? " was" : " was not") << " screened");
    std::cout << "207k vertices, U^" << h << ": relative L2 difference "
              << std::abs(hd[h].l2_stretch - hm[h].l2_stretch) / hd[h].l2_stretch << (hm[h].screened ? " (screened)" : "") << std::endl;
    // a working cycle takes the residual to 1e-12 within 50 iterations even on the uneven
    // systems of the last steps (benchmark/results/multigrid_damping.md); one that stops working
    // goes on to the cap of 200
    SMP_CHECK(hd[h].solver_iterations == 0 && hm[h].solver_iterations > 0 && hm[h].solver_iterations <= 50,
              "U^" << h << ": " << hm[h].solver_iterations << " multigrid iterations, "
              << hd[h].solver_iterations << " reported for UMFPACK's factorization");
  }
  std::cout << "207k vertices, U^opt: multigrid and UMFPACK maps differ by " << max_distance(m, uvd, uvm) << std::endl;

  // symmetric weights on a large system: the Cholesky in METIS's order of the vertices where
  // CHOLMOD is used, else UMFPACK; the same map as the LU of concept-only traits
  namespace P = SMP::parameters;
  const auto lowest = P::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH).descent_iterations(0u).number_of_iterations(1u);
  Umfpack_smp symmetric(SMP::Shape_preserving_parameterizer_3<Mesh>(), lowest);
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Concept_only_traits>
    concept_lu(SMP::Shape_preserving_parameterizer_3<Mesh>(), lowest);
  UV_map uvs = new_uv(m, "v:uv_symmetric"), uvc = new_uv(m, "v:uv_concept_lu");
  check_run("207k vertices, symmetric weights", m, l.bhd, symmetric, uvs, SMP::parameterize(m, symmetric, l.bhd, uvs));
  SMP_CHECK(SMP::parameterize(m, concept_lu, l.bhd, uvc) == SMP::OK, "207k vertices, symmetric weights by the LU");
  SMP_CHECK(max_distance(m, uvs, uvc) < 1e-9, "symmetric weights: Cholesky and LU differ by " << max_distance(m, uvs, uvc));
#if defined(CGAL_SMP_USE_CHOLMOD)
  { // the order shared by the systems: each vertex once
    SMP::internal::Disk_component<Mesh> dc;
    SMP_CHECK(dc.build(m, l.bhd, get(CGAL::vertex_point, m)) == SMP::OK, "207k vertices: no disk");
    const std::vector<int> rank = SMP::internal::fill_reducing_vertex_rank(dc.flat.xyz.size(), dc.flat.tri, dc.virtual_tri);
    std::vector<char> seen(rank.size(), 0);
    bool permutation = rank.size() == dc.flat.xyz.size();
    for(int r : rank) {
      permutation = permutation && r >= 0 && std::size_t(r) < rank.size() && !seen[std::size_t(r)];
      if(permutation) seen[std::size_t(r)] = 1;
    }
    SMP_CHECK(permutation, "207k vertices: the vertex order is not a permutation of the vertices");
    // the same order when two threads ask for it at once (METIS's random numbers are the
    // process's: charts of an atlas polished side by side drew from each other's sequence)
    std::vector<std::vector<int> > side_by_side(4);
    std::thread other([&] {
      for(std::size_t k = 0; k < 2; ++k)
        side_by_side[k] = SMP::internal::fill_reducing_vertex_rank(dc.flat.xyz.size(), dc.flat.tri, dc.virtual_tri);
    });
    for(std::size_t k = 2; k < 4; ++k)
      side_by_side[k] = SMP::internal::fill_reducing_vertex_rank(dc.flat.xyz.size(), dc.flat.tri, dc.virtual_tri);
    other.join();
    for(std::size_t k = 0; k < side_by_side.size(); ++k)
      SMP_CHECK(side_by_side[k] == rank, "207k vertices: the vertex order asked for on two threads at once differs (" << k << ")");
  }
#endif

  // a plain Eigen::UmfPackLU given by the user, as the class documentation offers
  typedef CGAL::Eigen_solver_traits<Eigen::UmfPackLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > Plain_umfpack;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, SMP::Shape_preserving_parameterizer_3<Mesh>, Plain_umfpack>
    plain(SMP::Shape_preserving_parameterizer_3<Mesh>(), SMP::parameters::number_of_iterations(1));
  UV_map uvp = new_uv(m, "v:uv_plain");
  check_run("207k vertices, plain UmfPackLU", m, l.bhd, plain, uvp, SMP::parameterize(m, plain, l.bhd, uvp));
  SMP_CHECK(max_distance(m, uvp, uvr) < 1e-9, "plain UmfPackLU and SparseLU differ by " << max_distance(m, uvp, uvr));
}
#endif

// Meshes with several boundaries: the longest is fixed, every other one is closed by a
// virtual fan inside the linear system (the user's mesh is not modified).
void check_mesh_with_holes(const std::string& name, std::size_t boundaries)
{
  Loaded l = load(name);
  Mesh& m = l.mesh;
  const std::size_t nv = num_vertices(m), nf = num_faces(m);
  UV_map uv = new_uv(m, "v:uv");
  Default_smp p;
  check_run(name + " with holes", m, l.bhd, p, uv, SMP::parameterize(m, p, l.bhd, uv));
  const SMP::Stretch_minimizing_report& r = p.report();
  SMP_CHECK(r.holes_closed + 1 == boundaries, name << ": closed " << r.holes_closed << " holes");
  SMP_CHECK(num_vertices(m) == nv && num_faces(m) == nf, name << ": the mesh was modified");
  SMP_CHECK(r.interior_vertices == nv - r.border_vertices + r.holes_closed, name << ": hole centers are not unknowns");
  if(!r.history.empty())
    SMP_CHECK(r.kept().l2_stretch < r.history[0].l2_stretch, name << ": no gain over U^0");
  std::cout << name << ": " << r.holes_closed << " holes closed, U^0 " << r.history.at(0).l2_stretch
            << "  U^opt " << r.kept().l2_stretch << " (h = " << r.kept_step << "), degenerate uv faces "
            << r.kept().degenerate_uv_faces << std::endl;

  // with corners that avoid flattened faces, only those four corners cannot save are left
  // (mech-holes-shark's outer border runs along a strip one face wide), and the border says so
  typedef SMP::Square_border_ear_aware_parameterizer_3<Mesh> Ear_aware;
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, Ear_aware> Floater_ear_aware;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater_ear_aware> ear_aware;
  check_run(name + " with holes, ear-aware border", m, l.bhd, ear_aware, uv, SMP::parameterize(m, ear_aware, l.bhd, uv));
  Ear_aware border;
  UV_map uvb = new_uv(m, "v:uvb");
  border.parameterize(m, l.bhd, uvb, get(CGAL::vertex_index, m),
                      m.add_property_map<vertex_descriptor, bool>("v:border_done", false).first);
  if(ear_aware.report().status == SMP::OK)
    SMP_CHECK(ear_aware.report().kept().degenerate_uv_faces == border.number_of_flattened_faces()
                && border.number_of_flattened_faces() <= r.kept().degenerate_uv_faces,
              name << ": " << ear_aware.report().kept().degenerate_uv_faces << " degenerate faces, the border reports "
                   << border.number_of_flattened_faces() << ", CGAL's square gives " << r.kept().degenerate_uv_faces);

  // on a circle no three border vertices are collinear: no degenerate face at all
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh> > Floater_circle;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater_circle> circle;
  UV_map uvc = new_uv(m, "v:uvc");
  const SMP::Error_code status = SMP::parameterize(m, circle, l.bhd, uvc);
  SMP_CHECK(status == SMP::OK && circle.report().kept().degenerate_uv_faces == 0 && circle.report().degenerate_3d_faces == 0
              && circle.report().kept().flipped_faces == 0,
            name << ": circular border: " << circle.report().message << " degenerate "
                 << (circle.report().history.empty() ? 0 : circle.report().kept().degenerate_uv_faces));
  if(status == SMP::OK) { // (on holes.off the circle's U^0 is already its best: the rule stops there)
    std::cout << name << ": ear-aware square U^opt " << ear_aware.report().kept().l2_stretch << " ("
              << ear_aware.report().kept().degenerate_uv_faces << " flattened), circle U^opt "
              << circle.report().kept().l2_stretch << std::endl;
  }
}

// The ear-aware square border puts corners where a face would otherwise have its three
// vertices on one side: no degenerate face on the bundled disk meshes, and the stretch
// minimizer runs on it as on CGAL's square.
void check_ear_aware_border(const std::string& name)
{
  typedef SMP::Square_border_ear_aware_parameterizer_3<Mesh> Border;
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, Border> Floater;
  Loaded l = load(name);
  UV_map uv = new_uv(l.mesh, "v:uv");
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> p;
  check_run(name + " ear-aware border", l.mesh, l.bhd, p, uv, SMP::parameterize(l.mesh, p, l.bhd, uv));
  SMP_CHECK(p.report().status == SMP::OK && p.report().kept().degenerate_uv_faces == 0,
            name << ": " << p.report().kept().degenerate_uv_faces << " degenerate faces with the ear-aware border");

  // the border alone: what it reports as flattened is what the map has
  Border border;
  UV_map uvb = new_uv(l.mesh, "v:uvb");
  auto vp = l.mesh.add_property_map<vertex_descriptor, bool>("v:border_done", false).first;
  SMP_CHECK(border.parameterize(l.mesh, l.bhd, uvb, get(CGAL::vertex_index, l.mesh), vp) == SMP::OK, name << ": border failed");
  SMP_CHECK(border.number_of_flattened_faces() == 0, name << ": " << border.number_of_flattened_faces() << " flattened faces");
  std::size_t corners = 0;
  for(halfedge_descriptor h : halfedges_around_face(l.bhd, l.mesh)) {
    const Point_2 q = uvb[target(h, l.mesh)];
    SMP_CHECK(q.x() == 0. || q.x() == 1. || q.y() == 0. || q.y() == 1., name << ": border vertex off the square");
    if((q.x() == 0. || q.x() == 1.) && (q.y() == 0. || q.y() == 1.))
      ++corners;
  }
  SMP_CHECK(corners == 4, name << ": " << corners << " corners");
  std::cout << name << ": ear-aware border, U^opt " << p.report().kept().l2_stretch << " (h = "
            << p.report().kept_step << ")" << std::endl;
}

// The natural border (the border of CGAL's LSCM map, fixed): not convex, so every step is
// checked for flips. Where LSCM folds its border over itself, the option says so.
void check_natural_border()
{
  typedef SMP::Natural_border_parameterizer_3<Mesh> Natural;
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, Natural> Floater;
  auto run = [](const std::string& name, double bar) {
    Loaded l = load(name);
    UV_map uv = new_uv(l.mesh, "v:uv");
    SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> p;
    const SMP::Error_code status = SMP::parameterize(l.mesh, p, l.bhd, uv);
    SMP_CHECK(status == SMP::OK, name << " natural border: " << p.report().message);
    if(status != SMP::OK)
      return;
    for(const auto& s : p.report().history)
      SMP_CHECK(s.flipped_faces == 0 || p.report().stop == SMP::Stretch_minimizing_stop::FLIPPED_FACES,
                name << " natural border: flips at U^" << s.step << " without a stop");
    const SMP::Stretch_statistics st = SMP::compute_stretch_statistics(l.mesh, uv);
    SMP_CHECK(st.flipped_faces == 0, name << " natural border: " << st.flipped_faces << " flipped faces returned");
    SMP_CHECK(std::abs(st.l2_stretch - p.report().kept().l2_stretch) < 1e-9 * st.l2_stretch, name << ": report and map differ");
    SMP_CHECK(st.l2_stretch <= bar, name << " natural border: U^opt " << st.l2_stretch << " above " << bar);
    std::cout << name << ": natural border U^opt " << st.l2_stretch << " (h = " << p.report().kept_step << ")" << std::endl;
  };
  run("mesh_with_border.off", 1.05);
  run("mushroom.off", 1.27588 - 0.01); // below the square border's U^opt (1.2759)
  run("mannequin-devil.off", 1.6);     // LSCM flips ~4000 faces inside, but its border is simple

  // a null or an interior halfedge is a wrong parameter, as for the stretch minimizer
  {
    Loaded l = load("mushroom.off");
    UV_map uv = new_uv(l.mesh, "v:uv");
    auto vpmap = l.mesh.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    Natural natural;
    SMP_CHECK(natural.parameterize(l.mesh, halfedge_descriptor(), uv, get(CGAL::vertex_index, l.mesh), vpmap) ==
              SMP::ERROR_WRONG_PARAMETER, "natural border, null halfedge: " << natural.why());
    SMP_CHECK(natural.parameterize(l.mesh, opposite(l.bhd, l.mesh), uv, get(CGAL::vertex_index, l.mesh), vpmap) ==
              SMP::ERROR_WRONG_PARAMETER, "natural border, interior halfedge: " << natural.why());
  }

  // three_peaks: LSCM folds the border over itself: an error, and no interior written
  Loaded l = load("three_peaks.off");
  UV_map uv = new_uv(l.mesh, "v:uv");
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> p;
  SMP_CHECK(SMP::parameterize(l.mesh, p, l.bhd, uv) == SMP::ERROR_NO_1_TO_1_MAPPING && !p.report().message.empty(),
            "three_peaks natural border: " << p.report().message);
  Natural natural;
  natural.parameterize(l.mesh, l.bhd, uv, get(CGAL::vertex_index, l.mesh),
                       l.mesh.add_property_map<vertex_descriptor, bool>("v:done", false).first);
  SMP_CHECK(!natural.why().empty() && natural.number_of_free_border_flipped_faces() > 0,
            "three_peaks: the natural border does not say why");
  std::size_t written = 0;
  for(vertex_descriptor v : vertices(l.mesh))
    if(!CGAL::is_border(v, l.mesh) && uv[v] != Point_2(-7, -7))
      ++written;
  SMP_CHECK(written == 0, "three_peaks: " << written << " interior vertices written after an error");
}

// The README's tables of the paper's method and of its borders are what the parameterizer
// gives: every value as printed there (to its last digit), for every row whose mesh is bundled
// and parameterized as it is (the rows of cut meshes come from make_disk_seam(), checked in
// test_mesh_types).
std::vector<std::vector<std::string> > readme_table(const std::string& header)
{
  std::ifstream in(std::string(SMP_TEST_DIR) + "/../../README.md");
  SMP_CHECK(bool(in), "cannot read the README");
  std::vector<std::vector<std::string> > rows;
  std::string line;
  bool inside = false;
  while(std::getline(in, line)) {
    if(line.rfind(header, 0) == 0) { inside = true; continue; }
    if(!inside || line.rfind("|---", 0) == 0) continue;
    if(line.empty() || line[0] != '|') break;
    std::vector<std::string> cells;
    std::stringstream cs(line.substr(1));
    std::string cell;
    while(std::getline(cs, cell, '|'))
      cells.push_back(cell.substr(cell.find_first_not_of(' '), cell.find_last_not_of(' ') - cell.find_first_not_of(' ') + 1));
    rows.push_back(cells);
  }
  SMP_CHECK(!rows.empty(), "no README table starts with " << header);
  return rows;
}

// `printed` is `value` written with as many decimals as `printed` has.
bool as_printed(double value, const std::string& printed)
{
  const std::size_t dot = printed.find('.');
  const int decimals = dot == std::string::npos ? 0 : int(printed.size() - dot - 1);
  return std::abs(value - std::stod(printed)) <= 0.5 * std::pow(10., -decimals) + 1e-12;
}

void check_readme_tables()
{
  // | mesh | V | U^0 (Floater) | U^1 | U^opt (eta = 1) | h |  and  | mesh | V | holes closed | U^0 | U^opt | h |
  for(const bool holes : {false, true}) {
    const auto rows = readme_table(holes ? "| mesh | V | holes closed |" : "| mesh | V | U^0 (Floater) |");
    std::size_t checked = 0;
    for(const auto& row : rows) {
      if(row.size() != 6 || row[0].find("(cut)") != std::string::npos)
        continue;
      const std::string name = row[0].substr(0, row[0].find(' ')) + ".off";
      Loaded l = load(name);
      UV_map uv = new_uv(l.mesh, "v:uv_readme");
      Default_smp p;
      SMP_CHECK(SMP::parameterize(l.mesh, p, l.bhd, uv) == SMP::OK, name);
      const SMP::Stretch_minimizing_report r = p.report();
      const std::size_t vertices = l.mesh.number_of_vertices();
      bool same = row[1] == std::to_string(vertices) && row[5] == std::to_string(r.kept_step) &&
                  as_printed(r.history[0].l2_stretch, holes ? row[3] : row[2]) && as_printed(r.kept().l2_stretch, row[4]);
      if(holes)
        same = same && row[2] == std::to_string(r.holes_closed);
      else
        same = same && r.history.size() > 1 && as_printed(r.history[1].l2_stretch, row[3]);
      SMP_CHECK(same, "README row '" << row[0] << "' differs: V " << vertices << ", U^0 " << r.history[0].l2_stretch
                << ", U^opt " << r.kept().l2_stretch << ", h " << r.kept_step << ", holes closed " << r.holes_closed);
      ++checked;
    }
    SMP_CHECK(checked >= 5, "only " << checked << " README rows checked");
  }

  // | mesh | CGAL square | ear-aware square | natural (LSCM) border |: U^opt, and in parentheses
  // the faces flattened on the border where the cell gives their number; a natural border
  // that LSCM folds is refused
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, SMP::Square_border_ear_aware_parameterizer_3<Mesh> > Ear_aware;
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, SMP::Natural_border_parameterizer_3<Mesh> > Natural;
  auto cell_agrees = [](const SMP::Stretch_minimizing_report& r, SMP::Error_code status, const std::string& cell) {
    if(cell.find("refused") != std::string::npos)
      return status == SMP::ERROR_NO_1_TO_1_MAPPING;
    const std::size_t space = cell.find(' ');
    bool ok = status == SMP::OK && as_printed(r.kept().l2_stretch, cell.substr(0, space));
    const std::size_t open = cell.find('(');
    if(ok && open != std::string::npos && std::isdigit(static_cast<unsigned char>(cell[open + 1])) &&
       cell.find("flips") == std::string::npos)
      ok = std::stoul(cell.substr(open + 1)) == r.kept().degenerate_uv_faces;
    return ok;
  };
  const auto rows = readme_table("| mesh | CGAL square | ear-aware square | natural (LSCM) border |");
  for(const auto& row : rows) {
    if(row.size() != 4)
      continue;
    Loaded l = load(row[0] + ".off");
    UV_map uv = new_uv(l.mesh, "v:uv_readme_borders");
    Default_smp square;
    SMP::Stretch_minimizing_parameterizer_3<Mesh, Ear_aware> ear_aware;
    SMP::Stretch_minimizing_parameterizer_3<Mesh, Natural> natural;
    const SMP::Error_code es = SMP::parameterize(l.mesh, square, l.bhd, uv);
    const SMP::Error_code ee = SMP::parameterize(l.mesh, ear_aware, l.bhd, uv);
    const SMP::Error_code en = SMP::parameterize(l.mesh, natural, l.bhd, uv);
    SMP_CHECK(cell_agrees(square.report(), es, row[1]) && cell_agrees(ear_aware.report(), ee, row[2]) &&
              cell_agrees(natural.report(), en, row[3]),
              "README borders row '" << row[0] << "' differs: square " << SMP::error_message(es) << " "
              << (es == SMP::OK ? square.report().l2_stretch() : 0.) << " ("
              << (es == SMP::OK ? square.report().kept().degenerate_uv_faces : 0) << "), ear-aware "
              << SMP::error_message(ee) << " " << (ee == SMP::OK ? ear_aware.report().l2_stretch() : 0.)
              << ", natural " << SMP::error_message(en) << " " << (en == SMP::OK ? natural.report().l2_stretch() : 0.));
  }
  SMP_CHECK(rows.size() >= 4, "README borders table: " << rows.size() << " rows");
}

// The package's overload of CGAL's free function parameterize() for this class: it is the one
// called (a null halfedge gets an error code, where CGAL's function has a precondition), it
// numbers the vertices of the component as CGAL's function does (in the same order on a mesh
// of one component; on two, the component's vertices from 0 and the others -1) and the map is
// the member function's, bit for bit.
void check_free_function()
{
  Loaded l = load("three_peaks.off");
  Mesh& m = l.mesh;
  UV_map uv = new_uv(m, "v:uv"), uv_member = new_uv(m, "v:uv_member");
  Default_smp p;
  SMP_CHECK(SMP::parameterize(m, p, Mesh::null_halfedge(), uv) == SMP::ERROR_WRONG_PARAMETER,
            "the free function with a null halfedge: " << p.report().message);

  auto ours = get(CGAL::dynamic_vertex_property_t<int>(), m), cgal = get(CGAL::dynamic_vertex_property_t<int>(), m);
  SMP::internal::number_component_vertices(l.bhd, m, ours);
  SMP::internal::fill_index_map_of_cc(l.bhd, m, cgal);
  bool same = true;
  for(vertex_descriptor v : vertices(m))
    same = same && get(ours, v) == get(cgal, v);
  SMP_CHECK(same, "one component: the vertices are numbered otherwise than by CGAL's parameterize()");

  const std::size_t nv = num_vertices(m);
  Mesh twice = m;
  CGAL::copy_face_graph(m, twice); // a second component, its vertices after the first's
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), twice);
  const halfedge_descriptor second = *std::find_if(halfedges(twice).begin(), halfedges(twice).end(), [&](halfedge_descriptor h) {
    return is_border(h, twice) && std::size_t(source(h, twice)) >= nv;
  });
  SMP::internal::number_component_vertices(second, twice, index);
  std::vector<int> seen(nv, 0);
  bool numbered = true;
  for(vertex_descriptor v : vertices(twice)) {
    const int i = get(index, v);
    if(std::size_t(v) < nv)
      numbered = numbered && i == -1;
    else if(i >= 0 && std::size_t(i) < nv)
      ++seen[std::size_t(i)];
    else
      numbered = false;
  }
  SMP_CHECK(numbered && std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(nv),
            "two components: the second one's vertices are not numbered 0 to n - 1, the first one's -1");

  SMP_CHECK(SMP::parameterize(m, p, l.bhd, uv) == SMP::OK, "the free function failed: " << p.report().message);
  auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), m);
  auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), m);
  SMP::internal::fill_index_map_of_cc(l.bhd, m, vimap);
  Default_smp member;
  SMP_CHECK(member.parameterize(m, l.bhd, uv_member, vimap, vpmap) == SMP::OK && max_distance(m, uv, uv_member) == 0.,
            "the free function and the member function differ");
}

int run_test(int, char**)
{
  check_free_function();
  for(const char* name : {"nefertiti.off", "mesh_with_border.off", "patch-01.off", "three_peaks.off",
                          "mushroom.off", "mannequin-devil.off"}) {
    check_disk_mesh(name);
    check_ear_aware_border(name);
  }
  for(const auto& [name, boundaries] : {std::pair<const char*, std::size_t>{"head.off", 3}, {"pig.off", 7},
                                         {"holes.off", 7}, {"mech-holes-shark.off", 4}, {"blade.off", 2}})
    check_mesh_with_holes(name, boundaries);
  check_natural_border();
  check_mannequin_bar();
  check_options_and_visitor();
  check_parallel_for();
  check_threads();
  check_concurrent_copies();
  check_solver_configurations();
  check_solver_concept();
  for(const char* name : {"three_peaks.off", "mannequin-devil.off", "head.off"})
    check_symmetric_weights(name);
  check_readme_tables();
  check_ordered_solvers();
  for(const char* name : {"mannequin-devil.off", "holes.off"})
    check_multigrid(name);
#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
  check_umfpack_lu();
  check_large_system();
#endif
  return smp_test::summary();
}

} // namespace test_stretch_minimizing

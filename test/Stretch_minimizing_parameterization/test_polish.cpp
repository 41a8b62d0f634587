// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Newton polish of Sander's L2 stretch energy on the bundled meshes, from U^opt, with a
// fixed and with a free border: the energy never increases, no face flips, the free border
// stays a simple loop, guard faces around holes stay positive; and through the parameterizer's
// named parameters (test_polish_energy checks the energy itself on flat arrays).

#include "smp_test_mesh.h"
#include "polish_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_energy_polisher.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace test_polish {

using namespace smp_test;

namespace SMP = CGAL::Surface_mesh_parameterization;

// ---------------------------------------------------------------------------------------------
// bundled meshes, from U^opt

struct Start
{
  SI::Flat_triangles m;
  std::vector<Vec2> uv;
  std::vector<char> fixed;
  std::vector<int> border;
  std::vector<Triangle> guard;
  double l2_uopt = 0.;
  double uopt_seconds = 0.;
};

// A point inside the kernel of the hole polygon seen from its fan (s, t, centre): the fan
// faces must be oriented like the map, whose sign is `orient`.
Vec2 kernel_point(const std::vector<Triangle>& fan, const std::vector<Vec2>& uv, double orient)
{
  std::vector<Vec2> poly{{-1e3, -1e3}, {1e3, -1e3}, {1e3, 1e3}, {-1e3, 1e3}}, out;
  for(const Triangle& t : fan) {
    const Vec2 a = uv[t[0]], b = uv[t[1]];
    auto side = [&](const Vec2& p) { return orient * ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])); };
    out.clear();
    for(std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 p = poly[i], q = poly[(i + 1) % poly.size()];
      const double sp = side(p), sq = side(q);
      if(sp > 0.) out.push_back(p);
      if((sp > 0.) != (sq > 0.)) {
        const double w = sp / (sp - sq);
        out.push_back({p[0] + w * (q[0] - p[0]), p[1] + w * (q[1] - p[1])});
      }
    }
    poly.swap(out);
  }
  Vec2 c{0., 0.};
  for(const Vec2& p : poly) { c[0] += p[0] / double(poly.size()); c[1] += p[1] / double(poly.size()); }
  return c;
}

bool load_start(const std::string& name, Start& s)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(smp_test::data_file(name), mesh) || faces(mesh).empty()) {
    SMP_CHECK(false, "cannot read " << name);
    return false;
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  const auto t0 = std::chrono::steady_clock::now();
  SMP::Stretch_minimizing_parameterizer_3<Mesh> smp;
  const SMP::Error_code status = SMP::parameterize(mesh, smp, bhd, uvmap);
  s.uopt_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  SMP_CHECK(status == SMP::OK, name << ": U^opt failed: " << smp.report().message);
  if(status != SMP::OK) return false;
  s.l2_uopt = smp.report().kept().l2_stretch;

  SI::Disk_component<Mesh> dc;
  SMP_CHECK(dc.build(mesh, bhd, get(CGAL::vertex_point, mesh)) == SMP::OK, name << ": " << dc.message);
  s.m = dc.flat;
  s.border = dc.border;
  s.guard = dc.virtual_tri;
  s.uv.assign(dc.flat.xyz.size(), Vec2{0., 0.});
  s.fixed.assign(dc.flat.xyz.size(), 0);
  for(std::size_t v = 0; v < dc.vertices.size(); ++v)
    s.uv[v] = {uvmap[dc.vertices[v]].x(), uvmap[dc.vertices[v]].y()};
  for(int v : dc.border) s.fixed[v] = 1;

  // hole centres: fixed inside the kernel of their hole
  const double orient = total_signed_area(s.m, s.uv) > 0. ? 1. : -1.;
  for(std::size_t v = dc.vertices.size(); v < dc.flat.xyz.size(); ++v) {
    std::vector<Triangle> fan;
    for(const Triangle& t : dc.virtual_tri)
      if(t[2] == int(v)) fan.push_back(t);
    s.uv[v] = kernel_point(fan, s.uv, orient);
    s.fixed[v] = 1;
  }
  return true;
}

struct Run
{
  SI::Sander_polish_result r;
  std::size_t max_flipped = 0;
  bool monotone = true;
  double l2_at_1s = 0.;     // of the last step within one second
  double target_seconds = -1.; // when the L2 first reached the target (0: at the start, < 0: never)
  std::size_t target_iterations = 0;
};

Run run_polish(const Start& s, std::vector<Vec2>& uv, const SI::Sander_polish_settings& st, double target)
{
  Run run;
  if(s.l2_uopt <= target) run.target_seconds = 0.;
  double last = HUGE_VAL;
  SI::Flat_stretch fs;
  auto visitor = [&](const SI::Sander_polish_step& step) {
    if(!(step.energy <= last)) run.monotone = false;
    last = step.energy;
    run.max_flipped = (std::max)(run.max_flipped, fs.evaluate(s.m, *step.uv).flipped);
    if(step.seconds <= 1.) run.l2_at_1s = step.l2_stretch;
    if(run.target_seconds < 0. && step.l2_stretch <= target) {
      run.target_seconds = step.seconds;
      run.target_iterations = step.iteration;
    }
    return true;
  };
  SI::Sander_energy_polisher<> polisher;
  run.r = polisher.polish(s.m, s.guard, s.fixed, s.border, uv, st, visitor);
  if(!(run.r.energy_after <= run.r.energy_before)) run.monotone = false;
  return run;
}

// The iteration cap, the time budget and the visitor stop where they should.
void test_controls(const Start& s)
{
  SI::Sander_energy_polisher<> polisher;
  SI::Sander_polish_settings st;
  std::vector<Vec2> uv = s.uv;
  st.max_iterations = 0;
  SI::Sander_polish_result r = polisher.polish(s.m, s.guard, s.fixed, s.border, uv, st);
  SMP_CHECK(r.stop == SI::Sander_polish_stop::ITERATION_CAP && r.iterations == 0 && max_displacement(uv, s.uv) == 0.,
            "cap 0: " << stop_name(r.stop) << ", " << r.iterations << " iterations");

  st.max_iterations = 3;
  r = polisher.polish(s.m, s.guard, s.fixed, s.border, uv, st);
  SMP_CHECK(r.stop == SI::Sander_polish_stop::ITERATION_CAP && r.iterations == 3, "cap 3: " << r.iterations);

  uv = s.uv;
  st.max_iterations = 100;
  st.time_budget = 1e-9;
  r = polisher.polish(s.m, s.guard, s.fixed, s.border, uv, st);
  SMP_CHECK(r.stop == SI::Sander_polish_stop::TIME_BUDGET && r.iterations == 0, "time budget: " << stop_name(r.stop));

  st.time_budget = 0.;
  std::vector<Vec2> seen;
  r = polisher.polish(s.m, s.guard, s.fixed, s.border, uv, st, [&](const SI::Sander_polish_step& step) {
    seen = *step.uv;
    return step.iteration < 2;
  });
  SMP_CHECK(r.stop == SI::Sander_polish_stop::VISITOR && r.iterations == 2,
            "visitor: " << stop_name(r.stop) << " after " << r.iterations);
  SMP_CHECK(max_displacement(uv, seen) == 0., "the result is not the visitor's last map");
}

// The rule on the energy over a window of steps: the steps end at the first step after which
// the last `window` of them (all of them, while there are fewer) lowered the energy by less
// than `window` times the tolerance, relatively, and not before. The steps are those of a
// window of one, and while each step gains more than the tolerance, so do the last `window`
// together: a wider window takes the same steps, and at least as many.
void test_tolerance_window(const Start& s)
{
  std::vector<double> previous;
  for(const unsigned int window : {1u, 3u}) {
    SI::Sander_polish_settings st;
    st.direction = SI::Sander_polish_direction::SPLIT_NEWTON;
    st.tolerance = 2e-3;
    st.tolerance_window = window;
    st.max_iterations = 200;
    std::vector<double> energies;
    std::vector<Vec2> uv = s.uv;
    SI::Sander_energy_polisher<> polisher;
    const SI::Sander_polish_result r = polisher.polish(s.m, s.guard, s.fixed, s.border, uv, st,
                                                       [&](const SI::Sander_polish_step& step) {
                                                         energies.push_back(step.energy);
                                                         return true;
                                                       });
    energies.insert(energies.begin(), r.energy_before);
    SMP_CHECK(r.status == SI::Sander_polish_status::OK && r.stop == SI::Sander_polish_stop::CONVERGED &&
              r.iterations > 0 && r.iterations + 1 == energies.size(),
              "window " << window << ": " << stop_name(r.stop) << " after " << r.iterations << " steps");
    for(std::size_t j = 1; j < energies.size(); ++j) {
      const std::size_t k = (std::min)(std::size_t(window), j);
      const bool below = energies[j - k] - energies[j] <= double(k) * st.tolerance * energies[j];
      SMP_CHECK(below == (j + 1 == energies.size()),
                "window " << window << ": step " << j << " of " << r.iterations << " is " << (below ? "" : "not ")
                          << "below the tolerance");
    }
    if(!previous.empty()) {
      SMP_CHECK(energies.size() >= previous.size() && std::equal(previous.begin(), previous.end(), energies.begin()),
                "window " << window << ": " << r.iterations << " steps, not those of a window of one ("
                          << previous.size() - 1 << ") and more");
    }
    std::cout << "tolerance window " << window << ": " << r.iterations << " split steps" << std::endl;
    previous = energies;
  }
}

// The descent steps of either kind (along the proxy, split Newton) from U^opt, border fixed and
// free: the energy never increases,
// no face flips at any step, fixed vertices stay, the free border stays simple, and it gains.
void test_descent(const std::string& name, const Start& s)
{
  SI::Flat_stretch fs;
  for(const auto direction : {SI::Sander_polish_direction::DIRICHLET_PROXY, SI::Sander_polish_direction::SPLIT_NEWTON})
  for(bool free : {false, true}) {
    const bool split = direction == SI::Sander_polish_direction::SPLIT_NEWTON;
    const std::string what = name + (split ? " split" : " proxy") + (free ? " descent, free border" : " descent");
    SI::Sander_polish_settings st;
    st.direction = direction;
    st.max_iterations = 30;
    st.free_border = free;
    std::vector<Vec2> uv = s.uv;
    const Run run = run_polish(s, uv, st, 0.);
    SMP_CHECK(run.r.status == SI::Sander_polish_status::OK, what << ": " << run.r.message);
    SMP_CHECK(run.monotone, what << ": the energy increased");
    SMP_CHECK(run.max_flipped == 0, what << ": " << run.max_flipped << " flipped faces during the descent");
    SMP_CHECK(run.r.l2_after < run.r.l2_before, what << ": no gain, L2 " << run.r.l2_before << " -> " << run.r.l2_after);
    SMP_CHECK(fs.evaluate(s.m, uv).flipped == 0, what << ": flipped faces in the result");
    double moved = 0.;
    for(std::size_t v = 0; v < uv.size(); ++v)
      if(s.fixed[v] && !(free && std::find(s.border.begin(), s.border.end(), int(v)) != s.border.end()))
        moved = (std::max)(moved, std::hypot(uv[v][0] - s.uv[v][0], uv[v][1] - s.uv[v][1]));
    SMP_CHECK(moved == 0., what << ": a fixed vertex moved by " << moved);
    if(free)
      SMP_CHECK(simple_loop(s.border, uv), what << ": the border loop intersects itself");
    std::cout << std::fixed << std::setprecision(4) << what << ": L2 " << run.r.l2_before << " -> " << run.r.l2_after
              << " in " << run.r.iterations << " steps, " << std::setprecision(3) << run.r.seconds << " s"
              << std::defaultfloat << std::endl;
  }
}

// Fixed border (`reference`: the optimum measured elsewhere); then, if `free_goal` > 0, a free
// border, and when the L2 reaches the goal.
void test_mesh(const std::string& name, double reference, double free_goal, bool controls = false)
{
  Start s;
  if(!load_start(name, s)) return;
  if(controls) {
    test_controls(s);
    test_tolerance_window(s);
  }
  test_descent(name, s);
  SI::Flat_stretch fs;

  SI::Sander_polish_settings st;
  st.max_iterations = 500;
  std::vector<Vec2> uv = s.uv;
  const Run fixed = run_polish(s, uv, st, 1.03 * reference);
  SMP_CHECK(fixed.r.status == SI::Sander_polish_status::OK, name << ": " << fixed.r.message);
  SMP_CHECK(fixed.monotone, name << ": the energy increased");
  SMP_CHECK(fixed.max_flipped == 0, name << ": " << fixed.max_flipped << " flipped faces during the polish");
  SMP_CHECK(fs.evaluate(s.m, uv).flipped == 0, name << ": flipped faces in the result");
  SMP_CHECK(std::abs(fixed.r.l2_before - s.l2_uopt) < 1e-9, name << ": start L2 " << fixed.r.l2_before << " vs U^opt " << s.l2_uopt);
  SMP_CHECK(fixed.r.l2_after < fixed.r.l2_before, name << ": no gain");
  double border_moved = 0.;
  for(std::size_t v = 0; v < uv.size(); ++v)
    if(s.fixed[v]) border_moved = (std::max)(border_moved, std::hypot(uv[v][0] - s.uv[v][0], uv[v][1] - s.uv[v][1]));
  SMP_CHECK(border_moved == 0., name << ": a fixed vertex moved by " << border_moved);
  for(const Triangle& t : s.guard)
    if(!(signed_area(uv[t[0]], uv[t[1]], uv[t[2]]) * total_signed_area(s.m, uv) > 0.)) {
      SMP_CHECK(false, name << ": a guard face is not positive");
      break;
    }
  std::cout << std::fixed << std::setprecision(4) << name << " (U^opt " << s.l2_uopt << " in " << std::setprecision(2)
            << s.uopt_seconds << " s): fixed border L2 " << std::setprecision(4) << fixed.r.l2_after
            << " (reference " << reference << ", " << std::showpos << std::setprecision(2)
            << 100. * (fixed.r.l2_after / reference - 1.) << std::noshowpos << " %) in " << fixed.r.iterations
            << " iterations, " << std::setprecision(3) << fixed.r.seconds << " s, " << stop_name(fixed.r.stop)
            << "; within 3 % after " << fixed.target_iterations << " iterations, " << fixed.target_seconds << " s"
            << std::defaultfloat << std::endl;

  if(!(free_goal > 0.)) return;
  SI::Sander_polish_settings sf = st;
  sf.free_border = true;
  uv = s.uv;
  const Run free = run_polish(s, uv, sf, free_goal);
  SMP_CHECK(free.r.status == SI::Sander_polish_status::OK, name << " free: " << free.r.message);
  SMP_CHECK(free.monotone, name << " free: the objective increased");
  SMP_CHECK(free.max_flipped == 0, name << " free: " << free.max_flipped << " flipped faces during the polish");
  SMP_CHECK(fs.evaluate(s.m, uv).flipped == 0, name << " free: flipped faces in the result");
  SMP_CHECK(simple_loop(s.border, uv), name << " free: the border loop intersects itself");
  SMP_CHECK(free.r.l2_after < fixed.r.l2_after,
            name << " free: L2 " << free.r.l2_after << " not below the fixed border's " << fixed.r.l2_after);
  std::cout << std::fixed << std::setprecision(4) << name << ": free border L2 " << free.r.l2_after << " in "
            << free.r.iterations << " iterations, " << std::setprecision(3) << free.r.seconds << " s, "
            << stop_name(free.r.stop) << std::setprecision(4) << "; L2 " << free.l2_at_1s << " after 1 s; goal "
            << free_goal << " after " << free.target_iterations << " iterations, " << std::setprecision(3)
            << free.target_seconds << " s" << std::defaultfloat << std::endl;
  SMP_CHECK(free.r.l2_after <= free_goal, name << " free: L2 " << free.r.l2_after << " above the goal " << free_goal);
}

void test_holes()
{
  Start s;
  if(!load_start("holes.off", s)) return;
  SMP_CHECK(!s.guard.empty(), "holes.off: no hole closed");
  test_descent("holes.off", s);
  SI::Sander_polish_settings st;
  st.max_iterations = 500;
  std::vector<Vec2> uv = s.uv;
  const Run run = run_polish(s, uv, st, 0.);
  SMP_CHECK(run.r.status == SI::Sander_polish_status::OK, "holes.off: " << run.r.message);
  SMP_CHECK(run.monotone && run.max_flipped == 0, "holes.off: flips " << run.max_flipped);
  SMP_CHECK(run.r.l2_after < run.r.l2_before, "holes.off: no gain");
  const double orient = total_signed_area(s.m, uv);
  std::size_t negative = 0;
  for(const Triangle& t : s.guard)
    if(!(signed_area(uv[t[0]], uv[t[1]], uv[t[2]]) * orient > 0.)) ++negative;
  SMP_CHECK(negative == 0, "holes.off: " << negative << " guard faces not positive");
  std::cout << std::fixed << std::setprecision(4) << "holes.off (" << s.guard.size() << " guard faces): L2 "
            << run.r.l2_before << " -> " << run.r.l2_after << " in " << run.r.iterations << " iterations, "
            << std::setprecision(3) << run.r.seconds << " s, " << stop_name(run.r.stop) << std::defaultfloat << std::endl;
}

// A planar mesh whose four faces along the x axis have zero area (CGAL's degtri_sliding.off):
// interior vertices 2 and 5 lie on the segment between vertices 4 and 6, at straight angles, so
// U^0 and U^opt have flat faces in uv, from which the polish cannot step. It opens them
// first, and it must then lower the stretch (the faces of zero 3D area take uv area from the
// others: the energy times the area is what the polish lowers), flip nothing, and with a free
// border reach the isometry.
void test_flat_slivers()
{
  Mesh mesh;
  const double xy[8][2] = {{4, -2}, {6, 0}, {4, 0}, {2, 0}, {1, 0}, {3, 0}, {5, 0}, {3, 2}};
  std::vector<vertex_descriptor> v;
  for(const auto& p : xy) v.push_back(mesh.add_vertex(Point_3(p[0], p[1], 0.)));
  const int tri[8][3] = {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {2, 1, 6}, {2, 6, 4}, {4, 6, 5}, {5, 6, 7}, {4, 5, 7}};
  for(const auto& t : tri) mesh.add_face(v[t[0]], v[t[1]], v[t[2]]);
  SMP_CHECK(CGAL::is_valid_polygon_mesh(mesh) && num_faces(mesh) == 8, "slivers: the mesh is not valid");
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  namespace P = SMP::parameters;

  auto faces_positive = [&]() { // every face, the slivers too, oriented like the whole map
    double total = 0.;
    std::vector<double> a;
    for(Mesh::Face_index f : faces(mesh)) {
      std::vector<Point_2> q;
      for(vertex_descriptor w : vertices_around_face(halfedge(f, mesh), mesh)) q.push_back(uvmap[w]);
      a.push_back(CGAL::area(q[0], q[1], q[2]));
      total += a.back();
    }
    return std::all_of(a.begin(), a.end(), [total](double x) { return x * total > 0.; });
  };

  SMP::Stretch_minimizing_parameterizer_3<Mesh> paper;
  SMP_CHECK(SMP::parameterize(mesh, paper, bhd, uvmap) == SMP::OK, "slivers: " << paper.report().message);
  const double l2_uopt = paper.report().l2_stretch();
  SMP_CHECK(!faces_positive(), "slivers: U^opt has no flat face (the test lost its point)");

  SMP::Stretch_minimizing_parameterizer_3<Mesh> fixed(P::polish_iterations(20u, P::descent_iterations(30u)));
  SMP_CHECK(SMP::parameterize(mesh, fixed, bhd, uvmap) == SMP::OK, "slivers: " << fixed.report().message);
  const SMP::Stretch_minimizing_report fixed_report = fixed.report();
  const SMP::Stretch_minimizing_polish& pol = fixed_report.polish;
  SMP_CHECK(pol.ran() && pol.message.empty(), "slivers: the polish did not run: " << pol.message);
  SMP_CHECK(std::abs(pol.l2_before - l2_uopt) < 1e-12, "slivers: l2_before " << pol.l2_before << " is not U^opt's " << l2_uopt);
  SMP_CHECK(pol.l2_after < 0.99 * l2_uopt, "slivers: fixed border L2 " << pol.l2_after << " vs U^opt " << l2_uopt);
  const SMP::Stretch_statistics st = SMP::compute_stretch_statistics(mesh, uvmap);
  SMP_CHECK(std::abs(st.l2_stretch - pol.l2_after) < 1e-9, "slivers: reported L2 " << pol.l2_after << ", measured " << st.l2_stretch);
  SMP_CHECK(st.flipped_faces == 0 && faces_positive(), "slivers: fixed border result has flipped or flat faces");

  SMP::Stretch_minimizing_parameterizer_3<Mesh> free(P::polish_iterations(20u, P::free_border(true)));
  SMP_CHECK(SMP::parameterize(mesh, free, bhd, uvmap) == SMP::OK, "slivers: " << free.report().message);
  SMP_CHECK(free.report().polish.l2_after < 1.001, "slivers: free border L2 " << free.report().polish.l2_after);
  SMP_CHECK(faces_positive(), "slivers: free border result has flipped or flat faces");
  std::cout << std::setprecision(6) << "slivers: U^opt L2 " << l2_uopt << ", fixed border polish " << pol.l2_after << ", free border "
            << free.report().polish.l2_after << std::endl;
}

// The polisher's default solver, counting its factorizations.
struct Counting_solver : SI::Sander_vertex_solver
{
  using SI::Sander_vertex_solver::Sander_vertex_solver;
  std::size_t factorizations = 0;
  void factorize(const Matrix& a)
  {
    ++factorizations;
    SI::Sander_vertex_solver::factorize(a);
  }
};

// A planar grid whose uv is its own shape scaled, its interior moved by `shift`: with the
// stretch that close to the least (L2^2 - 1 at most the tolerance) no step can gain enough,
// and the polish returns before any factorization, the map untouched; a little further, it
// steps and gains.
void test_near_isometry()
{
  const int n = 12;
  SI::Flat_triangles m;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) m.xyz.push_back({double(i), double(j), 0.});
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.tri.push_back({a, b, d});
      m.tri.push_back({a, d, c});
    }
  std::vector<char> fixed(m.xyz.size(), 0);
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      if(i == 0 || j == 0 || i == n || j == n) fixed[std::size_t(j * (n + 1) + i)] = 1;
  SI::Sander_polish_settings st;
  st.direction = SI::Sander_polish_direction::NEWTON;
  for(const double shift : {1e-5, 3e-2}) {
    std::vector<Vec2> uv;
    for(std::size_t v = 0; v < m.xyz.size(); ++v) {
      const double s = fixed[v] ? 0. : shift * std::sin(3. * m.xyz[v][0]) * std::cos(2. * m.xyz[v][1]);
      uv.push_back({2. * m.xyz[v][0] + s, 2. * m.xyz[v][1] - s});
    }
    const std::vector<Vec2> start = uv;
    SI::Sander_energy_polisher<Counting_solver> polisher;
    const SI::Sander_polish_result r = polisher.polish(m, {}, fixed, {}, uv, st);
    SMP_CHECK(r.status == SI::Sander_polish_status::OK, "near isometry: " << r.message);
    const bool below = r.l2_before * r.l2_before - 1. <= st.tolerance;
    SMP_CHECK(below == (shift < 1e-3), "near isometry: L2 " << r.l2_before << " for a shift of " << shift);
    if(below) {
      SMP_CHECK(r.iterations == 0 && r.stop == SI::Sander_polish_stop::CONVERGED && uv == start &&
                polisher.newton_solver().factorizations == 0,
                "near isometry: the polish factored or stepped from L2 " << r.l2_before);
    } else {
      SMP_CHECK(r.iterations > 0 && r.l2_after < r.l2_before,
                "near isometry: no step from L2 " << r.l2_before << " (" << r.iterations << " steps)");
    }
  }
}

// The Newton system factored by the supernodal method (forced from one row on), its rows in a
// vertex order given by the caller, or in a minimum degree order, through BLAS (CHOLMOD's, when
// it is used) or not (Eigen's SparseLU); and the split systems forced from one row on, factored
// by CHOLMOD's LL^T when CHOLMOD is used, else by the simplicial LDL^T still (Eigen's SparseLU is
// not taken for them): the same polish as the simplicial factorization's, to rounding.
void test_supernodal(SI::Sander_polish_direction direction)
{
  const bool split = direction == SI::Sander_polish_direction::SPLIT_NEWTON;
  Start s;
  if(!load_start("three_peaks.off", s)) return;
  SI::Sander_polish_settings st;
  st.direction = direction;
  st.max_iterations = 8;
  // whether the last polish of `p` factored its systems by a supernodal method
  auto supernodal_used = [split](const SI::Sander_energy_polisher<Counting_solver>& p) {
    return split ? p.split_solver(0).supernodal() && p.split_solver(1).supernodal() : p.newton_solver().supernodal();
  };
  std::vector<Vec2> simplicial_uv = s.uv;
  SI::Sander_energy_polisher<Counting_solver> simplicial;
  const SI::Sander_polish_result reference = simplicial.polish(s.m, s.guard, s.fixed, s.border, simplicial_uv, st);
  SMP_CHECK(reference.status == SI::Sander_polish_status::OK && reference.iterations > 0 && !supernodal_used(simplicial),
            "supernodal (split: " << split << "): the simplicial reference " << reference.message);
  std::vector<int> rank(s.m.xyz.size()); // the vertices backwards: any order is valid
  for(std::size_t v = 0; v < rank.size(); ++v) rank[v] = int(rank.size() - 1 - v);
  (split ? st.split_supernodal_rows : st.newton_supernodal_rows) = 1;
  for(const int run : split ? std::vector<int>{0} : std::vector<int>{0, 1, 2, 3}) {
    const bool given = run % 2 == 1;
    st.vertex_rank = given ? &rank : nullptr;
    st.supernodal_blas = run < 2;
    std::vector<Vec2> uv = s.uv;
    SI::Sander_energy_polisher<Counting_solver> supernodal;
    const SI::Sander_polish_result r = supernodal.polish(s.m, s.guard, s.fixed, s.border, uv, st);
    SMP_CHECK(r.status == SI::Sander_polish_status::OK && supernodal_used(supernodal) == (!split || Counting_solver::cholmod),
              "supernodal (split: " << split << ", order given: " << given << "): " << r.message);
    SMP_CHECK(r.iterations == reference.iterations && std::abs(r.l2_after - reference.l2_after) < 1e-9 * reference.l2_after,
              "supernodal (split: " << split << ", order given: " << given << "): L2 " << r.l2_after << " in "
              << r.iterations << " steps, simplicial " << reference.l2_after << " in " << reference.iterations);
    double largest = 0.;
    for(std::size_t v = 0; v < uv.size(); ++v)
      largest = (std::max)(largest, std::hypot(uv[v][0] - simplicial_uv[v][0], uv[v][1] - simplicial_uv[v][1]));
    SMP_CHECK(largest < 1e-8, "supernodal (split: " << split << ", order given: " << given
              << "): uv off the simplicial polish by " << largest);
  }
}

// The faces' terms are computed on several threads and added in their order: every direction
// polishes to the same map, bit for bit, on one thread and on three (mushroom's faces are
// enough for two blocks of work).
void test_threads()
{
  Start s;
  if(!load_start("mushroom.off", s)) return;
  typedef SI::Sander_polish_direction Direction;
  for(const Direction direction : {Direction::NEWTON, Direction::SPLIT_NEWTON, Direction::DIRICHLET_PROXY}) {
    SI::Sander_polish_settings st;
    st.direction = direction;
    st.free_border = direction == Direction::DIRICHLET_PROXY;
    st.max_iterations = 4;
    std::vector<Vec2> one = s.uv, three = s.uv;
    st.threads = 1;
    const SI::Sander_polish_result r1 = SI::Sander_energy_polisher<>().polish(s.m, s.guard, s.fixed, s.border, one, st);
    st.threads = 3;
    const SI::Sander_polish_result r3 = SI::Sander_energy_polisher<>().polish(s.m, s.guard, s.fixed, s.border, three, st);
    SMP_CHECK(r1.status == SI::Sander_polish_status::OK && r1.iterations > 0 && r3.iterations == r1.iterations &&
              one == three && r1.energy_after == r3.energy_after,
              "threads (direction " << int(direction) << "): " << r1.iterations << " and " << r3.iterations
              << " steps, energy " << r1.energy_after << " and " << r3.energy_after << " " << r1.message);
  }
}

int run_test(int, char**)
{
  if(!smp_test::sanitized)
    test_mesh("mannequin-devil.off", 1.316, 1.38);
  test_mesh("three_peaks.off", 1.223, 1.24, true);
  test_mesh("mushroom.off", 1.197, 1.19);
  test_mesh("patch-01.off", 1.081, 0.);
  test_mesh("nefertiti.off", 1.049, 0.);
  test_mesh("mesh_with_border.off", 1.093, 0.);
  test_holes();
  test_flat_slivers();
  test_near_isometry();
  test_supernodal(SI::Sander_polish_direction::NEWTON);
  test_supernodal(SI::Sander_polish_direction::SPLIT_NEWTON);
  test_threads();
  return smp_test::summary();
}

} // namespace test_polish

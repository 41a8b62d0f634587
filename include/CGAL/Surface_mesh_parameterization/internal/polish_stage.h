// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_POLISH_STAGE_H
#define CGAL_SMP_INTERNAL_POLISH_STAGE_H

// The polish stage of the stretch minimizer, after U^opt: the polisher run on the component,
// its steps reported like the others.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_energy_polisher.h>
#include <CGAL/Surface_mesh_parameterization/internal/Stretch_minimizing_settings.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// What a visitor sees of the map of step h, measured by `s`.
inline Stretch_minimizing_step make_step(std::size_t h, const Flat_stretch_summary& s,
                                         std::chrono::steady_clock::time_point start)
{
  Stretch_minimizing_step step;
  step.step = h;
  step.l2_stretch = s.l2;
  step.linf_stretch = s.linf;
  step.flipped_faces = s.flipped;
  step.degenerate_uv_faces = s.degenerate_uv;
  step.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return step;
}

// A fixed polygonal border flattens an ear (a face whose middle vertex has no other face)
// lying along one side; the free polish needs every face positive: move such a middle vertex
// off the side, outwards, by a tenth of the ear's width. Its only face is the ear, so no other
// face changes.
inline void open_flat_ears(const Disk_component_base& dc, std::vector<Vec2>& uv)
{
  std::vector<int> faces_of(dc.flat.xyz.size(), 0);
  for(const Triangle& t : dc.flat.tri)
    for(int v : t)
      ++faces_of[v];
  auto signed_area = [&uv](const Triangle& t) {
    const Vec2 &a = uv[t[0]], &b = uv[t[1]], &c = uv[t[2]];
    return 0.5 * twice_signed_area(a, b, c);
  };
  double total = 0.;
  for(const Triangle& t : dc.flat.tri)
    total += signed_area(t);
  const double orientation = total >= 0. ? 1. : -1.;
  for(const Triangle& t : dc.flat.tri) {
    const double a = signed_area(t);
    const double width = std::hypot(uv[t[1]][0] - uv[t[0]][0], uv[t[1]][1] - uv[t[0]][1]) +
                         std::hypot(uv[t[2]][0] - uv[t[1]][0], uv[t[2]][1] - uv[t[1]][1]);
    if(orientation * a > 1e-12 * width * width)
      continue;
    for(int k = 0; k < 3; ++k) {
      const int v = t[k], p = t[(k + 2) % 3], n = t[(k + 1) % 3];
      if(faces_of[v] != 1 || dc.row[v] != -1)
        continue;
      // the normal of the side (p, n) on the side that gives the face the mesh's orientation
      const double dx = uv[n][0] - uv[p][0], dy = uv[n][1] - uv[p][1];
      const Vec2 normal = {dy * orientation, -dx * orientation};
      uv[v] = {uv[v][0] + 0.1 * normal[0], uv[v][1] + 0.1 * normal[1]};
      break;
    }
  }
}

// A face of zero 3D area with a straight angle at a moving vertex (e.g. a T-junction closed by a
// sliver) comes out flat in uv too, since every start weight reproduces straight lines; the
// polish needs the faces of its moving vertices positive. Moves such a vertex part of the way
// towards the centroid of its neighbours: the largest part, from a half down to 1/1024, that
// leaves all its faces positive (the middle vertex of the flat face is tried first). A vertex
// no part works for stays, and the polish then declines to start, as before. Returns whether a
// vertex moved.
inline bool open_flat_faces(const Disk_component_base& dc, const std::vector<char>& fixed, std::vector<Vec2>& uv)
{
  auto signed_area = [&uv](const Triangle& t) {
    const Vec2 &a = uv[t[0]], &b = uv[t[1]], &c = uv[t[2]];
    return twice_signed_area(a, b, c);
  };
  double total = 0.;
  for(const Triangle& t : dc.flat.tri)
    total += signed_area(t);
  const double orientation = total >= 0. ? 1. : -1.;
  auto flat = [&](const Triangle& t) {
    return !(orientation * signed_area(t) > 0.) && !(fixed[t[0]] && fixed[t[1]] && fixed[t[2]]);
  };
  if(std::none_of(dc.flat.tri.begin(), dc.flat.tri.end(), flat) &&
     std::none_of(dc.virtual_tri.begin(), dc.virtual_tri.end(), flat))
    return false;
  std::vector<Triangle> faces(dc.flat.tri);
  faces.insert(faces.end(), dc.virtual_tri.begin(), dc.virtual_tri.end());

  // faces around each vertex, compressed
  const std::size_t nv = uv.size();
  std::vector<int> first(nv + 1, 0), around(3 * faces.size());
  for(const Triangle& t : faces)
    for(int v : t) ++first[std::size_t(v) + 1];
  for(std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<int> fill(first.begin(), first.end() - 1);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int v : faces[f]) around[std::size_t(fill[std::size_t(v)]++)] = int(f);

  // moves v towards the centroid of its neighbours if some part of the way opens all its faces
  auto open = [&](int v) {
    Vec2 c = {0., 0.};
    int n = 0;
    for(int k = first[std::size_t(v)]; k < first[std::size_t(v) + 1]; ++k)
      for(int w : faces[std::size_t(around[std::size_t(k)])])
        if(w != v) { c[0] += uv[w][0]; c[1] += uv[w][1]; ++n; }
    const Vec2 p = uv[v];
    for(double s = 0.5; s >= 1. / 1024.; s *= 0.5) {
      uv[v] = {p[0] + s * (c[0] / n - p[0]), p[1] + s * (c[1] / n - p[1])};
      bool positive = true;
      for(int k = first[std::size_t(v)]; k < first[std::size_t(v) + 1] && positive; ++k)
        positive = orientation * signed_area(faces[std::size_t(around[std::size_t(k)])]) > 0.;
      if(positive)
        return true;
    }
    uv[v] = p;
    return false;
  };
  bool moved = false;
  for(const Triangle& t : faces) {
    if(!flat(t))
      continue;
    // the middle vertex first: the one the other two lie on either side of
    int middle = 0;
    for(int k = 0; k < 3; ++k) {
      const Vec2 &m = uv[t[k]], &a = uv[t[(k + 1) % 3]], &b = uv[t[(k + 2) % 3]];
      if((a[0] - m[0]) * (b[0] - m[0]) + (a[1] - m[1]) * (b[1] - m[1]) < 0.)
        middle = k;
    }
    for(int v : {t[middle], t[(middle + 1) % 3], t[(middle + 2) % 3]})
      if(!fixed[v] && open(v)) {
        moved = true;
        break;
      }
  }
  return moved;
}

// A free border leaves the map at any place and scale: move it into the unit square, keeping
// its proportions, as the fixed borders are.
inline void fit_in_unit_square(std::vector<Vec2>& uv)
{
  Vec2 lo = uv.front(), hi = uv.front();
  for(const Vec2& p : uv)
    for(int k = 0; k < 2; ++k) {
      lo[k] = (std::min)(lo[k], p[k]);
      hi[k] = (std::max)(hi[k], p[k]);
    }
  const double extent = (std::max)(hi[0] - lo[0], hi[1] - lo[1]);
  if(!(extent > 0.))
    return;
  for(Vec2& p : uv)
    p = {(p[0] - lo[0]) / extent, (p[1] - lo[1]) / extent};
}

// The descent steps of the polish stage with a fixed border: split Newton steps while the last
// `split_descent_window` steps lower the energy by at least `split_descent_tolerance` each on
// average, relatively: past that each step gains little more, where the Newton steps
// (polish_iterations) go on to the optimum. On large meshes most split steps are cut short by
// a fold, and one of them may gain little where the next ones gain again: a rule on one step
// stopped the descent there, far above where it goes on to. (Steps along the
// proxy first, while they gained 1%, ended higher on most meshes measured: from U^opt, the
// proxy's first step is cut short by a fold.) With a free border, steps along the proxy only, to
// the polisher's tolerance: on the charts of the atlas (a circle's U^opt, then a free border) the
// split steps cost more flattening time than the seams they saved.
constexpr double split_descent_tolerance = 2e-3;
constexpr unsigned int split_descent_window = 3;

// Lowers the stretch of `uv` (U^opt) further, flip-free: first by descent steps (projected Newton
// steps on u and v apart with a fixed border, along the proxy with a free one: cheap), then by
// projected Newton steps; `uv` is left as it is if the polish cannot start. The vertices from
// `real_vertices` on are the centres of the fans closing the holes. `vertex_rank`: the
// elimination order of the vertices for the descent's systems (vertex_order.h), empty for the
// solvers' own.
inline void polish_stage(const Disk_component_base& dc, std::size_t real_vertices,
                         const std::vector<int>& vertex_rank, const Stretch_minimizing_settings& settings,
                         std::chrono::steady_clock::time_point start, std::vector<Vec2>& uv,
                         Stretch_minimizing_polish& pol)
{
  pol.free_border = settings.free_border;
  std::vector<char> fixed(dc.flat.xyz.size(), 0);
  for(std::size_t v = real_vertices; v < fixed.size(); ++v)
    fixed[v] = 1; // hole centres: they only keep the holes from folding
  if(!settings.free_border)
    for(int v : dc.border)
      fixed[v] = 1;

  bool descent = false; // the phase running, for the visitor
  std::size_t steps = 0;
  auto visitor = [&](const Sander_polish_step& s) {
    const Flat_stretch_summary& m = s.measures; // measured once, by the polisher
    Stretch_minimizing_step step = make_step(++steps, m, start);
    step.polish = true;
    step.descent = descent;
    pol.history.push_back(step);
    if(settings.verbose)
      std::cerr << "stretch minimization: " << (descent ? "descent " : "polish ") << step.step << "  L2 " << m.l2
                << "  Linf " << m.linf << "  " << step.seconds << " s" << std::endl;
    return settings.visitor ? settings.visitor(step) : true;
  };
  // on a copy: if the polish cannot start, `uv` stays U^opt, ears and all
  std::vector<Vec2> polished = uv;
  if(settings.free_border)
    open_flat_ears(dc, polished);
  const bool opened = open_flat_faces(dc, fixed, polished);
  typedef Sander_polish_stop Stop;
  Sander_polish_result r;
  double seconds = 0.;
  bool first = true;
  for(Sander_polish_direction direction : {Sander_polish_direction::DIRICHLET_PROXY, Sander_polish_direction::SPLIT_NEWTON,
                                           Sander_polish_direction::NEWTON}) {
    descent = direction != Sander_polish_direction::NEWTON;
    Sander_polish_settings ps;
    ps.direction = direction;
    if(direction == (settings.free_border ? Sander_polish_direction::SPLIT_NEWTON : Sander_polish_direction::DIRICHLET_PROXY))
      continue;
    if(direction == Sander_polish_direction::SPLIT_NEWTON) {
      ps.tolerance = split_descent_tolerance;
      ps.tolerance_window = split_descent_window;
    }
    ps.free_border = settings.free_border;
    ps.threads = thread_count(settings.threads);
    ps.vertex_rank = &vertex_rank;
    // a time budget alone leaves the Newton steps uncapped
    ps.max_iterations = descent ? settings.descent_iterations
                      : settings.polish_iterations > 0 || settings.polish_seconds <= 0.
                        ? settings.polish_iterations : (std::numeric_limits<unsigned int>::max)();
    if(ps.max_iterations == 0)
      continue;
    if(settings.polish_seconds > 0.) {
      ps.time_budget = settings.polish_seconds - seconds;
      if(!(ps.time_budget > 0.))
        break;
    }
    Sander_energy_polisher<> polisher;
    r = polisher.polish(dc.flat, dc.virtual_tri, fixed, dc.border, polished, ps, visitor);
    seconds += r.seconds;
    if(r.status != Sander_polish_status::OK) {
      pol.message = r.message;
      break;
    }
    if(first)
      pol.l2_before = r.l2_before;
    first = false;
    (descent ? pol.descent_iterations : pol.iterations) += r.iterations;
    pol.l2_after = r.l2_after;
    pol.stop = r.stop == Stop::CONVERGED ? Polish_stop::CONVERGED
             : r.stop == Stop::ITERATION_CAP ? Polish_stop::ITERATION_CAP
             : r.stop == Stop::TIME_BUDGET ? Polish_stop::TIME_BUDGET
             : r.stop == Stop::VISITOR ? Polish_stop::VISITOR : Polish_stop::NO_PROGRESS;
    if(r.stop == Stop::TIME_BUDGET || r.stop == Stop::VISITOR)
      break;
  }
  pol.seconds = seconds;
  if(first) // nothing ran, or the first phase could not start: `uv` stays U^opt
    return;
  if(opened) { // the polish started from a moved U^opt: keep U^opt if it ended above it
    const double l2_opt = Flat_stretch().evaluate(dc.flat, uv, thread_count(settings.threads)).l2;
    if(!(pol.l2_after < l2_opt)) {
      pol.l2_before = pol.l2_after = l2_opt;
      pol.stop = Polish_stop::NO_PROGRESS;
      pol.message = "the polish did not get below U^opt";
      return;
    }
    pol.l2_before = l2_opt;
  }
  uv.swap(polished);
  if(settings.free_border)
    fit_in_unit_square(uv);
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_POLISH_STAGE_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CONFORMAL_MAP_H
#define CGAL_SMP_INTERNAL_ATLAS_CONFORMAL_MAP_H

// Two free-border conformal maps of a chart. The boundary-first map (Sawhney and Crane 2017),
// whose border keeps its lengths, solves one scalar system. LSCM's (Lévy et al. 2002), as the
// minimum of the conformal energy written as the Dirichlet energy of u and of v less the area of the map
// (Desbrun, Meyer and Alliez 2002, who show the two are one energy): u and v are then coupled
// on the border only, where CGAL's LSCM_parameterizer_3, with two residuals per triangle,
// couples them at every vertex; its factorization takes a fraction of the flops. (CGAL's
// residuals also weigh each triangle's conformal energy by its area, so the two maps differ on
// meshes of uneven triangles; this one is the conformal map of the surface.)

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/Sander_vertex_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/sort_by_vertex.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// The two vertices a conformal map pins, and where: the extremes along the longest side of the
// bounding box, at their coordinates along its two longest sides, the box scaled to the unit
// square (CGAL's Two_vertices_parameterizer_3's rule). `found` is false when the box has no
// extent along two axes.
struct Conformal_pins
{
  std::array<int, 2> vertex = {-1, -1};
  std::array<Vec2, 2> uv;
  bool found = false;
};

inline Conformal_pins conformal_pins(const std::vector<Vec3>& xyz)
{
  Conformal_pins pins;
  Vec3 low = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, high = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(const Vec3& p : xyz)
    for(std::size_t i = 0; i < 3; ++i) {
      low[i] = (std::min)(low[i], p[i]);
      high[i] = (std::max)(high[i], p[i]);
    }
  std::array<std::size_t, 3> axis = {0, 1, 2};
  std::stable_sort(axis.begin(), axis.end(), [&](std::size_t a, std::size_t b) { return high[a] - low[a] > high[b] - low[b]; });
  const double du = high[axis[0]] - low[axis[0]], dv = high[axis[1]] - low[axis[1]];
  if(!(dv > 0.) || !std::isfinite(du))
    return pins;
  for(std::size_t i = 0; i < xyz.size(); ++i) {
    const Vec2 q = {(xyz[i][axis[0]] - low[axis[0]]) / du, (xyz[i][axis[1]] - low[axis[1]]) / dv};
    if(pins.vertex[0] < 0 || q[0] < pins.uv[0][0] || (q[0] == pins.uv[0][0] && q[1] < pins.uv[0][1])) {
      pins.vertex[0] = int(i);
      pins.uv[0] = q;
    }
    if(pins.vertex[1] < 0 || q[0] > pins.uv[1][0] || (q[0] == pins.uv[1][0] && q[1] > pins.uv[1][1])) {
      pins.vertex[1] = int(i);
      pins.uv[1] = q;
    }
  }
  pins.found = pins.vertex[0] != pins.vertex[1];
  return pins;
}

// How much of a triangle's conformal energy counts: all of it, but on a needle, whose
// cotangents (the weights of its Dirichlet energy) would dwarf every other weight and leave
// the factorization to rounding: there, in proportion to its height over its longest side.
// A triangle without area counts for nothing (CGAL's LSCM gives it no weight either).
inline double conformal_weight(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
  const double needle = 1e-4; // the least ratio of twice the area to the longest side squared
  const double twice_area = norm3(cross3(sub3(p1, p0), sub3(p2, p0)));
  const double longest = (std::max)({dot3(sub3(p1, p0), sub3(p1, p0)), dot3(sub3(p2, p1), sub3(p2, p1)),
                                     dot3(sub3(p0, p2), sub3(p0, p2))});
  if(!(twice_area > 0.) || !std::isfinite(twice_area * longest))
    return 0.;
  return (std::min)(1., twice_area / (needle * longest));
}

// The conformal map of the chart of `triangles` (indices into `xyz`, every vertex in one, all
// of one piece), the vertices of `conformal_pins(xyz)` pinned: `uv` per vertex of `xyz`.
// Minimizes the sum over the triangles of their weight times their conformal energy
// E_D(u) + E_D(v) - A(u, v), E_D the Dirichlet energy (cotangent weights), A the signed uv area.
// The areas of the triangles of full weight add up to a sum over the border of their union,
// where alone u and v are coupled. False if there are no pins or the system cannot be solved.
inline bool conformal_map(const std::vector<Vec3>& xyz, const std::vector<Triangle>& triangles, std::vector<Vec2>& uv)
{
  const Conformal_pins pins = conformal_pins(xyz);
  if(!pins.found)
    return false;
  const std::size_t n = xyz.size();
  std::vector<int> row(n, -1); // per vertex, the row of its u (its v: the next one); -1 pinned
  int rows = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(int(v) != pins.vertex[0] && int(v) != pins.vertex[1]) {
      row[v] = rows;
      rows += 2;
    }
  std::vector<Vec2> pinned(n, Vec2{0., 0.});
  for(std::size_t k = 0; k < 2; ++k)
    pinned[std::size_t(pins.vertex[k])] = pins.uv[k];

  // the energy as (1/2) x^T M x over x = (u_0, v_0, u_1, ...): M's lower triangle on the free
  // rows, and the right-hand side -M_fp x_p of the pinned ones
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(24 * triangles.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows);
  // M[a][b] += c, for a and b coordinates (2 v + 0 for u, 2 v + 1 for v)
  auto add = [&](int a, int b, double c) {
    const int ra = row[std::size_t(a / 2)];
    if(ra < 0)
      return;
    const int rb = row[std::size_t(b / 2)];
    if(rb < 0)
      rhs[ra + a % 2] -= c * pinned[std::size_t(b / 2)][std::size_t(b % 2)];
    else if(ra + a % 2 >= rb + b % 2)
      entries.emplace_back(ra + a % 2, rb + b % 2, c);
  };
  // - w (u_i v_j - u_j v_i) / 2, the part of the side from i to j of -w times a uv area
  auto add_area_side = [&](int i, int j, double w) {
    add(2 * i, 2 * j + 1, -0.5 * w);
    add(2 * j + 1, 2 * i, -0.5 * w);
    add(2 * j, 2 * i + 1, 0.5 * w);
    add(2 * i + 1, 2 * j, 0.5 * w);
  };
  std::vector<std::tuple<int, int, int, int> > sides; // (lower, higher, from, to) of full-weight triangles
  sides.reserve(3 * triangles.size());
  for(const Triangle& t : triangles) {
    const double w = conformal_weight(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]);
    if(w == 0.)
      continue;
    const Vec3 &p0 = xyz[std::size_t(t[0])], &p1 = xyz[std::size_t(t[1])], &p2 = xyz[std::size_t(t[2])];
    const double twice_area = norm3(cross3(sub3(p1, p0), sub3(p2, p0)));
    for(std::size_t k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      const Vec3& o = xyz[std::size_t(t[k])];
      // E_D = (1/4) sum over the sides of cot(angle at o) (u_i - u_j)^2: M gains the weight
      // times cot / 2 at (i, i) and (j, j), less at (i, j) and (j, i)
      const double c = 0.5 * w * dot3(sub3(xyz[std::size_t(i)], o), sub3(xyz[std::size_t(j)], o)) / twice_area;
      for(int d = 0; d < 2; ++d) {
        add(2 * i + d, 2 * i + d, c);
        add(2 * j + d, 2 * j + d, c);
        add(2 * i + d, 2 * j + d, -c);
        add(2 * j + d, 2 * i + d, -c);
      }
      if(w < 1.)
        add_area_side(t[k], t[(k + 1) % 3], w);
      else
        sides.emplace_back((std::min)(t[k], t[(k + 1) % 3]), (std::max)(t[k], t[(k + 1) % 3]), t[k], t[(k + 1) % 3]);
    }
  }
  // the area of the full-weight triangles: their inner sides cancel, those of one triangle remain
  sort_by_vertex(sides, [](const std::tuple<int, int, int, int>& e) { return std::get<0>(e); });
  for(std::size_t s = 0; s < sides.size();) {
    std::size_t e = s + 1;
    while(e < sides.size() && std::get<0>(sides[e]) == std::get<0>(sides[s]) && std::get<1>(sides[e]) == std::get<1>(sides[s]))
      ++e;
    for(std::size_t k = s; k < e; ++k) // an edge of three or more sides: each has its own
      if(e - s != 2 || std::get<2>(sides[s]) == std::get<2>(sides[s + 1]))
        add_area_side(std::get<2>(sides[k]), std::get<3>(sides[k]), 1.);
    s = e;
  }
  Sander_vertex_solver::Matrix lower(rows, rows);
  lower.setFromTriplets(entries.begin(), entries.end());
  Sander_vertex_solver solver(true);
  // like the other systems of the charts, flattened on several threads at once: without BLAS
  solver.set_supernodal_rows(Sander_vertex_solver::blocked_supernodal_rows, false);
  solver.set_paired_rows(true);
  solver.compute(lower);
  if(solver.info() != Eigen::Success)
    return false;
  const Eigen::VectorXd x = solver.solve(rhs);
  uv.assign(n, Vec2{0., 0.});
  for(std::size_t v = 0; v < n; ++v) {
    uv[v] = row[v] < 0 ? pinned[v] : Vec2{x[row[v]], x[row[v] + 1]};
    if(!std::isfinite(uv[v][0]) || !std::isfinite(uv[v][1]))
      return false;
  }
  return true;
}

// The flat map of a disk whose border keeps its lengths: Boundary First Flattening (Sawhney and
// Crane 2017) with zero scale factors on the border, the conformal map of least area
// distortion. The scale factors u inside flatten the interior (A u = -K there, A the cotangent
// Laplacian weighed as in conformal_map(), K the angle defects); the border then turns, at each
// vertex, by its geodesic curvature plus (A u) there, its sides are lengthened or shortened as
// little as closes it, and the inside is the harmonic extension of that border. One scalar
// factorization for the three solves, where LSCM factors a system of twice the rows.
// `loop`: the border of the disk that the triangles make (its only border), each side from a
// vertex to the next a side of a triangle (the inside on its left). With `convex`, the border
// turns one way only: every turn raised to at least a twentieth of the mean turn, all scaled
// back to a full turn, which makes it a strictly convex polygon near the conformal border (a
// border on which any positive weights give a bijection, where the conformal one can overlap
// itself); only the border is placed then (the inside stays at the origin), for a map of the
// caller's inside it. False if a vertex is twice on it, the system cannot be solved, or (with
// `convex`) closing the border would take a side's whole length.
inline bool boundary_first_map(const std::vector<Vec3>& xyz, const std::vector<Triangle>& triangles,
                               const std::vector<int>& loop, std::vector<Vec2>& uv, bool convex = false)
{
  const std::size_t n = xyz.size();
  if(loop.size() < 3)
    return false;
  std::vector<int> row(n, 0); // -1 on the border, else the row of the vertex
  for(int b : loop) {
    if(row[std::size_t(b)] < 0)
      return false;
    row[std::size_t(b)] = -1;
  }
  int rows = 0;
  for(std::size_t v = 0; v < n; ++v)
    if(row[v] == 0)
      row[v] = rows++;
  // angle sums, and the Laplacian: its interior rows (lower triangle), and its sides to the border
  std::vector<double> angle(n, 0.);
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(9 * triangles.size());
  struct Side_weight { int from, to; double c; };
  std::vector<Side_weight> to_border;
  for(const Triangle& t : triangles) {
    const double w = conformal_weight(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]);
    for(std::size_t k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      const Vec3& o = xyz[std::size_t(t[k])];
      const Vec3 a = sub3(xyz[std::size_t(i)], o), b = sub3(xyz[std::size_t(j)], o);
      const double cross = norm3(cross3(a, b)), dot = dot3(a, b);
      angle[std::size_t(t[k])] += std::atan2(cross, dot);
      if(w == 0.)
        continue;
      const double c = 0.5 * w * dot / cross;
      const int ri = row[std::size_t(i)], rj = row[std::size_t(j)];
      if(ri >= 0) entries.emplace_back(ri, ri, c);
      if(rj >= 0) entries.emplace_back(rj, rj, c);
      if(ri >= 0 && rj >= 0) entries.emplace_back((std::max)(ri, rj), (std::min)(ri, rj), -c);
      else if(ri >= 0) to_border.push_back({i, j, c});
      else if(rj >= 0) to_border.push_back({j, i, c});
    }
  }
  const double pi = 3.14159265358979323846;
  Eigen::VectorXd scale = Eigen::VectorXd::Zero(rows);
  Sander_vertex_solver solver(true);
  solver.set_supernodal_rows(Sander_vertex_solver::default_supernodal_rows, false);
  if(rows > 0) {
    Sander_vertex_solver::Matrix lower(rows, rows);
    lower.setFromTriplets(entries.begin(), entries.end());
    solver.compute(lower);
    if(solver.info() != Eigen::Success)
      return false;
    Eigen::VectorXd defect(rows);
    for(std::size_t v = 0; v < n; ++v)
      if(row[v] >= 0)
        defect[row[v]] = -(2. * pi - angle[v]);
    scale = solver.solve(defect);
  }
  // the turning of the border at each vertex: its geodesic curvature plus (A u) there
  std::vector<double> turn(n, 0.);
  for(int b : loop)
    turn[std::size_t(b)] = pi - angle[std::size_t(b)];
  for(const Side_weight& s : to_border)
    turn[std::size_t(s.to)] -= s.c * scale[row[std::size_t(s.from)]];
  if(convex) {
    const double least = 0.05 * 2. * pi / double(loop.size());
    double sum = 0.;
    for(int b : loop)
      sum += turn[std::size_t(b)] = (std::max)(turn[std::size_t(b)], least);
    for(int b : loop)
      turn[std::size_t(b)] *= 2. * pi / sum;
  }
  // the border's sides, in turn, then their lengths changed as little as closes it (least
  // squares weighed by 1 / length)
  const std::size_t m = loop.size();
  std::vector<Vec2> tangent(m);
  std::vector<double> length(m);
  double phi = 0.;
  double M[2][2] = {{0., 0.}, {0., 0.}}, gap[2] = {0., 0.};
  for(std::size_t i = 0; i < m; ++i) {
    if(i > 0) phi += turn[std::size_t(loop[i])];
    tangent[i] = {std::cos(phi), std::sin(phi)};
    length[i] = norm3(sub3(xyz[std::size_t(loop[(i + 1) % m])], xyz[std::size_t(loop[i])]));
    for(int r = 0; r < 2; ++r) {
      gap[r] += length[i] * tangent[i][std::size_t(r)];
      for(int c = 0; c < 2; ++c)
        M[r][c] += length[i] * tangent[i][std::size_t(r)] * tangent[i][std::size_t(c)];
    }
  }
  const double det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  if(!(std::abs(det) > 0.))
    return false;
  const Vec2 lambda = {(M[1][1] * gap[0] - M[0][1] * gap[1]) / det, (M[0][0] * gap[1] - M[1][0] * gap[0]) / det};
  uv.assign(n, Vec2{0., 0.});
  Vec2 at = {0., 0.};
  for(std::size_t i = 0; i < m; ++i) {
    uv[std::size_t(loop[i])] = at;
    const double l = length[i] * (1. - (tangent[i][0] * lambda[0] + tangent[i][1] * lambda[1]));
    if(convex && !(l > 0.))
      return false;
    at = {at[0] + l * tangent[i][0], at[1] + l * tangent[i][1]};
  }
  if(rows > 0 && !convex) { // a convex border is for a map of the caller's inside it
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(rows, 2);
    for(const Side_weight& s : to_border)
      for(int d = 0; d < 2; ++d)
        rhs(row[std::size_t(s.from)], d) += s.c * uv[std::size_t(s.to)][std::size_t(d)];
    const Eigen::MatrixXd inside = solver.solve(rhs);
    for(std::size_t v = 0; v < n; ++v)
      if(row[v] >= 0)
        uv[v] = {inside(row[v], 0), inside(row[v], 1)};
  }
  for(const Vec2& q : uv)
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]))
      return false;
  return true;
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CONFORMAL_MAP_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Newton polish of Sander's L2 stretch energy: the per-face derivatives against finite
// differences, fixed points and recovery on planar meshes, and on the bundled meshes from
// U^opt, with a fixed and with a free border: the energy never increases, no face flips, the
// free border stays a simple loop, guard faces around holes stay positive.

#include "smp_test_util.h"

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

typedef CGAL::Simple_cartesian<double>      Kernel;
typedef Kernel::Point_2                     Point_2;
typedef Kernel::Point_3                     Point_3;
typedef CGAL::Surface_mesh<Point_3>         Mesh;
typedef Mesh::Vertex_index                  vertex_descriptor;
typedef Mesh::Halfedge_index                halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace SI = CGAL::Surface_mesh_parameterization::internal;

using SI::Vec2;
using SI::Triangle;

// ---------------------------------------------------------------------------------------------
// helpers

double signed_area(const Vec2& a, const Vec2& b, const Vec2& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

double total_signed_area(const SI::Flat_triangles& m, const std::vector<Vec2>& uv)
{
  double s = 0.;
  for(const Triangle& t : m.tri) s += signed_area(uv[t[0]], uv[t[1]], uv[t[2]]);
  return s;
}

double max_displacement(const std::vector<Vec2>& a, const std::vector<Vec2>& b)
{
  double d = 0.;
  for(std::size_t v = 0; v < a.size(); ++v)
    d = (std::max)(d, std::hypot(a[v][0] - b[v][0], a[v][1] - b[v][1]));
  return d;
}

// Independent O(n^2) check that a closed polygon is simple: no two non-adjacent edges meet.
bool simple_loop(const std::vector<int>& loop, const std::vector<Vec2>& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  const std::size_t n = loop.size();
  auto pt = [&](std::size_t i) { return P(uv[loop[i % n]][0], uv[loop[i % n]][1]); };
  auto on_segment = [](const P& p, const P& a, const P& b) {
    return CGAL::collinear(a, b, p) && CGAL::collinear_are_ordered_along_line(a, p, b);
  };
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 2; j < n; ++j) {
      if(i == 0 && j == n - 1) continue; // adjacent through the wrap
      const P a = pt(i), b = pt(i + 1), c = pt(j), d = pt(j + 1);
      const CGAL::Orientation o1 = CGAL::orientation(a, b, c), o2 = CGAL::orientation(a, b, d);
      const CGAL::Orientation o3 = CGAL::orientation(c, d, a), o4 = CGAL::orientation(c, d, b);
      const bool none_collinear = o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR
                                  && o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR;
      if(none_collinear && o1 != o2 && o3 != o4)
        return false;
      if(on_segment(c, a, b) || on_segment(d, a, b) || on_segment(a, c, d) || on_segment(b, c, d))
        return false;
    }
  return true;
}

// A planar grid of (k+1) x (k+1) vertices on [0,1]^2 in the plane z = 0, interior vertices
// jittered by `jitter` cells; border loop counter-clockwise.
struct Grid
{
  SI::Flat_triangles m;
  std::vector<int> border;
  std::vector<char> fixed;
};

Grid make_grid(int k, double jitter, std::mt19937& rng)
{
  Grid g;
  std::uniform_real_distribution<double> u(-1., 1.);
  const double h = 1. / k;
  auto id = [k](int i, int j) { return j * (k + 1) + i; };
  for(int j = 0; j <= k; ++j)
    for(int i = 0; i <= k; ++i) {
      const bool inner = i > 0 && j > 0 && i < k && j < k;
      g.m.xyz.push_back({i * h + (inner ? jitter * h * u(rng) : 0.), j * h + (inner ? jitter * h * u(rng) : 0.), 0.});
      g.fixed.push_back(inner ? 0 : 1);
    }
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      g.m.tri.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      g.m.tri.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for(int i = 0; i < k; ++i) g.border.push_back(id(i, 0));
  for(int j = 0; j < k; ++j) g.border.push_back(id(k, j));
  for(int i = k; i > 0; --i) g.border.push_back(id(i, k));
  for(int j = k; j > 0; --j) g.border.push_back(id(0, j));
  return g;
}

// Gradient of E over the free vertices, assembled independently of the polisher.
double max_free_gradient(const SI::Flat_triangles& m, const std::vector<char>& fixed, const std::vector<Vec2>& uv)
{
  std::vector<Vec2> g(m.xyz.size(), Vec2{0., 0.});
  for(const Triangle& t : m.tri) {
    const SI::Sander_face_operator op = SI::sander_face_operator(m.xyz[t[0]], m.xyz[t[1]], m.xyz[t[2]]);
    Eigen::Matrix<double, 2, 3> Q;
    for(int a = 0; a < 3; ++a) Q.col(a) << uv[t[a]][0], uv[t[a]][1];
    Eigen::Vector4d gJ;
    SI::sander_face_energy(Q * op.D, op.area, 0., &gJ);
    for(int a = 0; a < 3; ++a)
      for(int r = 0; r < 2; ++r)
        g[t[a]][r] += gJ(2 * r) * op.D(a, 0) + gJ(2 * r + 1) * op.D(a, 1);
  }
  double mx = 0.;
  for(std::size_t v = 0; v < g.size(); ++v)
    if(!fixed[v]) mx = (std::max)(mx, std::hypot(g[v][0], g[v][1]));
  return mx;
}

const char* stop_name(SI::Sander_polish_stop s)
{
  switch(s) {
    case SI::Sander_polish_stop::NOT_RUN: return "not run";
    case SI::Sander_polish_stop::CONVERGED: return "converged";
    case SI::Sander_polish_stop::ITERATION_CAP: return "iteration cap";
    case SI::Sander_polish_stop::TIME_BUDGET: return "time budget";
    case SI::Sander_polish_stop::VISITOR: return "visitor";
    case SI::Sander_polish_stop::NO_PROGRESS: return "no progress";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// per face

// The analytic projection against the eigen decomposition of the exact Hessian H.
void check_projection(const Eigen::Matrix2d& J, double area, double mu, const Eigen::Matrix4d& H)
{
  const double ratio = 1e-8;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(H);
  const Eigen::Vector4d clamped = es.eigenvalues().cwiseMax(ratio * es.eigenvalues()(3));
  const Eigen::Matrix4d expected = es.eigenvectors() * clamped.asDiagonal() * es.eigenvectors().transpose();
  const Eigen::Matrix4d P = SI::sander_face_projected_hessian(J, area, mu, ratio);
  const double e = (P - expected).norm() / expected.norm();
  SMP_CHECK(e < 1e-9, "projected Hessian relative error " << e << " at J = " << J(0, 0) << " " << J(0, 1) << " "
                      << J(1, 0) << " " << J(1, 1) << " (eigenvalues " << es.eigenvalues().transpose() << ")");
  const double lp = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(P).eigenvalues()(0);
  SMP_CHECK(lp > 0., "projected Hessian has eigenvalue " << lp);
}

void test_face_derivatives()
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2., 2.);
  int tried = 0;
  for(int k = 0; tried < 200 && k < 10000; ++k) {
    Eigen::Matrix2d J;
    J << u(rng), u(rng), u(rng), u(rng);
    if(J.determinant() < 0.2) continue;
    ++tried;
    const double area = 0.1 + std::abs(u(rng)), mu = (tried % 2) ? 0. : std::abs(u(rng));
    Eigen::Vector4d g;
    Eigen::Matrix4d H;
    const double f = SI::sander_face_energy(J, area, mu, &g, &H);

    // the definition: area * (a + c) / 2 with J^-1, plus mu * area * det
    const double f_def = 0.5 * area * J.inverse().squaredNorm() + mu * area * J.determinant();
    SMP_CHECK(std::abs(f - f_def) <= 1e-12 * std::abs(f_def), "energy " << f << " vs " << f_def);

    const double step = 1e-5;
    Eigen::Vector4d g_fd;
    Eigen::Matrix4d H_fd;
    for(int i = 0; i < 4; ++i) {
      Eigen::Matrix2d Jp = J, Jm = J;
      Jp(i / 2, i % 2) += step;
      Jm(i / 2, i % 2) -= step;
      Eigen::Vector4d gp, gm;
      const double fp = SI::sander_face_energy(Jp, area, mu, &gp);
      const double fm = SI::sander_face_energy(Jm, area, mu, &gm);
      g_fd(i) = (fp - fm) / (2. * step);
      H_fd.col(i) = (gp - gm) / (2. * step);
    }
    const double eg = (g - g_fd).norm() / g.norm(), eh = (H - H_fd).norm() / H.norm();
    SMP_CHECK(eg < 1e-5, "gradient relative error " << eg);
    SMP_CHECK(eh < 1e-5, "Hessian relative error " << eh);
    SMP_CHECK((H - H.transpose()).norm() <= 1e-14 * H.norm(), "Hessian not symmetric");

    check_projection(J, area, mu, H);
  }
  SMP_CHECK(tried == 200, "too few random Jacobians");

  // conformal Jacobians, where the singular vectors are not unique
  for(double angle : {0., 0.3, 2.5})
    for(double scale : {0.5, 1., 3.}) {
      Eigen::Matrix2d J;
      J << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
      J *= scale;
      Eigen::Matrix4d H;
      SI::sander_face_energy(J, 0.7, 0.2, nullptr, &H);
      check_projection(J, 0.7, 0.2, H);
    }

  // the face operator: an isometric uv triangle has a rotation as Jacobian
  const SI::Vec3 p1{0.3, -1., 2.}, p2{1.7, 0.2, 2.5}, p3{-0.4, 0.9, 1.1};
  const SI::Sander_face_operator op = SI::sander_face_operator(p1, p2, p3);
  const SI::Vec3 e1 = SI::sub3(p2, p1), e2 = SI::sub3(p3, p1);
  const double l1 = SI::norm3(e1), x3 = SI::dot3(e1, e2) / l1, y3 = SI::norm3(SI::cross3(e1, e2)) / l1;
  const double c = std::cos(0.7), s = std::sin(0.7);
  Eigen::Matrix<double, 2, 3> Q;
  Q << 5., 5. + c * l1, 5. + c * x3 - s * y3,
       1., 1. + s * l1, 1. + s * x3 + c * y3;
  const Eigen::Matrix2d R = Q * op.D;
  SMP_CHECK((R.transpose() * R - Eigen::Matrix2d::Identity()).norm() < 1e-12 && R.determinant() > 0.,
            "the Jacobian of an isometry is not a rotation");
  SMP_CHECK(std::abs(op.area - 0.5 * SI::norm3(SI::cross3(e1, e2))) < 1e-14, "face area");
}

// ---------------------------------------------------------------------------------------------
// planar meshes

void test_isometric_fixed_point()
{
  std::mt19937 rng(11);
  Grid g = make_grid(12, 0.3, rng);
  std::vector<Vec2> uv;
  for(const SI::Vec3& p : g.m.xyz) uv.push_back({p[0], p[1]});
  const std::vector<Vec2> start = uv;

  double area = 0.; // of the faces that can move: E = area at an isometry
  for(const Triangle& t : g.m.tri)
    if(!(g.fixed[t[0]] && g.fixed[t[1]] && g.fixed[t[2]]))
      area += signed_area(uv[t[0]], uv[t[1]], uv[t[2]]);
  SMP_CHECK(max_free_gradient(g.m, g.fixed, uv) < 1e-9, "gradient at the isometry " << max_free_gradient(g.m, g.fixed, uv));

  SI::Sander_energy_polisher<> polisher;
  const SI::Sander_polish_result r = polisher.polish(g.m, {}, g.fixed, g.border, uv);
  SMP_CHECK(r.status == SI::Sander_polish_status::OK, r.message);
  SMP_CHECK(std::abs(r.energy_before - area) < 1e-12 * area, "energy at the isometry " << r.energy_before << " vs area " << area);
  SMP_CHECK(max_displacement(uv, start) < 1e-9, "the isometry moved by " << max_displacement(uv, start));
  SMP_CHECK(std::abs(r.l2_after - 1.) < 1e-9 && std::abs(r.l2_before - 1.) < 1e-9, "L2 " << r.l2_before << " -> " << r.l2_after);

  // free border: the isometry is a minimum there too
  SI::Sander_polish_settings free;
  free.free_border = true;
  const SI::Sander_polish_result rf = polisher.polish(g.m, {}, g.fixed, g.border, uv, free);
  SMP_CHECK(rf.status == SI::Sander_polish_status::OK, rf.message);
  SMP_CHECK(max_displacement(uv, start) < 1e-9, "free border: the isometry moved by " << max_displacement(uv, start));
  SMP_CHECK(std::abs(rf.l2_after - 1.) < 1e-9, "free border: L2 " << rf.l2_after);

  // the descent along the proxy: the gradient is zero, nothing moves
  SI::Sander_polish_settings proxy;
  proxy.direction = SI::Sander_polish_direction::DIRICHLET_PROXY;
  const SI::Sander_polish_result rp = polisher.polish(g.m, {}, g.fixed, g.border, uv, proxy);
  SMP_CHECK(rp.status == SI::Sander_polish_status::OK && rp.iterations == 0, "proxy: " << rp.message << " " << rp.iterations << " steps");
  SMP_CHECK(max_displacement(uv, start) < 1e-9, "proxy: the isometry moved by " << max_displacement(uv, start));
}

void test_perturbed_grid()
{
  std::mt19937 rng(5);
  Grid g = make_grid(20, 0., rng);
  std::vector<Vec2> identity, uv;
  for(const SI::Vec3& p : g.m.xyz) identity.push_back({p[0], p[1]});
  std::uniform_real_distribution<double> u(-0.3 / 20., 0.3 / 20.);
  uv = identity;
  for(std::size_t v = 0; v < uv.size(); ++v)
    if(!g.fixed[v]) { uv[v][0] += u(rng); uv[v][1] += u(rng); }
  SI::Flat_stretch fs;
  const SI::Flat_stretch_summary s0 = fs.evaluate(g.m, uv);
  SMP_CHECK(s0.flipped == 0 && s0.degenerate_uv == 0 && s0.l2 > 1.01, "perturbed start: flips " << s0.flipped << " L2 " << s0.l2);
  const std::vector<Vec2> start_of_perturbed = uv;

  SI::Sander_energy_polisher<> polisher;
  SI::Sander_polish_settings st;
  st.tolerance = 1e-14;
  const SI::Sander_polish_result r = polisher.polish(g.m, {}, g.fixed, g.border, uv, st);
  SMP_CHECK(r.status == SI::Sander_polish_status::OK, r.message);
  SMP_CHECK(std::abs(r.l2_after - 1.) < 1e-6, "perturbed grid: L2 " << r.l2_before << " -> " << r.l2_after);
  SMP_CHECK(max_displacement(uv, identity) < 1e-5, "perturbed grid: " << max_displacement(uv, identity) << " from the identity");
  std::cout << "perturbed grid: L2 " << r.l2_before << " -> " << std::setprecision(12) << r.l2_after
            << std::setprecision(6) << " in " << r.iterations << " iterations (" << stop_name(r.stop) << ")" << std::endl;

  // the descent along the proxy (the Dirichlet energy's Hessian, which on a flat grid is the
  // Hessian of E at the identity but for the twists) reaches the identity too
  std::vector<Vec2> by_proxy = start_of_perturbed;
  SI::Sander_polish_settings sp = st;
  sp.direction = SI::Sander_polish_direction::DIRICHLET_PROXY;
  sp.max_iterations = 2000;
  const SI::Sander_polish_result rp = polisher.polish(g.m, {}, g.fixed, g.border, by_proxy, sp);
  SMP_CHECK(rp.status == SI::Sander_polish_status::OK, rp.message);
  SMP_CHECK(std::abs(rp.l2_after - 1.) < 1e-6 && max_displacement(by_proxy, identity) < 1e-5,
            "perturbed grid, proxy: L2 " << rp.l2_before << " -> " << rp.l2_after << ", "
            << max_displacement(by_proxy, identity) << " from the identity");
  std::cout << "perturbed grid, proxy: L2 " << rp.l2_before << " -> " << std::setprecision(12) << rp.l2_after
            << std::setprecision(6) << " in " << rp.iterations << " iterations (" << stop_name(rp.stop) << ")" << std::endl;

  // a mirrored start gives the mirrored result
  std::vector<Vec2> mirrored = uv;
  for(std::size_t v = 0; v < uv.size(); ++v)
    if(!g.fixed[v]) { mirrored[v] = identity[v]; mirrored[v][0] += u(rng); mirrored[v][1] += u(rng); }
  for(Vec2& q : mirrored) q[1] = -q[1];
  const SI::Sander_polish_result rm = polisher.polish(g.m, {}, g.fixed, g.border, mirrored, st);
  for(Vec2& q : mirrored) q[1] = -q[1];
  SMP_CHECK(rm.status == SI::Sander_polish_status::OK && max_displacement(mirrored, identity) < 1e-5,
            "mirrored grid: " << max_displacement(mirrored, identity) << " from the mirrored identity");

  // a flipped start is refused and left as it is
  std::vector<Vec2> bad = identity;
  bad[std::size_t(21 * 10 + 10)] = {2., 2.};
  const std::vector<Vec2> bad_copy = bad;
  const SI::Sander_polish_result rb = polisher.polish(g.m, {}, g.fixed, g.border, bad);
  SMP_CHECK(rb.status == SI::Sander_polish_status::BAD_START, "a flipped start was accepted");
  SMP_CHECK(max_displacement(bad, bad_copy) == 0., "a refused start was changed");
}

// A strip of `rows` x (k + 1) vertices wound `turns` times around the z axis, rising by `pitch`
// per radian, flattened along a straight line (the start) or along its own spiral.
Grid make_strip(double turns, double pitch, bool spiral_uv, std::vector<Vec2>& uv)
{
  const int k = 120, rows = 3;
  const double pi = 3.14159265358979323846;
  Grid g;
  uv.clear();
  auto id = [k](int i, int j) { return j * (k + 1) + i; };
  for(int j = 0; j < rows; ++j)
    for(int i = 0; i <= k; ++i) {
      const double theta = 2. * pi * turns * i / k, r = 1. + 0.15 * j;
      g.m.xyz.push_back({r * std::cos(theta), r * std::sin(theta), pitch * theta});
      const double ru = r + 0.1 * theta / (2. * pi); // a spiral: the second turn crosses the first
      uv.push_back(spiral_uv ? Vec2{ru * std::cos(theta), ru * std::sin(theta)} : Vec2{1.15 * theta, 0.15 * j});
      g.fixed.push_back(0);
    }
  for(int j = 0; j + 1 < rows; ++j)
    for(int i = 0; i < k; ++i) {
      g.m.tri.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      g.m.tri.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for(int i = 0; i < k; ++i) g.border.push_back(id(i, 0));
  for(int j = 0; j + 1 < rows; ++j) g.border.push_back(id(k, j));
  for(int i = k; i > 0; --i) g.border.push_back(id(i, rows - 1));
  for(int j = rows - 1; j > 0; --j) g.border.push_back(id(0, j));
  return g;
}

// With a free border, a strip whose isometric flattening overlaps itself (1.1 turns of a
// flat helix) curls up until its ends meet, and no further; a start whose border crosses
// itself is refused.
void test_free_border_strip()
{
  std::vector<Vec2> uv;
  Grid g = make_strip(1.1, 0.05, false, uv);
  SI::Sander_energy_polisher<> polisher;
  SI::Sander_polish_settings st;
  st.free_border = true;
  const SI::Sander_polish_result r = polisher.polish(g.m, {}, g.fixed, g.border, uv, st);
  SI::Flat_stretch fs;
  SMP_CHECK(r.status == SI::Sander_polish_status::OK, "strip: " << r.message);
  SMP_CHECK(fs.evaluate(g.m, uv).flipped == 0, "strip: flipped faces");
  SMP_CHECK(simple_loop(g.border, uv), "strip: the border loop intersects itself");
  const double gap = std::hypot(uv[0][0] - uv[120][0], uv[0][1] - uv[120][1]);
  SMP_CHECK(gap < 0.15 && r.l2_after < 1.001, "strip: did not curl up (ends " << gap << " apart, L2 " << r.l2_after << ")");
  std::cout << "curled strip: L2 " << r.l2_before << " -> " << r.l2_after << ", ends " << gap << " apart" << std::endl;

  g = make_strip(1.15, 0.05, true, uv);
  SMP_CHECK(!simple_loop(g.border, uv) && fs.evaluate(g.m, uv).flipped == 0, "the crossing spiral is not what it should be");
  const std::vector<Vec2> start = uv;
  const SI::Sander_polish_result rb = polisher.polish(g.m, {}, g.fixed, g.border, uv, st);
  SMP_CHECK(rb.status == SI::Sander_polish_status::BAD_START && max_displacement(uv, start) == 0.,
            "a start whose border crosses itself was accepted with a free border");
  for(int v : g.border) g.fixed[v] = 1;
  const SI::Sander_polish_result rf = polisher.polish(g.m, {}, g.fixed, g.border, uv, SI::Sander_polish_settings());
  SMP_CHECK(rf.status == SI::Sander_polish_status::OK, "the crossing spiral with a fixed border: " << rf.message);
}

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

// The descent along the proxy from U^opt, border fixed and free: the energy never increases,
// no face flips at any step, fixed vertices stay, the free border stays simple, and it gains.
void test_descent(const std::string& name, const Start& s)
{
  SI::Flat_stretch fs;
  for(bool free : {false, true}) {
    const std::string what = name + (free ? " descent, free border" : " descent");
    SI::Sander_polish_settings st;
    st.direction = SI::Sander_polish_direction::DIRICHLET_PROXY;
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
  if(controls) test_controls(s);
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

int main()
{
  test_face_derivatives();
  test_isometric_fixed_point();
  test_perturbed_grid();
  test_free_border_strip();
  test_mesh("mannequin-devil.off", 1.316, 1.38);
  test_mesh("three_peaks.off", 1.223, 1.24, true);
  test_mesh("mushroom.off", 1.197, 1.19);
  test_mesh("patch-01.off", 1.081, 0.);
  test_mesh("nefertiti.off", 1.049, 0.);
  test_mesh("mesh_with_border.off", 1.093, 0.);
  test_holes();
  test_flat_slivers();
  return smp_test::summary();
}

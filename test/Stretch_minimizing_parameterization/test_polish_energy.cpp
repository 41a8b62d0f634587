// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Newton polish of Sander's L2 stretch energy on flat arrays: the per-face derivatives and
// the projected Hessian against finite differences and an eigen decomposition, fixed points,
// recovery on perturbed planar grids, and a free border that must not cross itself.

#include "smp_test_util.h"
#include "polish_checks.h"
#include "flat_grid.h"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

namespace test_polish_energy {

using smp_test::Flat_grid;
using smp_test::make_flat_grid;

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
  // J^T J diagonal (its right singular vectors the axes), its larger entry first or second, and
  // nearly so
  for(const double off : {0., 1e-12, -1e-12})
    for(const std::array<double, 2>& diagonal : {std::array<double, 2>{2., 0.5}, std::array<double, 2>{0.5, 2.}}) {
      Eigen::Matrix2d J;
      J << diagonal[0], off, 0., diagonal[1];
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
  Flat_grid g = make_flat_grid(12, 0.3, rng);
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

  // the descent steps of either kind: the gradient is zero, nothing moves
  for(const auto direction : {SI::Sander_polish_direction::DIRICHLET_PROXY, SI::Sander_polish_direction::SPLIT_NEWTON}) {
    SI::Sander_polish_settings descent;
    descent.direction = direction;
    const SI::Sander_polish_result rp = polisher.polish(g.m, {}, g.fixed, g.border, uv, descent);
    SMP_CHECK(rp.status == SI::Sander_polish_status::OK && rp.iterations == 0, "descent: " << rp.message << " " << rp.iterations << " steps");
    SMP_CHECK(max_displacement(uv, start) < 1e-9, "descent: the isometry moved by " << max_displacement(uv, start));
  }
}

void test_perturbed_grid()
{
  std::mt19937 rng(5);
  Flat_grid g = make_flat_grid(20, 0., rng);
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

  // the descent steps reach the identity too: along the proxy (the Dirichlet energy's Hessian,
  // which on a flat grid is the Hessian of E at the identity but for the twists), and split
  // Newton steps (the Hessian without its coupling of u and v)
  for(const auto direction : {SI::Sander_polish_direction::DIRICHLET_PROXY, SI::Sander_polish_direction::SPLIT_NEWTON}) {
    const char* what = direction == SI::Sander_polish_direction::SPLIT_NEWTON ? "split" : "proxy";
    std::vector<Vec2> by_descent = start_of_perturbed;
    SI::Sander_polish_settings sp = st;
    sp.direction = direction;
    sp.max_iterations = 2000;
    const SI::Sander_polish_result rp = polisher.polish(g.m, {}, g.fixed, g.border, by_descent, sp);
    SMP_CHECK(rp.status == SI::Sander_polish_status::OK, rp.message);
    SMP_CHECK(std::abs(rp.l2_after - 1.) < 1e-6 && max_displacement(by_descent, identity) < 1e-5,
              "perturbed grid, " << what << ": L2 " << rp.l2_before << " -> " << rp.l2_after << ", "
              << max_displacement(by_descent, identity) << " from the identity");
    std::cout << "perturbed grid, " << what << ": L2 " << rp.l2_before << " -> " << std::setprecision(12) << rp.l2_after
              << std::setprecision(6) << " in " << rp.iterations << " iterations (" << stop_name(rp.stop) << ")" << std::endl;
  }

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
Flat_grid make_strip(double turns, double pitch, bool spiral_uv, std::vector<Vec2>& uv)
{
  const int k = 120, rows = 3;
  const double pi = 3.14159265358979323846;
  Flat_grid g;
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
  Flat_grid g = make_strip(1.1, 0.05, false, uv);
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

int run_test(int, char**)
{
  test_face_derivatives();
  test_isometric_fixed_point();
  test_perturbed_grid();
  test_free_border_strip();
  return smp_test::summary();
}

} // namespace test_polish_energy

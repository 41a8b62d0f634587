// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SANDER_FACE_ENERGY_H
#define CGAL_SMP_INTERNAL_SANDER_FACE_ENERGY_H

// Sander's L2 stretch energy of one face as a function of its Jacobian, with its gradient, its
// Hessian and the Hessian projected to a convex model: what the polisher sums over the faces.

#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The linear map from the uv corners of a face to its Jacobian, J = [q1 q2 q3] * D (2x3 times
// 3x2): the rows of D are the gradients of the barycentric coordinates in a 2D frame of the 3D
// triangle. `area` is the 3D area.
struct Sander_face_operator
{
  Eigen::Matrix<double, 3, 2> D;
  double area = 0.;
};

inline Sander_face_operator sander_face_operator(const Vec3& p1, const Vec3& p2, const Vec3& p3)
{
  // frame: p1 at the origin, p2 on the x axis, p3 above it
  const Vec3 e1 = sub3(p2, p1), e2 = sub3(p3, p1);
  const double l = norm3(e1);
  const double x3 = dot3(e1, e2) / l, y3 = norm3(cross3(e1, e2)) / l;
  Eigen::Matrix2d M; // inverse of the edge matrix [[l, x3], [0, y3]]
  M << 1. / l, -x3 / (l * y3),
       0.,      1. / y3;
  Sander_face_operator op;
  op.D.row(0) = -(M.row(0) + M.row(1));
  op.D.row(1) = M.row(0);
  op.D.row(2) = M.row(1);
  op.area = 0.5 * l * y3;
  return op;
}

// f(J) = area / 2 * ||J||_F^2 / det(J)^2 + mu * area * det(J), the energy of one face, with its
// gradient and Hessian with respect to vec(J) = (J00, J01, J10, J11) when asked.
// \pre det(J) > 0
inline double sander_face_energy(const Eigen::Matrix2d& J, double area, double mu,
                                 Eigen::Vector4d* gradient = nullptr, Eigen::Matrix4d* hessian = nullptr)
{
  const Eigen::Vector4d j(J(0, 0), J(0, 1), J(1, 0), J(1, 1));
  const Eigen::Vector4d c(J(1, 1), -J(1, 0), -J(0, 1), J(0, 0)); // d det / d vec(J): cofactors
  const double n = j.squaredNorm();
  const double d = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
  const double h = 0.5 * area, id = 1. / d, hid2 = h * id * id;
  if(gradient)
    *gradient = hid2 * (2. * j - (2. * n * id) * c) + (mu * area) * c;
  if(hessian) {
    Eigen::Matrix4d& H = *hessian;
    H.noalias() = (6. * n * id * id) * (c * c.transpose()) - (4. * id) * (j * c.transpose() + c * j.transpose());
    H.diagonal().array() += 2.;
    H *= hid2;
    // the Hessian of det is constant: 1 at (0, 3), -1 at (1, 2), symmetric
    const double k = mu * area - 2. * n * id * hid2;
    H(0, 3) += k; H(3, 0) += k;
    H(1, 2) -= k; H(2, 1) -= k;
  }
  return hid2 * n + mu * area * d;
}

// The Hessian of sander_face_energy() with its eigenvalues clamped from below to `ratio`
// times the largest one, so that every face contributes a convex quadratic model.
//
// f depends on the singular values of J = s1 u1 v1^T + s2 u2 v2^T only (s1 s2 = det J > 0):
// f = area / 2 (1 / s1^2 + 1 / s2^2) + mu area s1 s2. Its Hessian then has the eigenvectors
// (u2 v1^T - u1 v2^T) / sqrt 2 (twist), (u2 v1^T + u1 v2^T) / sqrt 2 (flip) and two
// combinations of u1 v1^T and u2 v2^T given by the 2x2 Hessian of f in (s1, s2); the twist
// eigenvalue (df/ds1 + df/ds2) / (s1 + s2) is negative wherever f falls as the singular values
// grow (as its stretch term does), which is what the clamp removes.
// \pre det(J) > 0
inline Eigen::Matrix4d sander_face_projected_hessian(const Eigen::Matrix2d& J, double area, double mu, double ratio)
{
  // right singular vectors: the eigenvectors of J^T J = [a b; b c], v1 = (cos t, sin t) with
  // (cos 2t, sin 2t) = ((a - c) / 2, b) / r, its half angle taken from the larger of
  // 1 + cos 2t and 1 - cos 2t (no cancellation)
  const Eigen::Matrix2d JtJ = J.transpose() * J;
  const double d = J.determinant(), n = JtJ.trace();
  const double half_gap = 0.5 * (JtJ(0, 0) - JtJ(1, 1)), b = JtJ(0, 1);
  const double r = std::sqrt(half_gap * half_gap + b * b);
  Eigen::Vector2d v1(1., 0.);
  if(r > 0. && half_gap >= 0.) {
    v1(0) = std::sqrt(0.5 * (1. + half_gap / r));
    v1(1) = b / (2. * r * v1(0));
  } else if(r > 0.) {
    v1(1) = std::copysign(std::sqrt(0.5 * (1. - half_gap / r)), b);
    v1(0) = b / (2. * r * v1(1));
  }
  const Eigen::Vector2d v2(-v1(1), v1(0));
  const double s1 = std::sqrt(0.5 * n + r);
  const double s2 = d / s1; // accurate where s2^2 from the eigenvalues would cancel
  const Eigen::Vector2d u1 = J * v1 / s1, u2 = J * v2 / s2;
  auto vec = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { // vec(a b^T), row-major
    return Eigen::Vector4d(a(0) * b(0), a(0) * b(1), a(1) * b(0), a(1) * b(1));
  };
  const Eigen::Vector4d d1 = vec(u1, v1), d2 = vec(u2, v2);
  const Eigen::Vector4d twist = (vec(u2, v1) - vec(u1, v2)) / std::sqrt(2.);
  const Eigen::Vector4d flip = (vec(u2, v1) + vec(u1, v2)) / std::sqrt(2.);

  const double h = 0.5 * area, id = 1. / d;
  Eigen::Matrix2d S; // Hessian in (s1, s2)
  S << 6. * h / (s1 * s1 * s1 * s1), mu * area,
       mu * area,                    6. * h / (s2 * s2 * s2 * s2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es;
  es.computeDirect(S);
  const double l_twist = 2. * h * id * id * (1. - n * id) + mu * area;
  const double l_flip = 2. * h * id * id * (1. + n * id) - mu * area;

  const double largest = (std::max)({es.eigenvalues()(1), l_twist, l_flip});
  const double floor = ratio * (std::max)(largest, (std::numeric_limits<double>::min)());
  Eigen::Matrix4d H;
  Eigen::Vector4d e;
  H.noalias() = (std::max)(l_twist, floor) * (twist * twist.transpose());
  H.noalias() += (std::max)(l_flip, floor) * (flip * flip.transpose());
  for(int k = 0; k < 2; ++k) {
    e = es.eigenvectors()(0, k) * d1 + es.eigenvectors()(1, k) * d2;
    H.noalias() += (std::max)(es.eigenvalues()(k), floor) * (e * e.transpose());
  }
  return H;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SANDER_FACE_ENERGY_H

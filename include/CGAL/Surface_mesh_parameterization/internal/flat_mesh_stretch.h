// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_FLAT_MESH_STRETCH_H
#define CGAL_SMP_INTERNAL_FLAT_MESH_STRETCH_H

// Stretch measures on a triangle soup held in flat arrays. The iteration and the public
// measures of stretch_measures.h both run on this form, so there is one implementation of
// every formula.

#include <CGAL/Surface_mesh_parameterization/Face_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

using Triangle = std::array<int, 3>;

inline double triangle_area(const Vec3& p1, const Vec3& p2, const Vec3& p3)
{
  return 0.5 * norm3(cross3(sub3(p2, p1), sub3(p3, p1)));
}

// Sander et al. (2001) stretch of the affine map from a parameter triangle to a 3D triangle
// (the formulas are in Face_stretch's documentation).
inline Face_stretch triangle_stretch(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                     const Vec2& q1, const Vec2& q2, const Vec2& q3)
{
  Face_stretch r;
  const double s1 = q1[0], t1 = q1[1], s2 = q2[0], t2 = q2[1], s3 = q3[0], t3 = q3[1];
  r.area_uv = 0.5 * twice_signed_area(q1, q2, q3);
  r.area_3d = triangle_area(p1, p2, p3);
  if(r.area_uv == 0.) {
    r.l2 = r.linf = HUGE_VAL;
    return r;
  }
  const double f = 1. / (2. * r.area_uv);
  Vec3 Ss, St;
  for(int i = 0; i < 3; ++i) {
    Ss[i] = (p1[i] * (t2 - t3) + p2[i] * (t3 - t1) + p3[i] * (t1 - t2)) * f;
    St[i] = (p1[i] * (s3 - s2) + p2[i] * (s1 - s3) + p3[i] * (s2 - s1)) * f;
  }
  const double a = dot3(Ss, Ss), b = dot3(Ss, St), c = dot3(St, St);
  r.l2 = std::sqrt(0.5 * (a + c));
  r.linf = std::sqrt(0.5 * ((a + c) + std::sqrt((a - c) * (a - c) + 4. * b * b)));
  return r;
}

// Vertex positions and triangles by local index.
struct Flat_triangles
{
  std::vector<Vec3> xyz;
  std::vector<Triangle> tri;
};

// What the iteration needs of one parameterization.
struct Flat_stretch_summary
{
  double l2 = 0.;                     // normalized: 1 is an isometry up to scale
  double linf = 0.;                   // normalized like l2
  double rms = 0.;                    // un-normalized area-weighted RMS of sigma(T)
  std::size_t flipped = 0;            // against the orientation of the total signed uv area
  std::size_t degenerate_uv = 0;      // zero uv area (not counted when also degenerate in 3D)
  std::size_t degenerate_3d = 0;      // zero 3D area
};

// Per-face stretch of one parameterization, and what derives from it.
class Flat_stretch
{
public:
  // Relative size below which a triangle area counts as zero.
  static constexpr double degenerate_ratio = 1e-12;

  // Evaluates every face (on `threads` threads); faces degenerate in 3D or in uv are marked and
  // left out of the summary and of the vertex stretch, so that they cannot turn it into inf or NaN.
  Flat_stretch_summary evaluate(const Flat_triangles& m, const std::vector<Vec2>& uv,
                                unsigned int threads = 1)
  {
    const std::size_t nf = m.tri.size();
    m_faces.resize(nf);
    m_used.assign(nf, 0);
    parallel_for(nf, threads, parallel_grain, [&](std::size_t begin, std::size_t end) {
      for(std::size_t f = begin; f < end; ++f) {
        const Triangle& t = m.tri[f];
        m_faces[f] = triangle_stretch(m.xyz[t[0]], m.xyz[t[1]], m.xyz[t[2]], uv[t[0]], uv[t[1]], uv[t[2]]);
      }
    });
    double sum_a3 = 0., sum_a2 = 0.;
    for(const Face_stretch& t : m_faces) {
      if(std::isfinite(t.area_3d)) sum_a3 += t.area_3d;
      if(std::isfinite(t.area_uv)) sum_a2 += std::abs(t.area_uv);
    }
    const double tol3 = degenerate_ratio * sum_a3 / double((std::max)(nf, std::size_t(1)));
    const double tol2 = degenerate_ratio * sum_a2 / double((std::max)(nf, std::size_t(1)));

    Flat_stretch_summary s;
    double signed_sum = 0.;
    for(std::size_t f = 0; f < nf; ++f) {
      const Face_stretch& t = m_faces[f];
      if(!(t.area_3d > tol3)) { ++s.degenerate_3d; continue; }
      if(!(std::abs(t.area_uv) > tol2) || !std::isfinite(t.l2) || !std::isfinite(t.linf)) {
        ++s.degenerate_uv;
        continue;
      }
      m_used[f] = 1;
      signed_sum += t.area_uv;
    }

    double a3 = 0., a2 = 0., e2 = 0., linf = 0.;
    for(std::size_t f = 0; f < nf; ++f) {
      if(!m_used[f]) continue;
      const Face_stretch& t = m_faces[f];
      if((t.area_uv > 0.) != (signed_sum > 0.)) ++s.flipped;
      a3 += t.area_3d;
      a2 += std::abs(t.area_uv);
      e2 += t.area_3d * t.l2 * t.l2;
      linf = (std::max)(linf, t.linf);
    }
    if(a3 > 0.) {
      const double normalization = std::sqrt(a2 / a3);
      s.rms = std::sqrt(e2 / a3);
      s.l2 = s.rms * normalization;
      s.linf = linf * normalization;
    }
    return s;
  }

  // Per-vertex stretch (paper, eq. 1) of the last evaluation: area-weighted RMS over the
  // faces around each vertex. A vertex with no usable face gets `fallback`.
  void vertex_stretch(const Flat_triangles& m, double fallback, std::vector<double>& sigma) const
  {
    const std::size_t nv = m.xyz.size();
    std::vector<double> num(nv, 0.), den(nv, 0.);
    for(std::size_t f = 0; f < m.tri.size(); ++f) {
      if(!m_used[f]) continue;
      const Face_stretch& t = m_faces[f];
      for(int v : m.tri[f]) {
        num[v] += t.area_3d * t.l2 * t.l2;
        den[v] += t.area_3d;
      }
    }
    sigma.resize(nv);
    for(std::size_t v = 0; v < nv; ++v)
      sigma[v] = den[v] > 0. ? std::sqrt(num[v] / den[v]) : fallback;
  }

  // Frees the per-face data until the next evaluation (it is not needed while a system is
  // factorized, when the memory peaks).
  void release()
  {
    std::vector<Face_stretch>().swap(m_faces);
    std::vector<char>().swap(m_used);
  }

  const std::vector<Face_stretch>& faces() const { return m_faces; }
  bool used(std::size_t f) const { return m_used[f] != 0; }

private:
  std::vector<Face_stretch> m_faces;
  std::vector<char> m_used;
};

// The paper's edge, angle and area distortions (sums over edges, face corners and faces).
struct Flat_distortions
{
  double edge = 0., angle = 0., area = 0.;
};

inline Flat_distortions flat_distortions(const Flat_triangles& m, const std::vector<Vec2>& uv,
                                         const Flat_stretch& evaluated)
{
  Flat_distortions d;
  auto length2 = [&](int i, int j) {
    const double du = uv[i][0] - uv[j][0], dv = uv[i][1] - uv[j][1];
    return std::sqrt(du * du + dv * dv);
  };

  // edges, each once
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * m.tri.size());
  for(const Triangle& t : m.tri)
    for(int k = 0; k < 3; ++k)
      edges.emplace_back((std::min)(t[k], t[(k + 1) % 3]), (std::max)(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double sum3 = 0., sum2 = 0.;
  for(const auto& e : edges) {
    sum3 += norm3(sub3(m.xyz[e.first], m.xyz[e.second]));
    sum2 += length2(e.first, e.second);
  }
  if(sum3 > 0. && sum2 > 0.)
    for(const auto& e : edges)
      d.edge += std::abs(norm3(sub3(m.xyz[e.first], m.xyz[e.second])) / sum3 - length2(e.first, e.second) / sum2);

  // corner angles of the faces that are not degenerate
  std::size_t used = 0;
  for(std::size_t f = 0; f < m.tri.size(); ++f) {
    if(!evaluated.used(f)) continue;
    ++used;
    const Triangle& t = m.tri[f];
    for(int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      const double theta = angle3(sub3(m.xyz[b], m.xyz[a]), sub3(m.xyz[c], m.xyz[a]));
      const double x1 = uv[b][0] - uv[a][0], y1 = uv[b][1] - uv[a][1];
      const double x2 = uv[c][0] - uv[a][0], y2 = uv[c][1] - uv[a][1];
      const double phi = std::atan2(std::abs(x1 * y2 - y1 * x2), x1 * x2 + y1 * y2);
      d.angle += std::abs(theta - phi);
    }
  }
  if(used > 0)
    d.angle /= 3. * double(used);

  // face areas
  double a3 = 0., a2 = 0.;
  for(const Face_stretch& t : evaluated.faces()) {
    a3 += t.area_3d;
    a2 += std::abs(t.area_uv);
  }
  if(a3 > 0. && a2 > 0.)
    for(const Face_stretch& t : evaluated.faces())
      d.area += std::abs(t.area_3d / a3 - std::abs(t.area_uv) / a2);
  return d;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_FLAT_MESH_STRETCH_H

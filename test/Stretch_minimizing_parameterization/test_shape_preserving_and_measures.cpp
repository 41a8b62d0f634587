// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The formulas, checked on cases with known answers: Floater's weights (positivity, partition
// of unity, linear precision), the shape-preserving and stretch-minimizing parameterizers on
// planar meshes (reproduced exactly), and the stretch measures on analytic linear maps.

#include "smp_test_mesh.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <cmath>
#include <random>
#include <vector>

namespace test_shape_preserving_and_measures {

using namespace smp_test;

namespace SMP = CGAL::Surface_mesh_parameterization;
using SMP::internal::Vec3;

const double pi = 3.14159265358979323846;


// A border parameterizer that puts each border vertex at a given position (its in-plane
// coordinates): with it, a method of linear precision must reproduce a planar mesh exactly.
struct Given_border_parameterizer_3
{
  UV_map position;

  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  SMP::Error_code parameterize(const Mesh& mesh, halfedge_descriptor bhd, VertexUVMap uvmap,
                               VertexIndexMap, VertexParameterizedMap vpmap)
  {
    for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) {
      put(uvmap, target(h, mesh), position[target(h, mesh)]);
      put(vpmap, target(h, mesh), true);
    }
    return SMP::OK;
  }
  bool is_border_convex() const { return false; }
};

// Random star-shaped rings around the origin, planar or lifted out of the plane.
void check_ring_weights(std::mt19937& rng)
{
  std::uniform_real_distribution<double> unit(0., 1.);
  SMP::internal::Shape_preserving_ring_weights computer;
  std::vector<double> w;
  int planar_rings = 0;
  for(int trial = 0; trial < 2000; ++trial) {
    const int d = 3 + int(unit(rng) * 12);
    const bool planar = trial % 2 == 0;
    // angles: sorted random gaps, each below pi so that the centre is inside (star-shaped,
    // generally non-convex since the radii vary)
    std::vector<double> gaps(d);
    double sum = 0.;
    for(double& g : gaps) { g = 0.05 + unit(rng); sum += g; }
    bool ok = true;
    for(double& g : gaps) { g *= 2. * pi / sum; ok = ok && g < pi * 0.98; }
    if(!ok) continue;
    std::vector<Vec3> ring;
    double a = unit(rng) * 2. * pi;
    for(int k = 0; k < d; ++k) {
      const double r = 0.1 + 3. * unit(rng);
      ring.push_back({r * std::cos(a), r * std::sin(a), planar ? 0. : unit(rng) - 0.5});
      a += gaps[k];
    }
    const Vec3 center{0., 0., 0.};
    const bool defined = computer.compute(center, ring, w);
    SMP_CHECK(defined, "shape-preserving weights undefined on a valid ring");
    double total = 0., min_w = 1.;
    Vec3 mix{0., 0., 0.};
    for(int k = 0; k < d; ++k) {
      total += w[k];
      min_w = (std::min)(min_w, w[k]);
      for(int i = 0; i < 3; ++i) mix[i] += w[k] * ring[k][i];
    }
    SMP_CHECK(min_w > 0., "weight not positive, ring of degree " << d);
    SMP_CHECK(std::abs(total - 1.) < 1e-12, "weights sum to " << total);
    if(planar) {
      ++planar_rings;
      SMP_CHECK(std::abs(mix[0]) < 1e-12 && std::abs(mix[1]) < 1e-12,
                "no linear precision: sum w_k p_k = (" << mix[0] << ", " << mix[1] << ")");
    }
  }
  SMP_CHECK(planar_rings > 500, "too few planar rings were generated: " << planar_rings);

  // a regular hexagon: every weight 1/6 by symmetry
  std::vector<Vec3> hexagon;
  for(int k = 0; k < 6; ++k)
    hexagon.push_back({std::cos(k * pi / 3.), std::sin(k * pi / 3.), 0.});
  computer.compute({0., 0., 0.}, hexagon, w);
  for(double x : w)
    SMP_CHECK(std::abs(x - 1. / 6.) < 1e-14, "hexagon weight " << x);

  // undefined: a zero-length spoke, fewer than three neighbours
  std::vector<Vec3> spoke = hexagon;
  spoke[2] = {0., 0., 0.};
  SMP_CHECK(!computer.compute({0., 0., 0.}, spoke, w), "zero-length spoke accepted");
  SMP_CHECK(!computer.compute({0., 0., 0.}, std::vector<Vec3>(hexagon.begin(), hexagon.begin() + 2), w),
            "ring of two accepted");

  // a sharp cone whose scaled ring has an angle above pi: mean-value fallback, still positive
  std::vector<Vec3> cone = {{1., 0., 5.}, {std::cos(2.9), std::sin(2.9), 5.}, {std::cos(3.0), std::sin(3.0), 5.}};
  SMP_CHECK(computer.compute({0., 0., 0.}, cone, w), "cone ring rejected");
  SMP_CHECK(w[0] > 0. && w[1] > 0. && w[2] > 0. && std::abs(w[0] + w[1] + w[2] - 1.) < 1e-12, "cone weights");
}

// A planar jittered grid, triangulated, in the plane z = 0.
Mesh planar_grid(std::mt19937& rng, int n)
{
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Mesh m;
  std::vector<vertex_descriptor> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      // a non-convex border: the middle of the top side dips in
      const double dip = (j == n && i > 0 && i < n) ? -0.4 * std::sin(pi * i / n) : 0.;
      v.push_back(m.add_vertex(Point_3(i + (border ? 0. : jitter(rng)), j + dip + (border ? 0. : jitter(rng)), 0.)));
    }
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      const vertex_descriptor a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1], c = v[(j + 1) * (n + 1) + i], d = v[(j + 1) * (n + 1) + i + 1];
      if((i + j) % 2) { m.add_face(a, b, d); m.add_face(a, d, c); }
      else            { m.add_face(a, b, c); m.add_face(b, d, c); }
    }
  return m;
}

// Runs both parameterizers on a planar mesh whose border is fixed at `target` (the in-plane
// coordinates of every vertex): both must give back `target` everywhere.
void check_reproduces(Mesh& m, UV_map target, const char* what)
{
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, Given_border_parameterizer_3> Floater;
  const Floater floater(Given_border_parameterizer_3{target});
  auto distance = [&](UV_map uv) {
    double err = 0.;
    for(vertex_descriptor v : vertices(m))
      err = (std::max)(err, std::hypot(uv[v].x() - target[v].x(), uv[v].y() - target[v].y()));
    return err;
  };

  UV_map uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv_floater").first;
  SMP_CHECK(SMP::parameterize(m, floater, bhd, uv) == SMP::OK, what << ": shape-preserving failed");
  SMP_CHECK(distance(uv) < 1e-9, what << ": shape-preserving moved a planar mesh by " << distance(uv));

  // the stretch minimizer starts there, where every sigma_j is equal: the weights do not
  // change, U^1 = U^0, and the mesh is reproduced with stretch 1
  UV_map uv2 = m.add_property_map<vertex_descriptor, Point_2>("v:uv_smp").first;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> p(floater);
  SMP_CHECK(SMP::parameterize(m, p, bhd, uv2) == SMP::OK, what << ": stretch minimizer failed: " << p.report().message);
  SMP_CHECK(distance(uv2) < 1e-9, what << ": stretch minimizer moved a planar mesh by " << distance(uv2));
  SMP_CHECK(std::abs(p.report().kept().l2_stretch - 1.) < 1e-9, what << ": L2 stretch " << p.report().kept().l2_stretch);
  SMP_CHECK(p.report().kept_step == 0 && p.report().history.size() == 2, what << ": kept step " << p.report().kept_step);

  const SMP::Stretch_statistics s = SMP::compute_stretch_statistics(m, uv2);
  SMP_CHECK(std::abs(s.l2_stretch - 1.) < 1e-9 && std::abs(s.linf_stretch - 1.) < 1e-9,
            what << ": isometry measured L2 " << s.l2_stretch << " Linf " << s.linf_stretch);
  SMP_CHECK(s.edge_distortion < 1e-9 && s.angle_distortion < 1e-9 && s.area_distortion < 1e-9,
            what << ": isometry distortions " << s.edge_distortion << " " << s.angle_distortion << " " << s.area_distortion);
}

void check_linear_precision(std::mt19937& rng)
{
  Mesh m = planar_grid(rng, 12);
  UV_map xy = m.add_property_map<vertex_descriptor, Point_2>("v:xy").first;
  for(vertex_descriptor v : vertices(m))
    xy[v] = Point_2(m.point(v).x(), m.point(v).y());
  check_reproduces(m, xy, "plane z = 0");

  // the same mesh in a tilted plane (orthonormal e1, e2): 3D ring angles, not planar ones
  const Vec3 e1{0.6, 0.8, 0.}, e2{-0.48, 0.36, 0.8};
  for(vertex_descriptor v : vertices(m)) {
    const double x = xy[v].x(), y = xy[v].y();
    m.point(v) = Point_3(x * e1[0] + y * e2[0], x * e1[1] + y * e2[1], x * e1[2] + y * e2[2]);
  }
  check_reproduces(m, xy, "tilted plane");
}

void check_face_stretch()
{
  const Point_3 p1(0, 0, 0), p2(2, 0, 0), p3(0.5, 1.5, 0);
  auto map = [&](double a, double b, double c, double d, const Point_3& p) {
    return Point_2(a * p.x() + b * p.y(), c * p.x() + d * p.y());
  };
  // identity
  SMP::Face_stretch f = SMP::face_stretch(p1, p2, p3, map(1, 0, 0, 1, p1), map(1, 0, 0, 1, p2), map(1, 0, 0, 1, p3));
  SMP_CHECK(std::abs(f.l2 - 1.) < 1e-14 && std::abs(f.linf - 1.) < 1e-14, "identity " << f.l2 << " " << f.linf);
  SMP_CHECK(std::abs(f.area_3d - 1.5) < 1e-14 && std::abs(f.area_uv - 1.5) < 1e-14, "areas " << f.area_3d << " " << f.area_uv);
  // uniform scale k: the inverse map shrinks by 1/k
  f = SMP::face_stretch(p1, p2, p3, map(4, 0, 0, 4, p1), map(4, 0, 0, 4, p2), map(4, 0, 0, 4, p3));
  SMP_CHECK(std::abs(f.l2 - 0.25) < 1e-14 && std::abs(f.linf - 0.25) < 1e-14, "scale " << f.l2 << " " << f.linf);
  // a general linear map M = [[2, 1], [0.5, 3]]: S = M^-1 whose singular values are known
  // from the eigenvalues of S^T S: L2 = sqrt(|S|_F^2 / 2), Linf = largest singular value
  const double a = 2, b = 1, c = 0.5, d = 3, det = a * d - b * c;
  const double i11 = d / det, i12 = -b / det, i21 = -c / det, i22 = a / det;
  const double fro2 = i11 * i11 + i12 * i12 + i21 * i21 + i22 * i22;
  const double t = fro2, dd = (i11 * i22 - i12 * i21) * (i11 * i22 - i12 * i21);
  const double smax = std::sqrt((t + std::sqrt(t * t - 4 * dd)) / 2);
  f = SMP::face_stretch(p1, p2, p3, map(a, b, c, d, p1), map(a, b, c, d, p2), map(a, b, c, d, p3));
  SMP_CHECK(std::abs(f.l2 - std::sqrt(fro2 / 2)) < 1e-13, "linear map L2 " << f.l2 << " vs " << std::sqrt(fro2 / 2));
  SMP_CHECK(std::abs(f.linf - smax) < 1e-13, "linear map Linf " << f.linf << " vs " << smax);
  SMP_CHECK(std::abs(f.area_uv - 1.5 * det) < 1e-12, "linear map area " << f.area_uv);
  // a stretch along one axis only: singular values 1/3 and 1 (S = diag(1/3, 1))
  f = SMP::face_stretch(p1, p2, p3, map(3, 0, 0, 1, p1), map(3, 0, 0, 1, p2), map(3, 0, 0, 1, p3));
  SMP_CHECK(std::abs(f.l2 - std::sqrt((1. / 9 + 1) / 2)) < 1e-14 && std::abs(f.linf - 1.) < 1e-14, "axis " << f.l2);
  // a mirrored (flipped) triangle: same stretch, negative area
  f = SMP::face_stretch(p1, p2, p3, map(1, 0, 0, -1, p1), map(1, 0, 0, -1, p2), map(1, 0, 0, -1, p3));
  SMP_CHECK(std::abs(f.l2 - 1.) < 1e-14 && f.area_uv < 0., "mirror " << f.l2 << " " << f.area_uv);
  // zero uv area: infinite stretch
  f = SMP::face_stretch(p1, p2, p3, Point_2(0, 0), Point_2(1, 0), Point_2(2, 0));
  SMP_CHECK(f.area_uv == 0. && !std::isfinite(f.l2), "collinear uv " << f.l2);
}

void check_mesh_statistics()
{
  // four separate triangles: two mapped by a similarity (scale 3, rotation), one mirrored,
  // one collapsed onto a segment in uv
  Mesh m;
  auto uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  const double cs = 3 * std::cos(0.7), sn = 3 * std::sin(0.7);
  auto add = [&](double ox, int mode) {
    vertex_descriptor v[3];
    const double xy[3][2] = {{0, 0}, {1, 0}, {0.3, 0.8}};
    for(int k = 0; k < 3; ++k) {
      const double x = ox + xy[k][0], y = xy[k][1];
      v[k] = m.add_vertex(Point_3(x, y, 0.5 * x));
      const double px = std::sqrt(1.25) * x; // in-plane coordinate along the slope
      if(mode == 0) uv[v[k]] = Point_2(cs * px - sn * y, sn * px + cs * y);
      else if(mode == 1) uv[v[k]] = Point_2(cs * px + sn * y, sn * px - cs * y);
      else uv[v[k]] = Point_2(px, 0.);
    }
    m.add_face(v[0], v[1], v[2]);
  };
  add(0, 0);
  add(2, 0);
  add(4, 1);
  SMP::Stretch_statistics s = SMP::compute_stretch_statistics(m, uv);
  SMP_CHECK(s.flipped_faces == 1, "flipped faces " << s.flipped_faces);
  SMP_CHECK(std::abs(s.l2_stretch - 1.) < 1e-12 && std::abs(s.linf_stretch - 1.) < 1e-12,
            "similarity normalized to " << s.l2_stretch << " " << s.linf_stretch);
  SMP_CHECK(s.angle_distortion < 1e-12 && s.area_distortion < 1e-12, "similarity distortions");
  add(6, 2);
  s = SMP::compute_stretch_statistics(m, uv);
  SMP_CHECK(s.degenerate_uv_faces == 1 && s.number_of_faces == 4, "degenerate uv faces " << s.degenerate_uv_faces);
  SMP_CHECK(std::isfinite(s.l2_stretch) && std::abs(s.l2_stretch - 1.) < 1e-12, "degenerate face leaked: " << s.l2_stretch);
  SMP_CHECK(s.area_distortion > 0.2, "collapsed face not in the area distortion: " << s.area_distortion);

  // per-vertex stretch of the similarity: 1 everywhere it is defined
  auto vs = m.add_property_map<vertex_descriptor, double>("v:stretch").first;
  SMP::compute_vertex_stretch(faces(m), m, uv, vs);
  int ones = 0, zeros = 0;
  for(vertex_descriptor v : vertices(m)) {
    if(std::abs(vs[v] - 1.) < 1e-12) ++ones;
    if(vs[v] == 0.) ++zeros;
  }
  SMP_CHECK(ones == 9 && zeros == 3, "vertex stretch: " << ones << " ones, " << zeros << " zeros");

  // an anisotropic map (x stretched by 2 in uv): known normalized L2 over a planar mesh
  Mesh q;
  auto uvq = q.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  vertex_descriptor a = q.add_vertex(Point_3(0, 0, 0)), b = q.add_vertex(Point_3(1, 0, 0)),
                    c = q.add_vertex(Point_3(1, 1, 0)), d = q.add_vertex(Point_3(0, 1, 0));
  q.add_face(a, b, c);
  q.add_face(a, c, d);
  for(vertex_descriptor v : vertices(q))
    uvq[v] = Point_2(2 * q.point(v).x(), q.point(v).y());
  s = SMP::compute_stretch_statistics(q, uvq);
  // S = diag(1/2, 1): sigma^2 = (1/4 + 1) / 2 = 5/8, normalization sqrt(A2 / A3) = sqrt(2)
  SMP_CHECK(std::abs(s.l2_stretch - std::sqrt(5. / 8.) * std::sqrt(2.)) < 1e-12, "anisotropic L2 " << s.l2_stretch);
  SMP_CHECK(std::abs(s.linf_stretch - std::sqrt(2.)) < 1e-12, "anisotropic Linf " << s.linf_stretch);
  // edges: 3D lengths 1,1,1,1,sqrt2 ; uv lengths 2,1,2,1,sqrt5
  const double l3[5] = {1, 1, 1, 1, std::sqrt(2.)}, l2[5] = {2, 1, 2, 1, std::sqrt(5.)};
  double s3 = 0, s2 = 0, edge = 0;
  for(int k = 0; k < 5; ++k) { s3 += l3[k]; s2 += l2[k]; }
  for(int k = 0; k < 5; ++k) edge += std::abs(l3[k] / s3 - l2[k] / s2);
  SMP_CHECK(std::abs(s.edge_distortion - edge) < 1e-12, "edge distortion " << s.edge_distortion << " vs " << edge);
  SMP_CHECK(s.area_distortion < 1e-12, "uniform area scaling has no area distortion");
}

// A border that folds over itself (the top side pushed below the bottom one): the weights are
// positive but the border is not convex, and U^0 flips faces. The stretch minimizer must say
// so (ERROR_NO_1_TO_1_MAPPING) and write no interior vertex.
void check_folded_border(std::mt19937& rng)
{
  Mesh m = planar_grid(rng, 6);
  UV_map target = m.add_property_map<vertex_descriptor, Point_2>("v:target").first;
  for(vertex_descriptor v : vertices(m)) {
    const Point_3& p = m.point(v);
    target[v] = Point_2(p.x(), p.y() > 5.5 ? -3. : p.y());
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(m).first;
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, Given_border_parameterizer_3> Floater;
  const Floater floater(Given_border_parameterizer_3{target});
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> p(floater);
  UV_map uv = m.add_property_map<vertex_descriptor, Point_2>("v:uv_folded", Point_2(-7, -7)).first;
  SMP_CHECK(SMP::parameterize(m, p, bhd, uv) == SMP::ERROR_NO_1_TO_1_MAPPING,
            "folded border: " << SMP::error_message(p.report().status) << " " << p.report().message);
  SMP_CHECK(p.report().history.size() == 1 && p.report().history[0].flipped_faces > 0
              && p.report().stop == SMP::Stretch_minimizing_stop::FLIPPED_FACES,
            "folded border: U^0 should be computed, flipped, and end the iteration");
  std::size_t written = 0;
  for(vertex_descriptor v : vertices(m))
    if(!CGAL::is_border(v, m) && uv[v] != Point_2(-7, -7))
      ++written;
  SMP_CHECK(written == 0, "folded border: " << written << " interior vertices written");
}

int run_test(int, char**)
{
  std::mt19937 rng(20261122);
  check_ring_weights(rng);
  check_linear_precision(rng);
  check_folded_border(rng);
  check_face_stretch();
  check_mesh_statistics();
  return smp_test::summary();
}

} // namespace test_shape_preserving_and_measures

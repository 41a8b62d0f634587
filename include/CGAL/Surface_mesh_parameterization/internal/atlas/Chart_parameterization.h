// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_PARAMETERIZATION_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_PARAMETERIZATION_H

// One chart of the atlas flattened by this package's parameterizer: the chart's triangles made
// into a Surface_mesh (one vertex per chart vertex), the stretch-minimizing iteration from a
// fixed square border, then the polish with a free border (flip-free, the border never
// crossing itself). A chart of one triangle is laid out isometrically.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_growing.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>

#include <Eigen/SparseLU>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// A flattened chart: its triangles, the chart vertex of each of their corners, and the uv of
// every chart vertex, in the orientation of the input's triangles (positive signed areas).
struct Chart_map
{
  std::vector<std::size_t> triangles;
  std::vector<int> corner_vertex;        // 3 per triangle: index into uv
  std::vector<Vec2> uv;
  Flat_triangles flat;                   // the chart in 3D, by chart vertex
  double l2 = HUGE_VAL;                  // normalized L2 stretch of the chart
  bool ok = false;
};

struct Chart_parameterization_settings
{
  unsigned int polish_iterations = 10;   // free-border Newton steps
};

// Numbers the chart vertices of `triangles` and fills `chart.flat`.
inline void make_chart_vertices(const Atlas_triangles& m, Chart_growing& g, Chart_map& chart)
{
  chart.corner_vertex.assign(3 * chart.triangles.size(), -1);
  chart.flat = Flat_triangles();
  std::vector<std::pair<int, int> > roots; // (root corner, chart corner slot)
  roots.reserve(chart.corner_vertex.size());
  for(std::size_t i = 0; i < chart.triangles.size(); ++i)
    for(int k = 0; k < 3; ++k)
      roots.emplace_back(g.chart_vertex(int(3 * chart.triangles[i]) + k), int(3 * i) + k);
  std::sort(roots.begin(), roots.end());
  int n = -1;
  for(std::size_t r = 0; r < roots.size(); ++r) {
    if(r == 0 || roots[r].first != roots[r - 1].first) {
      ++n;
      const int c = roots[r].first;
      chart.flat.xyz.push_back(m.xyz[std::size_t(m.vertex[std::size_t(c / 3)][std::size_t(c % 3)])]);
    }
    chart.corner_vertex[std::size_t(roots[r].second)] = n;
  }
  for(std::size_t i = 0; i < chart.triangles.size(); ++i)
    chart.flat.tri.push_back({chart.corner_vertex[3 * i], chart.corner_vertex[3 * i + 1], chart.corner_vertex[3 * i + 2]});
}

// The chart's triangle laid out with its 3D shape; a flat one gets a thin positive triangle
// instead (it has no 3D area, so it carries no stretch).
inline void layout_single_triangle(Chart_map& chart)
{
  // in the order of the triangle's corners (the input's orientation), whatever the order of
  // the chart's vertices
  const Triangle& t = chart.flat.tri[0];
  const Vec3 &p = chart.flat.xyz[std::size_t(t[0])], &q = chart.flat.xyz[std::size_t(t[1])],
             &r = chart.flat.xyz[std::size_t(t[2])];
  const double a = norm3(sub3(q, p));
  const Vec3 e = sub3(r, p);
  double x = a > 0. ? dot3(e, sub3(q, p)) / a : 0.;
  double y = a > 0. ? norm3(cross3(sub3(q, p), e)) / a : 0.;
  const double size = (std::max)({a, norm3(e), norm3(sub3(r, q)), 1e-300});
  std::array<Vec2, 3> corner = {Vec2{0., 0.}, Vec2{a > 0. ? a : size, 0.}, Vec2{x, y}};
  if(!(y > 1e-6 * size) || !std::isfinite(x) || !std::isfinite(size)) { // no 3D area: any thin positive triangle
    const double side = std::isfinite(size) ? size : 1.;
    corner = {Vec2{0., 0.}, Vec2{side, 0.}, Vec2{0.5 * side, 1e-3 * side}};
  }
  chart.uv.assign(3, Vec2{0., 0.});
  for(int k = 0; k < 3; ++k)
    chart.uv[std::size_t(t[k])] = corner[std::size_t(k)];
}

// Flattens the chart, whose vertices are made (`make_chart_vertices()`). On failure `chart.ok`
// is false and the caller splits the chart. Charts can be flattened on several threads at once.
inline void flatten_chart(Chart_map& chart, const Chart_parameterization_settings& settings)
{
  chart.ok = false;
  if(chart.triangles.size() == 1) {
    layout_single_triangle(chart);
  } else {
    typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
    typedef CGAL::Surface_mesh<K::Point_3> Mesh;
    typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
    typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
    Mesh sm;
    std::vector<vertex_descriptor> vd;
    vd.reserve(chart.flat.xyz.size());
    for(const Vec3& p : chart.flat.xyz)
      vd.push_back(sm.add_vertex(K::Point_3(p[0], p[1], p[2])));
    for(const Triangle& t : chart.flat.tri)
      if(sm.add_face(vd[std::size_t(t[0])], vd[std::size_t(t[1])], vd[std::size_t(t[2])]) == Mesh::null_face())
        return;
    const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
    if(bhd == boost::graph_traits<Mesh>::null_halfedge())
      return;
    auto uvmap = sm.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
    auto vimap = sm.add_property_map<vertex_descriptor, int>("v:index").first;
    auto vpmap = sm.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    for(vertex_descriptor v : vertices(sm))
      put(vimap, v, int(v));
    namespace P = parameters;
    // a strictly convex border: three border vertices in a row (an ear of the chart's jagged
    // border) would make a flat triangle on a side of a square
    // Eigen's LU: charts are small, and flattened on several threads at once, where
    // SuiteSparse's solvers (through a multithreaded BLAS) made results vary from run to run
    typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > > Solver;
    typedef Shape_preserving_parameterizer_3<Mesh, Circular_border_arc_length_parameterizer_3<Mesh>, Solver> Initial;
    Stretch_minimizing_parameterizer_3<Mesh, Initial, Solver> p(P::preset(Stretch_minimizing_preset::LOWEST_STRETCH)
        .polish_iterations(settings.polish_iterations).free_border(true).number_of_threads(1u));
    if(p.parameterize(sm, bhd, uvmap, vimap, vpmap) != OK)
      return;
    // only the piece of `bhd` is flattened: a chart of pieces that touch at a repeated
    // position only (not at a chart vertex) is split like a failed one
    for(vertex_descriptor v : vd)
      if(!get(vpmap, v))
        return;
    chart.uv.resize(vd.size());
    for(std::size_t i = 0; i < vd.size(); ++i) {
      const K::Point_2& q = get(uvmap, vd[i]);
      chart.uv[i] = {q.x(), q.y()};
    }
  }
  // the input's orientation
  double signed_area = 0.;
  for(const Triangle& t : chart.flat.tri) {
    const Vec2 &a = chart.uv[std::size_t(t[0])], &b = chart.uv[std::size_t(t[1])], &c = chart.uv[std::size_t(t[2])];
    signed_area += twice_signed_area(a, b, c);
  }
  if(signed_area < 0.)
    for(Vec2& q : chart.uv)
      q[0] = -q[0];
  Flat_stretch measure;
  const Flat_stretch_summary s = measure.evaluate(chart.flat, chart.uv);
  if(s.flipped > 0 || s.degenerate_uv > 0)
    return;
  chart.l2 = s.degenerate_3d == chart.flat.tri.size() ? 1. : s.l2;
  chart.ok = std::isfinite(chart.l2);
  for(const Vec2& q : chart.uv) // a chart is packed only with finite uv
    chart.ok = chart.ok && std::isfinite(q[0]) && std::isfinite(q[1]);
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_PARAMETERIZATION_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_PARAMETERIZATION_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_PARAMETERIZATION_H

// One chart of the atlas flattened: the chart's triangles made into a Surface_mesh (one vertex
// per chart vertex), then Sander's stretch lowered with a free border (flip-free, the border
// never crossing itself) from one of two starts: a conformal map (the boundary-first map, else
// LSCM's: Conformal_map.h) where it is a bijection (it is cheap, and often much closer to the
// least stretch), else this package's U^0 inside the boundary-first border made convex. A chart
// that closed around a hole is first flattened with the hole kept (the conformal map with the
// hole filled by guard triangles), without the seam to it. A chart of one triangle is laid out
// isometrically.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_energy_polisher.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_vertex_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Chart_growing.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Conformal_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/Fold_repair.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/triangulate_loop.h>
#include <CGAL/Surface_mesh_parameterization/internal/component_faces.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/hole_filling_compatibility.h>

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// The free-border polish of a chart's conformal map that is within the bound already, left for
// when the chart is final (finish_polish()): until then the chart may be joined to a neighbour
// or cut, and its polish would be lost. The start was checked to be one the polish takes, and
// the polish of it later gives the map that a polish at once gives.
struct Deferred_polish
{
  bool pending = false;
  std::vector<Triangle> guard; // as polish_free_border() takes them
  std::vector<int> border;
  // a chart mapped with its slits closed (flatten_with_holes()) is polished closed: the closed
  // chart, and each chart vertex's vertex in it (empty for the others)
  Flat_triangles closed;
  std::vector<int> merged;
};

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
  // The chart's slits: pairs of its sides (3 t + k, t an input triangle) that are the two sides
  // of one edge, both in the chart and not glued, where the growing closed around a hole or
  // another chart. `slits_closed`: the map glues them (uv equal on both sides).
  std::vector<std::pair<int, int> > slits;
  bool slits_closed = false;
  Deferred_polish deferred;
};

// Whether `a` and `b` are the same chart as flatten_chart() sees it (its triangles, their
// corners' chart vertices and positions, its slits), so that they get the same map.
inline bool same_input(const Chart_map& a, const Chart_map& b)
{
  return a.triangles == b.triangles && a.corner_vertex == b.corner_vertex && a.flat.xyz == b.flat.xyz &&
         a.flat.tri == b.flat.tri && a.slits == b.slits;
}

struct Chart_parameterization_settings
{
  unsigned int polish_iterations = 10;   // free-border Newton steps
  // descent steps along the proxy, with a free border, from the start of a chart whose conformal
  // maps are no bijection (see flatten_by_stretch_minimization())
  unsigned int descent_iterations = 5;
  // the Newton steps of a map that is within `max_stretch` end at a step that lowers the
  // energy by less than this, relatively: coarser than the polisher's own tolerance, as each of
  // the last steps costs a factorization for a gain far below the bound
  double polish_tolerance = 1e-4;
  // the Newton steps of a map above the bound go on while this many times the pace of the last
  // step would bring it within the bound in the steps left (see polish_goes_on())
  double pace_allowance = 4.;
  double max_stretch = HUGE_VAL;         // a conformal map at most this stretched is kept as it is
  unsigned int threads = 1;              // of the polish of one chart (the map does not depend on it)
  // a boundary-first map above this L2 stretch gives way to LSCM's (see flatten_from_conformal())
  double boundary_first_limit = 2.;
  // a conformal map within `max_stretch` is polished later (see Deferred_polish)
  bool defer_polish = false;
};

// The charts from `begin` to `end` by their number of triangles, the largest first (in their
// order among equals): charts flattened side by side are taken in this order, as a large chart
// started last would keep one thread busy alone.
inline std::vector<std::size_t> largest_first(const std::vector<Chart_map>& charts, std::vector<std::size_t> order)
{
  std::stable_sort(order.begin(), order.end(), [&charts](std::size_t a, std::size_t b) {
    return charts[a].triangles.size() > charts[b].triangles.size();
  });
  return order;
}

inline std::vector<std::size_t> largest_first(const std::vector<Chart_map>& charts, std::size_t begin, std::size_t end)
{
  std::vector<std::size_t> order(end - begin);
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = begin + i;
  return largest_first(charts, std::move(order));
}

// The settings of the first chart of `order` (see largest_first()), charts flattened side by
// side on `threads` threads: a chart of more than half of their triangles runs mostly alone,
// and its polish takes every thread; the others take one (`settings.threads`).
inline Chart_parameterization_settings first_in_batch(const std::vector<Chart_map>& charts,
                                                       const std::vector<std::size_t>& order,
                                                       const Chart_parameterization_settings& settings,
                                                       unsigned int threads)
{
  Chart_parameterization_settings first = settings;
  std::size_t total = 0;
  for(std::size_t c : order) total += charts[c].triangles.size();
  if(!order.empty() && 2 * charts[order[0]].triangles.size() > total)
    first.threads = threads;
  return first;
}

// Whether the Newton steps of a chart go on after their step `done` (from 1) took the energy
// from `before` to `after` (the normalized L2 stretch `l2` then). Within the bound: while a step
// gains more than `polish_tolerance` relatively. Above it: after the first step (whose gain
// follows the start or the descent steps, not a Newton step), while `pace_allowance` times the
// step's gain in each step left could bring the energy, which goes as the square of the stretch,
// to the bound; the allowance is for the steps that speed up once a fold no longer cuts them
// short. Past that, the chart is cut whatever its last steps do, and where depends on a stretch
// they barely change, while each of them costs a factorization.
inline bool polish_goes_on(double before, double after, double l2, unsigned int done,
                           const Chart_parameterization_settings& settings)
{
  const double gain = before - after;
  if(l2 <= settings.max_stretch)
    return gain > settings.polish_tolerance * after;
  if(done < 2)
    return true;
  const double left = double(settings.polish_iterations) - double(done);
  const double at_bound = after * (settings.max_stretch / l2) * (settings.max_stretch / l2);
  return settings.pace_allowance * left * gain >= after - at_bound;
}

// Numbers the chart vertices of `triangles` and fills `chart.flat`.
inline void make_chart_vertices(const Atlas_triangles& m, Chart_growing& g, Chart_map& chart)
{
  chart.corner_vertex.assign(3 * chart.triangles.size(), -1);
  chart.flat = Flat_triangles();
  // (root corner, chart corner slot) in one integer, whose order is that of the pairs: the
  // chart vertices are numbered by root corner
  std::vector<std::uint64_t> roots;
  roots.reserve(chart.corner_vertex.size());
  for(std::size_t i = 0; i < chart.triangles.size(); ++i)
    for(std::size_t k = 0; k < 3; ++k)
      roots.push_back(std::uint64_t(g.chart_vertex(int(3 * chart.triangles[i] + k))) << 32 | std::uint64_t(3 * i + k));
  std::sort(roots.begin(), roots.end());
  int n = -1;
  for(std::size_t r = 0; r < roots.size(); ++r) {
    const std::size_t c = std::size_t(roots[r] >> 32);
    if(r == 0 || c != std::size_t(roots[r - 1] >> 32)) {
      ++n;
      chart.flat.xyz.push_back(m.xyz[std::size_t(m.vertex[c / 3][c % 3])]);
    }
    chart.corner_vertex[std::size_t(roots[r] & 0xffffffffu)] = n;
  }
  for(std::size_t i = 0; i < chart.triangles.size(); ++i)
    chart.flat.tri.push_back({chart.corner_vertex[3 * i], chart.corner_vertex[3 * i + 1], chart.corner_vertex[3 * i + 2]});
  chart.slits.clear();
  chart.slits_closed = false;
  for(std::size_t t : chart.triangles)
    for(int k = 0; k < 3; ++k) {
      const int side = int(3 * t) + k, mate = g.mate(side);
      if(side < mate && !g.glued(side) && g.chart(std::size_t(mate / 3)) == g.chart(t))
        chart.slits.emplace_back(side, mate);
    }
}

// The chart's triangle laid out with its 3D shape; a flat one gets a thin positive triangle
// instead (it has no 3D area to speak of, so it carries no stretch). Flat means a least height
// below a millionth of the longest side: a needle laid out on its shortest side would have a
// height far above that side, and the packing would round that side, and the area, away.
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
  if(!((a / size) * y > 1e-6 * size) || !std::isfinite(x) || !std::isfinite(size)) { // any thin positive triangle
    const double side = std::isfinite(size) ? size : 1.;
    corner = {Vec2{0., 0.}, Vec2{side, 0.}, Vec2{0.5 * side, 1e-3 * side}};
  }
  chart.uv.assign(3, Vec2{0., 0.});
  for(int k = 0; k < 3; ++k)
    chart.uv[std::size_t(t[k])] = corner[std::size_t(k)];
}

typedef CGAL::Exact_predicates_inexact_constructions_kernel Chart_kernel;
typedef CGAL::Surface_mesh<Chart_kernel::Point_3> Chart_mesh;
typedef boost::graph_traits<Chart_mesh>::vertex_descriptor Chart_vertex;
typedef boost::graph_traits<Chart_mesh>::halfedge_descriptor Chart_halfedge;

// The uv of every vertex of `sm` (vertex i of the chart is vertex i of `sm`).
template <typename UVMap>
std::vector<Vec2> read_uv(const Chart_mesh& sm, const UVMap& uvmap)
{
  std::vector<Vec2> uv;
  uv.reserve(num_vertices(sm));
  for(Chart_vertex v : vertices(sm)) {
    const Chart_kernel::Point_2& q = get(uvmap, v);
    uv.push_back({q.x(), q.y()});
  }
  return uv;
}

// The polisher's settings for a chart (polish_free_border()).
inline Sander_polish_settings free_border_polish_settings(const Chart_parameterization_settings& settings)
{
  Sander_polish_settings ps;
  // Split Newton steps (u and v apart, an eighth of the flops to factor): from a map within
  // the bound as from one above it, in the steps allowed, they come within the bound about as
  // often as the coupled steps, in less time.
  ps.direction = Sander_polish_direction::SPLIT_NEWTON;
  ps.free_border = true;
  ps.threads = settings.threads;
  ps.supernodal_blas = false; // charts are flattened on several threads at once
  ps.max_iterations = settings.polish_iterations;
  return ps;
}

// Polishes the flip-free map `uv` of a chart (faces `flat`, then the `guard` faces, which keep
// their place without counting in the stretch) by free-border Newton steps, the border loop
// `border` kept simple, until polish_goes_on() ends them; false if the polisher refuses the
// start (a flipped or flat face, or a border that is not simple), `uv` then unchanged.
inline bool polish_free_border(const Flat_triangles& flat, const std::vector<Triangle>& guard,
                               const std::vector<int>& border, const Chart_parameterization_settings& settings,
                               std::vector<Vec2>& uv)
{
  const Sander_polish_settings ps = free_border_polish_settings(settings);
  double energy = HUGE_VAL;
  const Sander_polish_visitor enough = [&](const Sander_polish_step& step) {
    const double before = energy;
    energy = step.energy;
    return polish_goes_on(before, step.energy, step.l2_stretch, unsigned(step.iteration), settings);
  };
  Sander_energy_polisher<> polisher;
  return polisher.polish(flat, guard, std::vector<char>(uv.size(), 0), border, uv, ps, enough).status ==
         Sander_polish_status::OK;
}

// A conformal map of the chart (the boundary-first map, else LSCM's: see below) polished by
// free-border Newton steps, if the chart is a disk and that map is a bijection (every face of
// positive area, the border loop simple: then no two triangles overlap, and the polish keeps it
// so); false otherwise. The faces of `sm` are
// those of `flat`, then the `guard` faces (holes filled): they keep their place in the map
// without counting in its stretch. With `later`, a map within the bound that the polish takes
// is not polished: `later` receives what its polish needs.
inline bool flatten_from_conformal(Chart_mesh& sm, Chart_halfedge bhd, const Flat_triangles& flat,
                                   const std::vector<Triangle>& guard, const Chart_parameterization_settings& settings,
                                   std::vector<Vec2>& uv, Deferred_polish* later = nullptr)
{
  std::vector<Chart_halfedge> loops;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(sm, std::back_inserter(loops));
  const long euler = long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm));
  if(loops.size() != 1 || euler != 1)
    return false;
  // a disk and closed pieces can add up to a disk's characteristic: one piece only
  if(component_faces(sm, face(opposite(bhd, sm), sm)).size() != num_faces(sm))
    return false;
  std::vector<Triangle> all = flat.tri;
  all.insert(all.end(), guard.begin(), guard.end());
  std::vector<int> border;
  for(Chart_halfedge h : halfedges_around_face(bhd, sm))
    border.push_back(int(target(h, sm)));
  const std::vector<int> inside_left(border.rbegin(), border.rend()); // the triangles' way round
  // The boundary-first map is taken first: it is the cheaper to solve (one scalar system), and
  // the conformal map of least area distortion. Where it is no bijection, or far above the
  // bound, LSCM's map is taken as before: far above the bound, the boundary-first map is often
  // a bijection where LSCM's is not, and polishing it at length leaves it above the bound all
  // the same, where LSCM's refusal hands the chart to the stretch-minimizing start at once.
  for(const bool boundary_first : {true, false}) {
    if(!(boundary_first ? boundary_first_map(flat.xyz, all, inside_left, uv) : conformal_map(flat.xyz, all, uv)))
      continue;
    // a map that is a bijection but for a few folded triangles inside is mended where they are
    repair_interior_folds(sm, flat.xyz, all, uv);
    const double l2 = Flat_stretch().evaluate(flat, uv).l2;
    if(boundary_first && !(l2 <= settings.boundary_first_limit))
      continue;
    const Sander_polish_settings ps = free_border_polish_settings(settings);
    // within the bound, the polish ends at a gain below `polish_tolerance` (polish_goes_on()):
    // a map that cannot gain that much is taken as it is, once the polish would take it
    const bool within = l2 <= settings.max_stretch;
    const bool as_it_is = within && polish_takes_no_step(l2, (std::max)(ps.tolerance, settings.polish_tolerance));
    if(within && (as_it_is || later != nullptr)) {
      if(!Sander_energy_polisher<>().accepts(flat, guard, std::vector<char>(uv.size(), 0), border, uv, ps.free_border))
        continue; // the polish would refuse it too
      if(!as_it_is) {
        later->pending = true;
        later->guard = guard;
        later->border = border;
      }
      return true;
    }
    if(polish_free_border(flat, guard, border, settings, uv))
      return true;
  }
  return false;
}

// A border parameterizer (CGAL's concept) that puts the border vertices where `uv` says (indexed
// by vertex: vertex i of a Chart_mesh is vertex i of the chart).
class Given_border_parameterizer
{
public:
  typedef Chart_mesh Triangle_mesh;
  explicit Given_border_parameterizer(const std::vector<Vec2>* uv = nullptr) : m_uv(uv) {}

  template <typename VertexUVMap, typename VertexIndexMap, typename VertexParameterizedMap>
  Error_code parameterize(const Chart_mesh& mesh, Chart_halfedge bhd, VertexUVMap uvmap, VertexIndexMap,
                          VertexParameterizedMap vpmap)
  {
    if(m_uv == nullptr)
      return ERROR_WRONG_PARAMETER;
    for(Chart_halfedge h : halfedges_around_face(bhd, mesh)) {
      const Vec2& q = (*m_uv)[std::size_t(target(h, mesh))];
      put(uvmap, target(h, mesh), Chart_kernel::Point_2(q[0], q[1]));
      put(vpmap, target(h, mesh), true);
    }
    return OK;
  }

  bool is_border_convex() const { return true; }

private:
  const std::vector<Vec2>* m_uv;
};

// A chart whose conformal maps are no bijection, flattened from this package's U^0 (clamped
// cotangent weights, positive) inside the boundary-first border made convex, on which any
// positive weights give a bijection: the conformal border where it turns outwards, straight
// where it turns inwards (else, if that border cannot be closed, inside a circle); then the
// descent steps along the proxy with a free border, and the free-border polish of
// polish_free_border(), as after a conformal start. No reweighting step: they lower the
// stretch under a border that the next steps move anyway, a factorization each (measured on the
// meshes of the comparison with xatlas: benchmark/results/atlas_convex_start.md). False if it
// fails or flattens only part of the chart.
inline bool flatten_by_stretch_minimization(Chart_mesh& sm, Chart_halfedge bhd, const Flat_triangles& flat,
                                            const Chart_parameterization_settings& settings, std::vector<Vec2>& uv)
{
  auto uvmap = sm.add_property_map<Chart_vertex, Chart_kernel::Point_2>("v:uv").first;
  auto vimap = sm.add_property_map<Chart_vertex, int>("v:index").first;
  auto vpmap = sm.add_property_map<Chart_vertex, bool>("v:done", false).first;
  for(Chart_vertex v : vertices(sm))
    put(vimap, v, int(v));
  std::vector<int> border; // the border halfedges' targets, as the polish takes them
  for(Chart_halfedge h : halfedges_around_face(bhd, sm))
    border.push_back(int(target(h, sm)));
  const std::vector<int> inside_left(border.rbegin(), border.rend());

  // Eigen's LU: charts are small, and flattened on several threads at once, where
  // SuiteSparse's solvers (through a multithreaded BLAS) made results vary from run to run
  typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int> > > Solver;
  const auto start = [&](const auto& initializer) {
    typedef typename std::decay<decltype(initializer)>::type Initial;
    namespace P = parameters;
    Stretch_minimizing_parameterizer_3<Chart_mesh, Initial, Solver> p(initializer,
      P::preset(Stretch_minimizing_preset::LOWEST_STRETCH).number_of_iterations(0u)
        .descent_iterations(settings.descent_iterations).free_border(true).number_of_threads(1u));
    return p.parameterize(sm, bhd, uvmap, vimap, vpmap) == OK;
  };
  std::vector<Vec2> convex;
  bool ok = boundary_first_map(flat.xyz, flat.tri, inside_left, convex, true) &&
            start(Shape_preserving_parameterizer_3<Chart_mesh, Given_border_parameterizer, Solver>(
              Given_border_parameterizer(&convex)));
  // a strictly convex circle: three border vertices in a row (an ear of the chart's jagged
  // border) would make a flat triangle on a side of a square
  if(!ok)
    ok = start(Shape_preserving_parameterizer_3<Chart_mesh, Circular_border_arc_length_parameterizer_3<Chart_mesh>, Solver>());
  // only the piece of `bhd` is flattened: a chart of pieces that touch at a repeated
  // position only (not at a chart vertex) is split like a failed one
  for(Chart_vertex v : vertices(sm))
    ok = ok && get(vpmap, v);
  if(ok) {
    uv = read_uv(sm, uvmap);
    polish_free_border(flat, std::vector<Triangle>(), border, settings, uv); // uv unchanged if refused
  }
  sm.remove_property_map(uvmap);
  sm.remove_property_map(vimap);
  sm.remove_property_map(vpmap);
  return ok;
}

// Measures `chart.uv` (turned to the input's orientation): `chart.ok` if it is finite, with no
// flipped face nor face of zero uv area; `chart.l2` its normalized L2 stretch.
inline void measure_chart(Chart_map& chart)
{
  chart.ok = false;
  chart.l2 = HUGE_VAL;
  Flat_stretch measure;
  Flat_stretch_summary s = measure.evaluate(chart.flat, chart.uv);
  // the chart's orientation is that of the faces measured: a face without area in 3D can
  // have any uv, and a large one would turn the whole chart against the others
  double signed_area = 0.;
  for(std::size_t f = 0; f < chart.flat.tri.size(); ++f)
    if(measure.used(f))
      signed_area += measure.faces()[f].area_uv;
  if(signed_area < 0.) {
    for(Vec2& q : chart.uv)
      q[0] = -q[0];
    s = measure.evaluate(chart.flat, chart.uv);
  }
  if(s.flipped > 0 || s.degenerate_uv > 0)
    return;
  chart.l2 = s.degenerate_3d == chart.flat.tri.size() ? 1. : s.l2;
  chart.ok = std::isfinite(chart.l2);
  for(const Vec2& q : chart.uv) // a chart is packed only with finite uv
    chart.ok = chart.ok && std::isfinite(q[0]) && std::isfinite(q[1]);
}

// The polish left for later on `chart` (see Deferred_polish), if any, and the chart measured
// again. Should the polish fail (its solver), the chart keeps its conformal map, within the
// bound.
inline void finish_polish(Chart_map& chart, const Chart_parameterization_settings& settings)
{
  if(!chart.deferred.pending)
    return;
  const Deferred_polish d = std::move(chart.deferred);
  chart.deferred = Deferred_polish();
  if(d.merged.empty()) {
    polish_free_border(chart.flat, d.guard, d.border, settings, chart.uv);
  } else {
    std::vector<Vec2> uv(d.closed.xyz.size());
    for(std::size_t v = 0; v < d.merged.size(); ++v)
      uv[std::size_t(d.merged[v])] = chart.uv[v];
    if(polish_free_border(d.closed, d.guard, d.border, settings, uv))
      for(std::size_t v = 0; v < d.merged.size(); ++v)
        chart.uv[v] = uv[std::size_t(d.merged[v])];
  }
  measure_chart(chart);
}

// Builds `sm` from `flat`; false if a face cannot be added (the triangles do not make a
// manifold surface).
inline bool make_chart_mesh(const Flat_triangles& flat, Chart_mesh& sm)
{
  std::vector<Chart_vertex> vd;
  vd.reserve(flat.xyz.size());
  for(const Vec3& p : flat.xyz)
    vd.push_back(sm.add_vertex(Chart_kernel::Point_3(p[0], p[1], p[2])));
  for(const Triangle& t : flat.tri)
    if(sm.add_face(vd[std::size_t(t[0])], vd[std::size_t(t[1])], vd[std::size_t(t[2])]) == Chart_mesh::null_face())
      return false;
  return true;
}

// `sm`, the faces of `flat` in their order, flattened from a conformal map of it with every hole but
// the longest border filled (a planar loop's constrained Delaunay triangles, else CGAL's
// exhaustive search, else ear clipping: see triangulate_loop.h), the fillers kept as guards
// through the polish (the holes stay open and nothing enters them): `uv` per vertex of `flat`.
// False if `sm` is not a surface of genus 0 with holes (`holes` false, `sm` unchanged), or a
// hole cannot be filled, or neither conformal map is a bijection.
inline bool flatten_holed(const Flat_triangles& flat, Chart_mesh& sm, const Chart_parameterization_settings& settings,
                          std::vector<Vec2>& uv, bool& holes, Deferred_polish* later = nullptr)
{
  holes = false;
  std::vector<Chart_halfedge> loops;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(sm, std::back_inserter(loops));
  const long euler = long(num_vertices(sm)) - long(num_edges(sm)) + long(num_faces(sm));
  if(loops.size() < 2 || euler != 2 - long(loops.size()))
    return false;
  holes = true;
  const Chart_halfedge bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  std::vector<Triangle> guard;
  for(Chart_halfedge h : loops) {
    std::vector<Chart_vertex> loop;
    bool outer = false;
    for(Chart_halfedge b : halfedges_around_face(h, sm)) {
      outer = outer || b == bhd;
      loop.push_back(target(b, sm));
    }
    if(outer)
      continue;
    // a planar loop's constrained Delaunay triangles, else CGAL's exhaustive search on the mesh,
    // else ears; none of whose new sides is an edge of the chart already (nor joins a vertex to
    // itself, where the loop passes twice)
    std::vector<Vec3> points;
    for(Chart_vertex v : loop)
      points.push_back(flat.xyz[std::size_t(v)]);
    const auto allowed = [&](int a, int b) {
      const Chart_vertex va = loop[std::size_t(a)], vb = loop[std::size_t(b)];
      return va != vb && !halfedge(va, vb, sm).second;
    };
    std::vector<Loop_triangle> fill;
    if(!triangulate_planar_loop(points, fill) || !new_sides_allowed(fill, points.size(), allowed)) {
      fill.clear();
      if(loop.size() <= exhaustive_loop_size) {
        std::vector<boost::graph_traits<Chart_mesh>::face_descriptor> filler;
        fill_hole_exhaustively(sm, h, std::back_inserter(filler));
        for(auto f : filler) {
          Triangle t;
          int k = 0;
          for(Chart_vertex v : vertices_around_face(halfedge(f, sm), sm))
            t[std::size_t(k++)] = int(v);
          guard.push_back(t);
        }
        if(!filler.empty())
          continue;
      }
      if(!clip_ears(points, allowed, fill))
        return false;
    }
    for(const Loop_triangle& t : fill) {
      const Chart_vertex a = loop[std::size_t(t[0])], b = loop[std::size_t(t[1])], c = loop[std::size_t(t[2])];
      if(sm.add_face(a, b, c) == Chart_mesh::null_face())
        return false;
      guard.push_back({int(a), int(b), int(c)});
    }
  }
  return flatten_from_conformal(sm, bhd, flat, guard, settings, uv, later);
}

// The chart with its slits closed, so that it has holes instead, flattened by flatten_holed(),
// so that a chart grown around a hole needs no seam to it. False if the chart has no slit, or
// the closed chart is not a surface of genus 0 with holes, or no conformal map of it is a bijection;
// `holes` tells whether it is one (a slit closed without a hole is the cut of a cone, which the
// other starts open). With `later`, as flatten_holed() (the closed chart goes with the polish left).
inline bool flatten_with_holes(Chart_map& chart, const Chart_parameterization_settings& settings, bool& holes,
                               Deferred_polish* later = nullptr)
{
  holes = false;
  if(chart.slits.empty())
    return false;
  // the chart vertices on the two sides of a slit made one
  std::unordered_map<int, std::size_t> local; // input triangle -> chart triangle
  for(std::size_t i = 0; i < chart.triangles.size(); ++i)
    local.emplace(int(chart.triangles[i]), i);
  auto vertex = [&](int corner) {
    return chart.corner_vertex[3 * local.at(corner / 3) + std::size_t(corner % 3)];
  };
  auto next = [](int corner) { return 3 * (corner / 3) + (corner % 3 + 1) % 3; };
  const std::size_t nv = chart.flat.xyz.size();
  std::vector<int> parent(nv);
  for(std::size_t v = 0; v < nv; ++v) parent[v] = int(v);
  auto find = [&parent](int v) {
    while(parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
  };
  for(const auto& slit : chart.slits) { // side a goes from corner a to next(a), its mate b the other way
    parent[std::size_t(find(vertex(slit.first)))] = find(vertex(next(slit.second)));
    parent[std::size_t(find(vertex(next(slit.first))))] = find(vertex(slit.second));
  }
  std::vector<int> merged(nv, -1);
  Flat_triangles closed;
  for(std::size_t v = 0; v < nv; ++v) {
    const std::size_t r = std::size_t(find(int(v)));
    if(merged[r] < 0) {
      merged[r] = int(closed.xyz.size());
      closed.xyz.push_back(chart.flat.xyz[r]);
    }
    merged[v] = merged[r];
  }
  for(const Triangle& t : chart.flat.tri) {
    closed.tri.push_back({merged[std::size_t(t[0])], merged[std::size_t(t[1])], merged[std::size_t(t[2])]});
    const Triangle& c = closed.tri.back();
    if(c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) // a triangle closed onto itself
      return false;
  }
  Chart_mesh sm;
  std::vector<Vec2> uv;
  if(!make_chart_mesh(closed, sm) || !flatten_holed(closed, sm, settings, uv, holes, later))
    return false;
  chart.uv.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
    chart.uv[v] = uv[std::size_t(merged[v])];
  const bool deferred = later != nullptr && later->pending;
  if(deferred) {
    later->closed = std::move(closed);
    later->merged = std::move(merged);
  }
  measure_chart(chart);
  if(deferred && !(chart.ok && chart.l2 <= settings.max_stretch))
    finish_polish(chart, settings); // not taken as it is: polished now, as without `later`
  chart.slits_closed = chart.ok;
  return chart.ok;
}

// Flattens the chart, whose vertices are made (`make_chart_vertices()`): the first map that
// ends at most `max_stretch` of, in turn, the chart with its slits closed, a conformal map of a chart
// without slits, and, if `minimize`, this package's; else the lowest of them. Without
// `minimize` (the cheap starts only), a chart with holes of its own and no slit (a union of
// charts) starts from flatten_holed(), as it has no other. On failure `chart.ok` is false and
// the caller splits the chart. Charts can be flattened on several threads at once.
inline void flatten_chart(Chart_map& chart, const Chart_parameterization_settings& settings, bool minimize = true)
{
  chart.ok = false;
  chart.slits_closed = false;
  chart.deferred = Deferred_polish();
  Deferred_polish* later = settings.defer_polish ? &chart.deferred : nullptr;
  if(chart.triangles.size() == 1) {
    layout_single_triangle(chart);
    measure_chart(chart);
    return;
  }
  // a map within the bound is taken at once; of maps above it, the lowest is kept
  std::vector<Vec2> best_uv;
  double best_l2 = HUGE_VAL;
  bool best_closed = false;
  auto keep = [&]() {
    if(!chart.ok || !(chart.l2 < best_l2)) return;
    best_uv = chart.uv;
    best_l2 = chart.l2;
    best_closed = chart.slits_closed;
  };
  auto take_best = [&]() {
    chart.ok = std::isfinite(best_l2);
    chart.l2 = best_l2;
    if(!chart.ok) return;
    chart.uv.swap(best_uv);
    chart.slits_closed = best_closed;
  };
  bool holes = false;
  if(flatten_with_holes(chart, settings, holes, later)) {
    if(chart.l2 <= settings.max_stretch)
      return;
    keep();
  }
  chart.ok = false;
  chart.slits_closed = false;
  Chart_mesh sm;
  const bool mesh = make_chart_mesh(chart.flat, sm);
  const Chart_halfedge bhd = mesh ? CGAL::Polygon_mesh_processing::longest_border(sm).first
                                  : boost::graph_traits<Chart_mesh>::null_halfedge();
  if(bhd == boost::graph_traits<Chart_mesh>::null_halfedge()) {
    take_best();
    return;
  }
  if(!minimize && chart.slits.empty() && flatten_holed(chart.flat, sm, settings, chart.uv, holes, later)) {
    measure_chart(chart);
    if(!(chart.ok && chart.l2 <= settings.max_stretch))
      finish_polish(chart, settings); // not taken as it is: polished now, as without `later`
    if(chart.ok && chart.l2 <= settings.max_stretch)
      return;
    keep();
  }
  // LSCM maps the two sides of a slit to a hole about onto each other, so its map of such a
  // chart is no bijection: that chart has had its LSCM start, with the slits closed
  if(!holes &&
     flatten_from_conformal(sm, bhd, chart.flat, std::vector<Triangle>(), settings, chart.uv, later)) {
    measure_chart(chart);
    if(!(chart.ok && chart.l2 <= settings.max_stretch))
      finish_polish(chart, settings);
    if(chart.ok && chart.l2 <= settings.max_stretch)
      return;
    keep();
  }
  chart.ok = false;
  if(minimize && flatten_by_stretch_minimization(sm, bhd, chart.flat, settings, chart.uv)) {
    measure_chart(chart);
    keep();
  }
  take_best();
}

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_PARAMETERIZATION_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_REMESHING_PIPELINE_H
#define CGAL_SMP_INTERNAL_REMESH_REMESHING_PIPELINE_H

// The stages of remesh_with_parameterizations() on a disk (with holes) copied into flat
// arrays: the two parameterizations, the samples, the triangulation, the lift to 3D.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/Remeshing_report.h>
#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Border_row.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Border_sampling.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Density_sampling.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Domain_locator.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Domain_relaxation.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Sampling_density.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Domain_triangulation.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Surface_delaunay_flips.h>
#include <CGAL/Surface_mesh_parameterization/internal/wall_clock.h>

#include <CGAL/Surface_mesh_parameterization/internal/aabb_tree_compatibility.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The input, copied, and its two parameterizations.
struct Remeshing_input
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;

  Mesh mesh;                          // vertices and faces numbered from 0, without gaps
  Flat_triangles flat;                // the same, as arrays
  std::vector<std::vector<int> > loops; // border loops, vertices by index
  std::vector<Vec2> triangulation_uv, sampling_uv;
  std::vector<double> density;        // the relative sampling density per vertex (Sampling_density.h)
};

// The settings of remesh_with_parameterizations() that the stages read.
struct Remeshing_settings
{
  std::size_t vertices = 0;
  Remeshing_pair pair = Remeshing_pair::U0_UOPT;
  int relaxation_steps = 3;
  std::chrono::steady_clock::time_point start;
};

// Angles, in degrees, and area spread of the triangles `tri` of `xyz` into `r`.
inline void measure_triangles(const std::vector<Vec3>& xyz, const std::vector<Triangle>& tri, Remeshing_report& r)
{
  r.angle_histogram.fill(0);
  r.min_angle = tri.empty() ? 0. : 180.;
  std::size_t wide = 0;
  double sum = 0., sum2 = 0.;
  for(const Triangle& t : tri) {
    for(int k = 0; k < 3; ++k) {
      const Vec3 &p = xyz[std::size_t(t[k])], &q = xyz[std::size_t(t[(k + 1) % 3])], &s = xyz[std::size_t(t[(k + 2) % 3])];
      const double a = angle3(sub3(q, p), sub3(s, p)) * 180. / CGAL_PI;
      r.min_angle = (std::min)(r.min_angle, a);
      ++r.angle_histogram[std::size_t((std::min)(17., (std::max)(0., std::floor(a / 10.))))];
      wide += a >= 30. ? 1 : 0;
    }
    const double area = triangle_area(xyz[std::size_t(t[0])], xyz[std::size_t(t[1])], xyz[std::size_t(t[2])]);
    sum += area;
    sum2 += area * area;
  }
  if(!tri.empty()) {
    const double n = double(tri.size()), mean = sum / n;
    r.angles_at_least_30 = double(wide) / (3. * n);
    r.area_variation = mean > 0. ? std::sqrt((std::max)(0., sum2 / n - mean * mean)) / mean : 0.;
  }
}

CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// U' and U'' of `in.mesh` into `in` (U' = U^0; U'' as `pair` asks); `np` holds the
// parameterizer's named parameters.
template <typename NamedParameters>
bool parameterize_for_remeshing(Remeshing_input& in, Remeshing_pair pair, const NamedParameters& np,
                                Remeshing_report& r)
{
  typedef Remeshing_input::Mesh Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef Circular_border_arc_length_parameterizer_3<Mesh> Border;
  typedef Shape_preserving_parameterizer_3<Mesh, Border> Initial;
  Mesh& mesh = in.mesh;
  const auto bhd = Polygon_mesh_processing::longest_border(mesh).first;
  if(bhd == boost::graph_traits<Mesh>::null_halfedge()) {
    r.status = ERROR_NO_TOPOLOGICAL_DISC;
    r.message = "the mesh has no border: remeshing takes a disk (with holes); cut a closed mesh open first";
    return false;
  }
  auto uvmap = mesh.add_property_map<vertex_descriptor, Remeshing_input::K::Point_2>("v:smp_remesh_uv").first;
  auto vimap = mesh.add_property_map<vertex_descriptor, int>("v:smp_remesh_index").first;
  auto vpmap = mesh.add_property_map<vertex_descriptor, bool>("v:smp_remesh_done", false).first;
  for(vertex_descriptor v : vertices(mesh))
    put(vimap, v, int(v));
  Stretch_minimizing_parameterizer_3<Mesh, Initial> p(np);
  const auto run = [&](std::size_t steps, std::vector<Vec2>& uv, double& l2) {
    const Error_code e = steps == 0 ? p.parameterize(mesh, bhd, uvmap, vimap, vpmap, parameters::number_of_iterations(0))
                       : steps == 1 ? p.parameterize(mesh, bhd, uvmap, vimap, vpmap, parameters::number_of_iterations(1))
                                    : p.parameterize(mesh, bhd, uvmap, vimap, vpmap);
    if(e != OK) {
      r.status = e;
      r.message = "the parameterization failed: " + p.report().message;
      return false;
    }
    uv.resize(num_vertices(mesh));
    for(vertex_descriptor v : vertices(mesh))
      uv[std::size_t(v)] = {get(uvmap, v).x(), get(uvmap, v).y()};
    l2 = p.report().l2_stretch();
    return true;
  };
  if(!run(0, in.triangulation_uv, r.triangulation_l2_stretch))
    return false;
  if(pair == Remeshing_pair::U0) {
    in.sampling_uv = in.triangulation_uv;
    r.sampling_l2_stretch = r.triangulation_l2_stretch;
    return true;
  }
  return run(pair == Remeshing_pair::U0_U1 ? 1 : 2, in.sampling_uv, r.sampling_l2_stretch);
}

CGAL_SMP_END_SOLVER_NAMESPACE

// The border loops of `mesh` (vertex indices, in the order of the border halfedges).
inline std::vector<std::vector<int> > border_loops(const Remeshing_input::Mesh& mesh)
{
  std::vector<std::vector<int> > loops;
  std::vector<char> seen(num_halfedges(mesh), 0);
  for(auto h : halfedges(mesh)) {
    if(!is_border(h, mesh) || seen[std::size_t(h)])
      continue;
    loops.emplace_back();
    for(auto g = h; !seen[std::size_t(g)]; g = next(g, mesh)) {
      seen[std::size_t(g)] = 1;
      loops.back().push_back(int(source(g, mesh)));
    }
  }
  return loops;
}

// The edge length of equilateral triangles that cover `area` with `vertices` vertices, of
// which the ones on the border (of length `border`) are `border / length` (Euler's formula for
// a disk: faces = 2 vertices - border vertices - 2).
inline double target_edge_length(double area, double border, std::size_t vertices)
{
  const double a = 4. * area / std::sqrt(3.), c = 2. * double(vertices) - 2.;
  const double x = (-border + std::sqrt(border * border + 4. * a * c)) / (2. * a); // 1 / length
  return 1. / x;
}

// The new mesh as a soup (`xyz`, `tri`, oriented as the input) with `r` filled; false with `r`
// telling why.
inline bool remesh_flat(const Remeshing_input& in, const Remeshing_settings& settings, std::vector<Vec3>& xyz,
                        std::vector<Triangle>& tri, Remeshing_report& r)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  const auto t0 = std::chrono::steady_clock::now();
  const Flat_triangles& m = in.flat;
  double area = 0., border = 0.;
  for(const Triangle& t : m.tri)
    area += triangle_area(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])]);
  // (where the density is not 1, the border's length in units of the local spacing, whose
  // square goes as 1 / density)
  std::vector<double> scale;
  for(const double d : in.density)
    scale.push_back(std::sqrt(d));
  for(const std::vector<int>& loop : in.loops)
    for(std::size_t k = 0; k < loop.size(); ++k)
      border += scaled_length(loop[k], loop[(k + 1) % loop.size()], m.xyz, scale);
  if(!(area > 0.) || !std::isfinite(area) || !(border > 0.)) {
    r.status = ERROR_WRONG_PARAMETER;
    r.message = "the mesh has no area to sample";
    return false;
  }
  const double spacing = target_edge_length(area, border, settings.vertices);

  // the border: evenly spaced samples on each loop
  std::vector<Edge_location> on_border;
  std::vector<std::vector<int> > loops;
  bool cut = false; // a cut that opened a closed surface: its two sides have the same points
  for(const std::vector<Edge_location>& samples : sample_loops(in.loops, m.xyz, scale, spacing, cut)) {
    loops.emplace_back();
    for(const Edge_location& e : samples) {
      loops.back().push_back(int(on_border.size()));
      on_border.push_back(e);
    }
  }
  r.border_loops = loops.size();
  if(on_border.size() + 3 > settings.vertices) {
    r.status = ERROR_WRONG_PARAMETER;
    r.message = "too few vertices asked for: the border loops alone take " + std::to_string(on_border.size());
    return false;
  }

  // the interior: error diffusion of the area density of U''
  typedef std::vector<K::Segment_3>::const_iterator Segment_iterator;
  typedef Aabb_tree<K, Aabb_segment_primitive<K, Segment_iterator> > Tree;
  std::vector<K::Segment_3> chords;
  for(const std::vector<int>& loop : loops)
    for(std::size_t k = 0; k < loop.size(); ++k) {
      const Vec3 a = on_border[std::size_t(loop[k])].in(m.xyz), b = on_border[std::size_t(loop[(k + 1) % loop.size()])].in(m.xyz);
      chords.emplace_back(K::Point_3(a[0], a[1], a[2]), K::Point_3(b[0], b[1], b[2]));
    }
  Tree tree(chords.begin(), chords.end());
  tree.accelerate_distance_queries();
  // the spacing where a sample is: spacing / sqrt(density)
  const auto local_spacing = [&](const Surface_location& s) { return spacing / std::sqrt(density_at(in.density, m.tri, s)); };
  const std::size_t wanted = settings.vertices - on_border.size();
  const std::size_t cells = raster_cells(m, in.sampling_uv, settings.vertices, in.density);
  const Density_raster raster = rasterize_density(m, in.sampling_uv, cells, in.density);
  if(!(raster.total_area > 0.)) {
    r.status = ERROR_WRONG_PARAMETER;
    r.message = "the sampling parameterization covers no area";
    return false;
  }
  double orientation = 0.;
  for(const Triangle& t : m.tri)
    orientation += twice_signed_area(in.triangulation_uv[std::size_t(t[0])], in.triangulation_uv[std::size_t(t[1])],
                                     in.triangulation_uv[std::size_t(t[2])]);
  const Domain_locator locator(m.tri, in.triangulation_uv);
  // the first row inside the borders (apexes closer than half the spacing merged), unless it
  // would take more than half the interior vertices (a strip narrower than two rows)
  std::vector<K::Point_3> row_xyz;
  std::vector<Surface_location> row =
      border_row(m, in.triangulation_uv, locator, on_border, loops, orientation < 0. ? -1. : 1.,
                 [&](const Surface_location& s) { return 0.5 * local_spacing(s); },
                 [&](const Surface_location& s, const K::Point_3& p) {
                   return tree.squared_distance(p) >= CGAL::square(0.5 * local_spacing(s));
                 },
                 row_xyz);
  if(2 * row.size() > wanted) {
    row.clear();
    row_xyz.clear();
  }
  const Nearby_points near_row(std::move(row_xyz));
  // The count asked for is met once the samples the triangulation leaves out are known: the
  // ones too close to the border in 3D (closer than half the spacing, where they would make
  // thin triangles with it) or to the border row (closer than 0.6 times the spacing, where
  // equilateral triangles put the next row at 0.87), and the ones beyond the border chords in
  // U' (the spacing: the local one, where a density is given). Where
  // the lifted mesh intersects itself, or where U' is so compressed that the order of the
  // samples in it is lost to rounding, the samples of those triangles are taken out, and no
  // sample is taken again from the input triangles they were in. A triangle turned over on the
  // surface where U' has room spans a fold narrower than the spacing (a mouth, a crease, a
  // horn's tip): an edge flip mends it where it can, else a sample is added at its centroid in
  // U', so that the triangles follow the fold (taking samples out widened the triangles that
  // span it, until the fold was bridged over).
  const std::size_t b = on_border.size();
  std::vector<Surface_location> inside;
  std::vector<char> excluded(m.tri.size(), 0);
  std::vector<Vec2> points, uv;
  Lifted_mesh mesh;
  // (the row stands for the samples it leaves out: the density is the one without it)
  double per_area = double(wanted) / raster.total_area;
  r.seconds_sampling = seconds_since(t0);
  // the round whose count is nearest the one asked for, among those the repair left without a
  // wrong face if any, else without a crossing: where U' is so compressed that samples fall
  // together there (and the triangulation keeps one), the count can jump from one density to
  // the next, and the rounds go back and forth
  Lifted_mesh best_mesh;
  std::vector<Vec2> best_uv;
  std::size_t best_wrong = 0;
  double best_miss = HUGE_VAL;
  int best_class = -1; // 2 without a wrong face, 1 without a crossing, 0 with one
  std::pair<double, double> fewer(0., 0.), more(0., 0.); // (density, vertices) of a round below, above the count
  for(int round = 0; round < 16; ++round) {
    const auto t1 = std::chrono::steady_clock::now();
    const std::ptrdiff_t excluded_before = std::count(excluded.begin(), excluded.end(), char(1));
    inside.clear();
    for(const Surface_location& s : row)
      if(!excluded[std::size_t(s.face)])
        inside.push_back(s);
    for(const Surface_location& s : diffuse_samples(raster, m.tri, in.sampling_uv, per_area)) {
      const Vec3 p = locate_in(s, m.tri, m.xyz);
      const K::Point_3 q(p[0], p[1], p[2]);
      const double local = local_spacing(s);
      if(!excluded[std::size_t(s.face)] && tree.squared_distance(q) >= CGAL::square(0.5 * local) &&
         !near_row.any_within(q, 0.6 * local))
        inside.push_back(s);
    }
    r.seconds_sampling += seconds_since(t1);
    const auto t2 = std::chrono::steady_clock::now();
    // the repair's best state: the fewest faces crossing another, then the fewest wrong ones
    // (samples added into a fold narrower than the spacing can make faces that cross)
    Lifted_mesh repaired;
    std::vector<Vec2> repaired_uv;
    std::pair<std::size_t, std::size_t> repaired_wrong(std::size_t(-1), std::size_t(-1));
    for(int repair = 0;; ++repair) {
      points.clear();
      for(const Edge_location& e : on_border)
        points.push_back(e.in(in.triangulation_uv));
      for(const Surface_location& s : inside)
        points.push_back(locate_in(s, m.tri, in.triangulation_uv));
      for(const Vec2& p : points)
        if(!std::isfinite(p[0]) || !std::isfinite(p[1])) {
          r.status = ERROR_NO_1_TO_1_MAPPING;
          r.message = "a point of the triangulation domain is not finite";
          return false;
        }
      std::vector<Triangle> triangles;
      if(!triangulate_domain(points, loops, triangles, r.message)) {
        r.status = ERROR_NO_1_TO_1_MAPPING;
        return false;
      }
      // the points in a triangle, numbered anew, lifted, in the input's orientation
      std::vector<int> index(points.size(), -1);
      std::vector<std::size_t> point_of;
      std::vector<K::Point_3> lifted;
      std::vector<double> lifted_density; // (none where the density is 1)
      uv.clear();
      for(Triangle& t : triangles) {
        if(orientation < 0.)
          std::swap(t[1], t[2]);
        for(int& v : t) {
          const std::size_t i = std::size_t(v);
          if(index[i] < 0) {
            index[i] = int(lifted.size());
            const Vec3 p = i < b ? on_border[i].in(m.xyz) : locate_in(inside[i - b], m.tri, m.xyz);
            lifted.emplace_back(p[0], p[1], p[2]);
            if(!in.density.empty())
              lifted_density.push_back(i < b ? on_border[i].in(in.density) : density_at(in.density, m.tri, inside[i - b]));
            uv.push_back(points[i]);
            point_of.push_back(i);
          }
          v = index[i];
        }
      }
      if(!Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(triangles)) {
        r.status = ERROR_NO_1_TO_1_MAPPING;
        r.message = "the triangulation is not a manifold mesh (border loops too close to each other in the parameter domain)";
        return false;
      }
      mesh.clear();
      Polygon_mesh_processing::polygon_soup_to_polygon_mesh(lifted, triangles, mesh);
      flip_to_surface_delaunay(mesh, uv, 16);
      relax_in_domain(mesh, uv, lifted_density, settings.relaxation_steps, orientation < 0. ? -1. : 1.,
                      [&](Lifted_mesh::Vertex_index v, const Vec2& q) {
                        const std::size_t i = point_of[std::size_t(v)];
                        Surface_location s;
                        if(i < b || !locator.locate_inside(q, s))
                          return false; // a border vertex, or outside the domain (in a hole, by a chord)
                        inside[i - b] = s;
                        points[i] = q;
                        const Vec3 p = locate_in(s, m.tri, m.xyz);
                        mesh.point(v) = K::Point_3(p[0], p[1], p[2]);
                        if(!lifted_density.empty())
                          lifted_density[std::size_t(v)] = density_at(in.density, m.tri, s);
                        return true;
                      });
      // the input surface's normal where each vertex is (0 on the border)
      std::vector<Vec3> normal(mesh.number_of_vertices(), Vec3{{0., 0., 0.}});
      for(const auto v : mesh.vertices()) {
        const std::size_t i = point_of[std::size_t(v)];
        if(i >= b) {
          const Triangle& t = m.tri[std::size_t(inside[i - b].face)];
          const Vec3& p = m.xyz[std::size_t(t[0])];
          const Vec3 n = cross3(sub3(m.xyz[std::size_t(t[1])], p), sub3(m.xyz[std::size_t(t[2])], p));
          const double length = norm3(n);
          if(length > 0.)
            normal[std::size_t(v)] = {{n[0] / length, n[1] / length, n[2] / length}};
        }
      }
      flip_turned_triangles(mesh, uv, normal);
      // the faces that cross another, and the ones turned against the input faces their
      // corners are in
      std::vector<Lifted_mesh::Face_index> wrong, turned;
      {
        std::vector<std::pair<Lifted_mesh::Face_index, Lifted_mesh::Face_index> > crossing;
        // the two sides of a cut touch: they are closed first (faces keep their indices), and
        // faces that meet at a corner of the cut where the stitching leaves it open (two
        // vertices at one point) are not taken as crossing; faces that share a vertex once
        // closed are, if they cross beyond it
        Lifted_mesh closed;
        const auto touch_at_cut = [&](Lifted_mesh::Face_index f, Lifted_mesh::Face_index g) {
          for(const auto v : vertices_around_face(closed.halfedge(f), closed))
            for(const auto w : vertices_around_face(closed.halfedge(g), closed))
              if(v != w && closed.is_border(v) && closed.is_border(w) && closed.point(v) == closed.point(w))
                return true;
          return false;
        };
        if(cut) {
          closed = mesh;
          Polygon_mesh_processing::stitch_borders(closed);
          Polygon_mesh_processing::self_intersections(closed, std::back_inserter(crossing));
        } else {
          Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(crossing));
        }
        for(const auto& pair : crossing)
          if(!cut || !touch_at_cut(pair.first, pair.second)) {
            wrong.push_back(pair.first);
            wrong.push_back(pair.second);
          }
      }
      for(const auto f : mesh.faces()) {
        const auto h = mesh.halfedge(f);
        if(turned_against(mesh, normal, mesh.source(h), mesh.target(h), mesh.target(mesh.next(h))))
          turned.push_back(f);
      }
      std::sort(wrong.begin(), wrong.end());
      wrong.erase(std::unique(wrong.begin(), wrong.end()), wrong.end());
      const std::size_t crossing_faces = wrong.size();
      for(const auto f : turned)
        if(!std::binary_search(wrong.begin(), wrong.begin() + std::ptrdiff_t(crossing_faces), f))
          wrong.push_back(f);
      if(std::make_pair(crossing_faces, wrong.size()) < repaired_wrong) {
        repaired_wrong = {crossing_faces, wrong.size()};
        repaired = mesh;
        repaired_uv = uv;
      }
      if(wrong.empty() || repair == 16)
        break;
      // (a triangle with less than a billionth of the mean area in U' is squeezed by rounding,
      // not by the surface's shape)
      double domain_area = 0.;
      for(const auto f : mesh.faces())
        domain_area += std::abs(twice_domain_area(mesh, uv, f));
      const double least_area = 1e-9 * domain_area / double(mesh.number_of_faces());
      std::vector<char> out(inside.size(), 0);
      std::vector<Surface_location> added;
      bool any = false;
      for(std::size_t k = 0; k < wrong.size(); ++k) {
        const auto f = wrong[k];
        if(k >= crossing_faces && std::abs(twice_domain_area(mesh, uv, f)) > least_area) {
          Vec2 centroid = {{0., 0.}};
          for(const auto v : vertices_around_face(mesh.halfedge(f), mesh))
            for(int i = 0; i < 2; ++i)
              centroid[i] += uv[std::size_t(v)][i] / 3.;
          Surface_location s;
          if(locator.locate_inside(centroid, s)) {
            added.push_back(s);
            any = true;
            continue;
          }
        }
        for(const auto v : vertices_around_face(mesh.halfedge(f), mesh)) {
          const std::size_t i = point_of[std::size_t(v)];
          if(i >= b) {
            out[i - b] = 1;
            excluded[std::size_t(inside[i - b].face)] = 1;
            any = true;
          }
        }
      }
      if(!any)
        break;
      std::size_t kept = 0;
      for(std::size_t i = 0; i < inside.size(); ++i)
        if(!out[i])
          inside[kept++] = inside[i];
      inside.resize(kept);
      inside.insert(inside.end(), added.begin(), added.end());
    }
    mesh = std::move(repaired);
    uv.swap(repaired_uv);
    r.seconds_triangulation += seconds_since(t2);
    const std::size_t used = mesh.number_of_vertices();
    const double miss = std::abs(double(used) - double(settings.vertices));
    const bool whole = repaired_wrong.second == 0;
    const int kind = whole ? 2 : repaired_wrong.first == 0 ? 1 : 0;
    if(kind > best_class || (kind == best_class && miss < best_miss)) {
      best_miss = miss;
      best_class = kind;
      best_mesh = mesh;
      best_uv = uv;
      best_wrong = repaired_wrong.second;
    }
    // (past 8 rounds, only while the rounds leave no wrong face: where each leaves some, a round
    // costs the repair's many triangulations, and more of them rarely find a round without)
    if((whole && miss <= 0.002 * double(settings.vertices)) || used <= b || (round >= 7 && best_class < 2))
      break;
    // the next density: between the last ones that gave too few and too many vertices once
    // both are known (the count is not proportional to the density where the samples left out
    // near the borders are many: a small count, a narrow strip), else scaled by the count's
    // ratio, by at most 4
    (used < settings.vertices ? fewer : more) = {per_area, double(used)};
    const double last = per_area;
    if(fewer.first > 0. && more.first > 0.)
      per_area = fewer.first + (more.first - fewer.first) * (double(settings.vertices) - fewer.second) /
                                   (more.second - fewer.second);
    else
      per_area *= (std::min)(4., (std::max)(0.25, double(wanted) / double(used - b)));
    // (the same density from the same input triangles would give this round again)
    if(per_area == last && std::count(excluded.begin(), excluded.end(), char(1)) == excluded_before)
      break;
  }
  mesh = std::move(best_mesh);
  uv.swap(best_uv);
  r.wrong_faces = best_wrong;
  xyz.clear();
  for(const auto v : mesh.vertices())
    xyz.push_back({{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}});
  for(std::size_t v = 0; v < uv.size(); ++v)
    r.border_vertices += mesh.is_border(Lifted_mesh::Vertex_index(Lifted_mesh::size_type(v))) ? 1 : 0;
  tri.clear();
  for(const auto f : mesh.faces()) {
    const auto h = mesh.halfedge(f);
    tri.push_back({{int(mesh.source(h)), int(mesh.target(h)), int(mesh.target(mesh.next(h)))}});
  }
  if(tri.empty()) {
    r.status = ERROR_WRONG_PARAMETER;
    r.message = "the new mesh has no triangle (the mesh is too degenerate to sample)";
    return false;
  }
  r.vertices = xyz.size();
  r.faces = tri.size();
  measure_triangles(xyz, tri, r);
  return true;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_REMESHING_PIPELINE_H

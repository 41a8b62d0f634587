// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// remesh_with_parameterizations(): the new mesh is a valid oriented triangle mesh on the input
// surface with the input's border loops, about the number of vertices asked for, on analytic
// cases (a planar disk, a cylinder patch: their triangles along the border as even as the
// others; a tube cut open: the two sides of the cut get the same vertices) and the bundled
// meshes; the relaxation evens the surface areas where the domain is squeezed, and the raster's
// resolution follows the squeeze of U''; {U^0, U^opt} samples more evenly than {U^0}; bad input
// gets an error and leaves the output alone.

#include "smp_test_util.h"
#include "smp_test_mesh.h"
#include "flat_grid.h"
#include "smp_surface_distance.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh_parameterization/internal/aabb_tree_compatibility.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Domain_relaxation.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace test_remeshing {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using smp_test::Mesh;
using smp_test::Point_3;
using smp_test::Vector_3;
typedef smp_test::Kernel K;

const SMP::Remeshing_pair all_pairs[] = {SMP::Remeshing_pair::U0, SMP::Remeshing_pair::U0_U1, SMP::Remeshing_pair::U0_UOPT};

std::size_t border_loops(const Mesh& m)
{
  std::vector<smp_test::halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
  return cycles.size();
}

double diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = PMP::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

// Whether `m` intersects itself, by exact predicates: the test meshes' kernel rounds its
// predicates, and then reports faces that share a vertex as crossing where they meet at it only
// (the two sides of a cut tube stitched, with clang++ -O1 and Eigen's SparseLU).
bool self_intersects(const Mesh& m)
{
  CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> exact;
  CGAL::copy_face_graph(m, exact);
  return PMP::does_self_intersect(exact);
}

// Everything promised of a new mesh `out` of `in` asked with `n` vertices.
void check_remeshed(const Mesh& in, const Mesh& out, const SMP::Remeshing_report& r, std::size_t n, const std::string& name,
                    double count_tolerance = 0.02)
{
  SMP_CHECK(r.status == SMP::OK, name << ": " << r.message);
  if(r.status != SMP::OK)
    return;
  SMP_CHECK(out.is_valid(false) && CGAL::is_triangle_mesh(out), name << ": not a valid triangle mesh");
  SMP_CHECK(out.number_of_vertices() == r.vertices && out.number_of_faces() == r.faces, name << ": the report is not the mesh");
  SMP_CHECK(std::abs(double(r.vertices) - double(n)) <= count_tolerance * double(n), name << ": " << r.vertices << " vertices for " << n);
  SMP_CHECK(border_loops(out) == border_loops(in) && r.border_loops == border_loops(in),
            name << ": " << border_loops(out) << " border loops for " << border_loops(in));
  const long euler_in = long(in.number_of_vertices()) - long(in.number_of_edges()) + long(in.number_of_faces());
  const long euler_out = long(out.number_of_vertices()) - long(out.number_of_edges()) + long(out.number_of_faces());
  SMP_CHECK(euler_in == euler_out, name << ": Euler characteristic " << euler_out << " for " << euler_in);
  // (the two sides of a cut that opened a closed surface touch: closed again first)
  Mesh closed = out;
  PMP::stitch_borders(closed);
  SMP_CHECK(!self_intersects(closed) && r.wrong_faces == 0,
            name << ": the new mesh intersects itself (" << r.wrong_faces << " wrong faces reported)");

  // on the input surface, border on its border, faces turned as the input's
  typedef CGAL::AABB_face_graph_triangle_primitive<Mesh> Primitive;
  typedef SMP::internal::Aabb_tree<K, Primitive> Tree;
  Tree tree(faces(in).first, faces(in).second, in);
  std::vector<K::Segment_3> border;
  for(auto h : halfedges(in))
    if(is_border(h, in))
      border.emplace_back(in.point(source(h, in)), in.point(target(h, in)));
  typedef SMP::internal::Aabb_tree<K, SMP::internal::Aabb_segment_primitive<K, std::vector<K::Segment_3>::const_iterator> > Border_tree;
  Border_tree border_tree(border.begin(), border.end());
  const double tolerance = 1e-9 * diagonal(in);
  std::size_t off_surface = 0, off_border = 0, on_border = 0, turned = 0;
  for(auto v : out.vertices()) {
    off_surface += std::sqrt(tree.squared_distance(out.point(v))) > tolerance;
    if(is_border(v, out)) {
      ++on_border;
      off_border += std::sqrt(border_tree.squared_distance(out.point(v))) > tolerance;
    }
  }
  // a face is turned if its normal is against the input's normals where its corners are (the
  // sum of the normals of the input faces they lie on)
  for(auto f : out.faces()) {
    const auto h = halfedge(f, out);
    const Point_3 &a = out.point(source(h, out)), &b = out.point(target(h, out)), &c = out.point(target(next(h, out), out));
    Vector_3 there = CGAL::NULL_VECTOR;
    for(const Point_3& p : {a, b, c})
      there = there + PMP::compute_face_normal(tree.closest_point_and_primitive(p).second, in);
    turned += CGAL::cross_product(b - a, c - a) * there < 0.;
  }
  SMP_CHECK(off_surface == 0, name << ": " << off_surface << " vertices off the input surface");
  SMP_CHECK(off_border == 0 && on_border == r.border_vertices,
            name << ": " << off_border << " border vertices off the input border, " << on_border << " on the border, "
            << r.border_vertices << " reported");
  SMP_CHECK(turned == 0, name << ": " << turned << " faces turned against the input");
  std::cout << name << ": " << r.vertices << " vertices (" << r.border_vertices << " on the border), angles >= 30: "
            << 100. * r.angles_at_least_30 << "%, smallest " << r.min_angle << ", area variation " << r.area_variation
            << ", " << r.seconds << " s" << std::endl;
}

// A planar disk of radius 1 (rings of vertices around the center) and a half cylinder of
// radius 1 and height 2: their new meshes are planar and on the cylinder within the input's chords.
Mesh planar_disk(int rings, int sectors)
{
  Mesh m;
  std::vector<std::vector<smp_test::vertex_descriptor> > ring(std::size_t(rings) + 1);
  ring[0].push_back(m.add_vertex(Point_3(0, 0, 0)));
  for(int r = 1; r <= rings; ++r)
    for(int k = 0; k < r * sectors; ++k) {
      const double a = 2. * CGAL_PI * k / (r * sectors), radius = double(r) / rings;
      ring[std::size_t(r)].push_back(m.add_vertex(Point_3(radius * std::cos(a), radius * std::sin(a), 0)));
    }
  // ring r-1 to ring r: sector s has s... vertices; each edge of the outer ring makes a triangle
  // with the inner ring's nearest vertex, and the gaps between them a triangle each
  for(int r = 1; r <= rings; ++r) {
    const auto& inner = ring[std::size_t(r - 1)];
    const auto& outer = ring[std::size_t(r)];
    const std::size_t no = outer.size(), ni = inner.size();
    for(std::size_t k = 0; k < no; ++k) {
      const std::size_t i0 = (k * ni) / no, i1 = ((k + 1) * ni) / no;
      m.add_face(inner[i0 % ni], outer[k], outer[(k + 1) % no]);
      if(i1 != i0 && ni > 1)
        m.add_face(inner[i0 % ni], outer[(k + 1) % no], inner[i1 % ni]);
    }
  }
  return m;
}

// The triangles of `m` with a corner on the border: their mean area over that of the others,
// and the coefficient of variation of their areas.
std::pair<double, double> border_band_areas(const Mesh& m)
{
  std::vector<double> band;
  double others = 0.;
  std::size_t n = 0;
  for(auto f : m.faces()) {
    bool on_border = false;
    for(auto v : vertices_around_face(m.halfedge(f), m))
      on_border = on_border || m.is_border(v);
    const double a = PMP::face_area(f, m);
    if(on_border) band.push_back(a);
    else { others += a; ++n; }
  }
  double mean = 0., spread = 0.;
  for(double a : band) mean += a / double(band.size());
  for(double a : band) spread += CGAL::square(a - mean) / double(band.size());
  return {mean / (others / double(n)), std::sqrt(spread) / mean};
}

Mesh half_cylinder(int nu, int nv)
{
  smp_test::Grid g = smp_test::make_grid(nu, nv);
  for(auto v : g.mesh.vertices()) {
    const Point_3 p = g.mesh.point(v);
    const double a = CGAL_PI * p.x() / nu;
    g.mesh.point(v) = Point_3(std::cos(a), std::sin(a), 2. * p.y() / nv);
  }
  return g.mesh;
}

void analytic_cases()
{
  const Mesh disk = planar_disk(12, 6);
  SMP_CHECK(disk.is_valid(false) && border_loops(disk) == 1, "the planar disk is not a disk");
  for(const SMP::Remeshing_pair pair : all_pairs) {
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(disk, 400, out, SMP::parameters::parameterization_pair(pair));
    check_remeshed(disk, out, r, 400, "planar disk, pair " + std::to_string(int(pair)));
    double z = 0., radius = 0.;
    for(auto v : out.vertices()) {
      z = (std::max)(z, std::abs(out.point(v).z()));
      radius = (std::max)(radius, std::hypot(out.point(v).x(), out.point(v).y()));
    }
    SMP_CHECK(z == 0. && radius <= 1. + 1e-12, "planar disk: |z| up to " << z << ", radius up to " << radius);
    // a plane is mapped without distortion: the samples are even and the angles wide
    SMP_CHECK(r.angles_at_least_30 >= 0.95 && r.area_variation < 0.3,
              "planar disk: " << r.angles_at_least_30 << " of the angles >= 30 degrees, area variation " << r.area_variation);
    // and the triangles along the border as even as the others (the row inside the border)
    const std::pair<double, double> band = border_band_areas(out);
    SMP_CHECK(band.first > 0.85 && band.first < 1.15 && band.second < 0.22,
              "planar disk: the triangles along the border " << band.first << " times the others' mean area, variation " << band.second);
  }
  const Mesh cylinder = half_cylinder(40, 16);
  Mesh out;
  const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(cylinder, 600, out);
  check_remeshed(cylinder, out, r, 600, "half cylinder");
  double off = 0.;
  for(auto v : out.vertices())
    off = (std::max)(off, 1. - std::hypot(out.point(v).x(), out.point(v).y()));
  // inside the cylinder by at most the sagitta of the input's chords
  SMP_CHECK(off >= -1e-12 && off <= 1. - std::cos(CGAL_PI / 80.) + 1e-12, "half cylinder: " << off << " inside");
  const std::pair<double, double> band = border_band_areas(out);
  SMP_CHECK(band.first > 0.85 && band.first < 1.15 && band.second < 0.22,
            "half cylinder: the triangles along the border " << band.first << " times the others' mean area, variation " << band.second);
}

// A tube (radius 1, height 2) cut open along a line from rim to rim, the two sides of the cut
// at the same points: the new mesh's two sides of the cut get the same points too, so that
// stitching its coincident border edges closes the cut all along (the two rims stay), and the
// closed mesh does not intersect itself (sampled apart, the two sides cross each other).
void cut_tube()
{
  const int nu = 48, nv = 16;
  smp_test::Grid g = smp_test::make_grid(nu, nv);
  for(auto v : g.mesh.vertices()) {
    const Point_3 p = g.mesh.point(v);
    const double a = 2. * CGAL_PI * double(int(p.x()) % nu) / nu; // the last column on the first, exactly
    g.mesh.point(v) = Point_3(std::cos(a), std::sin(a), 2. * p.y() / nv);
  }
  for(const SMP::Remeshing_pair pair : all_pairs) {
    const std::string name = "cut tube, pair " + std::to_string(int(pair));
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(g.mesh, 800, out, SMP::parameters::parameterization_pair(pair));
    check_remeshed(g.mesh, out, r, 800, name);
    PMP::stitch_borders(out);
    SMP_CHECK(out.is_valid(false) && border_loops(out) == 2,
              name << ": " << border_loops(out) << " border loops once the cut is stitched (the two rims expected)");
  }
  // a bulging tube, sampled by its curvature: the curvature estimated on each side of the cut
  // differs (each sees one side), the density on the cut does not
  for(auto v : g.mesh.vertices()) {
    const Point_3 p = g.mesh.point(v);
    const double bulge = 1. + 0.4 * std::sin(CGAL_PI * p.z() / 2.) * (1. + 0.5 * p.x());
    g.mesh.point(v) = Point_3(bulge * p.x(), bulge * p.y(), p.z());
  }
  Mesh out;
  const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(g.mesh, 800, out, SMP::parameters::curvature_adaptation(2.));
  check_remeshed(g.mesh, out, r, 800, "bulging cut tube, curvature adaptation 2");
  PMP::stitch_borders(out);
  SMP_CHECK(out.is_valid(false) && border_loops(out) == 2,
            "bulging cut tube: " << border_loops(out) << " border loops once the cut is stitched (the two rims expected)");
}

// A strip with a slot narrower than the spacing (as a mouth or a crease is): the triangles
// that span the slot are turned against the surface. Taking their samples out widened them
// until the slot was bridged over (the new mesh half its depth away from its bottom, and more);
// edge flips and samples added there let the new mesh go down into it, without crossing itself.
void narrow_slot()
{
  const double width = 0.01, depth = 0.3; // the spacing at 800 vertices is about 0.06
  std::vector<std::pair<double, double> > section; // (x, z) across the strip
  for(int i = 0; i < 50; ++i)
    section.emplace_back(i / 50., 0.);
  for(int i = 0; i <= 15; ++i)
    section.emplace_back(1., -depth * i / 15.);
  for(int i = 15; i >= 0; --i)
    section.emplace_back(1. + width, -depth * i / 15.);
  for(int i = 1; i <= 50; ++i)
    section.emplace_back(1. + width + i / 50., 0.);
  smp_test::Grid g = smp_test::make_grid(int(section.size()) - 1, 50);
  for(auto v : g.mesh.vertices()) {
    const Point_3 p = g.mesh.point(v);
    const std::pair<double, double>& s = section[std::size_t(p.x())];
    g.mesh.point(v) = Point_3(s.first, p.y() / 50., s.second);
  }
  for(const SMP::Remeshing_pair pair : {SMP::Remeshing_pair::U0, SMP::Remeshing_pair::U0_UOPT}) {
    const std::string name = "narrow slot, pair " + std::to_string(int(pair));
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(g.mesh, 800, out, SMP::parameters::parameterization_pair(pair));
    SMP_CHECK(r.status == SMP::OK, name << ": " << r.message);
    if(r.status != SMP::OK)
      continue;
    SMP_CHECK(out.is_valid(false) && CGAL::is_triangle_mesh(out) && border_loops(out) == 1 &&
              std::abs(double(r.vertices) - 800.) <= 16., name << ": " << r.vertices << " vertices, " << border_loops(out) << " border loops");
    SMP_CHECK(!self_intersects(out), name << ": the new mesh intersects itself");
    const double distance = smp_tools::symmetric_hausdorff_distance(out, g.mesh, diagonal(g.mesh));
    std::cout << name << ": Hausdorff distance " << distance << " (slot " << depth << " deep), " << r.wrong_faces
              << " wrong faces" << std::endl;
    SMP_CHECK(distance < 0.4 * depth, name << ": the new mesh is " << distance << " away from the slot's bottom");
  }
}

// The relaxation on a plane whose domain is squeezed along x (u = x^2, v = y): the vertices of a
// jittered grid settle where the triangles have even areas on the surface, whatever the
// squeeze (a rule that evens the areas in the domain, or weighs centroids of the domain by the
// surface areas alone, leaves the triangles larger where the domain is squeezed).
void relaxation_in_a_squeezed_domain()
{
  typedef SMP::internal::Lifted_mesh Lifted_mesh;
  typedef Lifted_mesh::Point Point;
  std::mt19937 random(7); // interior vertices moved by up to a quarter of the spacing
  const smp_test::Flat_grid grid = smp_test::make_flat_grid(24, 0.25, random);
  Lifted_mesh mesh;
  std::vector<SMP::internal::Vec2> uv;
  for(const auto& p : grid.m.xyz) {
    mesh.add_vertex(Point(p[0], p[1], 0));
    uv.push_back({{p[0] * p[0], p[1]}});
  }
  for(const auto& t : grid.m.tri)
    mesh.add_face(Lifted_mesh::Vertex_index(t[0]), Lifted_mesh::Vertex_index(t[1]), Lifted_mesh::Vertex_index(t[2]));
  // mean surface area of the triangles left of x = 1/4 over the one right of x = 3/4
  const auto left_over_right = [&mesh]() {
    double sum[2] = {0., 0.};
    int count[2] = {0, 0};
    for(auto f : mesh.faces()) {
      const auto h = mesh.halfedge(f);
      const Point &a = mesh.point(mesh.source(h)), &b = mesh.point(mesh.target(h)), &c = mesh.point(mesh.target(mesh.next(h)));
      const double x = (a.x() + b.x() + c.x()) / 3.;
      if(x < 0.25 || x > 0.75) {
        sum[x > 0.75] += std::sqrt(CGAL::squared_area(a, b, c));
        ++count[x > 0.75];
      }
    }
    return (sum[0] / count[0]) / (sum[1] / count[1]);
  };
  const double before = left_over_right();
  SMP::internal::relax_in_domain(mesh, uv, {}, 100, 1., [&](Lifted_mesh::Vertex_index v, const SMP::internal::Vec2& q) {
    if(!(q[0] >= 0. && q[0] <= 1. && q[1] >= 0. && q[1] <= 1.))
      return false;
    mesh.point(v) = Point(std::sqrt(q[0]), q[1], 0);
    return true;
  });
  const double after = left_over_right();
  std::size_t off = 0;
  for(auto v : mesh.vertices())
    off += std::abs(uv[std::size_t(v)][0] - CGAL::square(mesh.point(v).x())) > 1e-12 || uv[std::size_t(v)][1] != mesh.point(v).y();
  std::cout << "relaxation in a squeezed domain: triangles left of x = 1/4 over right of x = 3/4: " << before << " before, "
            << after << " after" << std::endl;
  SMP_CHECK(off == 0, "relaxation in a squeezed domain: " << off << " vertices off their domain points");
  SMP_CHECK(std::abs(after - 1.) < 0.1, "relaxation in a squeezed domain: the triangles left of x = 1/4 are "
            << after << " times as large as those right of x = 3/4 (" << before << " before)");
}

// The raster of U'': 16 cells a sample where U'' keeps areas (a unit square laid out as is, or
// scaled: only ratios count); where U'' squeezes half of the square 50 times, as many more as
// keep that half at about one sample a cell.
void raster_resolution()
{
  std::mt19937 unused;
  const SMP::internal::Flat_triangles square = smp_test::make_flat_grid(10, 0., unused).m;
  std::vector<SMP::internal::Vec2> same, scaled, squeezed;
  for(const auto& p : square.xyz) {
    same.push_back({{p[0], p[1]}});
    scaled.push_back({{3. * p[0], 3. * p[1]}});
    squeezed.push_back({{p[0] <= 0.5 ? p[0] : 0.5 + (p[0] - 0.5) / 50., p[1]}});
  }
  const std::size_t samples = 10000;
  const std::size_t cells_same = SMP::internal::raster_cells(square, same, samples, {});
  const std::size_t cells_scaled = SMP::internal::raster_cells(square, scaled, samples, {});
  SMP_CHECK(cells_same == 16 * samples && cells_scaled == 16 * samples,
            "raster of an area-preserving map: " << cells_same << " and " << cells_scaled << " cells for " << samples << " samples");
  // densities 1 and 50 over uv areas 1/2 and 1/100: the mean is 1 / 0.51, the squeezed half 50
  const double expected = 50. * 0.51 * double(samples);
  const double cells = double(SMP::internal::raster_cells(square, squeezed, samples, {}));
  SMP_CHECK(std::abs(cells - expected) <= 1. + 1e-6 * expected, "raster of a squeezed map: " << cells << " cells, " << expected << " expected");
}

// A rectangle 2 x 1 (a grid of 40 x 20 squares) with a bump of height `bump` centred at (0.5, 0.5).
Mesh bumpy_rectangle(double bump)
{
  smp_test::Grid g = smp_test::make_grid(40, 20);
  for(auto v : g.mesh.vertices()) {
    const double x = g.mesh.point(v).x() / 20., y = g.mesh.point(v).y() / 20.;
    g.mesh.point(v) = Point_3(x, y, bump * std::exp(-(CGAL::square(x - 0.5) + CGAL::square(y - 0.5)) / (2. * 0.12 * 0.12)));
  }
  return g.mesh;
}

// The vertices of `m` per unit of (x, y) area in the disk of radius `radius` centred at `c`,
// over the ones in the band x > 1.1 (of area 0.9).
double vertices_per_area(const Mesh& m, const Point_3& c, double radius)
{
  double in = 0., band = 0.;
  for(auto v : m.vertices()) {
    const Point_3& p = m.point(v);
    in += CGAL::square(p.x() - c.x()) + CGAL::square(p.y() - c.y()) < radius * radius ? 1. : 0.;
    band += p.x() > 1.1 ? 1. : 0.;
  }
  return (in / (CGAL_PI * radius * radius)) / (band / 0.9);
}

// A density given per vertex (4 on the left half of a plane rectangle, 1 on the right) gives
// about 4 times the vertices per unit area on the left, at the count asked for, the border
// sampled as densely; the curvature's density puts more vertices on a bump than on the plane.
void sampling_density()
{
  Mesh plane = bumpy_rectangle(0.);
  auto given = plane.add_property_map<smp_test::vertex_descriptor, double>("v:density", 1.).first;
  for(auto v : plane.vertices())
    put(given, v, plane.point(v).x() < 1. ? 4. : 1.);
  for(const bool dense : {false, true}) {
    const std::string name = std::string("plane rectangle, ") + (dense ? "density 4 on the left" : "no density");
    Mesh out;
    const SMP::Remeshing_report r =
        dense ? SMP::remesh_with_parameterizations(plane, 1500, out, SMP::parameters::vertex_density_map(given))
              : SMP::remesh_with_parameterizations(plane, 1500, out);
    check_remeshed(plane, out, r, 1500, name);
    double left = 0., right = 0., left_border = 0., right_border = 0.;
    for(auto v : out.vertices()) {
      const double x = out.point(v).x();
      const bool border = is_border(v, out) && out.point(v).y() == 0.; // (the bottom side)
      left += x < 0.9 ? 1. : 0.;
      right += x > 1.1 ? 1. : 0.;
      left_border += border && x < 0.9 ? 1. : 0.;
      right_border += border && x > 1.1 ? 1. : 0.;
    }
    const double ratio = left / right, border_ratio = left_border / right_border;
    std::cout << name << ": vertices left of x = 0.9 over right of x = 1.1: " << ratio << ", on the bottom side "
              << border_ratio << std::endl;
    // (4 times the density: 2 times the vertices along a line)
    SMP_CHECK(dense ? ratio > 3.4 && ratio < 4.6 : ratio > 0.85 && ratio < 1.15, name << ": " << ratio << " times the vertices on the left");
    SMP_CHECK(dense ? border_ratio > 1.7 && border_ratio < 2.3 : border_ratio > 0.85 && border_ratio < 1.15,
              name << ": " << border_ratio << " times the vertices on the left of the bottom side");
  }
  const Mesh bumpy = bumpy_rectangle(0.3);
  double on_bump[2] = {0., 0.};
  for(const double adaptation : {0., 4.}) {
    const std::string name = "bumpy rectangle, curvature adaptation " + std::to_string(adaptation);
    Mesh out;
    const SMP::Remeshing_report r =
        SMP::remesh_with_parameterizations(bumpy, 1500, out, SMP::parameters::curvature_adaptation(adaptation));
    check_remeshed(bumpy, out, r, 1500, name);
    on_bump[adaptation > 0.] = vertices_per_area(out, Point_3(0.5, 0.5, 0.), 0.25);
    std::cout << name << ": vertices per unit area on the bump over the plane's: " << on_bump[adaptation > 0.] << std::endl;
  }
  SMP_CHECK(on_bump[1] > 2. * on_bump[0], "curvature adaptation: " << on_bump[1] << " times the plane's vertices per unit area on the bump, "
            << on_bump[0] << " without");
}

// The bundled meshes: a disk with holes, a head; and the paper's claim on the head, where U^0
// is far from area-preserving: {U^0, U^opt} spreads the areas more evenly than {U^0} at a
// Hausdorff distance no larger.
void bundled_meshes()
{
  const Mesh holes = smp_test::read_mesh("holes.off");
  {
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(holes, 2000, out);
    check_remeshed(holes, out, r, 2000, "holes.off");
  }
  const Mesh head = smp_test::read_mesh("mannequin-devil.off");
  // (the mean distance, not the Hausdorff distance: the latter is decided at the tips of the
  // horns, thinner than the edges, by where a vertex falls, which OpenBLAS's kernels for one
  // processor or another move, past 1.05 times {U0}'s with some)
  double variation[3], distance[3];
  for(const SMP::Remeshing_pair pair : all_pairs) {
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(head, 3000, out, SMP::parameters::parameterization_pair(pair));
    check_remeshed(head, out, r, 3000, "mannequin-devil.off, pair " + std::to_string(int(pair)));
    variation[int(pair)] = r.area_variation;
    distance[int(pair)] = smp_tools::symmetric_mean_distance(out, head);
  }
  {
    // with {U^0} at 5000 vertices, the samples that fall together in U^0's compressed arms (and
    // are dropped by the triangulation) change a lot from one sampling density to the next:
    // the rounds that correct the count went back and forth, and the last was kept (5654)
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(head, 5000, out,
        SMP::parameters::parameterization_pair(SMP::Remeshing_pair::U0));
    check_remeshed(head, out, r, 5000, "mannequin-devil.off, {U0}, 5000 vertices");
  }
  {
    // small counts, where the samples left out along the border are many: the count is not
    // proportional to the density, and the rounds scaling it by the count's ratio overshot (59
    // vertices for 100, 194 for 200). At 100, a quarter of them on the border, the count moves
    // by several vertices from one density to the next: within 5% there.
    const Mesh peaks = smp_test::read_mesh("three_peaks.off");
    Mesh out;
    SMP::Remeshing_report r = SMP::remesh_with_parameterizations(peaks, 200, out);
    check_remeshed(peaks, out, r, 200, "three_peaks.off, 200 vertices");
    r = SMP::remesh_with_parameterizations(peaks, 100, out);
    check_remeshed(peaks, out, r, 100, "three_peaks.off, 100 vertices", 0.05);
  }
  SMP_CHECK(variation[2] < variation[0] && distance[2] <= 1.05 * distance[0],
            "mannequin-devil.off: area variation " << variation[2] << " with {U0, Uopt}, " << variation[0]
            << " with {U0}; mean distance " << distance[2] << " and " << distance[0]);

  // the result does not depend on the thread count, and a Polyhedron_3 gets the same mesh
  Mesh one, two;
  SMP::remesh_with_parameterizations(holes, 1000, one, SMP::parameters::number_of_threads(1u));
  SMP::remesh_with_parameterizations(holes, 1000, two, SMP::parameters::number_of_threads(2u));
  bool same = one.number_of_vertices() == two.number_of_vertices();
  for(auto v : one.vertices())
    same = same && one.point(v) == two.point(v);
  SMP_CHECK(same, "holes.off: the new mesh depends on the thread count");
  CGAL::Polyhedron_3<K> polyhedron, polyhedron_out;
  CGAL::copy_face_graph(holes, polyhedron);
  const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(polyhedron, 1000, polyhedron_out, SMP::parameters::number_of_threads(1u));
  SMP_CHECK(r.status == SMP::OK && num_vertices(polyhedron_out) == one.number_of_vertices(),
            "Polyhedron_3: " << r.message << ", " << num_vertices(polyhedron_out) << " vertices");
}

// Bad input: an error code and a message, the output mesh untouched.
void bad_input()
{
  const auto expect = [](const Mesh& in, std::size_t n, SMP::Error_code code, const std::string& name) {
    Mesh out = planar_disk(2, 3);
    const std::size_t before = out.number_of_vertices();
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(in, n, out);
    SMP_CHECK(r.status == code && !r.message.empty() && out.number_of_vertices() == before,
              name << ": status " << r.status << " (" << r.message << "), " << out.number_of_vertices() << " vertices out");
  };
  const Mesh disk = planar_disk(6, 6);
  expect(Mesh(), 100, SMP::ERROR_EMPTY_MESH, "empty mesh");
  expect(disk, 2, SMP::ERROR_WRONG_PARAMETER, "2 vertices");
  expect(disk, 5, SMP::ERROR_WRONG_PARAMETER, "fewer vertices than the border takes");
  expect(smp_test::make_grid(4, 4, true).mesh, 100, SMP::ERROR_NON_TRIANGULAR_MESH, "quads");
  Mesh nan = disk;
  nan.point(*nan.vertices().begin()) = Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  expect(nan, 100, SMP::ERROR_WRONG_PARAMETER, "a NaN coordinate");
  // densities out of range
  for(const double d : {0., -1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mesh dense = disk;
    auto density = dense.add_property_map<smp_test::vertex_descriptor, double>("v:density", 1.).first;
    put(density, *dense.vertices().begin(), d);
    Mesh out = planar_disk(2, 3);
    const std::size_t before = out.number_of_vertices();
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(dense, 100, out, SMP::parameters::vertex_density_map(density));
    SMP_CHECK(r.status == SMP::ERROR_WRONG_PARAMETER && !r.message.empty() && out.number_of_vertices() == before,
              "density " << d << ": status " << r.status << " (" << r.message << ")");
  }
  for(const double a : {-1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    Mesh out;
    const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(disk, 100, out, SMP::parameters::curvature_adaptation(a));
    SMP_CHECK(r.status == SMP::ERROR_WRONG_PARAMETER && !r.message.empty() && out.is_empty(),
              "curvature adaptation " << a << ": status " << r.status << " (" << r.message << ")");
  }
  // two disks; a closed surface
  Mesh two = disk;
  {
    Mesh other = disk;
    for(auto v : other.vertices())
      other.point(v) = other.point(v) + Vector_3(3, 0, 0);
    CGAL::copy_face_graph(other, two);
  }
  expect(two, 100, SMP::ERROR_NO_TOPOLOGICAL_DISC, "two components");
  Mesh closed;
  CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1), closed);
  expect(closed, 100, SMP::ERROR_NO_TOPOLOGICAL_DISC, "a closed mesh");
}

int run_test(int, char**)
{
  analytic_cases();
  cut_tube();
  narrow_slot();
  relaxation_in_a_squeezed_domain();
  raster_resolution();
  sampling_density();
  bundled_meshes();
  bad_input();
  return smp_test::summary();
}

} // namespace test_remeshing

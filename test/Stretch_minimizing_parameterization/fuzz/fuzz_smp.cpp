// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer harness (clang -fsanitize=fuzzer,address,undefined). The first byte chooses the
// target, the rest is its input:
//   0: a file for the tool's readers (OFF, OBJ, PLY or STL by the next byte), read as the tool
//      reads it, then made into an atlas and, when it is a disk-like mesh, parameterized;
//   1: a polygon soup made from the bytes (special coordinates, bad indices, degenerate,
//      repeated and non-manifold polygons) and options, made into an atlas;
//   2: the same soup as a mesh, parameterized with options, presets and a border halfedge
//      drawn from the bytes (interior or null ones too);
//   3: the same soup as a mesh, remeshed (a vertex count, a pair of parameterizations, a
//      curvature adaptation and a density per vertex, bad ones too, drawn from the bytes).
// A mesh read in target 0 is remeshed too.
// Any crash, sanitizer report, uncaught exception, hang (-timeout) or broken promise (abort
// below) is a finding.

#include "smp_input.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

// inputs above these sizes are skipped: each run must stay short
constexpr std::size_t max_polygons = 3000;
constexpr std::size_t max_soup_points = 48;

void promise(bool kept, const char* what)
{
  if(!kept) {
    std::fprintf(stderr, "broken promise: %s\n", what);
    std::abort();
  }
}

// Reads the bytes in order; past the end, zeros.
struct Bytes
{
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;

  bool empty() const { return at >= size; }
  std::uint8_t byte() { return at < size ? data[at++] : 0; }
  double unit() { return byte() / 255.; }
  double coordinate()
  {
    static const double special[] = {0., 1., -1., 0.5, 1e300, -1e300, 1e-300, 4.9e-324,
                                     std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::quiet_NaN(), 1e-9, 1e9};
    const std::uint8_t kind = byte();
    if(kind < 160)
      return (kind % 16) * 0.25 - 2.; // a small lattice: repeated points, flat and degenerate faces
    if(kind < 220)
      return special[kind % (sizeof(special) / sizeof(double))];
    double d = 0.;
    std::uint8_t raw[sizeof(double)];
    for(std::uint8_t& r : raw) r = byte();
    std::memcpy(&d, raw, sizeof(double));
    return d;
  }
};

struct Soup
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
};

Soup make_soup(Bytes& in)
{
  Soup s;
  const std::size_t n = 1 + in.byte() % max_soup_points;
  for(std::size_t i = 0; i < n; ++i) {
    const double x = in.coordinate(), y = in.coordinate(), z = in.coordinate();
    s.points.emplace_back(x, y, z);
  }
  const std::size_t m = in.byte() % 64;
  for(std::size_t f = 0; f < m && !in.empty(); ++f) {
    std::vector<std::size_t> polygon(in.byte() % 7); // 0 to 6 corners
    for(std::size_t& v : polygon) {
      const std::uint8_t b = in.byte();
      v = b == 255 ? std::size_t(-1) : b % (n + 1); // now and then out of range
    }
    s.polygons.push_back(polygon);
  }
  return s;
}

// The atlas keeps its promises: a uv per corner in the unit square and a chart per polygon.
void check_atlas(const std::vector<Point_3>& points, const std::vector<std::vector<std::size_t> >& polygons,
                 Bytes& options)
{
  namespace P = SMP::parameters;
  const double max_stretch = 1. + 4. * options.unit() - 0.01; // a little below 1 too
  const unsigned resolution = 1u + options.byte() * 4u;
  const double gutter = 4. * options.unit();
  const unsigned polish = options.byte() % 3;
  const SMP::Atlas atlas = SMP::make_atlas(points, polygons,
      P::max_stretch(max_stretch).resolution(resolution).gutter(gutter).polish_iterations(polish).number_of_threads(1u));
  if(atlas.report.status != SMP::OK) {
    promise(!atlas.report.message.empty(), "an atlas error without a message");
    return;
  }
  promise(atlas.uv.size() == polygons.size() && atlas.chart.size() == polygons.size(), "a polygon lost");
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    promise(atlas.uv[f].size() == polygons[f].size(), "a corner lost");
    promise(atlas.chart[f] < atlas.report.charts, "a chart out of range");
    for(const auto& q : atlas.uv[f])
      promise(q[0] >= 0. && q[0] <= 1. && q[1] >= 0. && q[1] <= 1., "a uv outside the unit square");
  }
  promise(atlas.report.flipped_faces == 0, "a flipped face in the atlas");
}

// The parameterizer on a mesh: an error code, or a finite map of the component.
void check_parameterizer(Mesh& mesh, Bytes& options)
{
  namespace P = SMP::parameters;
  auto uv = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:fuzz_uv", Point_2(0., 0.)).first;
  Mesh::Halfedge_index bhd;
  const std::uint8_t border = options.byte();
  if(border < 200 && !CGAL::is_closed(mesh))
    bhd = PMP::longest_border(mesh).first;
  else if(border < 250 && !mesh.is_empty())
    bhd = Mesh::Halfedge_index(border % mesh.number_of_halfedges()); // any halfedge, on the border or not
  const std::uint8_t choice = options.byte();
  const double eta = options.byte() == 0 ? -1. : 1.2 * options.unit(); // out of (0, 1] now and then
  const unsigned iterations = options.byte() % 6;
  SMP::Stretch_minimizing_parameterizer_3<Mesh> p(
      P::preset(choice & 1 ? SMP::Stretch_minimizing_preset::LOWEST_STRETCH : SMP::Stretch_minimizing_preset::PAPER)
        .eta(eta)
        .number_of_iterations(iterations)
        .polish_iterations(unsigned(choice >> 1) % 3)
        .free_border(bool(choice & 8))
        .start_weights(choice & 16 ? SMP::Start_weights::CLAMPED_COTANGENT : SMP::Start_weights::INITIALIZER)
        .stretch_update(choice & 32 ? SMP::Stretch_update::EDGE : SMP::Stretch_update::VERTEX)
        .number_of_threads(1u));
  // the member function: CGAL's free parameterize() reads `bhd` before the package checks it
  auto vimap = mesh.add_property_map<Mesh::Vertex_index, int>("v:fuzz_index", 0).first;
  auto vpmap = mesh.add_property_map<Mesh::Vertex_index, bool>("v:fuzz_done", false).first;
  int index = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
    put(vimap, v, index++);
  const SMP::Error_code status = p.parameterize(mesh, bhd, uv, vimap, vpmap);
  if(status != SMP::OK) {
    promise(!p.report().message.empty(), "an error without a message");
    return;
  }
  for(Mesh::Vertex_index v : vertices(mesh))
    promise(std::isfinite(get(uv, v).x()) && std::isfinite(get(uv, v).y()), "a non-finite uv");
}

// A soup made into a mesh when CGAL can (valid indices, manifold, orientable).
bool to_mesh(const Soup& s, Mesh& mesh)
{
  for(const auto& polygon : s.polygons)
    for(std::size_t v : polygon)
      if(v >= s.points.size())
        return false;
  if(s.polygons.empty() || !PMP::is_polygon_soup_a_polygon_mesh(s.polygons))
    return false;
  PMP::polygon_soup_to_polygon_mesh(s.points, s.polygons, mesh);
  PMP::remove_isolated_vertices(mesh); // CGAL's parameterize() wants a valid polygon mesh
  mesh.collect_garbage();
  return true;
}

// Remeshes `mesh`: a valid triangle mesh of finite points that is what the report says, or an
// error with a message.
void check_remeshing(const Mesh& mesh, Bytes& options)
{
  const std::size_t vertices = 3 + options.byte() % 120;
  const SMP::Remeshing_pair pair = SMP::Remeshing_pair(options.byte() % 3);
  const std::uint8_t density_choice = options.byte();
  const double adaptation = density_choice & 1 ? (density_choice & 2 ? -1. : 8. * options.unit()) : 0.;
  const auto np = SMP::parameters::parameterization_pair(pair).number_of_threads(1u).curvature_adaptation(adaptation);
  Mesh out;
  SMP::Remeshing_report r;
  if(density_choice & 4) {
    Mesh dense = mesh;
    auto density = dense.add_property_map<Mesh::Vertex_index, double>("v:fuzz_density", 1.).first;
    for(const auto v : dense.vertices())
      put(density, v, options.byte() == 0 ? 0. : 0.01 + 4. * options.unit()); // 0 now and then
    r = SMP::remesh_with_parameterizations(dense, vertices, out, np.vertex_density_map(density));
  } else {
    r = SMP::remesh_with_parameterizations(mesh, vertices, out, np);
  }
  if(r.status != SMP::OK) {
    promise(!r.message.empty(), "a remeshing error without a message");
    return;
  }
  promise(out.is_valid(false) && CGAL::is_triangle_mesh(out), "a remeshed mesh that is not a valid triangle mesh");
  promise(out.number_of_vertices() == r.vertices && out.number_of_faces() == r.faces, "a remeshing report that is not its mesh");
  for(const auto v : out.vertices())
    promise(std::isfinite(out.point(v).x()) && std::isfinite(out.point(v).y()) && std::isfinite(out.point(v).z()),
            "a remeshed vertex that is not finite");
}

void fuzz_reader(Bytes& in)
{
  static const char* const extensions[] = {"off", "obj", "ply", "stl"};
  const std::string file = std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") +
                           "/smp_fuzz_" + std::to_string(getpid()) + "." + extensions[in.byte() % 4];
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(in.data + in.at), std::streamsize(in.size - in.at));
  }
  Bytes options{in.data, in.size, 0}; // the file's own bytes draw the options
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::string error;
  if(smp_tools::read_soup(file, points, polygons, error)) {
    if(polygons.size() <= max_polygons)
      check_atlas(points, polygons, options);
  } else {
    promise(!error.empty(), "a soup refused without a message");
  }
  Mesh mesh;
  std::size_t isolated = 0;
  if(smp_tools::read_mesh(file, mesh, error, isolated)) {
    if(mesh.number_of_faces() <= max_polygons && CGAL::is_triangle_mesh(mesh)) {
      check_parameterizer(mesh, options);
      check_remeshing(mesh, options);
    }
  } else {
    promise(!error.empty(), "a mesh refused without a message");
  }
  std::remove(file.c_str());
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes in{data, size};
  switch(in.byte() % 4) {
  case 0:
    fuzz_reader(in);
    break;
  case 1: {
    const Soup s = make_soup(in);
    check_atlas(s.points, s.polygons, in);
    break;
  }
  case 2: {
    const Soup s = make_soup(in);
    Mesh mesh;
    if(to_mesh(s, mesh) && CGAL::is_triangle_mesh(mesh))
      check_parameterizer(mesh, in);
    break;
  }
  default: {
    const Soup s = make_soup(in);
    Mesh mesh;
    if(to_mesh(s, mesh) && CGAL::is_triangle_mesh(mesh))
      check_remeshing(mesh, in);
  }
  }
  return 0;
}

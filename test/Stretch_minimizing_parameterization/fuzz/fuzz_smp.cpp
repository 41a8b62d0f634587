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
//   3: the same soup as a mesh, remeshed (a vertex count and a pair of parameterizations
//      drawn from the bytes).
// A mesh read in target 0 is remeshed too.
// Any crash, sanitizer report, uncaught exception, hang (-timeout) or broken promise (promise(),
// fuzz_smp.h) is a finding.

#include "fuzz_smp.h"
#include "smp_input.h"

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using namespace smp_fuzz;
namespace PMP = CGAL::Polygon_mesh_processing;

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

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A texture atlas by xatlas (https://github.com/jpcy/xatlas, MIT), for comparison with
// smp-parameterize --atlas. Only this driver is ours: it calls xatlas's public API and is built
// by scripts/compare-xatlas.sh against a checkout of xatlas given by the user (xatlas.h and
// xatlas.cpp are never part of this repository).
//   xatlas_driver MESH OUT.obj [--resolution 1024] [--padding P]
// Reads any OFF/OBJ/PLY/STL polygon soup, writes OUT.obj with the input's `v` lines in order,
// one `vt` per xatlas output vertex (texels divided by the atlas's longer side, so that the
// atlas lies in the unit square) and `f v/vt` faces in the input's order, and prints the timings
// and xatlas's own figures on one line of key=value.
//
// Polygons are split into fans here, and xatlas gets triangles: its own polygon path
// (MeshDecl::faceVertexCount) is unreliable in this version of xatlas.cpp: AddMesh reads the
// corners of polygon f from index f * faceVertexCount[f] (wrong when the sizes vary), and the
// output polygons are written at vertex indices rather than at corner positions
// (triangleToPolygonIndicesMap holds vertex indices). A polygon whose fan triangles give each
// of its corners one output vertex (all of it in one chart) is written back as the polygon;
// otherwise as its triangles (`split_polygons` counts them).
//
// Padding: xatlas packs each chart's conservative raster, widened by the texels that bilinear
// filtering samples (PackOptions::bilinear, on by default: about one texel around the chart),
// then dilated `padding` times (8-neighbourhood), and requires these images to be disjoint.
// So padding 0 already keeps charts about one texel apart or more, each padding texel adds 2
// to the gap. Our gutter of 2 texels keeps the charts' triangle boxes, widened by one texel
// each, on disjoint texels. Measured (smallest distance between two charts, in texels of the
// atlas's longer side) on bear, mannequin-devil and armadillo: ours 2.0 to 2.2; xatlas with
// padding 0: 1.0 to 1.5; padding 1: 4.0 (bear). Padding 0, xatlas's default, is the nearest
// to ours and a little tighter, so it is the default here: it does not handicap xatlas's
// utilization.
//
// Timing: xatlas::Generate is ComputeCharts then PackCharts (xatlas.cpp); the two are called
// here one after the other so that each is timed, and `xatlas_seconds` is their sum.

#include "xatlas.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;

[[noreturn]] void fail(const std::string& why) { std::cerr << "xatlas_driver: " << why << std::endl; std::exit(1); }

int main(int argc, char** argv)
{
  if(argc < 3) fail("usage: xatlas_driver MESH OUT.obj [--resolution 1024] [--padding P]");
  const std::string input = argv[1], output = argv[2];
  unsigned resolution = 1024, padding = 0;
  for(int i = 3; i < argc; ++i) {
    const std::string a = argv[i];
    if(i + 1 >= argc) fail("option " + a + " needs a value");
    if(a == "--resolution") resolution = unsigned(std::atoi(argv[++i]));
    else if(a == "--padding") padding = unsigned(std::atoi(argv[++i]));
    else fail("unknown option " + a);
  }
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(input, points, polygons, CGAL::parameters::verbose(false)) || polygons.empty())
    fail("cannot read polygons from " + input);

  // fans: triangle k of polygon p is (p[0], p[k + 1], p[k + 2]), from first_triangle[p] on
  std::vector<float> xyz;
  for(const Point_3& p : points) { xyz.push_back(float(p.x())); xyz.push_back(float(p.y())); xyz.push_back(float(p.z())); }
  std::vector<std::uint32_t> indices;
  std::vector<std::size_t> first_triangle;
  for(const auto& polygon : polygons) {
    first_triangle.push_back(indices.size() / 3);
    for(std::size_t k = 1; k + 1 < polygon.size(); ++k)
      for(std::size_t c : {polygon[0], polygon[k], polygon[k + 1]}) indices.push_back(std::uint32_t(c));
  }
  first_triangle.push_back(indices.size() / 3);

  xatlas::Atlas* atlas = xatlas::Create();
  xatlas::MeshDecl mesh;
  mesh.vertexPositionData = xyz.data();
  mesh.vertexPositionStride = 3 * sizeof(float);
  mesh.vertexCount = std::uint32_t(points.size());
  mesh.indexData = indices.data();
  mesh.indexCount = std::uint32_t(indices.size());
  mesh.indexFormat = xatlas::IndexFormat::UInt32;
  const auto t0 = std::chrono::steady_clock::now();
  const xatlas::AddMeshError error = xatlas::AddMesh(atlas, mesh);
  if(error != xatlas::AddMeshError::Success) fail(std::string("AddMesh: ") + xatlas::StringForEnum(error));
  xatlas::AddMeshJoin(atlas); // AddMesh works asynchronously: its time ends here
  const auto t1 = std::chrono::steady_clock::now();
  xatlas::PackOptions pack;
  pack.resolution = resolution;
  pack.padding = padding;
  xatlas::ComputeCharts(atlas, xatlas::ChartOptions()); // = Generate(atlas, ChartOptions(), pack)
  const auto t2 = std::chrono::steady_clock::now();
  xatlas::PackCharts(atlas, pack);
  const auto t3 = std::chrono::steady_clock::now();

  const xatlas::Mesh& out = atlas->meshes[0];
  if(out.indexCount != indices.size()) fail("xatlas returned " + std::to_string(out.indexCount) + " indices for " + std::to_string(indices.size()));
  const double side = double((std::max)((std::max)(atlas->width, atlas->height), 1u));
  std::ofstream obj(output);
  obj.precision(17);
  obj << "# " << input << ": texture atlas by xatlas (" << atlas->chartCount << " charts, " << atlas->width << "x"
      << atlas->height << " texels, padding " << padding << ")\n";
  for(const Point_3& p : points) obj << "v " << p << "\n";
  obj.precision(9);
  for(std::uint32_t v = 0; v < out.vertexCount; ++v)
    obj << "vt " << out.vertexArray[v].uv[0] / side << " " << out.vertexArray[v].uv[1] / side << "\n";
  std::size_t split = 0, xref_mismatch = 0;
  for(std::size_t p = 0; p < polygons.size(); ++p) {
    const std::size_t n = polygons[p].size();
    if(n < 3) continue;
    // per corner of the polygon, the output vertex of the fan triangles (it must be one)
    std::vector<std::int64_t> corner(n, -1);
    bool one = true;
    for(std::size_t t = first_triangle[p]; t < first_triangle[p + 1]; ++t) {
      const std::size_t k = t - first_triangle[p], c[3] = {0, k + 1, k + 2};
      for(int j = 0; j < 3; ++j) {
        const std::uint32_t o = out.indexArray[3 * t + std::size_t(j)];
        xref_mismatch += out.vertexArray[o].xref != indices[3 * t + std::size_t(j)];
        if(corner[c[j]] >= 0 && corner[c[j]] != o) one = false;
        corner[c[j]] = o;
      }
    }
    if(one) {
      obj << "f";
      for(std::size_t k = 0; k < n; ++k) obj << " " << out.vertexArray[corner[k]].xref + 1 << "/" << corner[k] + 1;
      obj << "\n";
      continue;
    }
    ++split;
    for(std::size_t t = first_triangle[p]; t < first_triangle[p + 1]; ++t) {
      obj << "f";
      for(int j = 0; j < 3; ++j) {
        const std::uint32_t o = out.indexArray[3 * t + std::size_t(j)];
        obj << " " << out.vertexArray[o].xref + 1 << "/" << o + 1;
      }
      obj << "\n";
    }
  }
  obj.close();
  if(!obj) fail("cannot write " + output);
  auto seconds = [](std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
  };
  std::cout << "xatlas_seconds=" << seconds(t1, t3) << " add_mesh_seconds=" << seconds(t0, t1)
            << " compute_charts_seconds=" << seconds(t1, t2) << " pack_charts_seconds=" << seconds(t2, t3)
            << " charts=" << atlas->chartCount
            << " width=" << atlas->width << " height=" << atlas->height << " atlases=" << atlas->atlasCount
            << " utilization=" << (atlas->utilization ? atlas->utilization[0] : 0.f) << " texels_per_unit=" << atlas->texelsPerUnit
            << " padding=" << padding << " split_polygons=" << split << " xref_mismatch=" << xref_mismatch << std::endl;
  xatlas::Destroy(atlas);
  return 0;
}

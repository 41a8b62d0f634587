// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's remeshing comparison (its figure 10): {U^0}, {U^0, U^1} and {U^0, U^opt} side by
// side, and CGAL's isotropic remeshing at the same vertex count as the anchor a CGAL user would
// pick instead. One Markdown table row per method and mesh on standard output; with a folder
// as last argument, the new meshes are written there as OFF.
//
//   remeshing_comparison VERTICES MESH... [--out DIR] [--relaxation N]
//
// --relaxation N: the relaxation steps of the three pairs (default: remesh_with_parameterizations()'s);
// with 0, the figures are those of the samples as the error diffusion placed them.
//
// Figures: vertices, angles (smallest, share of 30 degrees or more), coefficient of variation
// of the triangle areas, symmetric Hausdorff and mean distances to the input over its bounding
// box diagonal (as smp-remesh reports them: tools/smp_surface_distance.h),
// self-intersecting pairs (CGAL's self_intersections), time. The area variation is also given
// apart for the border band (the triangles with a corner on the border or one edge from it)
// and for the triangles further in: the sampling differs most near the border.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "smp_surface_distance.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// The figures of a new mesh, measured here the same way for every method.
void row(const std::string& mesh_name, const std::string& method, const Mesh& in, const Mesh& out, double seconds,
         double diagonal)
{
  SMP::Remeshing_report q;
  std::vector<SMP::internal::Vec3> xyz;
  std::vector<SMP::internal::Triangle> tri;
  for(auto v : out.vertices())
    xyz.push_back({out.point(v).x(), out.point(v).y(), out.point(v).z()});
  for(auto f : out.faces()) {
    const auto h = out.halfedge(f);
    tri.push_back({int(out.source(h)), int(out.target(h)), int(out.target(out.next(h)))});
  }
  SMP::internal::measure_triangles(xyz, tri, q);
  // edges from the border, per vertex (breadth first from the border vertices)
  std::vector<int> rings(out.number_of_vertices(), -1);
  std::vector<Mesh::Vertex_index> front;
  for(auto v : out.vertices())
    if(out.is_border(v)) {
      rings[std::size_t(v)] = 0;
      front.push_back(v);
    }
  for(std::size_t i = 0; i < front.size(); ++i)
    for(auto w : CGAL::vertices_around_target(front[i], out))
      if(rings[std::size_t(w)] < 0) {
        rings[std::size_t(w)] = rings[std::size_t(front[i])] + 1;
        front.push_back(w);
      }
  const auto near = [&](int v) { return rings[std::size_t(v)] >= 0 && rings[std::size_t(v)] <= 1; };
  std::vector<SMP::internal::Triangle> band, further;
  for(const auto& t : tri)
    (near(t[0]) || near(t[1]) || near(t[2]) ? band : further).push_back(t);
  SMP::Remeshing_report q_band, q_further;
  SMP::internal::measure_triangles(xyz, band, q_band);
  SMP::internal::measure_triangles(xyz, further, q_further);
  const double hausdorff = smp_tools::symmetric_hausdorff_distance(out, in, diagonal);
  const double mean_distance = smp_tools::symmetric_mean_distance(out, in);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index> > crossing;
  PMP::self_intersections(out, std::back_inserter(crossing));
  std::printf("| %s | %s | %zu | %.1f | %.2f | %.3f | %.3f | %.3f | %.5f | %.6f | %zu | %.2f |\n", mesh_name.c_str(),
              method.c_str(), std::size_t(out.number_of_vertices()), q.min_angle, 100. * q.angles_at_least_30,
              q.area_variation, q_band.area_variation, q_further.area_variation, hausdorff / diagonal,
              mean_distance / diagonal, crossing.size(), seconds);
  std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3) {
    std::cerr << "usage: remeshing_comparison VERTICES MESH... [--out DIR] [--relaxation N]\n";
    return 2;
  }
  const std::size_t n = std::stoul(argv[1]);
  std::string out_dir;
  int relaxation = -1; // the function's default
  std::vector<std::string> files;
  for(int i = 2; i < argc; ++i) {
    if(std::string(argv[i]) == "--out" && i + 1 < argc)
      out_dir = argv[++i];
    else if(std::string(argv[i]) == "--relaxation" && i + 1 < argc)
      relaxation = std::stoi(argv[++i]);
    else
      files.push_back(argv[i]);
  }
  std::printf("| mesh | method | vertices | smallest angle | angles >= 30 (%%) | area variation | in the border band | "
              "further in | Hausdorff / diagonal | mean distance / diagonal | self-intersecting pairs | seconds |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& file : files) {
    Mesh in;
    if(!CGAL::IO::read_polygon_mesh(file, in) || !CGAL::is_triangle_mesh(in)) {
      std::cerr << "cannot read a triangle mesh from " << file << "\n";
      return 1;
    }
    const std::string name = std::filesystem::path(file).filename().string();
    const double diagonal = smp_tools::bounding_box_diagonal(in);
    const auto write = [&](const std::string& method, const Mesh& m) {
      if(!out_dir.empty())
        CGAL::IO::write_polygon_mesh(out_dir + "/" + std::filesystem::path(file).stem().string() + "_" + method + ".off", m,
                                     CGAL::parameters::stream_precision(17));
    };
    const std::pair<SMP::Remeshing_pair, const char*> pairs[] = {{SMP::Remeshing_pair::U0, "{U0}"},
                                                                {SMP::Remeshing_pair::U0_U1, "{U0, U1}"},
                                                                {SMP::Remeshing_pair::U0_UOPT, "{U0, Uopt}"}};
    for(const auto& [pair, label] : pairs) {
      Mesh out;
      const auto t = std::chrono::steady_clock::now();
      const auto np = SMP::parameters::parameterization_pair(pair);
      const SMP::Remeshing_report r = relaxation < 0 ? SMP::remesh_with_parameterizations(in, n, out, np)
                                                     : SMP::remesh_with_parameterizations(in, n, out, np.number_of_relaxation_steps(relaxation));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      if(r.status != SMP::OK) {
        std::printf("| %s | %s | failed: %s |\n", name.c_str(), label, r.message.c_str());
        continue;
      }
      row(name, label, in, out, seconds, diagonal);
      write(std::string(label).substr(1, std::string(label).size() - 2), out);
    }
    // CGAL's isotropic remeshing (3 iterations, as in CGAL's example), at the edge length that
    // gives the same vertex count: an equilateral guess, then corrected from the count it
    // gave; the time is the one of the last call
    double length = std::sqrt(4. * PMP::area(in) / std::sqrt(3.) / (2. * double(n)));
    Mesh out;
    double seconds = 0.;
    for(int attempt = 0; attempt < 4; ++attempt) {
      out = in;
      const auto t = std::chrono::steady_clock::now();
      PMP::isotropic_remeshing(faces(out), length, out, CGAL::parameters::number_of_iterations(3));
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      const double ratio = double(out.number_of_vertices()) / double(n);
      if(std::abs(ratio - 1.) <= 0.02)
        break;
      length *= std::sqrt(ratio);
    }
    out.collect_garbage();
    row(name, "CGAL isotropic_remeshing", in, out, seconds, diagonal);
    write("isotropic", out);
  }
  return 0;
}

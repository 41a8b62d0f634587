// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Times parameterizers side by side on one mesh, in one process, with the same border
// (unit square, arc length), and measures their results.
//   benchmark_parameterizers mesh.off [runs]
// Prints a markdown table: median wall time of the parameterization call over `runs` runs
// (mesh loading excluded), normalized L2 / Linf stretch, flipped and degenerate faces, steps.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;
typedef Mesh::Halfedge_index                  halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Kernel::Point_2> UV_map;

namespace SMP = CGAL::Surface_mesh_parameterization;

typedef SMP::Square_border_arc_length_parameterizer_3<Mesh>           Square;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh, Square>     CGAL_MVC; // CGAL's default solver
typedef SMP::Shape_preserving_parameterizer_3<Mesh, Square>           Floater;
typedef SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater>        Stretch_minimizer;

struct Row
{
  std::string method;
  std::vector<double> seconds;
  SMP::Error_code status = SMP::OK;
  SMP::Stretch_statistics stats;
  std::string steps = "-";
};

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0. : v[v.size() / 2];
}

int main(int argc, char** argv)
{
  if(argc < 2) {
    std::cerr << "usage: " << argv[0] << " mesh.off [runs]" << std::endl;
    return EXIT_FAILURE;
  }
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  UV_map uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  std::vector<Row> rows;
  // Runs `call` `runs` times (interleaved with the other methods, so that machine noise
  // spreads evenly), then measures the map of the last run.
  std::vector<std::pair<std::string, std::function<SMP::Error_code(std::string&)> > > methods = {
    {"CGAL Mean_value_coordinates (BiCGSTAB, CGAL default)",
     [&](std::string&) { return SMP::parameterize(mesh, CGAL_MVC(), bhd, uv); }},
    {"(b) Floater shape-preserving U^0",
     [&](std::string&) { return SMP::parameterize(mesh, Floater(), bhd, uv); }},
    {"(e) U^1",
     [&](std::string& steps) {
       Stretch_minimizer p(SMP::parameters::number_of_iterations(1));
       const SMP::Error_code e = SMP::parameterize(mesh, p, bhd, uv);
       steps = std::to_string(p.report().kept_step);
       return e;
     }},
    {"(f) U^opt, eta = 1",
     [&](std::string& steps) {
       Stretch_minimizer p;
       const SMP::Error_code e = SMP::parameterize(mesh, p, bhd, uv);
       steps = std::to_string(p.report().kept_step) + " of " + std::to_string(p.report().steps_taken());
       return e;
     }},
    {"U^opt, eta = 0.5",
     [&](std::string& steps) {
       Stretch_minimizer p(SMP::parameters::eta(0.5));
       const SMP::Error_code e = SMP::parameterize(mesh, p, bhd, uv);
       steps = std::to_string(p.report().kept_step) + " of " + std::to_string(p.report().steps_taken());
       return e;
     }},
  };
  rows.resize(methods.size());
  for(int r = 0; r < runs; ++r)
    for(std::size_t m = 0; m < methods.size(); ++m) {
      rows[m].method = methods[m].first;
      const auto start = std::chrono::steady_clock::now();
      rows[m].status = methods[m].second(rows[m].steps);
      rows[m].seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      if(r + 1 == runs && rows[m].status == SMP::OK)
        rows[m].stats = SMP::compute_stretch_statistics(mesh, uv);
    }

  std::cout << "mesh " << argv[1] << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh)
            << " faces; median of " << runs << " runs\n\n"
            << "| method | time (s) | time / CGAL MVC | L2 | Linf | flipped | degenerate | kept step |\n"
            << "|---|---|---|---|---|---|---|---|\n";
  const double reference = median(rows[0].seconds);
  for(const Row& row : rows) {
    std::cout << "| " << row.method << " | " << std::setprecision(3) << median(row.seconds) << " | "
              << std::setprecision(3) << median(row.seconds) / reference << " | ";
    if(row.status != SMP::OK)
      std::cout << SMP::error_message(row.status) << " | | | | |\n";
    else
      std::cout << std::setprecision(4) << row.stats.l2_stretch << " | " << row.stats.linf_stretch << " | "
                << row.stats.flipped_faces << " | " << row.stats.degenerate_uv_faces << " | " << row.steps << " |\n";
  }
  return EXIT_SUCCESS;
}

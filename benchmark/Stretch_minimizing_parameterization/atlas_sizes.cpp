// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// make_atlas() on a mesh and its Loop refinements (CGAL's subdivision, each level 4 times the
// faces), up to a number of faces: one markdown row per level with the charts, the L2 stretch,
// the seams, the utilization, the seconds of each stage and the peak memory of the process so
// far (run by scripts/benchmark-atlas-sizes.sh, one process per mesh, which writes the header:
// | mesh | faces | charts | L2 | seams % | utilization | cut s | flatten s | pack s | total s | peak MiB |).
//   atlas_sizes MAX_FACES mesh.off ...

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>       Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>  Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;

// Peak resident memory of this process in MiB (Linux), 0 if unknown.
double peak_mib()
{
  std::ifstream status("/proc/self/status");
  for(std::string line; std::getline(status, line);)
    if(line.rfind("VmHWM:", 0) == 0)
      return std::atof(line.c_str() + 6) / 1024.;
  return 0.;
}

int main(int argc, char** argv)
{
  if(argc < 3) {
    std::cerr << "usage: atlas_sizes MAX_FACES mesh.off ..." << std::endl;
    return EXIT_FAILURE;
  }
  const std::size_t max_faces = std::strtoul(argv[1], nullptr, 10);
  for(int i = 2; i < argc; ++i) {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(argv[i], mesh) || !CGAL::is_triangle_mesh(mesh)) {
      std::cerr << "cannot read a triangle mesh from " << argv[i] << std::endl;
      return EXIT_FAILURE;
    }
    const std::string name = std::filesystem::path(argv[i]).stem().string();
    for(int level = 0; num_faces(mesh) <= max_faces; ++level) {
      auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
      auto chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart").first;
      const SMP::Atlas_report r = SMP::make_atlas(mesh, uv, chart);
      if(r.status != SMP::OK) {
        std::cerr << name << ": " << r.message << std::endl;
        return EXIT_FAILURE;
      }
      std::cout << std::fixed << "| " << name << (level ? " (" + std::to_string(level) + " Loop)" : std::string()) << " | "
                << num_faces(mesh) << " | " << r.charts << " | " << std::setprecision(4) << r.l2_stretch << " | "
                << std::setprecision(2) << 100. * r.seam_length / r.edge_length << " | " << std::setprecision(3) << r.utilization
                << " | " << std::setprecision(2) << r.seconds_cutting << " | " << r.seconds_parameterization << " | "
                << r.seconds_packing << " | " << r.seconds << " | " << std::setprecision(0) << peak_mib() << " |" << std::endl;
      mesh.remove_property_map(uv);
      mesh.remove_property_map(chart);
      CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
    }
  }
  return EXIT_SUCCESS;
}

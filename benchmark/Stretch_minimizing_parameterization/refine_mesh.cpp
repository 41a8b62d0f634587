// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes a mesh refined by CGAL's Loop subdivision, as the benchmark's FILE@loopN meshes are
// made at run time, for the programs that read files (scripts/compare-presets.sh):
//
//   refine_mesh IN LEVELS OUT

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/subdivision_method_3.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  const int levels = argc == 4 ? std::atoi(argv[2]) : -1;
  if(levels < 0) {
    std::cerr << "usage: refine_mesh IN LEVELS OUT" << std::endl;
    return 2;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || is_empty(mesh) || !CGAL::is_triangle_mesh(mesh)) {
    std::cerr << "refine_mesh: cannot read a triangle mesh from " << argv[1] << std::endl;
    return 1;
  }
  CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  if(!CGAL::IO::write_polygon_mesh(argv[3], mesh, CGAL::parameters::stream_precision(17))) {
    std::cerr << "refine_mesh: cannot write " << argv[3] << std::endl;
    return 1;
  }
  return 0;
}

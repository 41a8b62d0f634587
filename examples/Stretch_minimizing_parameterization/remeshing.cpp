// Remeshing a disk-like mesh with two of its parameterizations, {U^0, U^opt}: the new vertices
// are sampled evenly over the surface through U^opt and triangulated in U^0. Then again with a
// sampling density: more vertices where the surface curves, and twice as many per unit area
// above the middle height as below (a density given per vertex).
//   remeshing [mesh.off] [vertices] [out.off] [adaptive_out.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const char* file = argc > 1 ? argv[1] : "data/mannequin-devil.off";
  const std::size_t vertices = argc > 2 ? std::stoul(argv[2]) : 3000;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }

  Mesh remeshed;
  const SMP::Remeshing_report report = SMP::remesh_with_parameterizations(
      mesh, vertices, remeshed, SMP::parameters::parameterization_pair(SMP::Remeshing_pair::U0_UOPT));
  if(report.status != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(report.status) << ": " << report.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << report.vertices << " vertices (" << report.border_vertices << " on the border), "
            << report.faces << " triangles\n"
            << "sampled through U^opt (L2 stretch " << report.sampling_l2_stretch << "), triangulated in U^0 (L2 stretch "
            << report.triangulation_l2_stretch << ")\n"
            << "angles of 30 degrees or more: " << 100. * report.angles_at_least_30 << "%, the smallest "
            << report.min_angle << " degrees\n"
            << "coefficient of variation of the triangle areas: " << report.area_variation << std::endl;
  const std::string out = argc > 3 ? argv[3] : "remeshed.off";
  if(!CGAL::IO::write_polygon_mesh(out, remeshed, CGAL::parameters::stream_precision(17))) {
    std::cerr << "Error: cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << out << std::endl;

  // a relative density per vertex, multiplied by the curvature's
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(mesh);
  auto density = mesh.add_property_map<Mesh::Vertex_index, double>("v:density", 1.).first;
  for(Mesh::Vertex_index v : mesh.vertices())
    put(density, v, mesh.point(v).z() > 0.5 * (box.zmin() + box.zmax()) ? 2. : 1.);
  Mesh adaptive;
  const SMP::Remeshing_report adapted = SMP::remesh_with_parameterizations(
      mesh, vertices, adaptive, SMP::parameters::vertex_density_map(density).curvature_adaptation(1.));
  if(adapted.status != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(adapted.status) << ": " << adapted.message << std::endl;
    return EXIT_FAILURE;
  }
  const std::string adaptive_out = argc > 4 ? argv[4] : "remeshed_adaptive.off";
  if(!CGAL::IO::write_polygon_mesh(adaptive_out, adaptive, CGAL::parameters::stream_precision(17))) {
    std::cerr << "Error: cannot write " << adaptive_out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "with the density: " << adapted.vertices << " vertices (" << adapted.border_vertices
            << " on the border); wrote " << adaptive_out << std::endl;
  return EXIT_SUCCESS;
}

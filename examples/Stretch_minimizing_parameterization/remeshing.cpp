// Remeshing a disk-like mesh with two of its parameterizations, {U^0, U^opt}: the new vertices
// are sampled evenly over the surface through U^opt and triangulated in U^0.
//   remeshing [mesh.off] [vertices] [out.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>

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
  return EXIT_SUCCESS;
}

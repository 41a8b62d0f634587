// A mean-value start (Floater 2003) on a circular border instead of the paper's
// shape-preserving start on the square, and the measures of the result.
//   mean_value_circular_border [mesh.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

typedef SMP::Circular_border_arc_length_parameterizer_3<Mesh>        Border;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh, Border>    MVC;
typedef SMP::Stretch_minimizing_parameterizer_3<Mesh, MVC>           Parameterizer;

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/mushroom.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  Parameterizer parameterizer(MVC(), SMP::parameters::eta(0.8));
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
  if(status != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(status) << ": " << parameterizer.report().message << std::endl;
    return EXIT_FAILURE;
  }

  const SMP::Stretch_statistics s = SMP::compute_stretch_statistics(mesh, uvmap);
  std::cout << "mean-value start: L2 stretch " << parameterizer.report().history.front().l2_stretch << "\n"
            << "U^opt (h = " << parameterizer.report().kept_step << "): L2 stretch " << s.l2_stretch
            << ", Linf " << s.linf_stretch << "\n"
            << "edge distortion " << s.edge_distortion << ", angle distortion " << s.angle_distortion
            << ", area distortion " << s.area_distortion << ", flipped faces " << s.flipped_faces << std::endl;
  return s.flipped_faces == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

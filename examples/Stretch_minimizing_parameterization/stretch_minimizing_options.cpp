// Options: eta, the iteration cap and a visitor that prints the stretch of each step and may
// stop the iteration early.
//   stretch_minimizing_options [mesh.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/nefertiti.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  // Told after every solve; returning false stops the iteration (the best step is kept).
  auto print_step = [](const SMP::Stretch_minimizing_step& s) {
    std::cout << "  U^" << s.step << ": L2 stretch " << s.l2_stretch << ", Linf " << s.linf_stretch << "\n";
    return s.l2_stretch > 1.05; // good enough below 1.05
  };

  // Smaller eta: smaller, steadier steps, usually a lower final stretch after more of them.
  // A chain started in SMP::parameters takes the package's names (eta) and CGAL's in any order.
  for(double eta : {1.0, 0.5}) {
    SMP::Stretch_minimizing_parameterizer_3<Mesh> parameterizer(
      SMP::parameters::eta(eta).number_of_iterations(10).visitor(print_step));
    std::cout << "eta = " << eta << "\n";
    const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
    if(status != SMP::OK) {
      std::cerr << "Error: " << SMP::error_message(status) << ": " << parameterizer.report().message << std::endl;
      return EXIT_FAILURE;
    }
    std::cout << "  kept U^" << parameterizer.report().kept_step << "\n";
  }

  // One step only: U^1, most of the gain for one more solve.
  SMP::Stretch_minimizing_parameterizer_3<Mesh> one_step(SMP::parameters::number_of_iterations(1));
  if(SMP::parameterize(mesh, one_step, bhd, uvmap) != SMP::OK)
    return EXIT_FAILURE;
  std::cout << "U^1 alone: L2 stretch " << one_step.report().kept().l2_stretch << std::endl;
  return EXIT_SUCCESS;
}

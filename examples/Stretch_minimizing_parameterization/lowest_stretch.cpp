// Beyond the paper: the LOWEST_STRETCH preset, then a polish of Sander's stretch energy with
// the border fixed, and with the border free.
//   lowest_stretch [mesh.off]

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
namespace params = SMP::parameters;

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/three_peaks.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  auto run = [&](const char* what, auto&& parameterizer) {
    const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
    const SMP::Stretch_minimizing_report& r = parameterizer.report();
    if(status != SMP::OK) {
      std::cerr << "Error: " << SMP::error_message(status) << ": " << r.message << std::endl;
      return false;
    }
    std::cout << what << ": L2 stretch " << r.l2_stretch() << " (" << r.history.size() << " solves";
    if(r.polish.ran())
      std::cout << ", then " << r.polish.descent_iterations << " descent and " << r.polish.iterations
                << " Newton steps from " << r.polish.l2_before;
    else if(!r.polish.message.empty())
      std::cout << ", no polish: " << r.polish.message;
    std::cout << ")\n";
    return true;
  };

  typedef SMP::Stretch_minimizing_parameterizer_3<Mesh> Parameterizer;
  // the paper's method, then the preset: clamped cotangent start, edge update, and 30 cheap
  // descent steps on Sander's energy (flip-free) after U^opt
  if(!run("paper", Parameterizer()) ||
     !run("lowest stretch", Parameterizer(params::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH))))
    return EXIT_FAILURE;

  // then at most 50 Newton steps on Sander's energy: no face ever flips, the border stays
  // on the square
  if(!run("lowest stretch + polish", Parameterizer(params::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH,
                                                   params::polish_iterations(50u)))))
    return EXIT_FAILURE;

  // the same with the border free: it never crosses itself; the result is scaled into the unit square
  if(!run("lowest stretch + free border", Parameterizer(params::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH,
                                                        params::polish_iterations(50u, params::free_border(true))))))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}

// Choosing the border: CGAL's square (the paper's), the square with corners that avoid
// flattened border faces, a circle, and the natural border of a conformal map. The same
// stretch minimization runs on each; the table shows what the border costs.
//   borders [mesh.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Natural_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_ear_aware_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

// The paper's method with Floater's start on the given border.
template <typename Border>
bool run(const std::string& name, Mesh& mesh)
{
  typedef SMP::Shape_preserving_parameterizer_3<Mesh, Border> Floater;
  SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> parameterizer;
  auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
  const SMP::Stretch_minimizing_report& r = parameterizer.report();
  std::cout << name << ": ";
  if(status != SMP::OK) { // e.g. a natural border that folds over itself
    std::cout << SMP::error_message(status) << " (" << r.message << ")\n";
    return false;
  }
  std::cout << "L2 stretch " << r.kept().l2_stretch << " after " << r.kept_step << " steps, "
            << r.kept().degenerate_uv_faces << " flattened faces, " << r.kept().flipped_faces << " flipped\n";
  return true;
}

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/mesh_with_border.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  bool ok = run<SMP::Square_border_arc_length_parameterizer_3<Mesh> >("square (CGAL)    ", mesh);
  ok = run<SMP::Square_border_ear_aware_parameterizer_3<Mesh> >("square, ear-aware", mesh) && ok;
  ok = run<SMP::Circular_border_arc_length_parameterizer_3<Mesh> >("circle           ", mesh) && ok;
  // not convex: every step is checked, a flipped map is never returned
  run<SMP::Natural_border_parameterizer_3<Mesh> >("natural (LSCM)   ", mesh);
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

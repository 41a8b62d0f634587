// Default use: the paper's method on a disk-like mesh, written as an OBJ with texture coordinates.
//   stretch_minimizing_parameterization [mesh.off] [out.obj]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/mannequin-devil.off";
  const char* out = argc > 2 ? argv[2] : "mannequin-devil_uv.obj";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(in, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }
  auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  // Floater's shape-preserving start on the unit square, eta = 1, stop when the stretch rises
  SMP::Stretch_minimizing_parameterizer_3<Mesh> parameterizer;
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);

  const SMP::Stretch_minimizing_report& report = parameterizer.report();
  if(status != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(status) << ": " << report.message << std::endl;
    return EXIT_FAILURE;
  }
  for(const SMP::Stretch_minimizing_step& s : report.history)
    std::cout << "U^" << s.step << "  L2 stretch " << s.l2_stretch << "  Linf " << s.linf_stretch
              << "  (" << s.seconds << " s)\n";
  std::cout << "kept U^" << report.kept_step << " (U^opt), L2 stretch " << report.kept().l2_stretch << "\n";

  std::ofstream obj(out);
  obj.precision(17);
  for(vertex_descriptor v : vertices(mesh))
    obj << "v " << mesh.point(v) << "\n";
  for(vertex_descriptor v : vertices(mesh))
    obj << "vt " << uvmap[v].x() << " " << uvmap[v].y() << "\n";
  for(auto f : faces(mesh)) {
    obj << "f";
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      obj << " " << v.idx() + 1 << "/" << v.idx() + 1;
    obj << "\n";
  }
  if(!obj) {
    std::cerr << "Error: cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << out << std::endl;
  return EXIT_SUCCESS;
}

// A mesh made of several pieces: each piece with a border becomes a chart of its own, and
// the charts are laid side by side in one uv map, at one texel density.
//   several_components [mesh.off ...]   (the pieces are joined into one mesh)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize_components.h>

#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  std::vector<const char*> files(argv + 1, argv + argc);
  if(files.empty())
    files = {"data/nefertiti.off", "data/mushroom.off", "data/head.off"};
  Mesh mesh;
  for(const char* file : files) {
    Mesh part;
    if(!CGAL::IO::read_polygon_mesh(file, part) || faces(part).empty()) {
      std::cerr << "Error: cannot read a mesh from " << file << std::endl;
      return EXIT_FAILURE;
    }
    mesh.join(part);
  }
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  std::vector<SMP::Chart> charts;
  const SMP::Error_code status =
    SMP::parameterize_components(mesh, SMP::Stretch_minimizing_parameterizer_3<Mesh>(), uvmap, &charts);
  for(std::size_t c = 0; c < charts.size(); ++c) {
    std::cout << "chart " << c << ": " << charts[c].faces << " faces, ";
    if(charts[c].status == SMP::OK)
      std::cout << "box at (" << charts[c].x << ", " << charts[c].y << "), " << charts[c].width << " x "
                << charts[c].height << "\n";
    else
      std::cout << SMP::error_message(charts[c].status) << "\n";
  }
  return status == SMP::OK ? EXIT_SUCCESS : EXIT_FAILURE;
}

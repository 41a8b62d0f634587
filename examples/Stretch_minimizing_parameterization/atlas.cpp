// A texture atlas of a mesh of any genus, with any number of parts: a uv per halfedge (a vertex
// on a seam has one per chart) and a chart per face, written as an OBJ with a vt per corner.
//   atlas [mesh.off] [out.obj]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const char* file = argc > 1 ? argv[1] : "data/bear.off";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file, mesh) || faces(mesh).empty()) {
    std::cerr << "Error: cannot read a mesh from " << file << std::endl;
    return EXIT_FAILURE;
  }
  auto uv = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
  auto chart = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:chart").first;

  const SMP::Atlas_report report = SMP::make_atlas(mesh, uv, chart, SMP::parameters::gutter(4.));
  if(report.status != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(report.status) << ": " << report.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << report.charts << " charts, L2 stretch " << report.l2_stretch << ", seams "
            << 100. * report.seam_length / report.edge_length << "% of the edge length, utilization "
            << report.utilization << ", " << report.seconds << " s" << std::endl;

  std::ofstream out(argc > 2 ? argv[2] : "atlas.obj");
  out.precision(17);
  for(Mesh::Vertex_index v : vertices(mesh))
    out << "v " << mesh.point(v) << "\n";
  for(Mesh::Halfedge_index h : halfedges(mesh))
    if(!is_border(h, mesh))
      out << "vt " << uv[h] << "\n";
  // one vt per halfedge with a face, in the order written above
  std::size_t k = 0;
  auto vt = mesh.add_property_map<Mesh::Halfedge_index, std::size_t>("h:vt").first;
  for(Mesh::Halfedge_index h : halfedges(mesh))
    if(!is_border(h, mesh))
      vt[h] = ++k;
  for(Mesh::Face_index f : faces(mesh)) {
    out << "f";
    for(Mesh::Halfedge_index h : halfedges_around_face(halfedge(f, mesh), mesh))
      out << " " << std::size_t(target(h, mesh)) + 1 << "/" << vt[h];
    out << "\n";
  }
  return out ? EXIT_SUCCESS : EXIT_FAILURE;
}

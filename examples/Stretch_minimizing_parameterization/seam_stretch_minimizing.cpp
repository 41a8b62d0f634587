// A closed mesh (genus 0) cut open by a seam, then parameterized: make_disk_seam() marks the
// shortest edge path between two vertices far apart, and a CGAL::Seam_mesh presents the cut
// mesh as a disk without modifying it. A seam of your own goes in with Seam_mesh::add_seams().
//   seam_stretch_minimizing [closed_mesh.off] [out.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/make_disk_seam.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>                        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                   Surface_mesh;
typedef Surface_mesh::Vertex_index                            SM_vertex;
typedef Surface_mesh::Halfedge_index                          SM_halfedge;
typedef Surface_mesh::Edge_index                              SM_edge;
typedef Surface_mesh::Property_map<SM_edge, bool>             Seam_edge_map;
typedef Surface_mesh::Property_map<SM_vertex, bool>           Seam_vertex_map;
typedef CGAL::Seam_mesh<Surface_mesh, Seam_edge_map, Seam_vertex_map> Mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/bear.off";
  const char* out = argc > 2 ? argv[2] : "bear_uv.off";
  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(in, sm) || faces(sm).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }

  // view the mesh cut along a seam
  Seam_edge_map seam_edges = sm.add_property_map<SM_edge, bool>("e:on_seam", false).first;
  Seam_vertex_map seam_vertices = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
  Mesh mesh(sm, seam_edges, seam_vertices);
  boost::graph_traits<Mesh>::halfedge_descriptor bhd; // on the border made by the seam
  std::string why;
  const SMP::Error_code cut = SMP::make_disk_seam(mesh, bhd, &why);
  if(cut != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(cut) << ": " << why << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "seam of " << mesh.number_of_seam_edges() << " edges" << std::endl;

  // the uv map is stored per halfedge of the underlying mesh, so that a vertex on the seam
  // has one uv position on each side
  auto uvmap = sm.add_property_map<SM_halfedge, Kernel::Point_2>("h:uv").first;

  SMP::Stretch_minimizing_parameterizer_3<Mesh> parameterizer;
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
  if(status != SMP::OK) {
    std::cerr << "Error: " << SMP::error_message(status) << ": " << parameterizer.report().message << std::endl;
    return EXIT_FAILURE;
  }
  const SMP::Stretch_minimizing_report& report = parameterizer.report();
  std::cout << "U^0 L2 stretch " << report.history.front().l2_stretch << ", U^opt (h = " << report.kept_step
            << ") " << report.kept().l2_stretch << ", flipped faces " << report.kept().flipped_faces << std::endl;

  std::ofstream os(out);
  SMP::IO::output_uvmap_to_off(mesh, bhd, uvmap, os);
  std::cout << "wrote the uv layout to " << out << std::endl;
  return EXIT_SUCCESS;
}

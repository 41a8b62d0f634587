// A closed mesh (genus 0) cut open by a seam, then parameterized: the seam is the shortest
// edge path from a vertex to the vertex farthest from it, and a CGAL::Seam_mesh presents the
// cut mesh as a disk without modifying it.
//   seam_stretch_minimizing [closed_mesh.off] [out.off]

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <queue>
#include <vector>

typedef CGAL::Simple_cartesian<double>                        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                   Surface_mesh;
typedef Surface_mesh::Vertex_index                            SM_vertex;
typedef Surface_mesh::Halfedge_index                          SM_halfedge;
typedef Surface_mesh::Edge_index                              SM_edge;
typedef Surface_mesh::Property_map<SM_edge, bool>             Seam_edge_map;
typedef Surface_mesh::Property_map<SM_vertex, bool>           Seam_vertex_map;
typedef CGAL::Seam_mesh<Surface_mesh, Seam_edge_map, Seam_vertex_map> Mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;

// The shortest edge path (Dijkstra on edge lengths) from `source` to the vertex farthest from it.
std::vector<SM_vertex> longest_shortest_path(const Surface_mesh& sm, SM_vertex source)
{
  std::vector<double> dist(sm.number_of_vertices(), std::numeric_limits<double>::infinity());
  std::vector<SM_vertex> previous(sm.number_of_vertices());
  typedef std::pair<double, SM_vertex> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  dist[source] = 0.;
  queue.emplace(0., source);
  while(!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > dist[v])
      continue;
    for(SM_halfedge h : halfedges_around_source(v, sm)) {
      const SM_vertex w = target(h, sm);
      const double dw = d + std::sqrt(CGAL::squared_distance(sm.point(v), sm.point(w)));
      if(dw < dist[w]) {
        dist[w] = dw;
        previous[w] = v;
        queue.emplace(dw, w);
      }
    }
  }
  SM_vertex far = source;
  for(SM_vertex v : vertices(sm))
    if(dist[v] > dist[far] && dist[v] < std::numeric_limits<double>::infinity())
      far = v;
  std::vector<SM_vertex> path{far};
  while(path.back() != source)
    path.push_back(previous[path.back()]);
  return path;
}

int main(int argc, char** argv)
{
  const char* in = argc > 1 ? argv[1] : "data/bear.off";
  const char* out = argc > 2 ? argv[2] : "bear_uv.off";
  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(in, sm) || faces(sm).empty()) {
    std::cerr << "Error: cannot read a mesh from " << in << std::endl;
    return EXIT_FAILURE;
  }

  // mark the seam, then view the mesh cut along it
  Seam_edge_map seam_edges = sm.add_property_map<SM_edge, bool>("e:on_seam", false).first;
  Seam_vertex_map seam_vertices = sm.add_property_map<SM_vertex, bool>("v:on_seam", false).first;
  Mesh mesh(sm, seam_edges, seam_vertices);
  const std::vector<SM_vertex> path = longest_shortest_path(sm, *vertices(sm).begin());
  for(std::size_t i = 0; i + 1 < path.size(); ++i)
    mesh.add_seam(path[i], path[i + 1]);
  std::cout << "seam of " << path.size() - 1 << " edges" << std::endl;

  // a halfedge on the border created by the seam; the uv map is stored per halfedge of the
  // underlying mesh, so that a vertex on the seam has one uv position on each side
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
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

// Stretch_minimizing_parameterizer_3 through CGAL's free function
// CGAL::Surface_mesh_parameterization::parameterize(mesh, parameterizer, bhd, uvmap) on the
// mesh types of CGAL: Surface_mesh, Polyhedron_3 (uv in a Unique_hash_map) and a Seam_mesh
// cutting a closed surface open (uv keyed by halfedges of the underlying mesh).

#include "smp_test_util.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/make_disk_seam.h>
#include <CGAL/Surface_mesh_parameterization/parameterize_components.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace test_mesh_types {

typedef CGAL::Simple_cartesian<double>                       Kernel;
typedef Kernel::Point_2                                      Point_2;
typedef Kernel::Point_3                                      Point_3;

typedef CGAL::Surface_mesh<Point_3>                          SMesh;
typedef boost::graph_traits<SMesh>::vertex_descriptor        SM_vertex_descriptor;
typedef boost::graph_traits<SMesh>::halfedge_descriptor      SM_halfedge_descriptor;
typedef boost::graph_traits<SMesh>::edge_descriptor          SM_edge_descriptor;

typedef CGAL::Polyhedron_3<Kernel>                           Polyhedron;
typedef boost::graph_traits<Polyhedron>::vertex_descriptor   P_vertex_descriptor;
typedef boost::graph_traits<Polyhedron>::halfedge_descriptor P_halfedge_descriptor;

typedef SMesh::Property_map<SM_edge_descriptor, bool>        Seam_edge_pmap;
typedef SMesh::Property_map<SM_vertex_descriptor, bool>      Seam_vertex_pmap;
typedef CGAL::Seam_mesh<SMesh, Seam_edge_pmap, Seam_vertex_pmap> Seam_mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// Checks common to every mesh type, after
// `status = SMP::parameterize(mesh, p, bhd, uvmap)` with a copy of `p`:
// - OK, and the report (shared with the copy) says OK;
// - the kept step is the argmin of the L2 stretch of the history, has no flipped face, and
//   improves on U^0 (the method did something);
// - every vertex of the component got a finite uv in the unit square (convex square border);
// - compute_stretch_statistics() over the faces of the component, measured independently of
//   the iteration from what was written to `uvmap`, agrees with the kept L2 stretch and finds
//   no flipped face: what was written is the step the report describes.
template <typename TM, typename P, typename UVMap>
void check_run(const std::string& name, const TM& mesh,
               typename boost::graph_traits<TM>::halfedge_descriptor bhd,
               const P& p, UVMap uvmap, SMP::Error_code status)
{
  typedef typename boost::graph_traits<TM>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TM>::vertex_descriptor vertex_descriptor;
  const SMP::Stretch_minimizing_report& r = p.report();
  SMP_CHECK(status == SMP::OK, name << ": " << SMP::error_message(status) << ": " << r.message);
  SMP_CHECK(r.status == SMP::OK, name << ": report().status " << r.status);
  SMP_CHECK(!r.history.empty() && r.kept_step < r.history.size(),
            name << ": history of " << r.history.size() << " steps, kept " << r.kept_step);
  if(status != SMP::OK || r.history.empty() || r.kept_step >= r.history.size())
    return;

  std::size_t argmin = 0;
  for(std::size_t h = 1; h < r.history.size(); ++h)
    if(r.history[h].l2_stretch < r.history[argmin].l2_stretch)
      argmin = h;
  // the class ignores decreases below 1e-10 relative (rounding), so a later step may be lower by that
  SMP_CHECK(r.kept_step == argmin || r.kept().l2_stretch <= r.history[argmin].l2_stretch * (1. + 1e-10),
            name << ": kept U^" << r.kept_step << " (L2 " << r.kept().l2_stretch << ") but the least L2 stretch is U^"
                 << argmin << " (" << r.history[argmin].l2_stretch << ")");
  SMP_CHECK(r.kept().flipped_faces == 0, name << ": kept step has " << r.kept().flipped_faces << " flipped faces");
  SMP_CHECK(r.kept().l2_stretch < r.history.front().l2_stretch,
            name << ": kept L2 " << r.kept().l2_stretch << " not below U^0's " << r.history.front().l2_stretch);

  std::vector<face_descriptor> cc;
  PMP::connected_component(face(opposite(bhd, mesh), mesh), mesh, std::back_inserter(cc));
  SMP_CHECK(cc.size() == r.faces, name << ": component of " << cc.size() << " faces, report says " << r.faces);

  std::size_t outside = 0;
  for(face_descriptor f : cc)
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) {
      const Point_2 q = get(uvmap, v);
      if(!(q.x() >= -1e-12 && q.x() <= 1. + 1e-12 && q.y() >= -1e-12 && q.y() <= 1. + 1e-12))
        ++outside;
    }
  SMP_CHECK(outside == 0, name << ": " << outside << " face corners with a uv outside the unit square");

  const SMP::Stretch_statistics s = SMP::compute_stretch_statistics(cc, mesh, uvmap);
  const double kept = r.kept().l2_stretch;
  SMP_CHECK(std::abs(s.l2_stretch - kept) <= 1e-9 * kept,
            name << ": measured L2 " << s.l2_stretch << ", report says " << kept);
  SMP_CHECK(s.flipped_faces == 0, name << ": " << s.flipped_faces << " flipped faces measured");
  SMP_CHECK(s.number_of_faces == cc.size(), name << ": " << s.number_of_faces << " faces measured");
  std::cout << name << ": " << r.history.size() << " steps, kept U^" << r.kept_step << ", L2 "
            << r.history.front().l2_stretch << " -> " << kept << std::endl;
}

// (a) Surface_mesh and (b) Polyhedron_3 read from the same OFF file, with the same border
// halfedge (same source and target vertex): both must succeed, and since the algorithm is
// deterministic the uv of each vertex must agree (vertices in the order of the file).
void test_surface_mesh_and_polyhedron()
{
  const std::string file = smp_test::data_file("mushroom.off");

  SMesh sm;
  SMP_CHECK(CGAL::IO::read_polygon_mesh(file, sm) && !faces(sm).empty(), "cannot read " << file);
  const SM_halfedge_descriptor sm_bhd = PMP::longest_border(sm).first;
  SMesh::Property_map<SM_vertex_descriptor, Point_2> sm_uv =
    sm.add_property_map<SM_vertex_descriptor, Point_2>("v:uv", Point_2(-7., -7.)).first;
  SMP::Stretch_minimizing_parameterizer_3<SMesh> sm_p;
  const SMP::Error_code sm_status = SMP::parameterize(sm, sm_p, sm_bhd, sm_uv);
  check_run("Surface_mesh", sm, sm_bhd, sm_p, sm_uv, sm_status);

  Polyhedron poly;
  SMP_CHECK(CGAL::IO::read_polygon_mesh(file, poly) && !faces(poly).empty(), "cannot read " << file);
  std::vector<P_vertex_descriptor> pv(vertices(poly).begin(), vertices(poly).end());
  SMP_CHECK(pv.size() == num_vertices(sm), "Polyhedron has " << pv.size() << " vertices, Surface_mesh "
                                                             << num_vertices(sm));
  if(pv.size() != num_vertices(sm))
    return;
  std::size_t moved = 0;
  for(SM_vertex_descriptor v : vertices(sm))
    if(sm.point(v) != pv[v.idx()]->point())
      ++moved;
  SMP_CHECK(moved == 0, moved << " vertices are not in the same order in the Polyhedron");

  const std::pair<P_halfedge_descriptor, bool> ph =
    halfedge(pv[source(sm_bhd, sm).idx()], pv[target(sm_bhd, sm).idx()], poly);
  SMP_CHECK(ph.second && is_border(ph.first, poly), "the border halfedge has no counterpart in the Polyhedron");
  if(!ph.second)
    return;
  const P_halfedge_descriptor p_bhd = ph.first;

  typedef CGAL::Unique_hash_map<P_vertex_descriptor, Point_2> UV_uhm;
  UV_uhm uv_uhm(Point_2(-7., -7.));
  boost::associative_property_map<UV_uhm> p_uv(uv_uhm);
  SMP::Stretch_minimizing_parameterizer_3<Polyhedron> p_p;
  const SMP::Error_code p_status = SMP::parameterize(poly, p_p, p_bhd, p_uv);
  check_run("Polyhedron_3", poly, p_bhd, p_p, p_uv, p_status);

  SMP_CHECK(sm_p.report().kept_step == p_p.report().kept_step &&
            sm_p.report().history.size() == p_p.report().history.size(),
            "Surface_mesh kept U^" << sm_p.report().kept_step << " of " << sm_p.report().history.size()
                                   << ", Polyhedron U^" << p_p.report().kept_step << " of "
                                   << p_p.report().history.size());
  double worst = 0.;
  for(SM_vertex_descriptor v : vertices(sm)) {
    const Point_2 a = get(sm_uv, v), b = get(p_uv, pv[v.idx()]);
    worst = (std::max)(worst, (std::max)(std::abs(a.x() - b.x()), std::abs(a.y() - b.y())));
  }
  SMP_CHECK(worst <= 1e-12, "Surface_mesh and Polyhedron uv differ by " << worst);
  std::cout << "Surface_mesh vs Polyhedron_3: largest uv difference " << worst << std::endl;
}

// Shortest path (Dijkstra, edge lengths) from `from` to the vertex farthest from it; returns
// the path as a list of vertices from the far vertex back to `from`.
std::vector<SM_vertex_descriptor> path_to_farthest(const SMesh& sm, SM_vertex_descriptor from)
{
  const std::size_t n = sm.number_of_vertices() + sm.number_of_removed_vertices();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<SM_vertex_descriptor> pred(n, SMesh::null_vertex());
  typedef std::pair<double, SM_vertex_descriptor> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  dist[from.idx()] = 0.;
  queue.push(Entry(0., from));
  while(!queue.empty()) {
    const Entry e = queue.top();
    queue.pop();
    if(e.first > dist[e.second.idx()])
      continue;
    for(SM_vertex_descriptor w : vertices_around_target(halfedge(e.second, sm), sm)) {
      const double d = e.first + std::sqrt(CGAL::squared_distance(sm.point(e.second), sm.point(w)));
      if(d < dist[w.idx()]) {
        dist[w.idx()] = d;
        pred[w.idx()] = e.second;
        queue.push(Entry(d, w));
      }
    }
  }
  SM_vertex_descriptor far = from;
  for(SM_vertex_descriptor v : vertices(sm))
    if(std::isfinite(dist[v.idx()]) && dist[v.idx()] > dist[far.idx()])
      far = v;
  std::vector<SM_vertex_descriptor> path(1, far);
  while(path.back() != from && pred[path.back().idx()] != SMesh::null_vertex())
    path.push_back(pred[path.back().idx()]);
  return path;
}

// (c) A Seam_mesh over the closed bear: the seam is the shortest path from vertex 0 to the
// vertex farthest from it, which cuts the sphere into a disk whose border runs along both
// sides of the seam. bhd is a border halfedge of the seam mesh, the uv map is keyed by
// halfedges of the underlying Surface_mesh as in CGAL's seam example. Besides the common
// checks, the report's vertex counts must match the cut: 2 * seam edges on the border, and
// the inner vertices of the seam doubled.
void test_seam_mesh()
{
  const std::string file = smp_test::data_file("bear.off");
  SMesh sm;
  SMP_CHECK(CGAL::IO::read_polygon_mesh(file, sm) && !faces(sm).empty(), "cannot read " << file);
  SMP_CHECK(CGAL::is_closed(sm), "bear.off is expected to be closed");

  Seam_edge_pmap seam_edges = sm.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
  Seam_vertex_pmap seam_vertices = sm.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
  Seam_mesh mesh(sm, seam_edges, seam_vertices);

  const std::vector<SM_vertex_descriptor> path = path_to_farthest(sm, *vertices(sm).begin());
  SMP_CHECK(path.size() >= 3 && path.back() == *vertices(sm).begin(),
            "seam path of " << path.size() << " vertices does not reach vertex 0");
  std::vector<SM_vertex_descriptor> pairs; // consecutive pairs for add_seams()
  for(std::size_t i = 0; i + 1 < path.size(); ++i) {
    pairs.push_back(path[i]);
    pairs.push_back(path[i + 1]);
  }
  const SM_halfedge_descriptor seam_hd = mesh.add_seams(pairs.begin(), pairs.end());
  const std::size_t seam_length = path.size() - 1;
  SMP_CHECK(seam_hd != SMesh::null_halfedge() && mesh.number_of_seam_edges() == seam_length,
            mesh.number_of_seam_edges() << " seam edges marked, path has " << seam_length);

  typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor halfedge_descriptor;
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  SMP_CHECK(bhd != halfedge_descriptor() && is_border(bhd, mesh) && mesh.has_on_seam(bhd),
            "no border halfedge on the seam of the seam mesh");
  std::size_t border_length = 0;
  for(halfedge_descriptor h : halfedges_around_face(bhd, mesh)) {
    (void)h;
    ++border_length;
  }
  SMP_CHECK(border_length == 2 * seam_length,
            "the seam mesh border has " << border_length << " edges, expected " << 2 * seam_length);

  SMesh::Property_map<SM_halfedge_descriptor, Point_2> uvmap =
    sm.add_property_map<SM_halfedge_descriptor, Point_2>("h:uv", Point_2(-7., -7.)).first;
  SMP::Stretch_minimizing_parameterizer_3<Seam_mesh> p;
  const SMP::Error_code status = SMP::parameterize(mesh, p, bhd, uvmap);
  check_run("Seam_mesh", mesh, bhd, p, uvmap, status);
  SMP_CHECK(p.report().border_vertices == 2 * seam_length,
            "Seam_mesh: " << p.report().border_vertices << " border vertices, expected " << 2 * seam_length);
  SMP_CHECK(p.report().interior_vertices + p.report().border_vertices == num_vertices(sm) + seam_length - 1,
            "Seam_mesh: " << p.report().interior_vertices + p.report().border_vertices
                          << " vertices, expected " << num_vertices(sm) + seam_length - 1);
  SMP_CHECK(p.report().faces == num_faces(sm), "Seam_mesh: " << p.report().faces << " faces of " << num_faces(sm));
}

// make_disk_seam(): a closed genus-0 mesh is cut by one path into a disk and parameterized
// without degenerate faces; what it cannot cut gets an error and no seam.
void test_make_disk_seam()
{
  for(const char* name : {"bear.off", "bunny00.off"}) {
    SMesh sm;
    SMP_CHECK(CGAL::IO::read_polygon_mesh(smp_test::data_file(name), sm) && CGAL::is_closed(sm), "cannot read " << name);
    Seam_edge_pmap seam_edges = sm.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
    Seam_vertex_pmap seam_vertices = sm.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
    Seam_mesh mesh(sm, seam_edges, seam_vertices);
    boost::graph_traits<Seam_mesh>::halfedge_descriptor bhd;
    std::string why;
    const SMP::Error_code cut = SMP::make_disk_seam(mesh, bhd, &why);
    SMP_CHECK(cut == SMP::OK, name << ": make_disk_seam: " << why);
    if(cut != SMP::OK)
      continue;
    std::size_t border_length = 0;
    for(auto h : halfedges_around_face(bhd, mesh)) { (void)h; ++border_length; }
    SMP_CHECK(is_border(bhd, mesh) && border_length == 2 * mesh.number_of_seam_edges() && border_length >= 4,
              name << ": border of " << border_length << " edges for " << mesh.number_of_seam_edges() << " seam edges");

    SMesh::Property_map<SM_halfedge_descriptor, Point_2> uvmap =
      sm.add_property_map<SM_halfedge_descriptor, Point_2>("h:uv", Point_2(-7., -7.)).first;
    SMP::Stretch_minimizing_parameterizer_3<Seam_mesh> p;
    check_run(std::string(name) + " cut by make_disk_seam", mesh, bhd, p, uvmap, SMP::parameterize(mesh, p, bhd, uvmap));
    SMP_CHECK(p.report().status == SMP::OK && p.report().kept().degenerate_uv_faces == 0 && p.report().degenerate_3d_faces == 0,
              name << ": degenerate faces after the cut");
  }

  // what one path cannot cut into a disk: a border, a handle, two components, nothing
  auto expect_error = [](SMesh& sm, const char* what) {
    Seam_edge_pmap se = sm.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
    Seam_vertex_pmap sv = sm.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
    Seam_mesh mesh(sm, se, sv);
    boost::graph_traits<Seam_mesh>::halfedge_descriptor bhd;
    std::string why;
    const SMP::Error_code e = SMP::make_disk_seam(mesh, bhd, &why);
    SMP_CHECK(e != SMP::OK && !why.empty() && mesh.number_of_seam_edges() == 0,
              what << ": got " << SMP::error_message(e) << " (" << why << "), " << mesh.number_of_seam_edges() << " seam edges");
    return e;
  };
  SMesh with_border;
  CGAL::IO::read_polygon_mesh(smp_test::data_file("nefertiti.off"), with_border);
  SMP_CHECK(expect_error(with_border, "open mesh") == SMP::ERROR_NO_TOPOLOGICAL_BALL, "open mesh: wrong code");

  SMesh torus; // 8 x 6 quads split in triangles, genus 1
  std::vector<SM_vertex_descriptor> tv;
  const int n = 8, m = 6;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) {
      const double a = 2 * 3.14159265358979 * i / n, b = 2 * 3.14159265358979 * j / m;
      tv.push_back(torus.add_vertex(Point_3((3 + std::cos(b)) * std::cos(a), (3 + std::cos(b)) * std::sin(a), std::sin(b))));
    }
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) {
      auto V = [&](int x, int y) { return tv[((x + n) % n) * m + (y + m) % m]; };
      torus.add_face(V(i, j), V(i + 1, j), V(i + 1, j + 1));
      torus.add_face(V(i, j), V(i + 1, j + 1), V(i, j + 1));
    }
  SMP_CHECK(CGAL::is_closed(torus) && faces(torus).size() == std::size_t(2 * n * m), "torus construction");
  SMP_CHECK(expect_error(torus, "torus") == SMP::ERROR_NO_TOPOLOGICAL_BALL, "torus: wrong code");

  SMesh two;
  CGAL::IO::read_polygon_mesh(smp_test::data_file("bear.off"), two);
  SMesh copy = two;
  for(SM_vertex_descriptor v : vertices(copy))
    copy.point(v) = copy.point(v) + Kernel::Vector_3(100, 0, 0);
  two.join(copy);
  SMP_CHECK(expect_error(two, "two spheres") == SMP::ERROR_NO_TOPOLOGICAL_BALL, "two spheres: wrong code");

  SMesh empty;
  SMP_CHECK(expect_error(empty, "empty") == SMP::ERROR_EMPTY_MESH, "empty: wrong code");
}

// parameterize_components(): every component with a border becomes a chart of its own, the
// charts do not overlap and fit the unit square, each is the map the parameterizer gives for
// it alone (same stretch: the measure ignores scale and translation), and a closed component
// is reported and left alone.
void test_components()
{
  SMesh mesh, part;
  SMP_CHECK(CGAL::IO::read_polygon_mesh(smp_test::data_file("nefertiti.off"), mesh), "nefertiti");
  for(const char* name : {"mushroom.off", "head.off", "bear.off"}) {
    part.clear();
    SMP_CHECK(CGAL::IO::read_polygon_mesh(smp_test::data_file(name), part), name);
    for(SM_vertex_descriptor v : vertices(part))
      part.point(v) = part.point(v) + Kernel::Vector_3(1000, 0, 0); // far apart, not that it matters
    mesh.join(part);
  }
  auto uv = mesh.add_property_map<SM_vertex_descriptor, Point_2>("v:uv", Point_2(-7, -7)).first;
  std::vector<SMP::Chart> charts;
  SMP::Stretch_minimizing_parameterizer_3<SMesh> p;
  const SMP::Error_code e = SMP::parameterize_components(mesh, p, uv, &charts);
  SMP_CHECK(e == SMP::ERROR_NO_TOPOLOGICAL_DISC, "components: the closed bear should be reported, got " << SMP::error_message(e));
  SMP_CHECK(charts.size() == 4, "components: " << charts.size() << " charts");

  auto component = mesh.add_property_map<SMesh::Face_index, std::size_t>("f:cc").first;
  PMP::connected_components(mesh, component);
  std::size_t closed = 0;
  for(std::size_t c = 0; c < charts.size(); ++c) {
    std::vector<SMesh::Face_index> cc;
    for(auto f : faces(mesh))
      if(component[f] == c) cc.push_back(f);
    SMP_CHECK(cc.size() == charts[c].faces, "chart " << c << ": face count");
    if(charts[c].status != SMP::OK) {
      ++closed;
      for(auto f : cc)
        for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
          SMP_CHECK(uv[v] == Point_2(-7, -7), "the closed component was written");
      continue;
    }
    const SMP::Stretch_statistics s = SMP::compute_stretch_statistics(cc, mesh, uv);
    SMP_CHECK(s.flipped_faces == 0, "chart " << c << ": flipped faces");
    // the same component alone
    SMesh alone;
    CGAL::Face_filtered_graph<SMesh> filtered(mesh, cc);
    CGAL::copy_face_graph(filtered, alone);
    auto uva = alone.add_property_map<SM_vertex_descriptor, Point_2>("v:uv").first;
    SMP::Stretch_minimizing_parameterizer_3<SMesh> q;
    SMP_CHECK(SMP::parameterize(alone, q, PMP::longest_border(alone).first, uva) == SMP::OK, "chart " << c << " alone");
    SMP_CHECK(std::abs(q.report().kept().l2_stretch - s.l2_stretch) < 1e-8 * s.l2_stretch,
              "chart " << c << ": L2 " << s.l2_stretch << " in the atlas, " << q.report().kept().l2_stretch << " alone");
    for(auto f : cc)
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) {
        const Point_2 t = uv[v];
        SMP_CHECK(t.x() >= charts[c].x - 1e-12 && t.x() <= charts[c].x + charts[c].width + 1e-12 &&
                  t.y() >= charts[c].y - 1e-12 && t.y() <= charts[c].y + charts[c].height + 1e-12 &&
                  t.x() >= 0. && t.y() >= 0. && t.x() <= 1. + 1e-12 && t.y() <= 1. + 1e-12,
                  "chart " << c << ": a vertex outside its box or the unit square");
      }
    for(std::size_t d = 0; d < c; ++d)
      if(charts[d].status == SMP::OK)
        SMP_CHECK(charts[c].x + charts[c].width <= charts[d].x || charts[d].x + charts[d].width <= charts[c].x ||
                  charts[c].y + charts[c].height <= charts[d].y || charts[d].y + charts[d].height <= charts[c].y,
                  "charts " << c << " and " << d << " overlap");
  }
  SMP_CHECK(closed == 1, "components: " << closed << " charts failed, expected the bear only");
}

} // namespace

int run_test(int, char**)
{
  test_surface_mesh_and_polyhedron();
  test_seam_mesh();
  test_make_disk_seam();
  test_components();
  return smp_test::summary();
}

} // namespace test_mesh_types

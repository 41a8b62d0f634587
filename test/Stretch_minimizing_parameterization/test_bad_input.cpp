// Bad input for Stretch_minimizing_parameterizer_3::parameterize(): every case must return
// the Error_code that the class documentation gives, record it in report(), and leave the
// data it does not own untouched (uv of other components, of isolated vertices, and of the
// interior when the error is raised before any solve).

#include "smp_test_mesh.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace test_bad_input {

using namespace smp_test;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef SMP::Stretch_minimizing_parameterizer_3<Mesh>        Parameterizer;
typedef SMP::Stretch_minimizing_parameterizer_3<
          Mesh, SMP::Mean_value_coordinates_parameterizer_3<
                  Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh> > >
                                                             Circular_parameterizer;

namespace {

const Point_2 sentinel = smp_test::unwritten_uv;
const double nan_value = std::numeric_limits<double>::quiet_NaN();

bool is_sentinel(const Point_2& p) { return p.x() == sentinel.x() && p.y() == sentinel.y(); }

// Number of vertices of `vs` whose uv was changed / that are marked parameterized.
template <typename Range>
std::size_t changed_uv(const Maps& maps, const Range& vs)
{
  std::size_t n = 0;
  for(vertex_descriptor v : vs)
    if(!is_sentinel(get(maps.uv, v)))
      ++n;
  return n;
}

template <typename Range>
std::size_t marked(const Maps& maps, const Range& vs)
{
  std::size_t n = 0;
  for(vertex_descriptor v : vs)
    if(get(maps.vp, v))
      ++n;
  return n;
}

// Vertices of the faces of the connected component of `bhd`.
std::set<vertex_descriptor> component_vertices(const Mesh& m, halfedge_descriptor bhd)
{
  std::vector<face_descriptor> cc;
  PMP::connected_component(face(opposite(bhd, m), m), m, std::back_inserter(cc));
  std::set<vertex_descriptor> vs;
  for(face_descriptor f : cc)
    for(vertex_descriptor v : vertices_around_face(halfedge(f, m), m))
      vs.insert(v);
  return vs;
}

std::vector<vertex_descriptor> outside(const Mesh& m, const std::set<vertex_descriptor>& component)
{
  std::vector<vertex_descriptor> r;
  for(vertex_descriptor v : vertices(m))
    if(component.count(v) == 0)
      r.push_back(v);
  return r;
}

// Vertices of the component of `bhd` that are not on the border loop of `bhd`.
std::vector<vertex_descriptor> interior(const Mesh& m, halfedge_descriptor bhd)
{
  std::set<vertex_descriptor> border;
  for(halfedge_descriptor h : halfedges_around_face(bhd, m))
    border.insert(target(h, m));
  std::vector<vertex_descriptor> r;
  for(vertex_descriptor v : component_vertices(m, bhd))
    if(border.count(v) == 0)
      r.push_back(v);
  return r;
}

// (a)+(b)+(c): the call returned (no crash), with `expected`, and the report agrees.
template <typename P>
void check_code(const std::string& name, SMP::Error_code got, SMP::Error_code expected, const P& p)
{
  SMP_CHECK(got == expected, name << ": returned " << got << " (" << SMP::error_message(got)
                                  << "), expected " << expected << " (" << SMP::error_message(expected)
                                  << "); message: " << p.report().message);
  SMP_CHECK(p.report().status == got, name << ": report().status " << p.report().status
                                           << " differs from the returned " << got);
  if(expected != SMP::OK) {
    SMP_CHECK(!p.report().message.empty(), name << ": no report().message for an error");
  } else {
    SMP_CHECK(!p.report().history.empty(), name << ": OK but no step in report().history");
  }
}

// (d) for errors raised before any solve: no step in the history and no vertex of the mesh
// written; `written_border` tells whether the border parameterizer may have run (it writes
// the border loop of `bhd` and nothing else).
template <typename P>
void check_untouched(const std::string& name, const Mesh& m, halfedge_descriptor bhd,
                     const Maps& maps, const P& p, bool written_border)
{
  SMP_CHECK(p.report().history.empty(), name << ": error before any solve, yet "
                                              << p.report().history.size() << " steps in the history");
  if(!written_border || bhd == boost::graph_traits<Mesh>::null_halfedge()) {
    SMP_CHECK(changed_uv(maps, vertices(m)) == 0,
              name << ": " << changed_uv(maps, vertices(m)) << " uv written by a failed call");
    SMP_CHECK(marked(maps, vertices(m)) == 0,
              name << ": " << marked(maps, vertices(m)) << " vertices marked parameterized by a failed call");
    return;
  }
  std::set<vertex_descriptor> border;
  for(halfedge_descriptor h : halfedges_around_face(bhd, m))
    border.insert(target(h, m));
  std::vector<vertex_descriptor> not_border;
  for(vertex_descriptor v : vertices(m))
    if(border.count(v) == 0)
      not_border.push_back(v);
  SMP_CHECK(changed_uv(maps, not_border) == 0,
            name << ": " << changed_uv(maps, not_border) << " non-border uv written by a failed call");
  SMP_CHECK(marked(maps, not_border) == 0,
            name << ": " << marked(maps, not_border) << " non-border vertices marked by a failed call");
}

// A successful call wrote a finite uv to every vertex of the component of `bhd`, marked
// them, and left every other vertex alone.
template <typename P>
void check_success(const std::string& name, const Mesh& m, halfedge_descriptor bhd, const Maps& maps,
                   const P& p)
{
  const std::set<vertex_descriptor> cc = component_vertices(m, bhd);
  std::size_t bad = 0;
  for(vertex_descriptor v : cc) {
    const Point_2 q = get(maps.uv, v);
    if(is_sentinel(q) || !std::isfinite(q.x()) || !std::isfinite(q.y()) || !get(maps.vp, v))
      ++bad;
  }
  SMP_CHECK(bad == 0, name << ": " << bad << " vertices of the component without a finite uv");
  const std::vector<vertex_descriptor> out = outside(m, cc);
  SMP_CHECK(changed_uv(maps, out) == 0,
            name << ": " << changed_uv(maps, out) << " uv written outside the component");
  SMP_CHECK(marked(maps, out) == 0, name << ": " << marked(maps, out) << " vertices marked outside the component");
  SMP_CHECK(p.report().interior_vertices + p.report().border_vertices == cc.size(),
            name << ": report counts " << p.report().interior_vertices << " + " << p.report().border_vertices
                 << " vertices, the component has " << cc.size());
  if(!p.report().history.empty()) {
    SMP_CHECK(p.report().kept().flipped_faces == 0, name << ": the kept step has flipped faces");
    SMP_CHECK(std::isfinite(p.report().kept().l2_stretch) && p.report().kept().l2_stretch > 0.,
              name << ": kept L2 stretch " << p.report().kept().l2_stretch);
  }
}

std::size_t number_of_boundaries(const Mesh& m)
{
  std::vector<halfedge_descriptor> cycles;
  PMP::extract_boundary_cycles(m, std::back_inserter(cycles));
  return cycles.size();
}

// Signed area of every face of a mesh lying in the plane z = 0.
std::vector<double> planar_signed_areas(const Mesh& m)
{
  std::vector<double> r;
  for(face_descriptor f : faces(m)) {
    std::vector<Point_3> p;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, m), m))
      p.push_back(m.point(v));
    r.push_back(0.5 * ((p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) -
                       (p[2].x() - p[0].x()) * (p[1].y() - p[0].y())));
  }
  return r;
}

// A triangulated torus (n x k quads, each split in two), closed, genus 1.
Mesh make_torus(int n, int k)
{
  Mesh m;
  const double pi = 3.14159265358979323846, R = 3., r = 1.;
  std::vector<vertex_descriptor> v;
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < n; ++i) {
      const double u = 2. * pi * i / n, w = 2. * pi * j / k;
      v.push_back(m.add_vertex(Point_3((R + r * std::cos(w)) * std::cos(u),
                                       (R + r * std::cos(w)) * std::sin(u), r * std::sin(w))));
    }
  auto at = [&](int i, int j) { return v[std::size_t((j % k) * n + (i % n))]; };
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < n; ++i) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

// =============================================================================================

// An empty mesh has nothing to parameterize: ERROR_EMPTY_MESH, also when it holds vertices
// but no face (the "is there any border?" scan must not mistake it for a closed surface).
void test_empty_mesh()
{
  {
    Mesh m;
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, Mesh::null_halfedge(), maps.uv, maps.vi, maps.vp);
    check_code("empty mesh", e, SMP::ERROR_EMPTY_MESH, p);
    check_untouched("empty mesh", m, Mesh::null_halfedge(), maps, p, false);
  }
  {
    Mesh m;
    m.add_vertex(Point_3(0, 0, 0));
    m.add_vertex(Point_3(1, 0, 0));
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, Mesh::null_halfedge(), maps.uv, maps.vi, maps.vp);
    check_code("vertices without faces", e, SMP::ERROR_EMPTY_MESH, p);
    check_untouched("vertices without faces", m, Mesh::null_halfedge(), maps, p, false);
  }
}

// A closed surface has no border: with the null halfedge that is ERROR_NO_TOPOLOGICAL_DISC
// (cut it first); a halfedge that is not on a border is a wrong parameter. Checked on the
// bear (genus 0) and on a tetrahedron built here.
void test_closed_mesh()
{
  Mesh bear = read_mesh("bear.off");
  SMP_CHECK(number_of_boundaries(bear) == 0, "bear.off is expected to be closed");
  {
    Maps maps = make_maps(bear);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(bear, Mesh::null_halfedge(), maps.uv, maps.vi, maps.vp);
    check_code("closed bear, null halfedge", e, SMP::ERROR_NO_TOPOLOGICAL_DISC, p);
    check_untouched("closed bear, null halfedge", bear, Mesh::null_halfedge(), maps, p, false);
  }
  {
    Maps maps = make_maps(bear);
    Parameterizer p;
    const halfedge_descriptor h = halfedge(*faces(bear).begin(), bear);
    const SMP::Error_code e = p.parameterize(bear, h, maps.uv, maps.vi, maps.vp);
    check_code("closed bear, face halfedge", e, SMP::ERROR_WRONG_PARAMETER, p);
    check_untouched("closed bear, face halfedge", bear, h, maps, p, false);
  }

  Mesh tet;
  CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0, 0, 1), tet);
  {
    Maps maps = make_maps(tet);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(tet, Mesh::null_halfedge(), maps.uv, maps.vi, maps.vp);
    check_code("tetrahedron, null halfedge", e, SMP::ERROR_NO_TOPOLOGICAL_DISC, p);
    check_untouched("tetrahedron, null halfedge", tet, Mesh::null_halfedge(), maps, p, false);
  }
  for(halfedge_descriptor h : halfedges(tet)) { // every halfedge of a closed mesh is a face halfedge
    Maps maps = make_maps(tet);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(tet, h, maps.uv, maps.vi, maps.vp);
    check_code("tetrahedron, halfedge " + std::to_string(h.idx()), e, SMP::ERROR_WRONG_PARAMETER, p);
    check_untouched("tetrahedron, face halfedge", tet, h, maps, p, false);
  }
}

// On a disk, `bhd` must be a border halfedge: the opposite of a border halfedge (inner side
// of a border edge), an inner halfedge and the null halfedge are all ERROR_WRONG_PARAMETER,
// before anything is written.
void test_not_a_border_halfedge()
{
  Mesh m = read_mesh("nefertiti.off");
  const halfedge_descriptor b = PMP::longest_border(m).first;
  halfedge_descriptor inner = Mesh::null_halfedge();
  for(halfedge_descriptor h : halfedges(m))
    if(!is_border(edge(h, m), m)) {
      inner = h;
      break;
    }
  const std::pair<std::string, halfedge_descriptor> cases[] = {
    {"disk, inner side of a border edge", opposite(b, m)},
    {"disk, inner halfedge", inner},
    {"disk, null halfedge", Mesh::null_halfedge()}};
  for(const auto& c : cases) {
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, c.second, maps.uv, maps.vi, maps.vp);
    check_code(c.first, e, SMP::ERROR_WRONG_PARAMETER, p);
    check_untouched(c.first, m, c.second, maps, p, false);
  }
}

// A face with more than three sides in the component: ERROR_NON_TRIANGULAR_MESH, found while
// the component is read, so before the border is written. Two inner triangles of nefertiti
// merged with join_face (the mesh keeps garbage, which must not matter), and a grid of quads.
// A quad in ANOTHER component must not matter: only the component of bhd is read.
void test_non_triangular()
{
  {
    Mesh m = read_mesh("nefertiti.off");
    const halfedge_descriptor bhd = PMP::longest_border(m).first;
    // an edge whose two ends are inner vertices (the merged face stays a proper quad)
    halfedge_descriptor j = Mesh::null_halfedge();
    for(halfedge_descriptor h : halfedges(m))
      if(!is_border(source(h, m), m) && !is_border(target(h, m), m)) {
        j = h;
        break;
      }
    SMP_CHECK(j != Mesh::null_halfedge(), "nefertiti has no inner edge between inner vertices");
    CGAL::Euler::join_face(j, m);
    SMP_CHECK(m.has_garbage(), "join_face is expected to leave garbage in a Surface_mesh");
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("nefertiti with a quad", e, SMP::ERROR_NON_TRIANGULAR_MESH, p);
    check_untouched("nefertiti with a quad", m, bhd, maps, p, false);
  }
  {
    Grid g = make_grid(3, 3, true);
    const halfedge_descriptor bhd = border_halfedge_from(g.mesh, g.at(0, 0));
    Maps maps = make_maps(g.mesh);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(g.mesh, bhd, maps.uv, maps.vi, maps.vp);
    check_code("grid of quads", e, SMP::ERROR_NON_TRIANGULAR_MESH, p);
    check_untouched("grid of quads", g.mesh, bhd, maps, p, false);
  }
  {
    Mesh m = read_mesh("nefertiti.off");
    const halfedge_descriptor bhd = PMP::longest_border(m).first;
    Grid g = make_grid(2, 2, true);
    CGAL::copy_face_graph(g.mesh, m);
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("nefertiti + a separate grid of quads", e, SMP::OK, p);
    check_success("nefertiti + a separate grid of quads", m, bhd, maps, p);
  }
}

// Isolated vertices (no face) placed BEFORE the disk in the vertex numbering, one with a NaN
// coordinate: they are not part of the component of bhd, so the call succeeds, gives the uv
// of the disk alone, and leaves their uv alone. CGAL's free function numbers vimap over the
// whole mesh here (the component has all the faces), so a parameterizer that sizes its system
// by the component but indexes it by vimap goes out of bounds: CGAL 5.5.1's
// Fixed_border_parameterizer_3 (e.g. Mean_value_coordinates_parameterizer_3) does, ASan
// reports a heap-buffer-overflow in setFromTriplets. Under the sanitizers this case catches
// such indexing.
void test_isolated_vertices()
{
  Mesh disk = read_mesh("nefertiti.off");
  const halfedge_descriptor disk_bhd = PMP::longest_border(disk).first;
  Maps disk_maps = make_maps(disk);
  {
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(disk, disk_bhd, disk_maps.uv, disk_maps.vi, disk_maps.vp);
    check_code("nefertiti alone", e, SMP::OK, p);
  }

  Mesh m;
  std::vector<vertex_descriptor> isolated;
  for(int i = 0; i < 5; ++i)
    isolated.push_back(m.add_vertex(Point_3(100. + i, -50., 3.)));
  m.point(isolated[2]) = Point_3(nan_value, 0., 0.);
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > v2v;
  std::vector<std::pair<halfedge_descriptor, halfedge_descriptor> > h2h;
  CGAL::copy_face_graph(disk, m,
                        CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                                         .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h)));
  halfedge_descriptor bhd = Mesh::null_halfedge();
  for(const auto& hh : h2h)
    if(hh.first == disk_bhd)
      bhd = hh.second;
  SMP_CHECK(bhd != Mesh::null_halfedge() && is_border(bhd, m), "copied border halfedge not found");
  SMP_CHECK(isolated.front().idx() == 0, "the isolated vertices are expected first");

  auto same_as_disk = [&](const std::string& name, const Maps& maps) {
    double worst = 0.;
    for(const auto& vv : v2v) {
      const Point_2 a = get(disk_maps.uv, vv.first), b = get(maps.uv, vv.second);
      worst = (std::max)(worst, (std::max)(std::abs(a.x() - b.x()), std::abs(a.y() - b.y())));
    }
    SMP_CHECK(worst <= 1e-9, name << ": uv differs from the disk alone by " << worst);
  };

  {
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("isolated vertices, member", e, SMP::OK, p);
    check_success("isolated vertices, member", m, bhd, maps, p);
    SMP_CHECK(changed_uv(maps, isolated) == 0, "isolated vertices, member: their uv was written");
    same_as_disk("isolated vertices, member", maps);
  }
  {
    Maps maps = make_maps(m);
    Parameterizer p;
    // the free function copies the parameterizer; the copy shares the report
    const SMP::Error_code e = SMP::parameterize(m, p, bhd, maps.uv);
    check_code("isolated vertices, SMP::parameterize", e, SMP::OK, p);
    SMP_CHECK(changed_uv(maps, isolated) == 0, "isolated vertices, SMP::parameterize: their uv was written");
    same_as_disk("isolated vertices, SMP::parameterize", maps);
  }
}

// A face of zero 3D area with three distinct collinear vertices. Planar 4x4 grid, bhd starting
// at the corner (0, 0), the inner vertex (2, 2) moved to (3, 2.5): it lies on the segment of
// its neighbours a = (3, 2) and b = (3, 3), so the face (v, a, b) is flat; every other face
// keeps a positive area. Reading the code:
// - Disk_component accepts it (finite, triangles, a disk);
// - the shape-preserving weights stay finite and positive: all spokes have non-zero length,
//   the ring of v has one angle of exactly pi (scaled total 2 pi, so no mean-value fallback)
//   and the rings of a and b have a zero angle, both handled by the construction;
// - the flat face is counted in degenerate_3d_faces and left out of the measures, so the
//   stretch stays finite.
// Expected: OK with exactly one degenerate 3D face. Moreover the arc-length square border of
// this grid, starting at a corner, is the grid scaled by 1/4, so Floater's linear precision
// reproduces the whole planar mesh: v lands on the midpoint of a and b in uv, and the
// normalized L2 stretch is 1 (a similarity).
void test_flat_face()
{
  Grid g = make_grid(4, 4);
  const vertex_descriptor v = g.at(2, 2), a = g.at(3, 2), b = g.at(3, 3);
  g.mesh.point(v) = Point_3(3., 2.5, 0.);
  {
    const std::vector<double> areas = planar_signed_areas(g.mesh);
    std::size_t zero = 0, negative = 0;
    for(double s : areas) {
      if(s == 0.) ++zero;
      if(s < 0.) ++negative;
    }
    SMP_CHECK(zero == 1 && negative == 0, "flat face grid: " << zero << " flat and " << negative
                                                             << " reversed faces, expected 1 and 0");
  }
  const halfedge_descriptor bhd = border_halfedge_from(g.mesh, g.at(0, 0));
  Maps maps = make_maps(g.mesh);
  Parameterizer p;
  const SMP::Error_code e = p.parameterize(g.mesh, bhd, maps.uv, maps.vi, maps.vp);
  check_code("flat face", e, SMP::OK, p);
  check_success("flat face", g.mesh, bhd, maps, p);
  const SMP::Stretch_minimizing_report& r = p.report();
  SMP_CHECK(r.degenerate_3d_faces == 1, "flat face: " << r.degenerate_3d_faces << " degenerate 3D faces, expected 1");
  for(const SMP::Stretch_minimizing_step& s : r.history)
    SMP_CHECK(std::isfinite(s.l2_stretch) && std::isfinite(s.linf_stretch) && s.flipped_faces == 0,
              "flat face: step " << s.step << " L2 " << s.l2_stretch << " Linf " << s.linf_stretch
                                 << " flipped " << s.flipped_faces);
  if(!r.history.empty()) {
    SMP_CHECK(r.kept().degenerate_uv_faces == 0,
              "flat face: " << r.kept().degenerate_uv_faces << " faces degenerate in uv only");
    SMP_CHECK(std::abs(r.kept().l2_stretch - 1.) <= 1e-9,
              "flat face: a planar grid should be reproduced (L2 = 1), got " << r.kept().l2_stretch);
  }
  const Point_2 uv_v = get(maps.uv, v), uv_a = get(maps.uv, a), uv_b = get(maps.uv, b);
  SMP_CHECK(std::abs(uv_v.x() - 0.5 * (uv_a.x() + uv_b.x())) <= 1e-9 &&
            std::abs(uv_v.y() - 0.5 * (uv_a.y() + uv_b.y())) <= 1e-9,
            "flat face: uv of v " << uv_v << " is not the midpoint of " << uv_a << " and " << uv_b);
}

// Two coincident vertices: the inner vertex (2, 2) of a grid moved onto its inner neighbour
// (3, 2), so their edge has zero length (the grid is lifted to z = xy / 4 so that it is not
// planar). The shape-preserving weights of both rings are undefined (a zero spoke: compute()
// returns false, compute_w_ij gives NaN), initial_weights() rejects them:
// ERROR_CANNOT_SOLVE_LINEAR_SYSTEM after the border was written but before any solve, so no
// inner vertex has a uv.
void test_coincident_vertices()
{
  Grid g = make_grid(4, 4);
  for(vertex_descriptor v : g.v) {
    const Point_3 q = g.mesh.point(v);
    g.mesh.point(v) = Point_3(q.x(), q.y(), q.x() * q.y() / 4.);
  }
  g.mesh.point(g.at(2, 2)) = g.mesh.point(g.at(3, 2));
  const halfedge_descriptor bhd = border_halfedge_from(g.mesh, g.at(0, 0));
  Maps maps = make_maps(g.mesh);
  Parameterizer p;
  const SMP::Error_code e = p.parameterize(g.mesh, bhd, maps.uv, maps.vi, maps.vp);
  check_code("coincident vertices", e, SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, p);
  check_untouched("coincident vertices", g.mesh, bhd, maps, p, true);
  SMP_CHECK(changed_uv(maps, interior(g.mesh, bhd)) == 0, "coincident vertices: inner uv written");
}

// A non-finite coordinate on a vertex of the component (NaN inside, infinity on the border):
// ERROR_WRONG_PARAMETER before anything is written. The same NaN in ANOTHER component
// (a translated copy) must not matter: OK, and the same uv as without it.
void test_non_finite_coordinates()
{
  const Mesh disk = read_mesh("nefertiti.off");
  const halfedge_descriptor bhd = PMP::longest_border(disk).first;
  const std::vector<vertex_descriptor> inner = interior(disk, bhd);
  SMP_CHECK(!inner.empty(), "nefertiti has no inner vertex");
  {
    Mesh m = disk;
    m.point(inner[inner.size() / 2]) = Point_3(0., nan_value, 0.);
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("NaN inside", e, SMP::ERROR_WRONG_PARAMETER, p);
    check_untouched("NaN inside", m, bhd, maps, p, false);
  }
  {
    Mesh m = disk;
    m.point(target(bhd, m)) = Point_3(0., 0., std::numeric_limits<double>::infinity());
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("infinity on the border", e, SMP::ERROR_WRONG_PARAMETER, p);
    check_untouched("infinity on the border", m, bhd, maps, p, false);
  }

  // two components; the copy's vertices come after those of the disk
  Mesh two = disk;
  Mesh copy = disk;
  for(vertex_descriptor v : vertices(copy))
    copy.point(v) = copy.point(v) + Vector_3(1000., 0., 0.);
  CGAL::copy_face_graph(copy, two);
  std::vector<Point_2> clean_uv; // by vertex index (make_maps() reuses the same property)
  {
    Maps clean_maps = make_maps(two);
    Parameterizer p;
    check_code("two components, clean", p.parameterize(two, bhd, clean_maps.uv, clean_maps.vi, clean_maps.vp),
               SMP::OK, p);
    for(vertex_descriptor v : vertices(two))
      clean_uv.push_back(get(clean_maps.uv, v));
  }
  const std::size_t n = num_vertices(disk);
  Mesh::Vertex_index in_copy(static_cast<Mesh::size_type>(n + n / 2));
  two.point(in_copy) = Point_3(nan_value, nan_value, nan_value);
  Maps maps = make_maps(two);
  Parameterizer p;
  const SMP::Error_code e = p.parameterize(two, bhd, maps.uv, maps.vi, maps.vp);
  check_code("NaN in another component", e, SMP::OK, p);
  check_success("NaN in another component", two, bhd, maps, p);
  std::size_t differ = 0;
  for(vertex_descriptor v : vertices(two))
    if(get(maps.uv, v) != clean_uv[v.idx()])
      ++differ;
  SMP_CHECK(differ == 0, "NaN in another component: " << differ << " uv differ from the clean run");
}

// Several connected components: nefertiti plus a translated, rotated copy in the same mesh.
// Parameterizing the component of one border gives OK and leaves the other at the sentinel;
// parameterizing the copy (through the copied border halfedge, so with the same corners)
// gives the same uv as the original, since the stretch is invariant under rigid motions.
void test_several_components()
{
  Mesh m = read_mesh("nefertiti.off");
  const halfedge_descriptor bhd1 = PMP::longest_border(m).first;
  Mesh copy = m;
  for(vertex_descriptor v : vertices(copy)) { // rotation by 90 degrees about z, then translation
    const Point_3 q = copy.point(v);
    copy.point(v) = Point_3(-q.y() + 500., q.x() - 200., q.z() + 30.);
  }
  std::vector<std::pair<vertex_descriptor, vertex_descriptor> > v2v;
  std::vector<std::pair<halfedge_descriptor, halfedge_descriptor> > h2h;
  CGAL::copy_face_graph(copy, m,
                        CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
                                         .halfedge_to_halfedge_output_iterator(std::back_inserter(h2h)));
  halfedge_descriptor bhd2 = Mesh::null_halfedge();
  for(const auto& hh : h2h)
    if(hh.first == bhd1) // the halfedges of `copy` have the indices of those of the original
      bhd2 = hh.second;
  SMP_CHECK(bhd2 != Mesh::null_halfedge() && is_border(bhd2, m), "copied border halfedge not found");

  Maps maps1 = make_maps(m);
  Parameterizer p1;
  const SMP::Error_code e1 = p1.parameterize(m, bhd1, maps1.uv, maps1.vi, maps1.vp);
  check_code("two components, first", e1, SMP::OK, p1);
  check_success("two components, first", m, bhd1, maps1, p1);
  SMP_CHECK(p1.report().faces == num_faces(m) / 2, "two components: " << p1.report().faces
                                                    << " faces parameterized, expected half of " << num_faces(m));

  Mesh::Property_map<vertex_descriptor, Point_2> first_uv =
    m.add_property_map<vertex_descriptor, Point_2>("v:first_uv").first;
  for(vertex_descriptor v : vertices(m))
    put(first_uv, v, get(maps1.uv, v));

  Maps maps2 = make_maps(m);
  Parameterizer p2;
  const SMP::Error_code e2 = p2.parameterize(m, bhd2, maps2.uv, maps2.vi, maps2.vp);
  check_code("two components, second", e2, SMP::OK, p2);
  check_success("two components, second", m, bhd2, maps2, p2);
  double worst = 0.;
  for(const auto& vv : v2v) { // vv.first indexes the original too (same numbering as `copy`)
    const Point_2 a = get(first_uv, vv.first), b = get(maps2.uv, vv.second);
    worst = (std::max)(worst, (std::max)(std::abs(a.x() - b.x()), std::abs(a.y() - b.y())));
  }
  SMP_CHECK(worst <= 1e-8, "two components: the moved copy's uv differs by " << worst);
  SMP_CHECK(p1.report().kept_step == p2.report().kept_step,
            "two components: kept U^" << p1.report().kept_step << " vs U^" << p2.report().kept_step);
}

// A single triangle. CGAL's square border needs at least four border vertices:
// ERROR_BORDER_TOO_SHORT, returned before it writes anything. With a circular border it is
// fine: OK, no inner vertex, the three corners on the circle of center (0.5, 0.5), radius 0.5.
void test_single_triangle()
{
  Mesh m;
  CGAL::make_triangle(Point_3(0, 0, 0), Point_3(2, 0, 0), Point_3(0.5, 1, 0.3), m);
  halfedge_descriptor bhd = Mesh::null_halfedge();
  for(halfedge_descriptor h : halfedges(m))
    if(is_border(h, m))
      bhd = h;
  {
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("triangle, square border", e, SMP::ERROR_BORDER_TOO_SHORT, p);
    check_untouched("triangle, square border", m, bhd, maps, p, false);
  }
  {
    Maps maps = make_maps(m);
    Circular_parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("triangle, circular border", e, SMP::OK, p);
    check_success("triangle, circular border", m, bhd, maps, p);
    SMP_CHECK(p.report().interior_vertices == 0 && p.report().border_vertices == 3 && p.report().faces == 1,
              "triangle: report counts " << p.report().interior_vertices << " inner, "
                                         << p.report().border_vertices << " border, " << p.report().faces << " faces");
    for(vertex_descriptor v : vertices(m)) {
      const Point_2 q = get(maps.uv, v);
      const double r = std::sqrt((q.x() - 0.5) * (q.x() - 0.5) + (q.y() - 0.5) * (q.y() - 0.5));
      SMP_CHECK(std::abs(r - 0.5) <= 1e-12, "triangle: corner " << q << " not on the circle");
    }
  }
}

// eta must lie in (0, 1]: 0, a negative value, just above 1, 2, NaN and infinity are
// ERROR_WRONG_PARAMETER, given to the constructor or for one call, before anything is
// written. A bad constructor value overridden per call by a good one runs (OK), and an
// error does not stick to the parameterizer.
void test_eta()
{
  Mesh m = read_mesh("nefertiti.off");
  const halfedge_descriptor bhd = PMP::longest_border(m).first;
  const double bad[] = {0., -0.5, std::nextafter(1., 2.), 2., nan_value,
                        std::numeric_limits<double>::infinity()};
  for(double eta : bad) {
    const std::string name = "eta = " + std::to_string(eta);
    {
      Maps maps = make_maps(m);
      Parameterizer p(SMP::parameters::eta(eta));
      const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
      check_code(name + " (constructor)", e, SMP::ERROR_WRONG_PARAMETER, p);
      check_untouched(name + " (constructor)", m, bhd, maps, p, false);
    }
    {
      Maps maps = make_maps(m);
      Parameterizer p;
      const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp, SMP::parameters::eta(eta));
      check_code(name + " (per call)", e, SMP::ERROR_WRONG_PARAMETER, p);
      check_untouched(name + " (per call)", m, bhd, maps, p, false);
      // the same object, good options: the error is not remembered
      Maps maps2 = make_maps(m);
      const SMP::Error_code e2 = p.parameterize(m, bhd, maps2.uv, maps2.vi, maps2.vp);
      check_code(name + " then default", e2, SMP::OK, p);
    }
  }
  Maps maps = make_maps(m);
  Parameterizer p(SMP::parameters::eta(5.));
  const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp, SMP::parameters::eta(0.5));
  check_code("bad eta overridden per call", e, SMP::OK, p);
  check_success("bad eta overridden per call", m, bhd, maps, p);
}

// Found by the fuzz harness (a chart of the atlas): two triangles that share one vertex only. The
// mesh holds them (one border loop through both, passing the shared vertex twice), but the
// component of the border halfedge is one triangle: the loop reached vertices outside the
// component (an index of -1 into an array). ERROR_NO_TOPOLOGICAL_DISC, the maps untouched.
void test_pinched_vertex()
{
  Mesh m;
  const vertex_descriptor o = m.add_vertex(Point_3(0, 0, 0)), a = m.add_vertex(Point_3(1, 0, 0)),
                          b = m.add_vertex(Point_3(1, 1, 0)), c = m.add_vertex(Point_3(-1, 0, 0)),
                          d = m.add_vertex(Point_3(-1, -1, 0));
  const bool made = m.add_face(o, a, b) != Mesh::null_face() && m.add_face(o, c, d) != Mesh::null_face();
  SMP_CHECK(made, "a pinched vertex: the two triangles should be added");
  if(!made)
    return;
  for(halfedge_descriptor bhd : halfedges(m)) {
    if(!is_border(bhd, m))
      continue;
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("a pinched vertex", e, SMP::ERROR_NO_TOPOLOGICAL_DISC, p);
    check_untouched("a pinched vertex", m, bhd, maps, p, false);
  }
}

// A handle: a triangulated torus with one face removed has one border loop but Euler
// characteristic -1: ERROR_NO_TOPOLOGICAL_DISC. The same removal on a tetrahedron (genus 0)
// leaves a disk, which runs (circular border, the square needs four border vertices), so the
// failure is about the handle, not about the removal.
void test_handle()
{
  {
    Mesh m = make_torus(8, 6);
    CGAL::Euler::remove_face(halfedge(*faces(m).begin(), m), m);
    SMP_CHECK(number_of_boundaries(m) == 1, "the holed torus should have one boundary");
    // num_faces() of a Surface_mesh counts removed faces too: count the ranges
    const long long chi = (long long)vertices(m).size() - (long long)edges(m).size() + (long long)faces(m).size();
    SMP_CHECK(chi == -1, "the holed torus has Euler characteristic " << chi);
    halfedge_descriptor bhd = Mesh::null_halfedge();
    for(halfedge_descriptor h : halfedges(m))
      if(is_border(h, m))
        bhd = h;
    Maps maps = make_maps(m);
    Parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("torus with a hole", e, SMP::ERROR_NO_TOPOLOGICAL_DISC, p);
    check_untouched("torus with a hole", m, bhd, maps, p, false);
  }
  {
    Mesh m;
    CGAL::make_tetrahedron(Point_3(0, 0, 0), Point_3(1, 0, 0), Point_3(0, 1, 0), Point_3(0.3, 0.3, 1), m);
    CGAL::Euler::remove_face(halfedge(*faces(m).begin(), m), m);
    halfedge_descriptor bhd = Mesh::null_halfedge();
    for(halfedge_descriptor h : halfedges(m))
      if(is_border(h, m))
        bhd = h;
    Maps maps = make_maps(m);
    Circular_parameterizer p;
    const SMP::Error_code e = p.parameterize(m, bhd, maps.uv, maps.vi, maps.vp);
    check_code("tetrahedron with a hole", e, SMP::OK, p);
    check_success("tetrahedron with a hole", m, bhd, maps, p);
    SMP_CHECK(p.report().interior_vertices == 1, "tetrahedron with a hole: "
                                                   << p.report().interior_vertices << " inner vertices");
  }
}

// error_message(): non-empty, distinct for each Error_code, and about the right error
// (CGAL 5.5.1's own table is shifted by one after ERROR_NO_TOPOLOGICAL_DISC).
void test_error_messages()
{
  const std::pair<SMP::Error_code, const char*> codes[] = {
    {SMP::OK, "success"},
    {SMP::ERROR_EMPTY_MESH, "empty"},
    {SMP::ERROR_NON_TRIANGULAR_MESH, "triangular"},
    {SMP::ERROR_NO_TOPOLOGICAL_DISC, "disc"},
    {SMP::ERROR_NO_TOPOLOGICAL_BALL, "ball"},
    {SMP::ERROR_BORDER_TOO_SHORT, "border"},
    {SMP::ERROR_NON_CONVEX_BORDER, "convex"},
    {SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, "linear system"},
    {SMP::ERROR_NO_1_TO_1_MAPPING, "one-to-one"},
    {SMP::ERROR_WRONG_PARAMETER, "parameter"}};
  SMP_CHECK(sizeof(codes) / sizeof(codes[0]) == std::size_t(SMP::ERROR_WRONG_PARAMETER) + 1,
            "the list of codes is not complete");
  std::set<std::string> seen;
  for(const auto& c : codes) {
    const char* text = SMP::error_message(c.first);
    SMP_CHECK(text != nullptr && std::strlen(text) > 0, "error_message(" << c.first << ") is empty");
    if(text == nullptr)
      continue;
    SMP_CHECK(seen.insert(text).second, "error_message(" << c.first << ") = \"" << text << "\" is not distinct");
    std::string lower(text);
    for(char& ch : lower)
      ch = char(std::tolower((unsigned char)ch));
    SMP_CHECK(lower.find(c.second) != std::string::npos,
              "error_message(" << c.first << ") = \"" << text << "\" does not mention \"" << c.second << "\"");
  }
}


// A parameterizer reused on a mesh whose geometry changed, with maps left over from the
// previous call (vpmap still true, which CGAL's square border reads to find its corners),
// must give what a fresh parameterizer with fresh maps gives.
void test_reuse()
{
  Mesh m;
  const vertex_descriptor b0 = m.add_vertex(Point_3(0, 0, 0)), b1 = m.add_vertex(Point_3(1, 0, 0)),
                          b2 = m.add_vertex(Point_3(1, 1, 0)), b3 = m.add_vertex(Point_3(0, 1, 0)),
                          c = m.add_vertex(Point_3(0.5, 0.5, 0));
  m.add_face(b0, b1, c);
  m.add_face(b1, b2, c);
  m.add_face(b2, b3, c);
  m.add_face(b3, b0, c);
  const halfedge_descriptor bhd = PMP::longest_border(m).first;
  Maps reused = make_maps(m);
  Parameterizer p;
  check_code("reuse, first call", p.parameterize(m, bhd, reused.uv, reused.vi, reused.vp), SMP::OK, p);

  m.point(c) = Point_3(0.2, 0.3, 0);
  check_code("reuse, moved vertex", p.parameterize(m, bhd, reused.uv, reused.vi, reused.vp), SMP::OK, p);
  Mesh copy = m;
  Maps fresh = make_maps(copy);
  Parameterizer q;
  check_code("fresh, moved vertex", q.parameterize(copy, bhd, fresh.uv, fresh.vi, fresh.vp), SMP::OK, q);
  for(vertex_descriptor v : vertices(m))
    SMP_CHECK(std::hypot(reused.uv[v].x() - fresh.uv[v].x(), reused.uv[v].y() - fresh.uv[v].y()) < 1e-12,
              "reused parameterizer or maps: vertex " << v << " at " << reused.uv[v] << ", fresh at " << fresh.uv[v]);

  // and the weights must see the new geometry: a zero-length edge now leaves them undefined
  m.point(c) = m.point(b0);
  check_code("reuse, coincident vertices", p.parameterize(m, bhd, reused.uv, reused.vi, reused.vp),
             SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM, p);
}

} // namespace

int run_test(int, char**)
{
  test_empty_mesh();
  test_closed_mesh();
  test_not_a_border_halfedge();
  test_non_triangular();
  test_isolated_vertices();
  test_flat_face();
  test_coincident_vertices();
  test_non_finite_coordinates();
  test_several_components();
  test_single_triangle();
  test_eta();
  test_handle();
  test_pinched_vertex();
  test_error_messages();
  test_reuse();
  return smp_test::summary();
}

} // namespace test_bad_input

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// An independent grader of a texture atlas given as an OBJ file (`v`, `vt`, `f v/vt ...`,
// polygons of any size, negative indices allowed, other lines ignored), whoever made it: it
// uses nothing of the package, so that our atlases and other tools' are measured alike.
//   grade_atlas ATLAS.obj [--json]
// Prints one line of key=value (or one JSON object): the counts; the charts (faces connected
// through a shared vt or an edge whose uv agree on both sides, with some uv area); Sander et
// al.'s normalized L2 and Linf stretch; the flipped triangles; the uv overlaps (exact); the
// seams; the utilization of the uv bounding box scaled uniformly into the unit square.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <boost/variant.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <variant>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel   Epeck;
typedef std::array<double, 3>                               Vec3;
typedef std::array<double, 2>                               Vec2;

// The value of type T an intersection holds, or null: CGAL 5 returns a boost::variant, CGAL 6 a
// std::variant.
template <typename T, typename... U>
const T* alternative_if(const boost::variant<U...>& v) { return boost::get<T>(&v); }
template <typename T, typename... U>
const T* alternative_if(const std::variant<U...>& v) { return std::get_if<T>(&v); }

struct Corner { std::size_t v, t; };   // indices into the `v` and `vt` lines
struct Obj
{
  std::vector<Vec3> xyz;
  std::vector<Vec2> uv;
  std::vector<std::vector<Corner> > faces;
};

[[noreturn]] void fail(const std::string& why) { std::cerr << "grade_atlas: " << why << std::endl; std::exit(1); }

// An OBJ index: 1-based, or negative to count back from the last element read so far.
std::size_t obj_index(const std::string& s, std::size_t count, std::size_t line)
{
  const long long i = std::atoll(s.c_str());
  const long long k = i > 0 ? i - 1 : (long long)count + i;
  if(i == 0 || k < 0 || k >= (long long)count)
    fail("line " + std::to_string(line) + ": index " + s + " out of range");
  return std::size_t(k);
}

Obj read_obj(const std::string& file)
{
  std::ifstream in(file);
  if(!in) fail("cannot read " + file);
  Obj m;
  std::string line, tag;
  for(std::size_t n = 1; std::getline(in, line); ++n) {
    std::istringstream is(line);
    if(!(is >> tag)) continue;
    if(tag == "v") { Vec3 p; if(!(is >> p[0] >> p[1] >> p[2])) fail("bad v line " + std::to_string(n)); m.xyz.push_back(p); }
    else if(tag == "vt") { Vec2 q; if(!(is >> q[0] >> q[1])) fail("bad vt line " + std::to_string(n)); m.uv.push_back(q); }
    else if(tag == "f") {
      std::vector<Corner> f;
      for(std::string c; is >> c;) {
        const std::size_t slash = c.find('/');
        if(slash == std::string::npos || slash + 1 >= c.size() || c[slash + 1] == '/')
          fail("line " + std::to_string(n) + ": a corner without vt");
        f.push_back({obj_index(c.substr(0, slash), m.xyz.size(), n), obj_index(c.substr(slash + 1), m.uv.size(), n)});
      }
      if(f.size() < 3) fail("line " + std::to_string(n) + ": a face of fewer than 3 corners");
      m.faces.push_back(f);
    }
  }
  if(m.faces.empty()) fail(file + " has no face");
  return m;
}

struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i) { while(parent[i] != i) i = parent[i] = parent[parent[i]]; return i; }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

// One triangle of the fan split of a face: its corners, areas and Sander's stretch.
struct Triangle
{
  std::size_t face;
  std::array<Corner, 3> c;
  double area_3d = 0., area_uv = 0.;  // unsigned, signed
  double l2_squared = 0., linf = 0.;
  bool degenerate_3d = false, degenerate_uv = false;
};

void measure(const Obj& m, Triangle& t)
{
  const Vec3 &p1 = m.xyz[t.c[0].v], &p2 = m.xyz[t.c[1].v], &p3 = m.xyz[t.c[2].v];
  const Vec2 &q1 = m.uv[t.c[0].t], &q2 = m.uv[t.c[1].t], &q3 = m.uv[t.c[2].t];
  // exact predicates decide what is degenerate, so that the count does not depend on a tolerance
  t.degenerate_3d = CGAL::collinear(Epick::Point_3(p1[0], p1[1], p1[2]), Epick::Point_3(p2[0], p2[1], p2[2]),
                                    Epick::Point_3(p3[0], p3[1], p3[2]));
  t.degenerate_uv = CGAL::collinear(Epick::Point_2(q1[0], q1[1]), Epick::Point_2(q2[0], q2[1]), Epick::Point_2(q3[0], q3[1]));
  const Vec3 e1 = {p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]}, e2 = {p3[0] - p1[0], p3[1] - p1[1], p3[2] - p1[2]};
  const Vec3 n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  t.area_3d = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  t.area_uv = 0.5 * ((q2[0] - q1[0]) * (q3[1] - q1[1]) - (q3[0] - q1[0]) * (q2[1] - q1[1]));
  if(t.degenerate_3d || t.degenerate_uv || t.area_uv == 0.) return;
  // Sander et al. 2001: the partial derivatives S_s, S_t of the affine map uv -> 3D
  double a = 0., b = 0., c = 0.;
  for(int i = 0; i < 3; ++i) {
    const double ss = (p1[i] * (q2[1] - q3[1]) + p2[i] * (q3[1] - q1[1]) + p3[i] * (q1[1] - q2[1])) / (2. * t.area_uv);
    const double st = (p1[i] * (q3[0] - q2[0]) + p2[i] * (q1[0] - q3[0]) + p3[i] * (q2[0] - q1[0])) / (2. * t.area_uv);
    a += ss * ss; b += ss * st; c += st * st;
  }
  t.l2_squared = 0.5 * (a + c);
  t.linf = std::sqrt(0.5 * (a + c + std::sqrt((a - c) * (a - c) + 4. * b * b)));
}

// Pairs of uv triangles whose interiors meet, by exact predicates, with the sum of the areas of
// their intersections by exact constructions in `area`.
std::size_t count_overlaps(const Obj& m, const std::vector<Triangle>& tri, double& area)
{
  typedef std::array<Epick::Point_2, 3> Uv_triangle; // counter-clockwise
  std::vector<Uv_triangle> t;
  for(const Triangle& x : tri) {
    if(x.degenerate_uv) continue;
    Uv_triangle p;
    for(int k = 0; k < 3; ++k) p[k] = Epick::Point_2(m.uv[x.c[k].t][0], m.uv[x.c[k].t][1]);
    if(CGAL::orientation(p[0], p[1], p[2]) == CGAL::NEGATIVE) std::swap(p[1], p[2]);
    t.push_back(p);
  }
  typedef std::vector<Uv_triangle>::const_iterator Handle;
  typedef CGAL::Box_intersection_d::Box_with_handle_d<double, 2, Handle> Box;
  std::vector<Box> boxes;
  for(Handle h = t.begin(); h != t.end(); ++h)
    boxes.emplace_back((*h)[0].bbox() + (*h)[1].bbox() + (*h)[2].bbox(), h);
  // the interiors of two convex polygons are disjoint iff the line of an edge of one of them
  // leaves the other on its closed outer side: exact orientation tests, no construction
  auto separated = [](const Uv_triangle& a, const Uv_triangle& b) {
    for(int i = 0; i < 3; ++i)
      if(CGAL::orientation(a[i], a[(i + 1) % 3], b[0]) != CGAL::LEFT_TURN &&
         CGAL::orientation(a[i], a[(i + 1) % 3], b[1]) != CGAL::LEFT_TURN &&
         CGAL::orientation(a[i], a[(i + 1) % 3], b[2]) != CGAL::LEFT_TURN)
        return true;
    return false;
  };
  auto exact = [](const Uv_triangle& a) {
    return Epeck::Triangle_2(Epeck::Point_2(a[0].x(), a[0].y()), Epeck::Point_2(a[1].x(), a[1].y()),
                             Epeck::Point_2(a[2].x(), a[2].y()));
  };
  auto polygon_area = [](const std::vector<Epeck::Point_2>& p) {
    Epeck::FT a = 0;
    for(std::size_t i = 0; i < p.size(); ++i) a += p[i].x() * p[(i + 1) % p.size()].y() - p[(i + 1) % p.size()].x() * p[i].y();
    return CGAL::abs(a) / 2;
  };
  std::size_t count = 0;
  Epeck::FT sum = 0;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    if(separated(*a.handle(), *b.handle()) || separated(*b.handle(), *a.handle())) return;
    const auto result = CGAL::intersection(exact(*a.handle()), exact(*b.handle()));
    if(!result) return;
    if(const Epeck::Triangle_2* x = alternative_if<Epeck::Triangle_2>(*result)) { ++count; sum += CGAL::abs(x->area()); }
    else if(const auto* p = alternative_if<std::vector<Epeck::Point_2> >(*result)) { ++count; sum += polygon_area(*p); }
  });
  area = CGAL::to_double(sum);
  return count;
}

int main(int argc, char** argv)
{
  if(argc < 2 || argc > 3 || (argc == 3 && std::string(argv[2]) != "--json"))
    fail("usage: grade_atlas ATLAS.obj [--json]");
  const bool json = argc == 3;
  const Obj m = read_obj(argv[1]);
  std::size_t corners = 0, outside = 0;
  for(const auto& f : m.faces)
    for(const Corner& c : f) {
      ++corners;
      const Vec2& q = m.uv[c.t];
      outside += !(q[0] >= 0. && q[0] <= 1. && q[1] >= 0. && q[1] <= 1.);
    }

  // charts: faces joined through a shared vt index, or an edge of equal uv on both sides
  // (an atlas may give every corner its own vt, as ours does); vertices welded by position
  std::map<Vec3, std::size_t> first_at;
  std::vector<std::size_t> weld(m.xyz.size());
  for(std::size_t v = 0; v < m.xyz.size(); ++v) weld[v] = first_at.emplace(m.xyz[v], v).first->second;
  const std::size_t nf = m.faces.size();
  Union_find charts(nf);
  std::vector<std::size_t> face_of_vt(m.uv.size(), nf);
  typedef std::pair<std::size_t, std::size_t> Edge;   // welded vertices, smaller first
  std::map<Edge, std::vector<std::pair<Vec2, Vec2> > > sides; // uv at the edge's first and second vertex
  std::map<std::tuple<Edge, Vec2, Vec2>, std::size_t> face_of_side;
  for(std::size_t f = 0; f < nf; ++f) {
    const auto& face = m.faces[f];
    for(std::size_t k = 0; k < face.size(); ++k) {
      if(face_of_vt[face[k].t] == nf) face_of_vt[face[k].t] = f; else charts.join(f, face_of_vt[face[k].t]);
      Corner a = face[k], b = face[(k + 1) % face.size()];
      if(weld[a.v] == weld[b.v]) continue; // an edge of length 0 joins nothing
      if(weld[a.v] > weld[b.v]) std::swap(a, b);
      const Edge e(weld[a.v], weld[b.v]);
      sides[e].emplace_back(m.uv[a.t], m.uv[b.t]);
      const auto it = face_of_side.emplace(std::make_tuple(e, m.uv[a.t], m.uv[b.t]), f).first;
      if(it->second != f) charts.join(f, it->second);
    }
  }
  std::map<std::size_t, std::size_t> chart_index;
  std::vector<std::size_t> chart(nf);
  for(std::size_t f = 0; f < nf; ++f) chart[f] = chart_index.emplace(charts.find(f), chart_index.size()).first->second;

  // triangles: each polygon split into a fan, from its first corner whose fan keeps the uv
  // orientation of the whole polygon (a non-convex polygon has a flipped fan from some corners:
  // that would be the split's fault, not the atlas's); if none does, ear by ear if its outline
  // is simple but for corners repeated (a letter, a polygon with a hole written as one, along a
  // bridge to the hole and back), else from corner 0. Zero uv area
  // on a triangle of positive 3D area is an infinite stretch: counted apart, out of the sums.
  std::vector<Triangle> tri;
  std::size_t refanned = 0, ear_clipped = 0;
  for(std::size_t f = 0; f < nf; ++f) {
    const auto& face = m.faces[f];
    const std::size_t n = face.size();
    auto uv = [&](std::size_t k) { const Vec2& q = m.uv[face[k % n].t]; return Epick::Point_2(q[0], q[1]); };
    double area = 0.;
    for(std::size_t k = 0; k < n; ++k) area += uv(k).x() * uv(k + 1).y() - uv(k + 1).x() * uv(k).y();
    const CGAL::Orientation polygon = area > 0. ? CGAL::POSITIVE : area < 0. ? CGAL::NEGATIVE : CGAL::ZERO;
    std::size_t apex = 0;
    bool fan = n <= 3 || polygon == CGAL::ZERO;
    for(std::size_t a = 0; !fan && a < n; ++a) {
      std::size_t k = 1;
      while(k + 1 < n && CGAL::orientation(uv(a), uv(a + k), uv(a + k + 1)) == polygon) ++k;
      if(k + 1 == n) { apex = a; fan = true; }
    }
    if(!fan) { // no corner sees the whole outline (e.g. a letter): cut it ear by ear if it is simple
      std::vector<std::size_t> left(n);
      for(std::size_t k = 0; k < n; ++k) left[k] = k;
      std::vector<std::array<std::size_t, 3> > ears;
      while(left.size() >= 3) {
        const std::size_t r = left.size();
        bool cut = false;
        for(std::size_t i = 0; i < r && !cut; ++i) {
          const std::size_t a = left[(i + r - 1) % r], b = left[i], c = left[(i + 1) % r];
          if(CGAL::orientation(uv(a), uv(b), uv(c)) != polygon) continue;
          const Epick::Triangle_2 ear(uv(a), uv(b), uv(c));
          bool empty = true;
          for(std::size_t j : left)
            if(j != a && j != b && j != c && uv(j) != uv(a) && uv(j) != uv(b) && uv(j) != uv(c) &&
               ear.bounded_side(uv(j)) != CGAL::ON_UNBOUNDED_SIDE)
              empty = false; // (a corner repeated, as at the ends of a bridge to a hole, is no obstacle)
          if(!empty) continue;
          ears.push_back({a, b, c});
          left.erase(left.begin() + std::ptrdiff_t(i));
          cut = true;
        }
        if(!cut) break;
      }
      if(ears.size() + 2 == n) {
        ++ear_clipped;
        for(const auto& e : ears) {
          Triangle t;
          t.face = f;
          t.c = {face[e[0]], face[e[1]], face[e[2]]};
          measure(m, t);
          tri.push_back(t);
        }
        continue;
      }
    }
    refanned += apex != 0;
    for(std::size_t k = 1; k + 1 < n; ++k) {
      Triangle t;
      t.face = f;
      t.c = {face[apex], face[(apex + k) % n], face[(apex + k + 1) % n]};
      measure(m, t);
      tri.push_back(t);
    }
  }
  double a3 = 0., a2 = 0., e2 = 0., linf = 0.;
  std::size_t degenerate_3d = 0, degenerate_uv = 0;
  std::vector<long> chart_sign(chart_index.size(), 0); // triangles counter-clockwise minus clockwise
  std::vector<double> chart_area(chart_index.size(), 0.);
  std::vector<char> chart_used(chart_index.size(), 0);
  for(const Triangle& t : tri) {
    if(t.degenerate_3d) { ++degenerate_3d; continue; }
    if(t.degenerate_uv || t.area_uv == 0.) { ++degenerate_uv; continue; }
    a3 += t.area_3d; a2 += std::abs(t.area_uv); e2 += t.area_3d * t.l2_squared;
    linf = (std::max)(linf, t.linf);
    chart_sign[chart[t.face]] += t.area_uv > 0. ? 1 : -1;
    chart_area[chart[t.face]] += t.area_uv;
    chart_used[chart[t.face]] = 1;
  }
  // faces left out of an atlas (all their corners at one uv, as xatlas leaves the faces it
  // ignores) make no chart
  const std::size_t used_charts = std::size_t(std::count(chart_used.begin(), chart_used.end(), 1));
  const double normalization = a3 > 0. ? std::sqrt(a2 / a3) : 0.;
  const double l2 = a3 > 0. ? std::sqrt(e2 / a3) * normalization : 0.;

  // flipped: against the majority of their chart (by count, then by signed area); a whole chart
  // against the majority of all triangles is mirrored, not flipped
  auto chart_orientation = [&](std::size_t c) { return chart_sign[c] != 0 ? (chart_sign[c] > 0 ? 1 : -1) : (chart_area[c] >= 0. ? 1 : -1); };
  long total_sign = 0;
  for(long s : chart_sign) total_sign += s;
  const int orientation = total_sign >= 0 ? 1 : -1;
  std::size_t flipped = 0, mirrored = 0;
  for(const Triangle& t : tri)
    if(!t.degenerate_3d && !t.degenerate_uv && t.area_uv != 0. && (t.area_uv > 0. ? 1 : -1) != chart_orientation(chart[t.face]))
      ++flipped;
  for(std::size_t c = 0; c < chart_sign.size(); ++c) mirrored += chart_used[c] && chart_orientation(c) != orientation;

  double overlap_area = 0.;
  const std::size_t overlaps = count_overlaps(m, tri, overlap_area);

  // seams: edges of two or more sides, except two sides whose uv agree at both ends
  double seam_length = 0., edge_length = 0.;
  std::size_t seam_edges = 0, boundary_edges = 0, non_manifold_edges = 0;
  for(const auto& e : sides) {
    const Vec3 &p = m.xyz[e.first.first], &q = m.xyz[e.first.second];
    const double l = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    edge_length += l;
    const auto& s = e.second;
    if(s.size() == 1) { ++boundary_edges; continue; }
    non_manifold_edges += s.size() > 2;
    if(!(s.size() == 2 && s[0] == s[1])) { seam_length += l; ++seam_edges; }
  }

  // the uv bounding box, scaled uniformly so that its longer side is 1
  double umin = HUGE_VAL, vmin = HUGE_VAL, umax = -HUGE_VAL, vmax = -HUGE_VAL;
  for(const auto& f : m.faces)
    for(const Corner& c : f) {
      umin = (std::min)(umin, m.uv[c.t][0]); umax = (std::max)(umax, m.uv[c.t][0]);
      vmin = (std::min)(vmin, m.uv[c.t][1]); vmax = (std::max)(vmax, m.uv[c.t][1]);
    }
  const double side = (std::max)(umax - umin, vmax - vmin);
  const double utilization = side > 0. ? a2 / (side * side) : 0.;

  std::vector<std::pair<std::string, std::string> > out;
  auto put = [&](const std::string& key, double x) {
    std::ostringstream s;
    s << std::setprecision(10) << x;
    out.emplace_back(key, std::isfinite(x) ? s.str() : std::string("null"));
  };
  put("faces", double(nf)); put("corners", double(corners)); put("triangles", double(tri.size()));
  put("refanned_faces", double(refanned));
  put("ear_clipped_faces", double(ear_clipped));
  put("charts", double(used_charts)); put("mirrored_charts", double(mirrored));
  put("l2", l2); put("linf", linf * normalization);
  put("degenerate_uv", double(degenerate_uv)); put("degenerate_3d", double(degenerate_3d));
  put("flipped", double(flipped)); put("orientation", orientation);
  put("overlaps", double(overlaps)); put("overlap_area", a2 > 0. ? overlap_area / a2 : 0.);
  put("seam_length", seam_length); put("edge_length", edge_length);
  put("seam_fraction", edge_length > 0. ? seam_length / edge_length : 0.);
  put("seam_edges", double(seam_edges)); put("boundary_edges", double(boundary_edges));
  put("non_manifold_edges", double(non_manifold_edges));
  put("utilization", utilization);
  put("bbox_umin", umin); put("bbox_vmin", vmin); put("bbox_umax", umax); put("bbox_vmax", vmax);
  put("outside", double(outside));
  for(std::size_t i = 0; i < out.size(); ++i) {
    if(json) std::cout << (i ? ", " : "{") << '"' << out[i].first << "\": " << out[i].second;
    else std::cout << (i ? " " : "") << out[i].first << '=' << out[i].second;
  }
  std::cout << (json ? "}" : "") << std::endl;
  return 0;
}

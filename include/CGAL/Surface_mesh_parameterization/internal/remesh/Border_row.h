// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_BORDER_ROW_H
#define CGAL_SMP_INTERNAL_REMESH_BORDER_ROW_H

// The first row of vertices inside a border: one at the apex of the equilateral triangle on
// each chord between two border samples, found on the surface through the parameter domain.
// Samples drawn by error diffusion fall near a border in clumps and gaps (the diffusion's
// error cannot spread past it), and the relaxation, which keeps the border fixed, cannot
// move vertices in or out of the band along it: a row laid out along the chords starts that
// band as even as the border samples themselves.

#include <CGAL/Surface_mesh_parameterization/internal/remesh/Border_sampling.h>
#include <CGAL/Surface_mesh_parameterization/internal/remesh/Domain_locator.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Points in space (kept), and which of them are near a point: CGAL's kd-tree.
class Nearby_points
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef Search_traits_adapter<std::size_t, Pointer_property_map<K::Point_3>::type, Search_traits_3<K> > Traits;
  typedef Fuzzy_sphere<Traits> Sphere;

public:
  explicit Nearby_points(std::vector<K::Point_3> points) : m_points(std::move(points)), m_traits(make_property_map(m_points))
  {
    std::vector<std::size_t> ids(m_points.size());
    for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
    m_tree.insert(ids.begin(), ids.end());
  }

  Nearby_points(const Nearby_points&) = delete; // the traits point into m_points
  Nearby_points& operator=(const Nearby_points&) = delete;

  bool any_within(const K::Point_3& q, double radius) const
  {
    return !m_points.empty() && bool(m_tree.search_any_point(Sphere(q, radius, 0., m_traits)));
  }
  std::vector<std::size_t> within(const K::Point_3& q, double radius) const
  {
    std::vector<std::size_t> near;
    m_tree.search(std::back_inserter(near), Sphere(q, radius, 0., m_traits));
    return near;
  }

private:
  std::vector<K::Point_3> m_points;
  Traits m_traits;
  Kd_tree<Traits> m_tree{Kd_tree<Traits>::Splitter(), m_traits};
};

// The apexes of the chords of `loops` (indices into `on_border`) on the surface `m` laid out
// by `domain` (`locator` on it), on the side of the chords where the surface is (`inside`:
// 1 if the surface is on the right of a loop in the domain, -1 if on the left). A chord
// whose apex is not in the domain (in a hole, past another border) or that is not found near
// the height asked for (a domain folded too sharply there) gets none; nor one that `keep`
// refuses (given its location and 3D point), nor one closer than `gap(location)` to the apex of
// an earlier chord (where the border turns inwards). `xyz` receives the apexes' 3D points.
template <typename Gap, typename Keep>
std::vector<Surface_location> border_row(const Flat_triangles& m, const std::vector<Vec2>& domain,
                                         const Domain_locator& locator, const std::vector<Edge_location>& on_border,
                                         const std::vector<std::vector<int> >& loops, double inside, Gap gap, Keep keep,
                                         std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>& xyz)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<Surface_location> apexes;
  std::vector<K::Point_3> at; // their surface points
  for(const std::vector<int>& loop : loops)
    for(std::size_t k = 0; k < loop.size(); ++k) {
      const Edge_location &ea = on_border[std::size_t(loop[k])], &eb = on_border[std::size_t(loop[(k + 1) % loop.size()])];
      const Vec2 a = ea.in(domain), b = eb.in(domain);
      const Vec3 pa = ea.in(m.xyz), pb = eb.in(m.xyz);
      const double height = 0.5 * std::sqrt(3.) * norm3(sub3(pb, pa));
      const Vec3 middle = {{0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])}};
      const Vec2 mid = {{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])}};
      const Vec2 normal = {{inside * (b[1] - a[1]), -inside * (b[0] - a[0])}}; // as long as the chord
      if(!(height > 0.))
        continue;
      // the height in the domain: scaled until the surface point is at the height asked for
      double t = 0.5 * std::sqrt(3.);
      for(int step = 0; step < 4; ++step) {
        const Vec2 q = {{mid[0] + t * normal[0], mid[1] + t * normal[1]}};
        Surface_location s;
        if(!locator.locate_inside(q, s))
          break;
        const Vec3 p = locate_in(s, m.tri, m.xyz);
        const double reached = norm3(sub3(p, middle));
        if(std::abs(reached - height) <= 0.05 * height) {
          apexes.push_back(s);
          at.emplace_back(p[0], p[1], p[2]);
          break;
        }
        if(!(reached > 0.))
          break;
        t *= height / reached;
      }
    }
  const Nearby_points all(at);
  std::vector<char> dropped(at.size(), 0);
  std::vector<Surface_location> row;
  xyz.clear();
  for(std::size_t i = 0; i < at.size(); ++i) {
    if(dropped[i] || !keep(apexes[i], at[i]))
      continue;
    for(std::size_t j : all.within(at[i], gap(apexes[i])))
      if(j > i) dropped[j] = 1;
    row.push_back(apexes[i]);
    xyz.push_back(at[i]);
  }
  return row;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_BORDER_ROW_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_DOMAIN_TRIANGULATION_H
#define CGAL_SMP_INTERNAL_REMESH_DOMAIN_TRIANGULATION_H

// The triangles of a new mesh: CGAL's constrained Delaunay triangulation of its vertices in a
// parameter domain, the border loops as constraints, keeping the faces inside the outer loop
// and outside the holes.

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Triangulates `points` (in the plane) with the polygons `loops` (indices into `points`, each
// closed) as constraints: `triangles` receives the faces enclosed by an odd number of loops,
// counterclockwise, by indices into `points`; a point in no such face is in none. False, with
// `error`, if two constraints cross (the loops are not disjoint simple polygons).
inline bool triangulate_domain(const std::vector<Vec2>& points, const std::vector<std::vector<int> >& loops,
                               std::vector<Triangle>& triangles, std::string& error)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> Vb;
  typedef CGAL::Constrained_triangulation_face_base_2<K> Cfb;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, Cfb> Fb; // nesting level, -1 unknown
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag> CDT;

  CDT cdt;
  std::vector<std::pair<K::Point_2, int> > input;
  input.reserve(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    input.emplace_back(K::Point_2(points[i][0], points[i][1]), int(i));
  cdt.insert(input.begin(), input.end());
  std::vector<CDT::Vertex_handle> handle(points.size());
  for(CDT::Vertex_handle v : cdt.finite_vertex_handles())
    handle[std::size_t(v->info())] = v;
  // a point repeated is one vertex: its other indices take that vertex
  for(std::size_t i = 0; i < points.size(); ++i)
    if(handle[i] == CDT::Vertex_handle()) {
      CDT::Locate_type lt;
      int li;
      const CDT::Face_handle f = cdt.locate(input[i].first, lt, li);
      if(lt == CDT::VERTEX)
        handle[i] = f->vertex(li);
    }
  try {
    for(const std::vector<int>& loop : loops)
      for(std::size_t k = 0; k < loop.size(); ++k) {
        const CDT::Vertex_handle a = handle[std::size_t(loop[k])], b = handle[std::size_t(loop[(k + 1) % loop.size()])];
        if(a != b)
          cdt.insert_constraint(a, b);
      }
  } catch(const CDT::Intersection_of_constraints_exception&) {
    error = "the border loops cross in the parameter domain";
    return false;
  }

  // nesting levels: 0 for the faces reached from the infinite face without crossing a
  // constraint, one more behind each constraint crossed
  for(CDT::Face_handle f : cdt.all_face_handles())
    f->info() = -1;
  std::deque<CDT::Face_handle> next;
  std::vector<CDT::Edge> border;
  const auto flood = [&](CDT::Face_handle start, int level) {
    next.clear();
    next.push_back(start);
    while(!next.empty()) {
      const CDT::Face_handle f = next.front();
      next.pop_front();
      if(f->info() != -1)
        continue;
      f->info() = level;
      for(int i = 0; i < 3; ++i) {
        const CDT::Face_handle g = f->neighbor(i);
        if(g->info() != -1)
          continue;
        if(cdt.is_constrained(CDT::Edge(f, i)))
          border.push_back(CDT::Edge(f, i));
        else
          next.push_back(g);
      }
    }
  };
  flood(cdt.infinite_face(), 0);
  while(!border.empty()) {
    const CDT::Edge e = border.back();
    border.pop_back();
    const CDT::Face_handle g = e.first->neighbor(e.second);
    if(g->info() == -1)
      flood(g, e.first->info() + 1);
  }

  triangles.clear();
  for(CDT::Face_handle f : cdt.finite_face_handles())
    if(f->info() % 2 == 1)
      triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return true;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_DOMAIN_TRIANGULATION_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_SAMPLING_DENSITY_H
#define CGAL_SMP_INTERNAL_REMESH_SAMPLING_DENSITY_H

// The relative sampling density of the remeshing, per input vertex: a user's density times the
// curvature's, scaled so that its mean over the surface (by area) is 1; linear over each
// triangle. An empty density stands for 1 everywhere (the surface sampled evenly).

#include <CGAL/Surface_mesh_parameterization/internal/remesh/Density_sampling.h>

#include <CGAL/Eigen_svd.h>
#include <CGAL/Monge_via_jet_fitting.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The mean over the surface `m`, by area, of `value` (per vertex, linear over each triangle);
// 0 if `m` has no area.
inline double area_mean(const Flat_triangles& m, const std::vector<double>& value)
{
  double area = 0., sum = 0.;
  for(const Triangle& t : m.tri) {
    const double a = triangle_area(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])]);
    area += a;
    sum += a * mean_density(value, t);
  }
  return area > 0. ? sum / area : 0.;
}

// `density` scaled to a mean of 1 over the surface `m` (by area); false if its mean is not a
// positive number.
inline bool normalize_density(const Flat_triangles& m, std::vector<double>& density)
{
  if(density.empty())
    return true;
  const double mean = area_mean(m, density);
  if(!(mean > 0.) || !std::isfinite(mean))
    return false;
  for(double& d : density)
    d /= mean;
  return true;
}

// `density` made the same at the border vertices of `loops` that have the same position (their
// mean), so that the two sides of a cut are sampled alike.
inline void weld_density_on_borders(const Flat_triangles& m, const std::vector<std::vector<int> >& loops,
                                    std::vector<double>& density)
{
  if(density.empty())
    return;
  std::map<Vec3, std::pair<double, int> > at;
  for(const std::vector<int>& loop : loops)
    for(const int v : loop) {
      std::pair<double, int>& sum = at[m.xyz[std::size_t(v)]];
      sum.first += density[std::size_t(v)];
      ++sum.second;
    }
  for(const std::vector<int>& loop : loops)
    for(const int v : loop) {
      const std::pair<double, int>& sum = at[m.xyz[std::size_t(v)]];
      density[std::size_t(v)] = sum.first / double(sum.second);
    }
}

// The density that adapts the sampling to the curvature: 1 + `adaptation` * k / mean(k) per
// vertex, where k is the largest absolute principal curvature, estimated by fitting a quadric
// (CGAL's jet fitting) to the vertex's rings out to 16 vertices at least, and mean(k) its mean
// over the surface by area; the ratio is capped at 16 so that a few spikes (a cone's apex, noise)
// do not take the samples of the rest. Proportional to k, a density makes the edge lengths go as
// 1 / sqrt(k), which keeps the distance between a triangle and the surface even.
template <typename Mesh>
std::vector<double> curvature_density(const Mesh& mesh, const Flat_triangles& m, double adaptation)
{
  typedef typename Mesh::Vertex_index vertex_descriptor;
  typedef typename Mesh::Point Point_3;
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel K;
  typedef Monge_via_jet_fitting<K, Simple_cartesian<double>, Eigen_svd> Fitting;
  const std::size_t n = m.xyz.size();
  std::vector<double> curvature(n, 0.);
  std::vector<int> mark(n, -1);
  std::vector<vertex_descriptor> ring, next;
  std::vector<Point_3> points;
  Fitting fitting;
  for(const vertex_descriptor v : vertices(mesh)) {
    if(halfedge(v, mesh) == boost::graph_traits<Mesh>::null_halfedge())
      continue;
    // the vertex first (the fitting is centered on the first point), then its rings
    points.assign(1, mesh.point(v));
    ring.assign(1, v);
    mark[std::size_t(v)] = int(v);
    for(int rings = 0; rings < 4 && points.size() < 16 && !ring.empty(); ++rings) {
      next.clear();
      for(const vertex_descriptor u : ring)
        for(const vertex_descriptor w : vertices_around_target(halfedge(u, mesh), mesh))
          if(mark[std::size_t(w)] != int(v)) {
            mark[std::size_t(w)] = int(v);
            next.push_back(w);
            points.push_back(mesh.point(w));
          }
      ring.swap(next);
    }
    // (fewer than the 6 coefficients of a quadric, or all at one point: no curvature known)
    double reach = 0.;
    for(const Point_3& p : points)
      reach = (std::max)(reach, CGAL::to_double(CGAL::squared_distance(p, points.front())));
    if(points.size() < 6 || !(reach > 0.))
      continue;
    const typename Fitting::Monge_form form = fitting(points.begin(), points.end(), 2, 2);
    const double k = (std::max)(std::abs(form.principal_curvatures(0)), std::abs(form.principal_curvatures(1)));
    if(std::isfinite(k))
      curvature[std::size_t(v)] = k;
  }
  const double mean = area_mean(m, curvature);
  std::vector<double> density(n, 1.);
  if(mean > 0. && std::isfinite(mean))
    for(std::size_t i = 0; i < n; ++i)
      density[i] = 1. + adaptation * (std::min)(16., curvature[i] / mean);
  return density;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_SAMPLING_DENSITY_H

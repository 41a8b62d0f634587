// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_REMESH_DENSITY_SAMPLING_H
#define CGAL_SMP_INTERNAL_REMESH_DENSITY_SAMPLING_H

// Sampling of a surface through one of its parameterizations (Alliez, Meyer and Desbrun 2002):
// the parameter domain is rasterized, each cell holding the 3D area it covers (the map's area
// distortion times the cell's area), and error diffusion turns that density into samples, as
// many as the density sums to. Samples are kept as surface locations (a triangle and
// barycentric coordinates), so that any other parameterization of the same triangles, or the
// surface itself, can place them.

#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/small_vectors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A point of the surface: in triangle `face`, at barycentric coordinates `weight`.
struct Surface_location
{
  int face = -1;
  std::array<double, 3> weight = {{1. / 3., 1. / 3., 1. / 3.}};
};

// The point of `location` in a map given per vertex (3D positions or a parameterization).
template <typename Point>
Point locate_in(const Surface_location& location, const std::vector<Triangle>& tri, const std::vector<Point>& at)
{
  const Triangle& t = tri[std::size_t(location.face)];
  Point p{};
  for(std::size_t i = 0; i < p.size(); ++i)
    for(int k = 0; k < 3; ++k)
      p[i] += location.weight[std::size_t(k)] * at[std::size_t(t[std::size_t(k)])][i];
  return p;
}

// The relative sampling density (per vertex, linear over each triangle; see
// Sampling_density.h) at barycentric coordinates `w` of triangle `t`: 1 if `density` is empty.
inline double density_at(const std::vector<double>& density, const Triangle& t, const std::array<double, 3>& w)
{
  if(density.empty())
    return 1.;
  return w[0] * density[std::size_t(t[0])] + w[1] * density[std::size_t(t[1])] + w[2] * density[std::size_t(t[2])];
}

// The density at a surface location.
inline double density_at(const std::vector<double>& density, const std::vector<Triangle>& tri, const Surface_location& s)
{
  return density.empty() ? 1. : density_at(density, tri[std::size_t(s.face)], s.weight);
}

// The mean density of triangle `t`.
inline double mean_density(const std::vector<double>& density, const Triangle& t)
{
  return density_at(density, t, {{1. / 3., 1. / 3., 1. / 3.}});
}

// Barycentric coordinates of `p` in the triangle (a, b, c); false if the triangle is flat or
// `p` is outside it.
inline bool barycentric_inside(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c, std::array<double, 3>& w)
{
  const double area = twice_signed_area(a, b, c);
  if(area == 0.)
    return false;
  w = {{twice_signed_area(p, b, c) / area, twice_signed_area(a, p, c) / area, twice_signed_area(a, b, p) / area}};
  return w[0] >= 0. && w[1] >= 0. && w[2] >= 0.;
}

// The parameter domain on a grid of square cells: the triangle holding each cell's center
// (-1 outside the domain, in holes included) and the 3D area the cell stands for.
struct Density_raster
{
  Vec2 origin = {{0., 0.}};
  double cell = 1.;
  int width = 0, height = 0;
  std::vector<int> face;
  std::vector<double> area;
  double total_area = 0.;

  Vec2 center(int x, int y) const { return {{origin[0] + (x + 0.5) * cell, origin[1] + (y + 0.5) * cell}}; }
};

// The surface area and the uv area of triangle `t` of `m` laid out by `uv`.
inline std::array<double, 2> triangle_areas(const Flat_triangles& m, const std::vector<Vec2>& uv, const Triangle& t)
{
  return {{triangle_area(m.xyz[std::size_t(t[0])], m.xyz[std::size_t(t[1])], m.xyz[std::size_t(t[2])]),
           0.5 * std::abs(twice_signed_area(uv[std::size_t(t[0])], uv[std::size_t(t[1])], uv[std::size_t(t[2])]))}};
}

// The number of raster cells for sampling `samples` points through `uv` with the relative
// sampling density `sampling`: 16 a sample where `uv` keeps areas (error diffusion spreads
// samples less evenly at much smaller fractions of a sample a cell), and as many as keep the
// densest tenth of the samples at no more than about one sample a cell, where `uv` squeezes the
// surface or the density is high; within [2^16, 2^23].
inline std::size_t raster_cells(const Flat_triangles& m, const std::vector<Vec2>& uv, std::size_t samples,
                                const std::vector<double>& sampling)
{
  // (samples per uv area, samples) per triangle, up to a common factor
  std::vector<std::pair<double, double> > density;
  double area_3d = 0., area_uv = 0.;
  for(const Triangle& t : m.tri) {
    std::array<double, 2> a = triangle_areas(m, uv, t);
    a[0] *= mean_density(sampling, t);
    if(a[0] > 0. && a[1] > 0. && std::isfinite(a[0] / a[1])) {
      density.emplace_back(a[0] / a[1], a[0]);
      area_3d += a[0];
      area_uv += a[1];
    }
  }
  double per_sample = 16.;
  if(!density.empty()) {
    std::sort(density.begin(), density.end());
    double below = 0., high = density.back().first; // the density below which 90% of the area is
    for(const auto& d : density)
      if((below += d.second) >= 0.9 * area_3d) {
        high = d.first;
        break;
      }
    per_sample = (std::max)(per_sample, high / (area_3d / area_uv));
  }
  const double cells = per_sample * double(samples);
  return std::size_t((std::min)(double(std::size_t(1) << 23), (std::max)(double(std::size_t(1) << 16), cells)));
}

// Rasterizes the triangles `m.tri` laid out by `uv` on about `cells` cells, each cell's 3D area
// weighted by the relative sampling density `sampling` at its center; a triangle flat in the
// plane holds no cell, one flat in space holds cells without area.
inline Density_raster rasterize_density(const Flat_triangles& m, const std::vector<Vec2>& uv, std::size_t cells,
                                        const std::vector<double>& sampling)
{
  Density_raster r;
  Vec2 lo = {{HUGE_VAL, HUGE_VAL}}, hi = {{-HUGE_VAL, -HUGE_VAL}};
  for(const Triangle& t : m.tri)
    for(int k = 0; k < 3; ++k)
      for(int i = 0; i < 2; ++i) {
        lo[i] = (std::min)(lo[i], uv[std::size_t(t[k])][i]);
        hi[i] = (std::max)(hi[i], uv[std::size_t(t[k])][i]);
      }
  const double w = hi[0] - lo[0], h = hi[1] - lo[1];
  if(!(w > 0.) || !(h > 0.) || !std::isfinite(w * h))
    return r;
  // square cells, about `cells` of them, and no more than that along either side
  const double n = double((std::max)(cells, std::size_t(1)));
  r.cell = (std::max)(std::sqrt(w * h / n), (std::max)(w, h) / n);
  r.width = (std::max)(1, int(std::ceil(w / r.cell)));
  r.height = (std::max)(1, int(std::ceil(h / r.cell)));
  r.origin = lo;
  r.face.assign(std::size_t(r.width) * std::size_t(r.height), -1);
  r.area.assign(r.face.size(), 0.);
  const double cell_area = r.cell * r.cell;
  for(std::size_t f = 0; f < m.tri.size(); ++f) {
    const Vec2 &a = uv[std::size_t(m.tri[f][0])], &b = uv[std::size_t(m.tri[f][1])], &c = uv[std::size_t(m.tri[f][2])];
    const std::array<double, 2> area = triangle_areas(m, uv, m.tri[f]);
    if(!(area[1] > 0.))
      continue;
    const double ratio = area[0] / area[1];
    const auto first = [&](double v, double o) { return (std::max)(0, int(std::floor((v - o) / r.cell - 0.5))); };
    const int x0 = first((std::min)({a[0], b[0], c[0]}), lo[0]), y0 = first((std::min)({a[1], b[1], c[1]}), lo[1]);
    const int x1 = (std::min)(r.width - 1, int(std::ceil(((std::max)({a[0], b[0], c[0]}) - lo[0]) / r.cell)));
    const int y1 = (std::min)(r.height - 1, int(std::ceil(((std::max)({a[1], b[1], c[1]}) - lo[1]) / r.cell)));
    std::array<double, 3> weight;
    for(int y = y0; y <= y1; ++y)
      for(int x = x0; x <= x1; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(r.width) + std::size_t(x);
        if(r.face[i] < 0 && barycentric_inside(r.center(x, y), a, b, c, weight)) {
          r.face[i] = int(f);
          r.area[i] = std::isfinite(ratio) ? ratio * cell_area * density_at(sampling, m.tri[f], weight) : 0.;
          r.total_area += r.area[i];
        }
      }
  }
  return r;
}

// A number in [0, 1) drawn from `key` (splitmix64): the samples are the same on every run.
inline double hashed_unit(std::uint64_t key)
{
  key += 0x9e3779b97f4a7c15ull;
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ull;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebull;
  key ^= key >> 31;
  return double(key >> 11) * (1. / 9007199254740992.);
}

// Samples of the raster's density times `per_area` (samples per unit of 3D area) by error
// diffusion (Floyd-Steinberg, serpentine), the error kept inside the domain. A cell gives as
// many samples as its accumulated density rounds to, each at a point of the cell drawn within
// its triangle.
inline std::vector<Surface_location> diffuse_samples(const Density_raster& r, const std::vector<Triangle>& tri,
                                                     const std::vector<Vec2>& uv, double per_area)
{
  std::vector<Surface_location> samples;
  std::vector<double> error(r.face.size(), 0.);
  const auto inside = [&](int x, int y) {
    return x >= 0 && x < r.width && y >= 0 && y < r.height && r.face[std::size_t(y) * std::size_t(r.width) + std::size_t(x)] >= 0;
  };
  for(int y = 0; y < r.height; ++y) {
    const int step = y % 2 == 0 ? 1 : -1;
    for(int k = 0; k < r.width; ++k) {
      const int x = step > 0 ? k : r.width - 1 - k;
      const std::size_t i = std::size_t(y) * std::size_t(r.width) + std::size_t(x);
      if(r.face[i] < 0)
        continue;
      const double value = r.area[i] * per_area + error[i];
      const double count = value > 0.5 ? std::floor(value + 0.5) : 0.;
      for(double j = 0.; j < count; ++j) {
        Surface_location s;
        s.face = r.face[i];
        const Triangle& t = tri[std::size_t(s.face)];
        const Vec2 c = r.center(x, y);
        const std::uint64_t key = (std::uint64_t(i) << 8) ^ std::uint64_t(j);
        // a point drawn past the triangle's sides is pulled toward the cell's center, which is
        // in the triangle (the center itself, the same for each sample of the cell, would put
        // them all at one point, and corners of the triangle likewise)
        const Vec2 drawn = {{(hashed_unit(2 * key) - 0.5) * r.cell, (hashed_unit(2 * key + 1) - 0.5) * r.cell}};
        const Vec2 &a = uv[std::size_t(t[0])], &b = uv[std::size_t(t[1])], &e = uv[std::size_t(t[2])];
        bool placed = false;
        double scale = 1.;
        for(int halving = 0; halving < 40 && !placed; ++halving, scale *= 0.5)
          placed = barycentric_inside({{c[0] + scale * drawn[0], c[1] + scale * drawn[1]}}, a, b, e, s.weight);
        if(!placed)
          barycentric_inside(c, a, b, e, s.weight); // (in the triangle: the raster put the cell there)
        samples.push_back(s);
      }
      // the rest goes ahead and below, shared among the neighbours inside the domain
      const double rest = value - count;
      const int dx[4] = {step, -step, 0, step};
      const int dy[4] = {0, 1, 1, 1};
      const double share[4] = {7. / 16., 3. / 16., 5. / 16., 1. / 16.};
      double kept = 0.;
      for(int n = 0; n < 4; ++n)
        if(inside(x + dx[n], y + dy[n]))
          kept += share[n];
      if(kept > 0.)
        for(int n = 0; n < 4; ++n)
          if(inside(x + dx[n], y + dy[n]))
            error[std::size_t(y + dy[n]) * std::size_t(r.width) + std::size_t(x + dx[n])] += rest * share[n] / kept;
    }
  }
  return samples;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_REMESH_DENSITY_SAMPLING_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fuzz harness's check of the atlas (see fuzz_smp.h).

#include "fuzz_smp.h"

#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>

namespace smp_fuzz {

namespace SMP = CGAL::Surface_mesh_parameterization;

void check_atlas(const std::vector<Point_3>& points, const std::vector<std::vector<std::size_t> >& polygons,
                 Bytes& options)
{
  namespace P = SMP::parameters;
  const double max_stretch = 1. + 4. * options.unit() - 0.01; // a little below 1 too
  const unsigned resolution = 1u + options.byte() * 4u;
  const double gutter = 4. * options.unit();
  const unsigned polish = options.byte() % 3;
  const SMP::Atlas atlas = SMP::make_atlas(points, polygons,
      P::max_stretch(max_stretch).resolution(resolution).gutter(gutter).polish_iterations(polish).number_of_threads(1u));
  if(atlas.report.status != SMP::OK) {
    promise(!atlas.report.message.empty(), "an atlas error without a message");
    return;
  }
  promise(atlas.uv.size() == polygons.size() && atlas.chart.size() == polygons.size(), "a polygon lost");
  for(std::size_t f = 0; f < polygons.size(); ++f) {
    promise(atlas.uv[f].size() == polygons[f].size(), "a corner lost");
    promise(atlas.chart[f] < atlas.report.charts, "a chart out of range");
    for(const auto& q : atlas.uv[f])
      promise(q[0] >= 0. && q[0] <= 1. && q[1] >= 0. && q[1] <= 1., "a uv outside the unit square");
  }
  promise(atlas.report.flipped_faces == 0, "a flipped face in the atlas");
}

} // namespace smp_fuzz

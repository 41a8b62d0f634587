// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fuzz harness's check of the remeshing (see fuzz_smp.h).

#include "fuzz_smp.h"

#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>

#include <cmath>

namespace smp_fuzz {

namespace SMP = CGAL::Surface_mesh_parameterization;

void check_remeshing(const Mesh& mesh, Bytes& options)
{
  const std::size_t vertices = 3 + options.byte() % 120;
  const SMP::Remeshing_pair pair = SMP::Remeshing_pair(options.byte() % 3);
  Mesh out;
  const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(
      mesh, vertices, out, SMP::parameters::parameterization_pair(pair).number_of_threads(1u));
  if(r.status != SMP::OK) {
    promise(!r.message.empty(), "a remeshing error without a message");
    return;
  }
  promise(out.is_valid(false) && CGAL::is_triangle_mesh(out), "a remeshed mesh that is not a valid triangle mesh");
  promise(out.number_of_vertices() == r.vertices && out.number_of_faces() == r.faces, "a remeshing report that is not its mesh");
  for(const auto v : out.vertices())
    promise(std::isfinite(out.point(v).x()) && std::isfinite(out.point(v).y()) && std::isfinite(out.point(v).z()),
            "a remeshed vertex that is not finite");
}

} // namespace smp_fuzz

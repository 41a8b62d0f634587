// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fuzz harness's check of the parameterizer (see fuzz_smp.h).

#include "fuzz_smp.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>

#include <cmath>

namespace smp_fuzz {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

void check_parameterizer(Mesh& mesh, Bytes& options)
{
  namespace P = SMP::parameters;
  auto uv = mesh.add_property_map<Mesh::Vertex_index, Point_2>("v:fuzz_uv", Point_2(0., 0.)).first;
  Mesh::Halfedge_index bhd;
  const std::uint8_t border = options.byte();
  if(border < 200 && !CGAL::is_closed(mesh))
    bhd = PMP::longest_border(mesh).first;
  else if(border < 250 && !mesh.is_empty())
    bhd = Mesh::Halfedge_index(border % mesh.number_of_halfedges()); // any halfedge, on the border or not
  const std::uint8_t choice = options.byte();
  const double eta = options.byte() == 0 ? -1. : 1.2 * options.unit(); // out of (0, 1] now and then
  const unsigned iterations = options.byte() % 6;
  SMP::Stretch_minimizing_parameterizer_3<Mesh> p(
      P::preset(choice & 1 ? SMP::Stretch_minimizing_preset::LOWEST_STRETCH : SMP::Stretch_minimizing_preset::PAPER)
        .eta(eta)
        .number_of_iterations(iterations)
        .polish_iterations(unsigned(choice >> 1) % 3)
        .free_border(bool(choice & 8))
        .start_weights(choice & 16 ? SMP::Start_weights::CLAMPED_COTANGENT : SMP::Start_weights::INITIALIZER)
        .stretch_update(choice & 32 ? SMP::Stretch_update::EDGE : SMP::Stretch_update::VERTEX)
        .number_of_threads(1u));
  // the member function: CGAL's free parameterize() reads `bhd` before the package checks it
  auto vimap = mesh.add_property_map<Mesh::Vertex_index, int>("v:fuzz_index", 0).first;
  auto vpmap = mesh.add_property_map<Mesh::Vertex_index, bool>("v:fuzz_done", false).first;
  int index = 0;
  for(Mesh::Vertex_index v : vertices(mesh))
    put(vimap, v, index++);
  const SMP::Error_code status = p.parameterize(mesh, bhd, uv, vimap, vpmap);
  if(status != SMP::OK) {
    promise(!p.report().message.empty(), "an error without a message");
    return;
  }
  for(Mesh::Vertex_index v : vertices(mesh))
    promise(std::isfinite(get(uv, v).x()) && std::isfinite(get(uv, v).y()), "a non-finite uv");
}

} // namespace smp_fuzz

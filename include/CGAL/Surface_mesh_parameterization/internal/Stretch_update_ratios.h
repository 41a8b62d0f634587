// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_STRETCH_UPDATE_RATIOS_H
#define CGAL_SMP_INTERNAL_STRETCH_UPDATE_RATIOS_H

#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_options.h>
#include <CGAL/Surface_mesh_parameterization/internal/Disk_component.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The update of the weights w_ij (one per ring entry of the system) by the stretch of each
// entry relative to the RMS stretch of the mesh: a common factor of all ratios leaves the
// solution unchanged, and dividing by the RMS keeps the weights from drifting in magnitude.
class Stretch_update_ratios
{
public:
  // Prepares `kind` for the rings of `dc` (the edge rule needs the faces of every ring edge).
  void init(Stretch_update kind, const Disk_component_base& dc)
  {
    m_kind = kind;
    if(kind != Stretch_update::EDGE)
      return;
    // (edge key, face) for every real face, sorted by key: the faces of an edge are adjacent
    std::vector<std::pair<std::uint64_t, int> > table;
    table.reserve(3 * dc.flat.tri.size());
    for(std::size_t f = 0; f < dc.flat.tri.size(); ++f)
      for(int k = 0; k < 3; ++k)
        table.emplace_back(key(dc.flat.tri[f][k], dc.flat.tri[f][(k + 1) % 3]), int(f));
    std::sort(table.begin(), table.end());
    m_edge_faces.assign(2 * dc.ring.size(), -1);
    for(std::size_t r = 0; r < dc.number_of_rows(); ++r)
      for(int e = dc.ring_begin[r]; e < dc.ring_begin[r + 1]; ++e) {
        const std::uint64_t k = key(dc.interior[r], dc.ring[e]);
        auto it = std::lower_bound(table.begin(), table.end(), std::make_pair(k, -1));
        for(int slot = 0; slot < 2 && it != table.end() && it->first == k; ++slot, ++it)
          m_edge_faces[2 * e + slot] = it->second;
      }
  }

  // w_out[e] = w_in[e] / ratio_e^eta for every ring entry e, where ratio_e is the stretch of
  // the entry (from the last evaluation of `stretch`) over `rms`. `w_out` may be `w_in`.
  void update(const Disk_component_base& dc, const Flat_stretch& stretch, double rms, double eta,
              const std::vector<double>& w_in, std::vector<double>& w_out, unsigned int threads = 1)
  {
    stretch.vertex_stretch(dc.flat, rms, m_sigma);
    w_out.resize(w_in.size());
    if(m_kind == Stretch_update::VERTEX) {
      // one power per vertex rather than per ring entry
      parallel_for(m_sigma.size(), threads, parallel_grain, [&](std::size_t begin, std::size_t end) {
        for(std::size_t v = begin; v < end; ++v)
          m_sigma[v] = std::pow(m_sigma[v] / rms, -eta);
      });
      parallel_for(w_in.size(), threads, parallel_grain, [&](std::size_t begin, std::size_t end) {
        for(std::size_t e = begin; e < end; ++e)
          w_out[e] = w_in[e] * m_sigma[dc.ring[e]];
      });
      return;
    }
    parallel_for(dc.number_of_rows(), threads, parallel_grain, [&](std::size_t begin, std::size_t end) {
      for(std::size_t r = begin; r < end; ++r) {
        const int i = dc.interior[r];
        for(int e = dc.ring_begin[r]; e < dc.ring_begin[r + 1]; ++e) {
          const int j = dc.ring[e];
          const double s = m_kind == Stretch_update::SYMMETRIC ? 0.5 * (m_sigma[i] + m_sigma[j])
                                                               : edge_stretch(e, stretch, m_sigma[i], m_sigma[j]);
          w_out[e] = w_in[e] * std::pow(s / rms, -eta);
        }
      }
    });
  }

private:
  static std::uint64_t key(int a, int b)
  {
    if(a > b)
      std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  }

  // area-weighted RMS stretch of the measured faces of the edge of ring entry e; for an edge
  // with none (e.g. a virtual edge of a closed hole), the RMS of its ends' stretches `si` and
  // `sj`: the same from either end, so that symmetric weights stay symmetric
  double edge_stretch(int e, const Flat_stretch& stretch, double si, double sj) const
  {
    double num = 0., den = 0.;
    for(int slot = 0; slot < 2; ++slot) {
      const int f = m_edge_faces[2 * e + slot];
      if(f < 0 || !stretch.used(std::size_t(f)))
        continue;
      const Face_stretch& t = stretch.faces()[std::size_t(f)];
      num += t.area_3d * t.l2 * t.l2;
      den += t.area_3d;
    }
    return den > 0. ? std::sqrt(num / den) : std::sqrt(0.5 * (si * si + sj * sj));
  }

  Stretch_update m_kind = Stretch_update::VERTEX;
  std::vector<int> m_edge_faces; // two per ring entry, -1 if none
  std::vector<double> m_sigma;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_STRETCH_UPDATE_RATIOS_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_ATLAS_CHART_GROWING_H
#define CGAL_SMP_INTERNAL_ATLAS_CHART_GROWING_H

// Cutting a triangle soup into charts that are topological disks, whatever the soup: any genus,
// closed parts, non-manifold edges and vertices, inconsistent orientation.
//
// A chart is grown triangle by triangle. Its topology is kept in the gluing of triangle sides:
// a triangle enters through one side glued to a side of the chart (its third corner is new, so
// the chart stays a disk), and two sides of the chart that meet at a corner of the chart are
// zipped together (a disk stays a disk). Corners glued together form the chart's vertices, so a
// vertex that the chart meets twice (a non-manifold vertex, or the end of a cut) becomes two
// chart vertices, and the sides never glued are the seams. Two sides can only be glued if they
// are the two sides of one edge with exactly two triangles oriented alike; the triangles of an
// input polygon always stay together.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/Atlas_input.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Chart_growing
{
public:
  // Side s = 3 t + k of triangle t goes from its corner 3 t + k to its corner 3 t + (k + 1) % 3.
  static int source_corner(int s) { return s; }
  static int target_corner(int s) { return 3 * (s / 3) + (s % 3 + 1) % 3; }

  explicit Chart_growing(const Atlas_triangles& m)
    : m_mesh(m)
  {
    const std::size_t nt = m.vertex.size();
    m_mate.assign(3 * nt, -1);
    m_glued.assign(3 * nt, 0);
    m_parent.resize(3 * nt);
    std::iota(m_parent.begin(), m_parent.end(), 0);
    m_chart.assign(nt, -1);

    // the triangles of a polygon: a unit, glued along its diagonals
    m_unit.resize(nt);
    for(std::size_t t = 0; t < nt; ++t) {
      if(t == 0 || m.polygon[t] != m.polygon[t - 1])
        m_unit_first.push_back(t);
      m_unit[t] = m_unit_first.size() - 1;
    }
    m_unit_first.push_back(nt);
    for(std::size_t u = 0; u + 1 < m_unit_first.size(); ++u)
      for(std::size_t a = m_unit_first[u]; a < m_unit_first[u + 1]; ++a)
        for(std::size_t b = a + 1; b < m_unit_first[u + 1]; ++b)
          for(int i = 0; i < 3; ++i)
            for(int j = 0; j < 3; ++j) {
              const int sa = int(3 * a) + i, sb = int(3 * b) + j;
              if(m_mate[sa] < 0 && m_mate[sb] < 0 && from(sa) == to(sb) && to(sa) == from(sb)) {
                m_mate[sa] = sb;
                m_mate[sb] = sa;
              }
            }

    // the other sides: mates when an edge has exactly two sides, in opposite directions
    std::unordered_map<std::pair<int, int>, std::array<int, 3>, Edge_hash> sides;
    sides.reserve(3 * nt);
    for(int s = 0; s < int(3 * nt); ++s) {
      if(m_mate[s] >= 0)
        continue;
      auto& e = sides.emplace(std::make_pair((std::min)(from(s), to(s)), (std::max)(from(s), to(s))),
                              std::array<int, 3>{0, -1, -1}).first->second;
      if(e[0] < 2)
        e[1 + e[0]] = s;
      ++e[0];
    }
    for(const auto& e : sides)
      if(e.second[0] == 2 && from(e.second[1]) == to(e.second[2])) {
        m_mate[e.second[1]] = e.second[2];
        m_mate[e.second[2]] = e.second[1];
      }

    // unit normals (area-weighted) and areas
    m_normal.assign(m_unit_first.size() - 1, Vec3{0., 0., 0.});
    for(std::size_t t = 0; t < nt; ++t) {
      const auto& v = m.vertex[t];
      const Vec3 n = cross3(sub3(m.xyz[v[1]], m.xyz[v[0]]), sub3(m.xyz[v[2]], m.xyz[v[0]]));
      Vec3& un = m_normal[m_unit[t]];
      for(int i = 0; i < 3; ++i) un[i] += 0.5 * n[i];
    }
  }

  std::size_t number_of_units() const { return m_unit_first.size() - 1; }
  // Whether `triangles` (none twice) hold every triangle of each unit they touch. Charts are
  // grown, split and cut by whole units: the triangles of a polygon laid out one by one must
  // not be joined to other charts, which a later cut would grow again by whole units.
  bool whole_units(const std::vector<std::size_t>& triangles) const
  {
    std::vector<std::size_t> units;
    units.reserve(triangles.size());
    for(std::size_t t : triangles) units.push_back(m_unit[t]);
    std::sort(units.begin(), units.end());
    for(std::size_t i = 0, j = 0; i < units.size(); i = j) {
      while(j < units.size() && units[j] == units[i]) ++j;
      if(j - i != m_unit_first[units[i] + 1] - m_unit_first[units[i]])
        return false;
    }
    return true;
  }
  int chart(std::size_t t) const { return m_chart[t]; }
  int mate(int s) const { return m_mate[s]; }
  bool glued(int s) const { return m_glued[s] != 0; }
  // The chart vertex of a corner: one representative corner per chart vertex.
  int chart_vertex(int corner) { return find(corner); }
  // Glues side s to its mate, both in one chart: a slit of the chart closed by its map, which
  // then has a hole (the caller checked that the chart stays a surface).
  void close_slit(int s)
  {
    if(m_mate[s] >= 0 && !m_glued[s])
      glue(s);
  }

  // Makes each of `triangles` (all of one chart) a chart of its own: `ids[i]` that of
  // `triangles[i]`, none glued to another (the triangles of a polygon laid out one by one).
  void separate(const std::vector<std::size_t>& triangles, const std::vector<int>& ids)
  {
    for(std::size_t i = 0; i < triangles.size(); ++i) {
      forget(triangles[i]);
      m_chart[triangles[i]] = ids[i];
    }
  }

  // Grows charts over the triangles whose `allowed` flag is set (one per triangle; a unit's
  // triangles all allowed or none, see whole_units(): a unit joins a chart whole), numbered
  // from `first_chart`: a triangle joins a chart while its polygon's normal stays within
  // `max_angle` (radians) of the chart's mean normal, and while the chart holds fewer than
  // `max_units` polygons (0: no limit). Every allowed triangle ends in a chart. Returns the
  // number of charts made.
  // Charts of fewer than `small_chart` polygons are then absorbed by a neighbour, while at
  // least `keep` charts remain (2 when splitting a chart: one would undo the split).
  int grow(const std::vector<char>& allowed, int first_chart, double max_angle, std::size_t max_units = 0,
           int keep = 1)
  {
    const double cos_max = std::cos(max_angle);
    const std::size_t nt = m_mesh.vertex.size();
    for(std::size_t t = 0; t < nt; ++t)
      if(allowed[t])
        forget(t);
    auto free_unit = [&](std::size_t u) {
      const std::size_t t = m_unit_first[u];
      return allowed[t] && m_chart[t] < 0;
    };

    // the first seed: the unit whose normal is closest to the mean normal of the region
    Vec3 mean = {0., 0., 0.};
    std::vector<std::size_t> units;
    for(std::size_t u = 0; u < number_of_units(); ++u)
      if(free_unit(u)) {
        units.push_back(u);
        for(int i = 0; i < 3; ++i) mean[i] += m_normal[u][i];
      }
    if(units.empty())
      return 0;
    std::size_t seed = units.front();
    double best = -HUGE_VAL;
    for(std::size_t u : units) {
      const double c = cosine(m_normal[u], mean);
      if(c > best) { best = c; seed = u; }
    }

    std::queue<std::size_t> frontier; // next seeds: units next to finished charts
    int made = 0;
    std::size_t next_unit = 0;
    for(;;) {
      while(!frontier.empty() && !free_unit(frontier.front()))
        frontier.pop();
      if(made > 0) {
        if(!frontier.empty()) {
          seed = frontier.front();
          frontier.pop();
        } else {
          while(next_unit < units.size() && !free_unit(units[next_unit]))
            ++next_unit;
          if(next_unit == units.size())
            break;
          seed = units[next_unit];
        }
      }
      const int c = first_chart + made++;
      start_chart(c);
      add_unit(seed, c, -1, allowed);
      extend(c, cos_max, max_units, allowed, &frontier);
    }
    absorb_small_charts(first_chart, made, keep);
    return renumber(first_chart, made);
  }

  // Charts of fewer polygons than this are absorbed by a neighbour when they have one.
  static constexpr std::size_t small_chart = 8;

private:
  struct Candidate
  {
    double cost;
    int side; // a side of the chart whose mate may join
    bool operator<(const Candidate& o) const { return cost > o.cost; }
  };

  int from(int s) const { return m_mesh.vertex[std::size_t(s / 3)][std::size_t(s % 3)]; }
  int to(int s) const { return m_mesh.vertex[std::size_t(s / 3)][std::size_t((s % 3 + 1) % 3)]; }

  static double cosine(const Vec3& a, const Vec3& b)
  {
    const double na = norm3(a), nb = norm3(b);
    return na > 0. && nb > 0. ? dot3(a, b) / (na * nb) : 1.;
  }

  // Takes triangle t out of its chart: no chart, its sides unglued, its corners apart. (The
  // sides glued to its own are those of triangles of its chart, forgotten with it.)
  void forget(std::size_t t)
  {
    m_chart[t] = -1;
    for(std::size_t k = 0; k < 3; ++k) {
      m_glued[3 * t + k] = 0;
      m_parent[3 * t + k] = int(3 * t + k);
    }
  }

  int find(int c)
  {
    while(m_parent[c] != c) {
      m_parent[c] = m_parent[m_parent[c]];
      c = m_parent[c];
    }
    return c;
  }

  void glue(int s)
  {
    const int m = m_mate[s];
    m_glued[s] = m_glued[m] = 1;
    m_parent[find(source_corner(s))] = find(target_corner(m));
    m_parent[find(target_corner(s))] = find(source_corner(m));
  }

  // Zips side s with its mate if both are in chart c, unglued, and meet at a chart vertex; the
  // border of the chart (`border`: its number of sides) stays at three sides at least.
  bool try_zip(int s, int c, std::size_t& border)
  {
    const int m = m_mate[s];
    if(m < 0 || m_glued[s] || m_chart[std::size_t(m / 3)] != c || border < 5)
      return false;
    const bool at_source = find(source_corner(s)) == find(target_corner(m));
    const bool at_target = find(target_corner(s)) == find(source_corner(m));
    if(at_source == at_target)
      return false;
    glue(s);
    border -= 2;
    return true;
  }

  struct Chart_state
  {
    std::vector<std::size_t> members; // triangles
    Vec3 normal = {0., 0., 0.};       // sum of the area-weighted normals
    std::size_t border = 0;           // sides on its border
    std::size_t units = 0;
    std::priority_queue<Candidate> heap;
  };

public:
  // What grow() changes: a copy taken before charts are grown again gives them back.
  struct Snapshot
  {
    std::vector<char> glued;
    std::vector<int> parent, chart;
    std::vector<Chart_state> state;
  };
  Snapshot snapshot() const { return Snapshot{m_glued, m_parent, m_chart, m_state}; }
  void restore(Snapshot s)
  {
    m_glued.swap(s.glued);
    m_parent.swap(s.parent);
    m_chart.swap(s.chart);
    m_state.swap(s.state);
  }

  // What join() changed, for undo(): the corners' parents before, the sides glued, and the
  // triangles moved with the chart they came from.
  struct Join_record
  {
    std::vector<std::pair<int, int> > parent;
    std::vector<int> glued;
    std::vector<std::size_t> moved;
    int from = -1;
  };

  // Joins the chart of `from_triangles` to chart `into` (of `into_triangles`): glued along one
  // edge they share, then zipped along the path of shared edges it starts (each side glued
  // meets the glued ones at a chart vertex), so that the union stays a disk; shared edges off
  // that path are left as slits of the union. Only the corners of the two charts change (their
  // classes hold no other corner).
  Join_record join(const std::vector<std::size_t>& into_triangles, const std::vector<std::size_t>& from_triangles,
                     int into)
  {
    Join_record r;
    r.from = from_triangles.empty() ? -1 : m_chart[from_triangles.front()];
    for(const std::vector<std::size_t>* list : {&into_triangles, &from_triangles})
      for(std::size_t t : *list)
        for(int k = 0; k < 3; ++k)
          r.parent.emplace_back(int(3 * t) + k, m_parent[3 * t + std::size_t(k)]);
    std::vector<int> shared;
    for(std::size_t t : from_triangles)
      for(int k = 0; k < 3; ++k) {
        const int s = int(3 * t) + k, mate = m_mate[s];
        if(mate >= 0 && !m_glued[s] && m_chart[std::size_t(mate / 3)] == into)
          shared.push_back(s);
      }
    for(bool zipped = !shared.empty(); zipped;) {
      zipped = false;
      for(int s : shared) {
        const int mate = m_mate[s];
        const bool at_source = find(source_corner(s)) == find(target_corner(mate));
        const bool at_target = find(target_corner(s)) == find(source_corner(mate));
        if(!m_glued[s] && (r.glued.empty() ? !at_source && !at_target : at_source != at_target)) {
          glue(s);
          r.glued.push_back(s);
          zipped = true;
        }
      }
    }
    for(std::size_t t : from_triangles)
      m_chart[t] = into;
    r.moved = from_triangles;
    return r;
  }

  // Takes back a join() (no other change of the two charts since).
  void undo(const Join_record& r)
  {
    for(const auto& p : r.parent)
      m_parent[std::size_t(p.first)] = p.second;
    for(int s : r.glued)
      m_glued[std::size_t(s)] = m_glued[std::size_t(m_mate[s])] = 0;
    for(std::size_t t : r.moved)
      m_chart[t] = r.from;
  }

private:

  void start_chart(int c)
  {
    if(m_state.size() <= std::size_t(c)) m_state.resize(std::size_t(c) + 1);
    m_state[std::size_t(c)] = Chart_state();
  }

  // Puts unit u into chart c, glued to the chart's side `entry` (or alone, with -1), zips what
  // can be zipped and queues its other sides.
  void add_unit(std::size_t u, int c, int entry, const std::vector<char>& allowed)
  {
    Chart_state& st = m_state[std::size_t(c)];
    const std::size_t first = m_unit_first[u], last = m_unit_first[u + 1];
    ++st.units;
    for(std::size_t t = first; t < last; ++t) {
      m_chart[t] = c;
      st.members.push_back(t);
    }
    st.border += 3 * (last - first) - 2 * (last - first - 1);
    if(entry >= 0) {
      glue(entry);
      st.border -= 2;
    }
    for(std::size_t t = first; t < last; ++t) // the diagonals
      for(int k = 0; k < 3; ++k) {
        const int s = int(3 * t + k), m = m_mate[s];
        if(m >= 0 && s < m && m_unit[std::size_t(m / 3)] == u)
          glue(s);
      }
    for(int i = 0; i < 3; ++i) st.normal[i] += m_normal[u][i];
    for(std::size_t t = first; t < last; ++t)
      for(int k = 0; k < 3; ++k) {
        const int s = int(3 * t + k), m = m_mate[s];
        if(m < 0 || m_glued[s])
          continue;
        const std::size_t tm = std::size_t(m / 3);
        if(m_chart[tm] == c)
          try_zip(s, c, st.border);
        else if(allowed[tm] && m_chart[tm] < 0)
          st.heap.push(Candidate{1. - cosine(m_normal[m_unit[tm]], st.normal), s});
      }
  }

  // Sides of unit u whose mates are in chart c.
  int sides_on(std::size_t u, int c) const
  {
    int k = 0;
    for(std::size_t t = m_unit_first[u]; t < m_unit_first[u + 1]; ++t)
      for(int i = 0; i < 3; ++i) {
        const int m = m_mate[3 * t + std::size_t(i)];
        k += m >= 0 && m_chart[std::size_t(m / 3)] == c && m_unit[std::size_t(m / 3)] != u;
      }
    return k;
  }

  // Grows chart c from its queued sides. A unit that touches the chart along two sides or
  // more fills a notch: it is taken within a wider cone, which keeps the border smooth.
  // Units refused go to `frontier` (if given) as seeds of later charts.
  void extend(int c, double cos_max, std::size_t max_units, const std::vector<char>& allowed,
              std::queue<std::size_t>* frontier)
  {
    const double cos_notch = cos_max < -1. ? cos_max : std::cos((std::min)(1.5 * std::acos((std::max)(-1., cos_max)), 3.14159265358979323846));
    for(;;) {
      Chart_state& st = m_state[std::size_t(c)];
      if(st.heap.empty()) break;
      const Candidate k = st.heap.top();
      st.heap.pop();
      const int m = m_mate[k.side];
      const std::size_t tm = std::size_t(m / 3);
      if(m_chart[tm] >= 0 || m_glued[k.side] || !allowed[tm])
        continue;
      const std::size_t u = m_unit[tm];
      const double cos_u = cosine(m_normal[u], st.normal);
      const double limit = sides_on(u, c) >= 2 ? cos_notch : cos_max;
      if(cos_u < limit || (max_units > 0 && st.units >= max_units)) {
        if(frontier != nullptr) frontier->push(u);
        continue;
      }
      add_unit(u, c, k.side, allowed);
    }
    // zips made possible by later ones, in passes over the sides that may still be zipped (the
    // unglued sides whose mates are in the chart) until a pass zips none
    Chart_state& st = m_state[std::size_t(c)];
    std::vector<int> open;
    for(std::size_t t : st.members)
      for(int k = 0; k < 3; ++k) {
        const int s = int(3 * t) + k, m = m_mate[s];
        if(m >= 0 && !m_glued[s] && m_chart[std::size_t(m / 3)] == c)
          open.push_back(s);
      }
    for(bool again = true; again;) {
      again = false;
      std::size_t kept = 0;
      for(const int s : open) {
        again = try_zip(s, c, st.border) || again;
        if(!m_glued[s])
          open[kept++] = s;
      }
      open.resize(kept);
    }
  }

  // Every chart of fewer than `small_chart` polygons goes to the neighbour it shares the most
  // sides with, whatever the normals (the stretch bound still applies to the result).
  void absorb_small_charts(int first_chart, int count, int keep)
  {
    int live = count;
    for(int c = first_chart; c < first_chart + count && live > keep; ++c) {
      Chart_state& st = m_state[std::size_t(c)];
      if(st.units == 0 || st.units >= small_chart)
        continue;
      std::unordered_map<int, int> shared;
      for(std::size_t t : st.members)
        for(int k = 0; k < 3; ++k) {
          const int m = m_mate[3 * t + std::size_t(k)];
          const int d = m < 0 ? -1 : m_chart[std::size_t(m / 3)];
          if(d >= first_chart && d != c && m_state[std::size_t(d)].units > 0) ++shared[d];
        }
      int best = -1, most = 0;
      for(const auto& e : shared)
        if(e.second > most || (e.second == most && e.first < best)) { most = e.second; best = e.first; }
      if(best < 0)
        continue;
      // forget chart c, then let its neighbour grow over it
      std::vector<char> mine(m_chart.size(), 0);
      for(std::size_t t : st.members) {
        mine[t] = 1;
        forget(t);
      }
      st = Chart_state();
      Chart_state& to = m_state[std::size_t(best)];
      for(std::size_t t : to.members)
        for(int k = 0; k < 3; ++k) {
          const int s = int(3 * t) + k, m = m_mate[s];
          if(m >= 0 && !m_glued[s] && mine[std::size_t(m / 3)])
            to.heap.push(Candidate{0., s});
        }
      extend(best, -2., 0, mine, nullptr);
      --live;
    }
  }

  // Numbers the charts that kept triangles from first_chart on; returns how many there are.
  int renumber(int first_chart, int count)
  {
    std::vector<int> id(std::size_t(count), -1);
    int n = 0;
    for(int c = first_chart; c < first_chart + count; ++c)
      if(m_state[std::size_t(c)].units > 0) id[std::size_t(c - first_chart)] = first_chart + n++;
    for(int c = first_chart; c < first_chart + count; ++c)
      for(std::size_t t : m_state[std::size_t(c)].members)
        m_chart[t] = id[std::size_t(c - first_chart)];
    for(int c = first_chart; c < first_chart + count; ++c) {
      const int to = id[std::size_t(c - first_chart)];
      if(to >= 0 && to != c) m_state[std::size_t(to)] = std::move(m_state[std::size_t(c)]);
    }
    m_state.resize(std::size_t(first_chart + n));
    return n;
  }

  const Atlas_triangles& m_mesh;
  std::vector<int> m_mate;               // per side: the side it can be glued to, -1 if none
  std::vector<char> m_glued;             // per side
  std::vector<int> m_parent;             // union-find of corners: the chart vertices
  std::vector<int> m_chart;              // per triangle, -1 if none yet
  std::vector<std::size_t> m_unit;       // per triangle: its polygon's unit
  std::vector<std::size_t> m_unit_first; // first triangle of each unit, and one past the last
  std::vector<Vec3> m_normal;            // per unit: area-weighted normal (its length: the area)
  std::vector<Chart_state> m_state;      // per chart
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_ATLAS_CHART_GROWING_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The options beyond the paper on meshes that are not in the repository (run by
// scripts/check-other-meshes.sh on CGAL's sample meshes): for every disk-like mesh given,
// the paper's U^opt, the LOWEST_STRETCH preset, its fixed-border polish (at most 100 steps),
// the paper's U^opt with a free-border polish (at most 5 Newton steps), and CGAL's
// Iterative_authalic (15 iterations), all on the unit-square arc-length border; one markdown
// row per mesh on stdout. The paper's time over CGAL MVC's, with its number of reweighting
// steps, tells how much of the free-border ratio the start U^opt already takes.
//   other_meshes mesh.off ...

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>                              Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                         Mesh;
typedef Mesh::Halfedge_index                                        halfedge_descriptor;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace P = SMP::parameters;
typedef SMP::Square_border_arc_length_parameterizer_3<Mesh>         Square;
typedef SMP::Stretch_minimizing_parameterizer_3<Mesh>               Minimizer;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh, Square>   CGAL_MVC;
typedef SMP::Iterative_authalic_parameterizer_3<Mesh, Square>       CGAL_iterative_authalic;

namespace {

// Median wall times of the calls of `f`, called in rounds, each round calling every one once
// (so that a slower spell of this shared machine weighs on all alike): at least `rounds`
// rounds, more while they add up to less than 0.3 s (at most 201). Medians of 5 sub-millisecond
// calls, method after method, moved ratios by 1.5x between two runs.
std::vector<double> interleaved_median_seconds(int rounds, const std::vector<std::function<void()> >& f)
{
  std::vector<std::vector<double> > t(f.size());
  double total = 0.;
  for(int r = 0; r < rounds || (total < 0.3 && r < 201); ++r)
    for(std::size_t k = 0; k < f.size(); ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      f[k]();
      t[k].push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      total += t[k].back();
    }
  std::vector<double> median;
  for(std::vector<double>& x : t) {
    std::sort(x.begin(), x.end());
    median.push_back(x[x.size() / 2]);
  }
  return median;
}

std::string fixed(double x, int digits)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << x;
  return s.str();
}

// A stream buffer that swallows what CGAL 5.5.1's Iterative_authalic prints.
class Null_buffer : public std::streambuf
{
protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

} // namespace

int main(int argc, char** argv)
{
  std::cout << "| mesh | V | paper U^opt | LOWEST_STRETCH | LOWEST / paper time | + fixed polish (100) | "
               "paper + free polish (5) | free / CGAL MVC time | paper / CGAL MVC time (steps) | CGAL Iterative_authalic (15) |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
  for(int a = 1; a < argc; ++a) {
    const std::string name = std::filesystem::path(argv[a]).filename().string();
    Mesh m;
    if(!CGAL::IO::read_polygon_mesh(argv[a], m) || faces(m).empty() || !CGAL::is_triangle_mesh(m))
      continue;
    std::vector<halfedge_descriptor> borders;
    CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(borders));
    auto component = m.add_property_map<Mesh::Face_index, std::size_t>("f:component").first;
    const long chi = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
    if(borders.size() != 1 || CGAL::Polygon_mesh_processing::connected_components(m, component) != 1 || chi != 1)
      continue; // not a disk
    const halfedge_descriptor bhd = borders.front();
    auto uv = m.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
    const int rounds = num_vertices(m) < 20000 ? 5 : 1;

    auto l2 = [&]() {
      const SMP::Stretch_statistics s = SMP::compute_stretch_statistics(m, uv);
      return fixed(s.l2_stretch, 4) + (s.flipped_faces ? " (" + std::to_string(s.flipped_faces) + " flips)" : "");
    };
    Minimizer paper, lowest(P::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH));
    Minimizer polished(P::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH, P::polish_iterations(100u)));
    Minimizer free(P::polish_iterations(5u, P::free_border(true)));
    CGAL_MVC mvc;
    auto call = [&](auto& parameterizer) {
      return [&m, &bhd, &uv, p = &parameterizer] { SMP::parameterize(m, *p, bhd, uv); };
    };
    const std::vector<double> t = interleaved_median_seconds(rounds, {call(paper), call(lowest), call(polished),
                                                                      call(free), call(mvc)});
    auto l2_of = [&](auto& parameterizer) { call(parameterizer)(); return l2(); };
    const std::string paper_l2 = l2_of(paper);
    const std::size_t paper_steps = paper.report().steps_taken();
    const std::string lowest_l2 = l2_of(lowest), polished_l2 = l2_of(polished), free_l2 = l2_of(free);

    // CGAL 5.5.1's Iterative_authalic prints every iteration and writes last_solve.off into
    // the working directory: run it with its output swallowed (the script runs this program
    // in a scratch directory)
    Null_buffer null;
    std::streambuf* out = std::cout.rdbuf(&null);
    auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), m);
    SMP::internal::fill_index_map_of_cc(bhd, m, vimap);
    auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), m);
    unsigned int iterations = 15;
    CGAL_iterative_authalic ia;
    ia.parameterize(m, bhd, uv, vimap, vpmap, iterations);
    std::cout.rdbuf(out);
    const std::string ia_l2 = l2();

    std::cout << "| " << name << " | " << num_vertices(m) << " | " << paper_l2 << " | " << lowest_l2 << " | "
              << fixed(t[1] / t[0], 2) << " | " << polished_l2 << " | " << free_l2 << " | " << fixed(t[3] / t[4], 2)
              << " | " << fixed(t[0] / t[4], 2) << " (" << paper_steps << ") | " << ia_l2 << " |" << std::endl;
  }
  return 0;
}

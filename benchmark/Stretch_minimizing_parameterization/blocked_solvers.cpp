// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The factorization of a system of 2 x 2 blocks, u and v of each vertex coupled (the pattern of
// LSCM's system and of the polisher's Newton system), on a mesh and its Loop refinements: Eigen's
// simplicial LDL^T in its minimum degree order, as the polisher factors the smaller systems, and
// Sander_vertex_solver's supernodal factorizations, as it factors those of
// Sander_vertex_solver::blocked_supernodal_rows rows or more: CHOLMOD's LL^T in the METIS vertex
// order when CGAL_SMP_USE_CHOLMOD is defined (else this column is SparseLU's too), and Eigen's
// SparseLU in a minimum degree order, which calls no BLAS (the atlas's). The values are made up,
// symmetric and diagonally dominant; the order and the fill depend on the pattern only.
// One markdown row per level: rows, then the best of a few factorizations (and solves) of each.
//   blocked_solvers mesh.off LEVELS

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_vertex_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/vertex_order.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <vector>

typedef CGAL::Simple_cartesian<double>       Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>  Mesh;
namespace SI = CGAL::Surface_mesh_parameterization::internal;
typedef Eigen::SparseMatrix<double>          Matrix;

template <typename F>
double best_seconds(F f, int runs)
{
  double best = HUGE_VAL;
  for(int k = 0; k < runs; ++k) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = (std::min)(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

// The lower triangle of the blocked system of the mesh's edges.
Matrix blocked_system(const Mesh& mesh)
{
  const int n = int(num_vertices(mesh));
  std::vector<Eigen::Triplet<double> > entries;
  std::vector<double> diagonal(std::size_t(2 * n), 1e-3);
  for(auto e : edges(mesh)) {
    const int a = int(source(halfedge(e, mesh), mesh)), b = int(target(halfedge(e, mesh), mesh));
    const int hi = (std::max)(a, b), lo = (std::min)(a, b);
    const double c = 1. + 0.05 * double((7 * a + 13 * b) % 10);
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j)
        entries.emplace_back(2 * hi + i, 2 * lo + j, i == j ? -c : -0.3 * c);
    for(int i = 0; i < 2; ++i) {
      diagonal[std::size_t(2 * a + i)] += 1.3 * c;
      diagonal[std::size_t(2 * b + i)] += 1.3 * c;
    }
    entries.emplace_back(2 * a + 1, 2 * a, 0.3 * c);
    entries.emplace_back(2 * b + 1, 2 * b, 0.3 * c);
  }
  for(int i = 0; i < 2 * n; ++i)
    entries.emplace_back(i, i, diagonal[std::size_t(i)]);
  Matrix lower(2 * n, 2 * n);
  lower.setFromTriplets(entries.begin(), entries.end());
  lower.makeCompressed();
  return lower;
}

int main(int argc, char** argv)
{
  if(argc < 3) {
    std::cerr << "usage: blocked_solvers mesh.off LEVELS\n";
    return 1;
  }
  Mesh mesh;
  std::ifstream in(argv[1]);
  if(!(in >> mesh) || faces(mesh).empty()) {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  std::cout << "| rows | simplicial LDL^T s | supernodal s | simplicial / supernodal | supernodal without BLAS s | simplicial / it |\n"
               "|---:|---:|---:|---:|---:|---:|\n";
  for(int level = 0; level <= std::atoi(argv[2]); ++level) {
    if(level > 0)
      CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(1));
    const Matrix lower = blocked_system(mesh);
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(lower.rows());
    const int runs = lower.rows() > 400000 ? 1 : 3;
    Eigen::VectorXd x;
    Eigen::SimplicialLDLT<Matrix, Eigen::Lower> simplicial;
    simplicial.analyzePattern(lower);
    const double simplicial_seconds = best_seconds([&]() { simplicial.factorize(lower); x = simplicial.solve(b); }, runs);
    // the vertex order of the mesh, two rows per vertex, as the polisher builds it (none without CHOLMOD)
    std::vector<SI::Triangle> triangles;
    for(auto f : faces(mesh)) {
      SI::Triangle t;
      int k = 0;
      for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) t[std::size_t(k++)] = int(v);
      triangles.push_back(t);
    }
    const std::vector<int> rank = SI::fill_reducing_vertex_rank(num_vertices(mesh), triangles, {});
    std::vector<int> order(rank.empty() ? 0 : 2 * rank.size());
    for(std::size_t v = 0; v < rank.size(); ++v) {
      order[2 * std::size_t(rank[v])] = 2 * int(v);
      order[2 * std::size_t(rank[v]) + 1] = 2 * int(v) + 1;
    }
    SI::Sander_vertex_solver supernodal(true, 1);
    supernodal.analyzePattern(lower, order);
    Eigen::VectorXd y;
    const double supernodal_seconds = best_seconds([&]() { supernodal.factorize(lower); y = supernodal.solve(b); }, runs);
    SI::Sander_vertex_solver without_blas(true);
    without_blas.set_supernodal_rows(1, false);
    without_blas.analyzePattern(lower);
    Eigen::VectorXd z;
    const double lu_seconds = best_seconds([&]() { without_blas.factorize(lower); z = without_blas.solve(b); }, runs);
    if(!supernodal.supernodal() || !without_blas.supernodal() || !((x - y).norm() <= 1e-8 * x.norm()) ||
       !((x - z).norm() <= 1e-8 * x.norm())) {
      std::cerr << "a supernodal factorization failed or disagrees at " << lower.rows() << " rows\n";
      return 1;
    }
    std::cout << "| " << lower.rows() << " | " << simplicial_seconds << " | " << supernodal_seconds << " | "
              << simplicial_seconds / supernodal_seconds << " | " << lu_seconds << " | " << simplicial_seconds / lu_seconds
              << " |" << std::endl;
  }
  return 0;
}

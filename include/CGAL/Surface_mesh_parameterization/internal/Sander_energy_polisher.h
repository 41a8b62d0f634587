// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_SMP_INTERNAL_SANDER_ENERGY_POLISHER_H
#define CGAL_SMP_INTERNAL_SANDER_ENERGY_POLISHER_H

// Minimizes the L2 stretch energy of Sander, Snyder, Gortler and Hoppe (2001),
//   E(uv) = sum_T A3(T) (a + c) / 2 = sum_T A3(T) ||J_T^-1||_F^2 / 2,
// from a flip-free parameterization, keeping it flip-free: by projected Newton steps (the
// Hessian of each face with its negative eigenvalues clamped, factored at every step), whole or
// without the terms that couple u and v (two smaller factorizations), or by descent along the
// gradient preconditioned by a fixed quadratic proxy, the Dirichlet energy of the 3D mesh (the
// cotangent Laplacian, factored once; the proxy of Kovalsky, Galun and Lipman 2016, without
// their acceleration). J_T is the Jacobian of the affine map from the face's 3D triangle (in a
// 2D frame of its plane) to its uv triangle; ||J^-1||_F^2 = ||J||_F^2 / det(J)^2 = 1 / s1^2 + 1 / s2^2.
//
// With a fixed border, no hole and no face of zero 3D area the uv area A of the energy faces is
// constant, so E is the normalized L2 stretch up to a constant factor. With a free border (E
// only shrinks as the map grows), with holes or with faces of zero 3D area (the uv area of
// either is left out of A, and changes) the normalized L2 stretch is a function of E * A: each step
// lowers G = E + mu * A with mu = E / A taken at the current map, where G = 2 E, and any G
// below that gives E * A below the current one (AM-GM). The border loop is kept simple, which
// with flip-free faces makes the map of a disk bijective.
//
// What it does not do: it does not change the connectivity, it does not move a vertex that is in
// no energy face (e.g. the centre of a fan closing a hole), and it stops at a local minimum.
//
// Longer than most headers: one class, whose driver, setup, assembly and line search share the
// state of one polish. The energy of one face, the bounds of a flip-free step and the solver of
// the proxy and of the split systems are in headers of their own.

#include <CGAL/Surface_mesh_parameterization/internal/solver_configuration.h>

#include <CGAL/Surface_mesh_parameterization/internal/Sander_face_energy.h>
#include <CGAL/Surface_mesh_parameterization/internal/flip_free_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/Sander_vertex_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/flat_mesh_stretch.h>
#include <CGAL/Surface_mesh_parameterization/internal/parallel_for.h>
#include <CGAL/Surface_mesh_parameterization/internal/vertex_order.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {
CGAL_SMP_BEGIN_SOLVER_NAMESPACE

// How a step finds its direction: NEWTON solves the projected Hessian (one system of twice the
// vertices); SPLIT_NEWTON leaves out its terms that couple u and v: two systems the size of
// the vertices, each with about an eighth of the flops of the coupled one to factor, solved
// side by side, for steps that lower the energy almost as much near the optimum; DIRICHLET_PROXY
// solves the proxy, factored once: cheap steps that move the whole map, which far from the
// optimum (a start compressed by orders of magnitude) go where the Newton steps stall.
enum class Sander_polish_direction { NEWTON, SPLIT_NEWTON, DIRICHLET_PROXY };

struct Sander_polish_settings
{
  Sander_polish_direction direction = Sander_polish_direction::NEWTON;
  unsigned int max_iterations = 200;
  double time_budget = 0.;    // seconds, checked before each step; <= 0: none
  bool free_border = false;   // let the outer border move (the vertices of `border`)
  bool pin_fixed_border = false; // with a free border, its vertices that are `fixed` stay (else all move)
  double tolerance = 1e-6;    // converged when a step lowers the energy by less than this, relatively
  // converged when the last `tolerance_window` steps together lower the energy by less than
  // that many times the tolerance (fewer steps at the start): a step cut short by a fold may
  // gain little where the next ones gain again, which one step alone cannot tell
  unsigned int tolerance_window = 1;
  unsigned int threads = 1;   // of the faces' terms, of the stretch measured after each step and of
                              // the two systems of SPLIT_NEWTON (the result does not depend on it)
  // the order in which the proxy and the split systems eliminate the vertices (rank per vertex,
  // see vertex_order.h), shared by the calls on one mesh; null: ordered here
  const std::vector<int>* vertex_rank = nullptr;
  // NEWTON: from this many rows on, the Newton system is factored by a supernodal method, its
  // rows in the vertex order (see Sander_vertex_solver)
  std::size_t newton_supernodal_rows = std::size_t(Sander_vertex_solver::blocked_supernodal_rows);
  // whether that factorization may call BLAS (see Sander_vertex_solver::set_supernodal_rows())
  bool supernodal_blas = true;
  // SPLIT_NEWTON: from this many rows on, the two systems are factored by CHOLMOD's supernodal
  // LL^T when CHOLMOD is used, both at once; below, or without CHOLMOD, by the simplicial LDL^T
  // (Eigen's SparseLU, the supernodal factorization without BLAS, falls behind it on these)
  std::size_t split_supernodal_rows = std::size_t(Sander_vertex_solver::default_supernodal_rows);
};

// Whether a start of normalized L2 stretch `l2` is taken as it is (no step) by a polish that
// ends at a relative gain of `tolerance`: the stretch is at least 1 and its square is in
// proportion to the energy (E * A with the area term), so no step can lower the energy by more
// than L2^2 - 1 relatively; below the tolerance the first step would end the polish, after a
// factorization (a developable chart's conformal map, an isometry up to rounding, is one).
inline bool polish_takes_no_step(double l2, double tolerance)
{
  return l2 * l2 - 1. <= tolerance;
}

// What a visitor sees after every Newton step.
struct Sander_polish_step
{
  std::size_t iteration = 0;               // 1 after the first step
  double l2_stretch = 0.;                  // normalized, by Flat_stretch
  Flat_stretch_summary measures;           // all of Flat_stretch's summary of the current map
  double energy = 0.;                      // E, or E * A with a free border or holes
  double seconds = 0.;                     // since the start of the call
  const std::vector<Vec2>* uv = nullptr;   // the current map, valid during the call only
};

typedef std::function<bool(const Sander_polish_step&)> Sander_polish_visitor;

// BAD_START: inconsistent arrays, or a face that is flipped or flat at the start (or, with a
// free border, a border loop that is not simple).
enum class Sander_polish_status { OK, BAD_START, SOLVER_FAILED };

// CONVERGED: the last step, or the one the Newton model predicts (NEWTON only), lowers the energy
// by less than the tolerance; NO_PROGRESS: the line search found no step that lowers it.
enum class Sander_polish_stop { NOT_RUN, CONVERGED, ITERATION_CAP, TIME_BUDGET, VISITOR, NO_PROGRESS };

struct Sander_polish_result
{
  Sander_polish_status status = Sander_polish_status::OK;
  Sander_polish_stop stop = Sander_polish_stop::NOT_RUN;
  std::string message;                     // why, when status is not OK
  std::size_t iterations = 0;              // steps taken
  double energy_before = 0., energy_after = 0.;  // E (or E * A) over the faces that can move
  double l2_before = 0., l2_after = 0.;    // normalized L2 stretch of all faces (Flat_stretch)
  double seconds = 0.;
};

// `VertexSolver`: a class with the interface of Sander_vertex_solver (constructed from whether
// the system is definite; analyzePattern() and compute() with an elimination order), for the
// Newton, the proxy and the split systems.
template <typename VertexSolver = Sander_vertex_solver>
class Sander_energy_polisher
{
public:
  // Relative eigenvalue floor of the per-face Hessians.
  static constexpr double eigenvalue_floor = 1e-8;
  // The energy faces whose terms (energy, gradient, Hessian block) are computed side by side
  // before they are added in order, and the fewest of them a thread takes (below parallel_grain:
  // a face's Hessian block costs far more than an item of the iteration's loops).
  static constexpr std::size_t face_block = 16384;
  static constexpr std::size_t face_grain = 2048;
  // Fewest moving vertices for which the two split systems are factored on two threads: below,
  // starting a thread at every step costs more than it saves (on a mesh of a few vertices, many
  // times the rest of the step); the value is near the crossover found by timing both thread
  // counts on CGAL's sample disks with the program of scripts/check-other-meshes.sh.
  static constexpr std::size_t split_parallel_rows = 1000;

  // Polishes `uv` (one entry per vertex of `m.xyz`) in place.
  // - energy faces: `m.tri`; those degenerate in 3D only have to stay positively oriented;
  // - `guard`: faces that only have to stay positively oriented (e.g. fans closing holes);
  // - `fixed`: per vertex, vertices that do not move (outer border vertices move with a free border);
  // - `border`: the outer border loop, in order; read with a free border only.
  // The start must be flip-free: every face with a free vertex has to be oriented like the total
  // signed uv area; faces whose vertices are all fixed are skipped (a negative one is an error).
  // On a status other than OK, `uv` is unchanged.
  Sander_polish_result polish(const Flat_triangles& m, const std::vector<Triangle>& guard,
                              const std::vector<char>& fixed, const std::vector<int>& border,
                              std::vector<Vec2>& uv, const Sander_polish_settings& settings = Sander_polish_settings(),
                              const Sander_polish_visitor& visitor = Sander_polish_visitor())
  {
    const auto start = std::chrono::steady_clock::now();
    auto seconds = [&start]() {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    Sander_polish_result r;
    auto fail = [&](Sander_polish_status s, const std::string& why) {
      r.status = s;
      r.message = why;
      r.seconds = seconds();
      return r;
    };

    std::string why;
    if(!setup(m, guard, fixed, border, uv, settings.free_border, settings.pin_fixed_border, why))
      return fail(Sander_polish_status::BAD_START, why);
    m_threads = (std::max)(settings.threads, 1u);
    m_solver.set_supernodal_rows(Eigen::Index(settings.newton_supernodal_rows), settings.supernodal_blas);
    m_solver.set_paired_rows(true); // u and v of an unknown: rows 2k and 2k + 1
    if(settings.direction != Sander_polish_direction::NEWTON || 2 * m_dofs >= settings.newton_supernodal_rows)
      order_vertex_systems(m, guard, settings.vertex_rank, settings.direction == Sander_polish_direction::NEWTON);
    else
      m_order.clear(); // a smaller Newton system orders itself
    r.l2_before = r.l2_after = m_stretch.evaluate(m, uv, settings.threads).l2;

    // With holes, a free border or faces without energy (zero 3D area) the uv area of the
    // energy faces changes, and the normalized L2 stretch is a function of E * A rather than of
    // E: each step then lowers
    // G = E + mu A with mu = E / A taken at the current map, which lowers E * A (AM-GM).
    m_area_term = settings.free_border || !m_guard.empty();
    m_mu = 0.;
    double E = energy_at(0.);
    r.energy_before = r.energy_after = m_area_term ? E * m_area_uv : E;
    if(m_dofs == 0 || polish_takes_no_step(r.l2_before, settings.tolerance)) {
      r.stop = Sander_polish_stop::CONVERGED;
      r.seconds = seconds();
      return r;
    }

    const bool proxy = settings.direction == Sander_polish_direction::DIRICHLET_PROXY;
    m_split = settings.direction == Sander_polish_direction::SPLIT_NEWTON;
    if(!proxy)
      build_newton_pattern();
    double first_trial = 1.; // of the line search; with the proxy, the last step taken
    bool factored = false;
    double reported = r.energy_before; // E, or E * A with the area term, after the last step
    std::vector<double> energies(1, reported); // the reported energies of the steps (window > 1)
    // with the area term: E without it and the uv area A at the current map, measured once a step
    double pure = E, area = m_area_term ? area_of(m_x) : 0.;
    for(;;) {
      if(r.iterations >= settings.max_iterations) { r.stop = Sander_polish_stop::ITERATION_CAP; break; }
      if(settings.time_budget > 0. && seconds() >= settings.time_budget) {
        r.stop = Sander_polish_stop::TIME_BUDGET;
        break;
      }

      if(m_area_term) {
        m_mu = pure / area;
        E = 2. * pure; // G at the current map
      }
      assemble(!proxy);
      if(proxy) {
        if(!factored) {
          assemble_proxy();
          m_proxy_solver.compute(m_P, m_order);
          factored = true;
          if(m_proxy_solver.info() != Eigen::Success)
            return fail(Sander_polish_status::SOLVER_FAILED, "the factorization of the proxy failed");
        }
        // the proxy acts on u and v alike: one solve with two columns
        m_rhs = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> >(m_g.data(), Eigen::Index(m_dofs), 2);
        m_pp = m_proxy_solver.solve(m_rhs);
        if(m_proxy_solver.info() != Eigen::Success)
          return fail(Sander_polish_status::SOLVER_FAILED, "the proxy could not be solved");
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> >(m_p.data(), Eigen::Index(m_dofs), 2) = m_pp;
      } else if(m_split) {
        if(!factored)
          for(VertexSolver& solver : m_split_solver)
            solver.set_supernodal_rows(VertexSolver::cholmod ? Eigen::Index(settings.split_supernodal_rows)
                                                             : (std::numeric_limits<Eigen::Index>::max)());
        if(!solve_split(!factored, settings.threads))
          return fail(Sander_polish_status::SOLVER_FAILED, "the factorization of the Newton system failed");
        factored = true;
      } else {
        if(!factored)
          m_solver.analyzePattern(m_H, m_order);
        m_solver.factorize(m_H);
        factored = true;
        if(m_solver.info() != Eigen::Success)
          return fail(Sander_polish_status::SOLVER_FAILED, "the factorization of the Newton system failed");
        m_p = m_solver.solve(m_g);
        if(m_solver.info() != Eigen::Success)
          return fail(Sander_polish_status::SOLVER_FAILED, "the Newton system could not be solved");
      }
      if(!m_p.allFinite())
        return fail(Sander_polish_status::SOLVER_FAILED, "the step is not finite");
      m_p = -m_p;
      const double slope = m_g.dot(m_p);
      // predicted decrease below the tolerance; the split model, which leaves out the coupling of
      // u and v, predicts less than its steps gain: only a step's gain ends the split steps
      if(!m_split && !(-slope > 2. * settings.tolerance * E)) {
        r.stop = Sander_polish_stop::CONVERGED;
        break;
      }
      for(std::size_t v = 0; v < m_dof.size(); ++v)
        if(m_dof[v] >= 0)
          m_dir[v] = {m_p(2 * m_dof[v]), m_p(2 * m_dof[v] + 1)};

      const double E_new = line_search(E, slope, settings.free_border, first_trial, !proxy);
      if(!(E_new < E)) { r.stop = Sander_polish_stop::NO_PROGRESS; break; }
      if(proxy) // a step longer than the last one taken in full, or as long as the last one cut
        first_trial = m_trial_t == first_trial ? 2. * m_trial_t : m_trial_t;
      m_x.swap(m_trial);
      const double decrease = E - E_new;
      E = E_new;
      if(m_area_term) {
        pure = energy_of(m_x, 0.);
        area = area_of(m_x);
      }
      reported = m_area_term ? pure * area : E;
      ++r.iterations;

      bool go_on = true;
      if(visitor) {
        write(m_current);
        Sander_polish_step s;
        s.iteration = r.iterations;
        s.measures = m_stretch.evaluate(m, m_current, settings.threads);
        s.l2_stretch = s.measures.l2;
        s.energy = reported;
        s.seconds = seconds();
        s.uv = &m_current;
        go_on = visitor(s);
      }
      if(converged(decrease, E, reported, settings, energies)) { r.stop = Sander_polish_stop::CONVERGED; break; }
      if(!go_on) { r.stop = Sander_polish_stop::VISITOR; break; }
    }

    if(r.iterations > 0) { // every step taken lowered the energy (E * A with the area term)
      write(uv);
      r.energy_after = reported;
      r.l2_after = m_stretch.evaluate(m, uv, settings.threads).l2;
    }
    r.seconds = seconds();
    return r;
  }

  // the solver of the Newton system, as the last polish left it
  const VertexSolver& newton_solver() const { return m_solver; }
  // the solver of the u (0) or the v (1) system of SPLIT_NEWTON, as the last polish left it
  const VertexSolver& split_solver(std::size_t c) const { return m_split_solver[c]; }

  // Whether polish() would take this start (its status not BAD_START): the checks alone, no step.
  bool accepts(const Flat_triangles& m, const std::vector<Triangle>& guard, const std::vector<char>& fixed,
               const std::vector<int>& border, const std::vector<Vec2>& uv, bool free_border)
  {
    std::string why;
    return setup(m, guard, fixed, border, uv, free_border, false, why);
  }

private:
  // Whether a step that lowered the energy by `decrease` to `E` ends the steps: with a window of
  // one step, by that decrease; with a wider one, by the energy as reported (`reported`: E, or
  // E * A with the area term, whose E changes with mu from step to step) over the last steps,
  // appended to `energies`.
  static bool converged(double decrease, double E, double reported, const Sander_polish_settings& settings,
                        std::vector<double>& energies)
  {
    if(settings.tolerance_window <= 1)
      return decrease <= settings.tolerance * E;
    energies.push_back(reported);
    const std::size_t k = (std::min)(std::size_t(settings.tolerance_window), energies.size() - 1);
    const double now = energies.back();
    return energies[energies.size() - 1 - k] - now <= double(k) * settings.tolerance * now;
  }

  struct Energy_face
  {
    Triangle v;
    Eigen::Matrix<double, 3, 2> D;
    double area;
  };

  // What one energy face adds to energy_of(), assemble() or max_step().
  struct Face_terms
  {
    double energy = 0.;
    bool folded = false;
    double fold_step = HUGE_VAL;             // along m_dir, see first_fold()
    Eigen::Matrix<double, 6, 1> gradient;    // with respect to (u1, v1, u2, v2, u3, v3)
    Eigen::Matrix<double, 6, 6> hessian;     // projected
  };

  // Checks the start, classifies the faces, numbers the unknowns and builds the sparse pattern.
  bool setup(const Flat_triangles& m, const std::vector<Triangle>& guard, const std::vector<char>& fixed,
             const std::vector<int>& border, const std::vector<Vec2>& uv, bool free_border, bool pin,
             std::string& why)
  {
    const std::size_t nv = m.xyz.size();
    auto valid = [nv](const Triangle& t) {
      for(int v : t)
        if(v < 0 || std::size_t(v) >= nv) return false;
      return true;
    };
    auto refuse = [&why](const char* message) {
      why = message;
      return false;
    };
    if(fixed.size() != nv || uv.size() != nv)
      return refuse("fixed and uv need one entry per vertex");
    for(const Triangle& t : m.tri)
      if(!valid(t)) return refuse("a face has a vertex index out of range");
    for(const Triangle& t : guard)
      if(!valid(t)) return refuse("a guard face has a vertex index out of range");
    for(int v : border)
      if(v < 0 || std::size_t(v) >= nv) return refuse("a border vertex index is out of range");
    if(free_border && border.size() < 3)
      return refuse("a free border needs a border loop");
    for(const Vec2& q : uv)
      if(!std::isfinite(q[0]) || !std::isfinite(q[1])) return refuse("a uv coordinate is not finite");
    for(const Vec3& p : m.xyz)
      if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        return refuse("a vertex position is not finite");

    // positive: the orientation of the total signed uv area
    double signed_area = 0.;
    for(const Triangle& t : m.tri)
      signed_area += twice_signed_area(uv[t[0]], uv[t[1]], uv[t[2]]);
    if(!(signed_area != 0.))
      return refuse("the start has no uv area");

    // A free border frees the outer loop, except the corners of faces of fixed vertices and
    // zero uv area (an ear flattened on a side of the square): such a face cannot carry energy.
    // Pinned, its fixed vertices stay.
    m_fixed.assign(fixed.begin(), fixed.end());
    if(free_border && !pin) {
      std::vector<char> keep_fixed(nv, 0);
      for(const Triangle& t : m.tri)
        if(fixed[t[0]] && fixed[t[1]] && fixed[t[2]] && twice_signed_area(uv[t[0]], uv[t[1]], uv[t[2]]) == 0.)
          for(int v : t) keep_fixed[v] = 1;
      for(int v : border)
        if(!keep_fixed[v]) m_fixed[v] = 0;
    }
    m_flip = signed_area < 0.;
    m_x.resize(nv);
    for(std::size_t v = 0; v < nv; ++v)
      m_x[v] = {uv[v][0], m_flip ? -uv[v][1] : uv[v][1]};

    double area_3d = 0.;
    for(const Triangle& t : m.tri)
      area_3d += triangle_area(m.xyz[t[0]], m.xyz[t[1]], m.xyz[t[2]]);
    const double tol3 = Flat_stretch::degenerate_ratio * area_3d / double((std::max)(m.tri.size(), std::size_t(1)));

    m_energy.clear();
    m_guard.clear();
    m_area_uv = 0.;
    std::vector<char> in_energy(nv, 0);
    auto keep = [&](const Triangle& t) { // false for a bad start
      const bool all_fixed = m_fixed[t[0]] && m_fixed[t[1]] && m_fixed[t[2]];
      const double a = twice_signed_area(m_x[t[0]], m_x[t[1]], m_x[t[2]]);
      return all_fixed ? a >= 0. : a > 0.;
    };
    for(const Triangle& t : m.tri) {
      if(!keep(t))
        return refuse("the start has a flipped or degenerate face");
      if(m_fixed[t[0]] && m_fixed[t[1]] && m_fixed[t[2]]) continue;
      const Sander_face_operator op = sander_face_operator(m.xyz[t[0]], m.xyz[t[1]], m.xyz[t[2]]);
      if(!(op.area > tol3) || !op.D.allFinite()) {
        m_guard.push_back(t);
        continue;
      }
      m_energy.push_back(Energy_face{t, op.D, op.area});
      m_area_uv += 0.5 * twice_signed_area(m_x[t[0]], m_x[t[1]], m_x[t[2]]);
      for(int v : t) in_energy[v] = 1;
    }
    for(const Triangle& t : guard) {
      if(!keep(t))
        return refuse("the start has a flipped or degenerate guard face");
      if(!(m_fixed[t[0]] && m_fixed[t[1]] && m_fixed[t[2]]))
        m_guard.push_back(t);
    }

    m_border.clear();
    if(free_border) {
      m_border.assign(border.begin(), border.end());
      m_trial = m_x;
      if(!m_simple(m_trial, m_border))
        return refuse("the border loop of the start is not simple");
    }

    // unknowns: free vertices of energy faces; with a free border, translation is pinned at
    // a border vertex unless a fixed vertex already holds the map in place
    int pinned = -1;
    if(free_border) {
      bool anchored = false;
      for(std::size_t v = 0; v < nv && !anchored; ++v)
        anchored = in_energy[v] && m_fixed[v];
      for(std::size_t k = 0; k < border.size() && !anchored && pinned < 0; ++k)
        if(in_energy[border[k]]) pinned = border[k];
    }
    m_dof.assign(nv, -1);
    m_dofs = 0;
    for(std::size_t v = 0; v < nv; ++v)
      if(in_energy[v] && !m_fixed[v] && int(v) != pinned)
        m_dof[v] = int(m_dofs++);
    m_dir.assign(nv, Vec2{0., 0.});
    m_trial = m_x;
    const Eigen::Index n = Eigen::Index(2 * m_dofs);
    m_g.resize(n);
    m_p.resize(n);
    return true;
  }

  // m_order: the unknowns of the proxy and the split systems in the order of `rank`, or of the
  // vertex rank computed here if there is none; with `newton`, the rows of the Newton system
  // instead (those of u and v of an unknown one after the other)
  void order_vertex_systems(const Flat_triangles& m, const std::vector<Triangle>& guard, const std::vector<int>* rank,
                            bool newton)
  {
    std::vector<int> vertex_of(m_dofs);
    for(std::size_t v = 0; v < m_dof.size(); ++v)
      if(m_dof[v] >= 0)
        vertex_of[std::size_t(m_dof[v])] = int(v);
    if(rank != nullptr) {
      m_order = rows_in_order(*rank, vertex_of);
    } else if(m_dofs >= nested_dissection_threshold) {
      m_order = rows_in_order(fill_reducing_vertex_rank(m.xyz.size(), m.tri, guard), vertex_of);
    } else {
      m_order.clear();
    }
    if(newton)
      m_order = paired_rows(m_order);
  }

  // The pattern of the lower triangle of the Newton system; every face keeps where its 6x6
  // block goes. Split: the pattern of one system of the vertices, the same for u and v, and
  // where the 3x3 block of each face goes.
  void build_newton_pattern()
  {
    if(m_split) {
      build_pattern(3, [this](int v, int) { return m_dof[v]; }, m_Hs[0]);
      m_Hs[1] = m_Hs[0];
    } else {
      build_pattern(6, [this](int v, int r) { return index(v, r); }, m_H);
    }
  }

  // The lower triangle of `M` over the unknowns `unknown(vertex, coordinate)` (-1: none) of the
  // `block` / 3 coordinates of each corner of the energy faces, and m_slot: per face, where
  // each entry of its block x block matrix goes (-1 if nowhere).
  template <typename Unknown>
  void build_pattern(int block, const Unknown& unknown, Eigen::SparseMatrix<double>& M)
  {
    const int per_corner = block / 3;
    auto row = [&](const Energy_face& f, int a) { return unknown(f.v[a / per_corner], a % per_corner); };
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(m_energy.size() * std::size_t(block * (block + 1) / 2));
    for(const Energy_face& f : m_energy)
      for(int a = 0; a < block; ++a)
        for(int b = 0; b < block; ++b) {
          const int i = row(f, a), j = row(f, b);
          if(i >= 0 && j >= 0 && i >= j)
            entries.emplace_back(i, j, 0.);
        }
    const Eigen::Index n = Eigen::Index(per_corner * m_dofs);
    M.resize(n, n);
    M.setFromTriplets(entries.begin(), entries.end());
    M.makeCompressed();
    const std::size_t size = std::size_t(block * block);
    m_slot.assign(size * m_energy.size(), -1);
    for(std::size_t k = 0; k < m_energy.size(); ++k)
      for(int a = 0; a < block; ++a)
        for(int b = 0; b < block; ++b) {
          const int i = row(m_energy[k], a), j = row(m_energy[k], b);
          if(i >= 0 && j >= 0 && i >= j) {
            const int* first = M.innerIndexPtr() + M.outerIndexPtr()[j];
            const int* last = M.innerIndexPtr() + M.outerIndexPtr()[j + 1];
            m_slot[size * k + std::size_t(block * a + b)] = int(std::lower_bound(first, last, i) - M.innerIndexPtr());
          }
        }
  }

  // The split Newton step into m_p: the u and the v system factored (the pattern analysed
  // first if `analyse`) and solved, side by side on two threads if there are two.
  bool solve_split(bool analyse, unsigned int threads)
  {
    const Eigen::Index n = Eigen::Index(m_dofs);
    bool ok[2] = {false, false};
    // the two systems share their pattern: a minimum degree order is found once for both
    std::vector<int> own;
    if(analyse && m_order.empty())
      own = minimum_degree_order(m_Hs[0]);
    const std::vector<int>& order = own.empty() ? m_order : own;
    const unsigned int split_threads = m_dofs >= split_parallel_rows ? (std::min)(threads, 2u) : 1u;
    parallel_for_each(2, split_threads, [&](std::size_t c) {
      VertexSolver& solver = m_split_solver[c];
      if(analyse)
        solver.analyzePattern(m_Hs[c], order);
      solver.factorize(m_Hs[c]);
      if(solver.info() != Eigen::Success)
        return;
      Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<2> > p(m_p.data() + c, n);
      p = solver.solve(Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<2> >(m_g.data() + c, n));
      ok[c] = solver.info() == Eigen::Success;
    });
    return ok[0] && ok[1];
  }

  // The uv area of the energy faces of `x`.
  double area_of(const std::vector<Vec2>& x) const
  {
    double a = 0.;
    for(const Energy_face& f : m_energy)
      a += 0.5 * twice_signed_area(x[f.v[0]], x[f.v[1]], x[f.v[2]]);
    return a;
  }

  // Calls `term(k, m_terms[i])` for the energy faces k, a block of them at a time on m_threads
  // threads, then `add(k, m_terms[i])` for the faces of the block in order: the sums are those
  // of one thread, bit for bit. Stops after a block where `add` returns false.
  template <typename Term, typename Add>
  void for_energy_faces(const Term& term, const Add& add)
  {
    const std::size_t n = m_energy.size();
    m_terms.resize((std::min)(n, face_block));
    for(std::size_t first = 0; first < n; first += face_block) {
      const std::size_t count = (std::min)(face_block, n - first);
      parallel_for(count, m_threads, face_grain, [&](std::size_t b, std::size_t e) {
        for(std::size_t i = b; i < e; ++i)
          term(first + i, m_terms[i]);
      });
      bool go_on = true;
      for(std::size_t i = 0; i < count; ++i)
        go_on = add(first + i, m_terms[i]) && go_on;
      if(!go_on)
        return;
    }
  }

  // Objective at x + t * dir, written to m_trial; +inf if a face folds.
  double energy_at(double t)
  {
    m_trial_t = t;
    for(std::size_t v = 0; v < m_x.size(); ++v)
      m_trial[v] = {m_x[v][0] + t * m_dir[v][0], m_x[v][1] + t * m_dir[v][1]};
    for(const Triangle& g : m_guard)
      if(!(twice_signed_area(m_trial[g[0]], m_trial[g[1]], m_trial[g[2]]) > 0.))
        return HUGE_VAL;
    return energy_of(m_trial, m_mu);
  }

  // The energy of the faces at `x` with the area term `mu`; +inf if a face folds.
  double energy_of(const std::vector<Vec2>& x, double mu)
  {
    double E = 0.;
    bool folded = false;
    for_energy_faces(
      [this, &x, mu](std::size_t k, Face_terms& out) {
        const Energy_face& f = m_energy[k];
        const Eigen::Matrix2d J = jacobian(f, x);
        out.folded = !(J.determinant() > 0.);
        if(!out.folded)
          out.energy = sander_face_energy(J, f.area, mu);
      },
      [&](std::size_t, const Face_terms& out) {
        folded = folded || out.folded;
        if(!folded)
          E += out.energy;
        return !folded;
      });
    return folded ? HUGE_VAL : E;
  }

  // Gradient at x, and the projected Hessian if asked.
  void assemble(bool hessian)
  {
    m_g.setZero();
    if(hessian && m_split) {
      for(Eigen::SparseMatrix<double>& M : m_Hs)
        std::fill(M.valuePtr(), M.valuePtr() + M.nonZeros(), 0.);
    } else if(hessian) {
      std::fill(m_H.valuePtr(), m_H.valuePtr() + m_H.nonZeros(), 0.);
    }
    for_energy_faces(
      [this, hessian](std::size_t k, Face_terms& out) {
        const Energy_face& f = m_energy[k];
        const Eigen::Matrix2d J = jacobian(f, m_x);
        Eigen::Vector4d gJ;
        sander_face_energy(J, f.area, m_mu, &gJ);
        for(int a = 0; a < 3; ++a) // d vec(J) / d(u_a, v_a), from J(r, c) = sum_a x(2a + r) D(a, c)
          for(int r = 0; r < 2; ++r)
            out.gradient(2 * a + r) = gJ(2 * r) * f.D(a, 0) + gJ(2 * r + 1) * f.D(a, 1);
        if(!hessian)
          return;
        Eigen::Matrix<double, 4, 6> B;
        jacobian_operator(f, B);
        const Eigen::Matrix4d HJ = sander_face_projected_hessian(J, f.area, m_mu, eigenvalue_floor);
        out.hessian.noalias() = B.transpose() * HJ * B;
      },
      [this, hessian](std::size_t k, const Face_terms& out) {
        const Energy_face& f = m_energy[k];
        for(int a = 0; a < 3; ++a)
          for(int r = 0; r < 2; ++r) {
            const int i = index(f.v[a], r);
            if(i >= 0) m_g(i) += out.gradient(2 * a + r);
          }
        if(hessian)
          add_block(k, out.hessian);
        return true;
      });
  }

  // The proxy, one row per moving vertex (it acts on u and v alike): the Hessian of the
  // Dirichlet energy sum_T A3(T) ||J_T||_F^2 / 2, i.e. the cotangent Laplacian of the 3D mesh,
  // scaled to the Hessian of E at a map of uniform scale s (J = s R, R a rotation), where E's
  // curvature is about 3 A3 / s^4 along most directions of vec(J).
  void assemble_proxy()
  {
    double area_3d = 0.;
    for(const Energy_face& f : m_energy)
      area_3d += f.area;
    const double s2 = area_of(m_x) / area_3d;
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(m_energy.size() * 6);
    for(const Energy_face& f : m_energy) {
      const Eigen::Matrix3d L = (3. * f.area / (s2 * s2)) * (f.D * f.D.transpose());
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b) {
          const int i = m_dof[f.v[a]], j = m_dof[f.v[b]];
          if(i >= 0 && j >= 0 && i >= j)
            entries.emplace_back(i, j, L(a, b));
        }
    }
    m_P.resize(Eigen::Index(m_dofs), Eigen::Index(m_dofs));
    m_P.setFromTriplets(entries.begin(), entries.end());
  }

  // vec(J) = B x with x = (u1, v1, u2, v2, u3, v3): J(r, c) = sum_a x(2a + r) D(a, c)
  static void jacobian_operator(const Energy_face& f, Eigen::Matrix<double, 4, 6>& B)
  {
    B.setZero();
    for(int a = 0; a < 3; ++a)
      for(int r = 0; r < 2; ++r)
        for(int c = 0; c < 2; ++c)
          B(2 * r + c, 2 * a + r) = f.D(a, c);
  }

  // Adds the 6x6 block of energy face k to the lower triangle of m_H (split: its u and v parts
  // to the u and v systems).
  void add_block(std::size_t k, const Eigen::Matrix<double, 6, 6>& Hx)
  {
    if(m_split) {
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b) {
          const int s = m_slot[9 * k + 3 * a + b];
          if(s < 0) continue;
          m_Hs[0].valuePtr()[s] += Hx(2 * a, 2 * b);
          m_Hs[1].valuePtr()[s] += Hx(2 * a + 1, 2 * b + 1);
        }
      return;
    }
    for(int a = 0; a < 6; ++a)
      for(int b = 0; b < 6; ++b) {
        const int s = m_slot[36 * k + 6 * a + b];
        if(s >= 0) m_H.valuePtr()[s] += Hx(a, b);
      }
  }

  // Largest t in (0, inf] with every face of a free vertex positively oriented on [0, t).
  double max_step()
  {
    double t_max = HUGE_VAL;
    for_energy_faces([this](std::size_t k, Face_terms& out) { out.fold_step = first_fold(m_x, m_dir, m_energy[k].v); },
                     [&t_max](std::size_t, const Face_terms& out) {
                       t_max = (std::min)(t_max, out.fold_step);
                       return true;
                     });
    for(const Triangle& g : m_guard) t_max = (std::min)(t_max, first_fold(m_x, m_dir, g));
    return t_max;
  }

  // Backtracking from min(first, 0.8 t_max) until Armijo holds (and the border stays simple).
  // With `extrapolate`, a first trial that passes is doubled while the energy keeps falling,
  // within 0.8 t_max: the clamped twists make the Newton model stiffer than the energy, and the
  // best step is often 2. Returns the objective at the step taken (left in m_trial), or E if none.
  double line_search(double E, double slope, bool free_border, double first, bool extrapolate)
  {
    const double t_max = max_step();
    double t = (std::min)(first, 0.8 * t_max);
    for(int k = 0; k < 60 && t > 0.; ++k, t *= 0.5) {
      const double E_t = energy_at(t);
      if(!(E_t < E) || !(E_t <= E + 1e-4 * t * slope))
        continue;
      if(free_border && !m_simple(m_trial, m_border))
        continue;
      if(k > 0 || !extrapolate)
        return E_t;
      double best = E_t, t_best = t;
      for(double s = 2. * t; s <= 0.8 * t_max && s <= 1e6; s *= 2.) {
        const double E_s = energy_at(s);
        if(!(E_s < best) || (free_border && !m_simple(m_trial, m_border)))
          break;
        best = E_s;
        t_best = s;
      }
      if(m_trial_t != t_best)
        energy_at(t_best);
      return best;
    }
    return E;
  }

  // Writes x in the caller's orientation.
  void write(std::vector<Vec2>& uv) const
  {
    uv.resize(m_x.size());
    for(std::size_t v = 0; v < m_x.size(); ++v)
      uv[v] = {m_x[v][0], m_flip ? -m_x[v][1] : m_x[v][1]};
  }

  static Eigen::Matrix2d jacobian(const Energy_face& f, const std::vector<Vec2>& x)
  {
    Eigen::Matrix<double, 2, 3> Q;
    for(int a = 0; a < 3; ++a)
      Q.col(a) << x[f.v[a]][0], x[f.v[a]][1];
    return Q * f.D;
  }


  // Row of coordinate r of vertex v in the system, -1 if it does not move.
  int index(int v, int r) const { return m_dof[v] < 0 ? -1 : 2 * m_dof[v] + r; }

  std::vector<char> m_fixed;
  std::vector<Energy_face> m_energy;
  std::vector<Face_terms> m_terms;         // of a block of energy faces
  unsigned int m_threads = 1;
  std::vector<Triangle> m_guard;           // faces without energy that must stay positive
  std::vector<int> m_border;
  std::vector<int> m_dof;                  // vertex -> unknown, -1 if it does not move
  std::vector<int> m_order;                // unknowns in the elimination order of the vertex systems (or rows of the Newton system)
  std::size_t m_dofs = 0;
  std::vector<int> m_slot;                 // 36 per energy face: entry of m_H, -1 if none (split: 9, of m_Hs)
  std::vector<Vec2> m_x, m_trial, m_dir, m_current;
  Simple_loop_check m_simple;              // of the border, with a free border
  bool m_flip = false;                     // uv is mirrored (v -> -v) in m_x so that faces are positive
  double m_mu = 0., m_area_uv = 0.;
  bool m_area_term = false;
  double m_trial_t = 0.;                   // m_trial = m_x + m_trial_t * m_dir
  Eigen::SparseMatrix<double> m_H, m_P;    // Newton system, proxy
  std::array<Eigen::SparseMatrix<double>, 2> m_Hs; // split Newton: the u and the v system
  bool m_split = false;
  Eigen::VectorXd m_g, m_p;
  Eigen::Matrix<double, Eigen::Dynamic, 2> m_rhs, m_pp; // proxy solve, u and v columns
  VertexSolver m_solver{true}; // the Newton system: projected Hessians, definite
  VertexSolver m_proxy_solver;
  // the split systems: positive definite with the fixed border that they are used with
  VertexSolver m_split_solver[2] = {VertexSolver(true), VertexSolver(true)};
  Flat_stretch m_stretch;
};

CGAL_SMP_END_SOLVER_NAMESPACE
} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SMP_INTERNAL_SANDER_ENERGY_POLISHER_H

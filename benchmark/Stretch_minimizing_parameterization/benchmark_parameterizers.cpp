// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Side-by-side benchmark of surface parameterizers: the rows of the tables of Yoshizawa,
// Belyaev and Seidel (2004) and CGAL 5.5.1's own parameterizers, on one mesh at a time, with
// the same border (unit square, arc length) wherever a border is fixed.
//
//   benchmark_parameterizers [options] MESH [MESH ...]
//   benchmark_parameterizers mesh.off [runs]                (the older form)
//
// MESH is a file (OFF, OBJ, PLY, ...) or FILE@loopN: the file refined N times by
// CGAL::Subdivision_method_3::Loop_subdivision at run time. Meshes are run in the order given
// (give them by increasing size: the skip rule predicts from the previous sizes).
//
// Options:
//   --out DIR       write DIR/<mesh>.md, tables.md, summary.md, results.csv, history.csv and the
//                   gnuplot data files plot_*.dat (default: print only)
//   --runs N        at most N timed runs per method (default 7; 7 below 20k vertices, 3 below
//                   100k, 1 above)
//   --budget S      skip a method on a mesh when its time, predicted from the previous sizes, is
//                   above S seconds (default 300); the references of the quoted ratios (CGAL MVC,
//                   U^opt, U^0 alone) are never skipped, only killed at the hard limit
//   --hard-limit S  kill a run that takes more than S seconds (default 900)
//   --scratch DIR   working directory for Iterative_authalic_parameterizer_3, which writes
//                   last_solve.off into the current directory (default: a temporary directory)
//   --methods a,b   run only these method ids (see --list)
//   --list          list the methods and exit
//
// Every run of every method happens in a forked child process: the child runs the method once,
// measures its map and its peak memory, and sends the figures to the parent through a pipe.
// Runs are interleaved across methods so that machine noise spreads evenly.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Iterative_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Shape_preserving_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>

#include "Intrinsic_parameterizer_3.h"
#include "Sander_line_search.h"

#include <Eigen/Core>

#include <boost/lexical_cast.hpp>

#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <streambuf>
#include <string>
#include <type_traits>
#include <vector>

typedef CGAL::Simple_cartesian<double>        Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>   Mesh;
typedef Mesh::Vertex_index                    vertex_descriptor;
typedef Mesh::Halfedge_index                  halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Kernel::Point_2> UV_map;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

typedef SMP::Square_border_arc_length_parameterizer_3<Mesh>              Square;
typedef SMP::Discrete_conformal_map_parameterizer_3<Mesh, Square>        Harmonic;      // (a), CGAL default solver
typedef SMP::Shape_preserving_parameterizer_3<Mesh, Square>              Floater;       // (b), SparseLU
typedef SMP_benchmark::Intrinsic_parameterizer_3<Mesh, Square>           Intrinsic;     // (c), CGAL default solver
typedef SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater>           Stretch_minimizer;
// the same with the default direct solver at every size (no multigrid solver on large systems)
typedef SMP::Stretch_minimizing_parameterizer_3<
  Mesh, Floater, CGAL::Eigen_solver_traits<SMP::internal::Default_direct_solver> > Direct_stretch_minimizer;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh, Square>        CGAL_MVC;
typedef SMP::Barycentric_mapping_parameterizer_3<Mesh, Square>           CGAL_Tutte;
typedef SMP::Discrete_authalic_parameterizer_3<Mesh, Square>             CGAL_Authalic;
typedef SMP::Iterative_authalic_parameterizer_3<Mesh, Square>            CGAL_Iterative_authalic;
typedef SMP::LSCM_parameterizer_3<Mesh>                                  CGAL_LSCM;     // its defaults
typedef SMP::ARAP_parameterizer_3<Mesh>                                  CGAL_ARAP;     // its defaults

// ------------------------------------------------------------------------------------------
// What a child sends back (one run of one method on one mesh)
// ------------------------------------------------------------------------------------------

constexpr int max_history = 64;

struct Child_result
{
  int status = SMP::OK;
  double seconds = 0.;                 // wall time of the parameterization call
  int has_stats = 0;
  SMP::Stretch_statistics stats;
  int history_size = 0;                // U^0, U^1, ... (stretch minimizer only)
  double history_l2[max_history];
  double history_linf[max_history];
  double history_seconds[max_history];
  double history_peak_kib[max_history] = {}; // peak resident memory of each step (the mesh included), 0 if unknown
  double steps_peak_kib = 0.;          // the largest of the steps' peaks (they reset VmHWM), polish steps included
  double rss_start_kib = 0.;           // resident memory of the child before the call (the mesh)
  double peak_kib = 0.;                // its peak during the call (VmHWM after a reset)
  double maxrss_kib = 0.;              // getrusage: peak of the child process, start included
  int kept_step = -1;                  // stretch minimizer: h of U^opt
  int steps_computed = -1;             // stretch minimizer: steps computed
  char steps[96] = {0};
  char note[160] = {0};
};
static_assert(std::is_trivially_copyable<Child_result>::value, "sent through a pipe");

struct Context
{
  Mesh& mesh;
  halfedge_descriptor bhd;
  UV_map uv;
  std::string scratch; // working directory for Iterative_authalic_parameterizer_3
};

template <typename F>
SMP::Error_code timed(Child_result& r, F&& call)
{
  const auto start = std::chrono::steady_clock::now();
  const SMP::Error_code e = call();
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return e;
}

void set_text(char* dst, std::size_t size, const std::string& s)
{
  std::snprintf(dst, size, "%s", s.c_str());
}

// A stream buffer that swallows everything (Iterative_authalic_parameterizer_3 prints every
// iteration to std::cout in CGAL 5.5.1).
class Null_buffer : public std::streambuf
{
protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// ------------------------------------------------------------------------------------------
// Methods
// ------------------------------------------------------------------------------------------

struct Method
{
  std::string id;      // short, for the CSV and the command line
  std::string label;   // for the tables
  std::string border;
  std::string solver;
  std::function<SMP::Error_code(Context&, Child_result&)> run;
};

// The references of the ratios the summary quotes: run on every mesh whatever the prediction
// (only the hard limit stops them).
bool is_reference(const std::string& id)
{
  return id == "cgal_mvc" || id == "f_uopt" || id == "u0_minimizer";
}

template <typename Parameterizer>
SMP::Error_code run_fixed(Context& c, Child_result& r)
{
  return timed(r, [&] { return SMP::parameterize(c.mesh, Parameterizer(), c.bhd, c.uv); });
}

// ------------------------------------------------------------------------------------------
// Memory of the current process (Linux /proc)
// ------------------------------------------------------------------------------------------

double proc_status_kib(const char* field)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while(std::getline(in, line))
    if(line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
      return std::atof(line.c_str() + n + 1);
  return 0.;
}

// Resets VmHWM to the current resident size (Linux >= 4.0); false if not possible.
bool reset_peak_memory()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return bool(out);
}

// The vertex numbering that CGAL's free function parameterize() makes (through
// PMP::connected_component()), for the calls of a parameterizer's member function as CGAL's makes them
auto cgal_vertex_index(Context& c)
{
  auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), c.mesh);
  SMP::internal::fill_index_map_of_cc(c.bhd, c.mesh, vimap);
  return vimap;
}

// How run_minimizer() calls the parameterizer: through CGAL's free function parameterize(), which
// resolves to the package's overload for this class, or as CGAL's own function body does (its
// vertex numbering by PMP::connected_component(), then the member function)
enum class Call { FREE_FUNCTION, CGAL_BODY };

template <typename Minimizer = Stretch_minimizer, typename NamedParameters>
SMP::Error_code run_minimizer(Context& c, Child_result& r, const NamedParameters& np, Call call = Call::FREE_FUNCTION)
{
  // the peak of each step (its solve and what comes before it: for U^0, the setup), read
  // after the step and reset for the next; on large meshes only, where reading /proc at every
  // step is lost in the time of a step (not in the milliseconds of a small mesh's call)
  constexpr std::size_t step_memory_vertices = 100000;
  const bool per_step = num_vertices(c.mesh) >= step_memory_vertices;
  std::vector<double> peaks;
  bool reset = per_step && reset_peak_memory();
  Minimizer p(np.visitor([&](const SMP::Stretch_minimizing_step&) {
    if(per_step) {
      peaks.push_back(reset ? proc_status_kib("VmHWM") : 0.);
      reset = reset_peak_memory();
    }
    return true;
  }));
  const SMP::Error_code e = timed(r, [&] {
    if(call == Call::FREE_FUNCTION)
      return SMP::parameterize(c.mesh, p, c.bhd, c.uv);
    return p.parameterize(c.mesh, c.bhd, c.uv, cgal_vertex_index(c), get(CGAL::dynamic_vertex_property_t<bool>(), c.mesh));
  });
  const SMP::Stretch_minimizing_report& rep = p.report();
  r.history_size = int(std::min<std::size_t>(rep.history.size(), max_history));
  for(int h = 0; h < r.history_size; ++h) {
    r.history_l2[h] = rep.history[h].l2_stretch;
    r.history_linf[h] = rep.history[h].linf_stretch;
    r.history_seconds[h] = rep.history[h].seconds;
    r.history_peak_kib[h] = std::size_t(h) < peaks.size() ? peaks[std::size_t(h)] : 0.;
  }
  for(double k : peaks)
    r.steps_peak_kib = std::max(r.steps_peak_kib, k);
  r.kept_step = int(rep.kept_step);
  r.steps_computed = int(rep.steps_taken());
  if(e == SMP::OK) {
    std::ostringstream s;
    s << "h = " << rep.kept_step;
    if(rep.steps_taken() != rep.kept_step)
      s << " (" << rep.steps_taken() << " computed)";
    if(rep.polish.descent_iterations > 0)
      s << " + " << rep.polish.descent_iterations << " descent steps";
    if(rep.polish.iterations > 0)
      s << " + " << rep.polish.iterations << " Newton steps";
    set_text(r.steps, sizeof r.steps, s.str());
  } else {
    set_text(r.note, sizeof r.note, rep.message);
  }
  return e;
}

SMP::Error_code run_minimizer(Context& c, Child_result& r, unsigned int cap, double eta)
{
  return run_minimizer(c, r, SMP::parameters::eta(eta).number_of_iterations(cap));
}

SMP::Error_code run_iterative_authalic(Context& c, Child_result& r)
{
  // CGAL 5.5.1 hard-codes DEBUG_L0: it prints every iteration to std::cout and writes
  // last_solve.off into the working directory at every iteration. Run it in a scratch
  // directory with std::cout / std::cerr swallowed; the time below includes that I/O.
  std::string dir = c.scratch + "/iterative_authalic.XXXXXX";
  std::vector<char> buf(dir.begin(), dir.end());
  buf.push_back('\0');
  if(mkdtemp(buf.data()) == nullptr || chdir(buf.data()) != 0) {
    set_text(r.note, sizeof r.note, "cannot create a scratch directory in " + c.scratch);
    return SMP::ERROR_WRONG_PARAMETER;
  }
  Null_buffer null;
  std::streambuf* out = std::cout.rdbuf(&null);
  std::streambuf* err = std::cerr.rdbuf(&null);

  auto vimap = cgal_vertex_index(c);
  auto vpmap = get(CGAL::dynamic_vertex_property_t<bool>(), c.mesh);
  unsigned int iterations = 15; // in: the cap; out: the iteration kept
  CGAL_Iterative_authalic p;
  const SMP::Error_code e = timed(r, [&] {
    return p.parameterize(c.mesh, c.bhd, c.uv, vimap, vpmap, iterations);
  });

  std::cout.rdbuf(out);
  std::cerr.rdbuf(err);
  std::error_code ec;
  fs::remove_all(buf.data(), ec); // last_solve.off
  r.kept_step = int(iterations);
  set_text(r.steps, sizeof r.steps, "best " + std::to_string(iterations) + " (cap 15)");
  set_text(r.note, sizeof r.note, "time includes CGAL 5.5.1's debug output (every iteration printed, "
                                  "last_solve.off written), swallowed");
  return e;
}

// Row (d): U^0 (the package's, as in row (b)), then Sander et al.'s line searches
// (Sander_line_search.h) until a sweep gains less than 1e-4, at most `sander_seconds`.
constexpr double sander_seconds = 300.;

SMP::Error_code run_sander(Context& c, Child_result& r)
{
  SMP_benchmark::Sander_line_search_result result;
  const SMP::Error_code e = timed(r, [&] {
    Stretch_minimizer start(SMP::parameters::number_of_iterations(0));
    const SMP::Error_code s = SMP::parameterize(c.mesh, start, c.bhd, c.uv);
    if(s != SMP::OK)
      return s;
    namespace SMPI = SMP::internal;
    SMPI::Flat_triangles m;
    std::vector<SMPI::Vec2> uv;
    for(vertex_descriptor v : vertices(c.mesh)) {
      const Kernel::Point_3& p = c.mesh.point(v);
      m.xyz.push_back({p.x(), p.y(), p.z()});
      uv.push_back({get(c.uv, v).x(), get(c.uv, v).y()});
    }
    for(Mesh::Face_index f : faces(c.mesh)) {
      const halfedge_descriptor h = halfedge(f, c.mesh);
      m.tri.push_back({int(source(h, c.mesh)), int(target(h, c.mesh)), int(target(next(h, c.mesh), c.mesh))});
    }
    std::vector<char> fixed(uv.size(), 0);
    for(vertex_descriptor v : vertices(c.mesh))
      fixed[std::size_t(v)] = c.mesh.is_border(v);
    result = SMP_benchmark::sander_line_search(m, uv, fixed, sander_seconds);
    for(vertex_descriptor v : vertices(c.mesh))
      put(c.uv, v, Kernel::Point_2(uv[std::size_t(v)][0], uv[std::size_t(v)][1]));
    return SMP::OK;
  });
  set_text(r.steps, sizeof r.steps, std::to_string(result.sweeps) + " sweeps" + (result.capped ? " (time cap)" : ""));
  return e;
}

std::vector<Method> all_methods()
{
  const std::string square = "unit square, arc length";
  const std::string bicgstab = "BiCGSTAB + ILUT (CGAL default)";
  const std::string sparse_lu = "SparseLU";
#if defined(CGAL_SMP_USE_SPARSESUITE_SOLVERS)
  const std::string direct_solver = "UMFPACK (AMD below 150k unknowns, METIS above; no refinement)";
#else
  const std::string direct_solver = "SparseLU (minimum degree order)";
#endif
  const std::string minimizer_solver = direct_solver + " below 30k unknowns, multigrid above";
  std::vector<Method> m = {
    {"a_harmonic", "(a) Eck et al. harmonic map (CGAL Discrete_conformal_map)", square, bicgstab,
     run_fixed<Harmonic>},
    {"b_floater", "(b) Floater shape-preserving U^0 (Fixed_border_parameterizer_3)", square, sparse_lu,
     run_fixed<Floater>},
    {"c_intrinsic", "(c) Desbrun et al. intrinsic, 0.5 conformal + 0.5 authalic", square, bicgstab,
     run_fixed<Intrinsic>},
    {"d_sander", "(d) Sander et al. 2001: per-vertex line searches on the L2 stretch from U^0 (cap 300 s)", square,
     minimizer_solver + " (U^0)", run_sander},
    {"u0_minimizer", "U^0 alone: stretch minimizer, 0 steps (one factorization, two solves)", square,
     minimizer_solver, [](Context& c, Child_result& r) { return run_minimizer(c, r, 0, 1.); }},
    {"e_u1", "(e) U^1", square, minimizer_solver,
     [](Context& c, Child_result& r) { return run_minimizer(c, r, 1, 1.); }},
    {"f_uopt", "(f_h) U^opt, eta = 1", square, minimizer_solver,
     [](Context& c, Child_result& r) {
       return run_minimizer(c, r, Stretch_minimizer::default_number_of_iterations, 1.);
     }},
    {"uopt_direct", "(f_h) U^opt, eta = 1, the direct solver at every size", square, direct_solver,
     [](Context& c, Child_result& r) {
       return run_minimizer<Direct_stretch_minimizer>(
         c, r, SMP::parameters::number_of_iterations(Stretch_minimizer::default_number_of_iterations));
     }},
    {"uopt_cgal_body", "(f_h) U^opt, eta = 1, called as CGAL's parameterize() body calls it (its vertex numbering)",
     square, minimizer_solver,
     [](Context& c, Child_result& r) {
       return run_minimizer(c, r, SMP::parameters::number_of_iterations(Stretch_minimizer::default_number_of_iterations),
                            Call::CGAL_BODY);
     }},
    {"uopt_one_thread", "(f_h) U^opt, eta = 1, on one thread (number_of_threads(1))", square, minimizer_solver,
     [](Context& c, Child_result& r) { return run_minimizer(c, r, SMP::parameters::number_of_threads(1u)); }},
    {"uopt_eta05", "U^opt, eta = 0.5", square, minimizer_solver,
     [](Context& c, Child_result& r) {
       return run_minimizer(c, r, Stretch_minimizer::default_number_of_iterations, 0.5);
     }},
    {"uopt_lowest", "preset LOWEST_STRETCH (U^opt + descent steps)", square,
     std::string("sparse Cholesky (the symmetric reweighting steps, the proxy, the split Newton steps)"),
     [](Context& c, Child_result& r) {
       return run_minimizer(c, r, SMP::parameters::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH));
     }},
    {"lowest_polish", "LOWEST_STRETCH + polish, fixed border (at most 100 Newton steps)", square,
     minimizer_solver + " + sparse Cholesky",
     [](Context& c, Child_result& r) {
       return run_minimizer(c, r, SMP::parameters::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH,
                                  SMP::parameters::polish_iterations(100u)));
     }},
    {"uopt_free", "U^opt (paper) + polish, free border (at most 5 Newton steps)",
     "square start, then free (no overlap)", minimizer_solver + " + sparse Cholesky",
     [](Context& c, Child_result& r) {
       return run_minimizer(c, r, SMP::parameters::polish_iterations(5u, SMP::parameters::free_border(true)));
     }},
    {"cgal_mvc", "CGAL Mean_value_coordinates", square, bicgstab, run_fixed<CGAL_MVC>},
    {"cgal_barycentric", "CGAL Barycentric_mapping (Tutte)", square, bicgstab, run_fixed<CGAL_Tutte>},
    {"cgal_authalic", "CGAL Discrete_authalic", square, bicgstab, run_fixed<CGAL_Authalic>},
    {"cgal_iterative_authalic", "CGAL Iterative_authalic, 15 iterations (*)", square, bicgstab,
     run_iterative_authalic},
    {"cgal_lscm", "CGAL LSCM (defaults)", "free (2 pinned vertices)", "SimplicialLDLT",
     [](Context& c, Child_result& r) {
       const SMP::Error_code e = run_fixed<CGAL_LSCM>(c, r);
       set_text(r.steps, sizeof r.steps, "1 solve");
       return e;
     }},
    {"cgal_arap", "CGAL ARAP (defaults: lambda 1000, LSCM start)", "free (2 pinned vertices)", "SparseLU",
     [](Context& c, Child_result& r) {
       const SMP::Error_code e = run_fixed<CGAL_ARAP>(c, r);
       set_text(r.steps, sizeof r.steps, "not reported (cap 50)");
       return e;
     }},
  };
  return m;
}

// ------------------------------------------------------------------------------------------
// Running one method once in a child process
// ------------------------------------------------------------------------------------------

enum class Outcome { OK, FAILED, CRASHED, KILLED };

struct Run
{
  Outcome outcome = Outcome::FAILED;
  Child_result r;
  std::string why;
};

bool write_all(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while(size > 0) {
    const ssize_t k = write(fd, p, size);
    if(k < 0 && errno == EINTR)
      continue;
    if(k <= 0)
      return false;
    p += k;
    size -= std::size_t(k);
  }
  return true;
}

Run run_in_child(const Method& method, Context& c, bool measure, double hard_limit)
{
  Run run;
  int fds[2];
  if(pipe(fds) != 0) {
    run.why = "pipe() failed";
    return run;
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if(pid < 0) {
    close(fds[0]);
    close(fds[1]);
    run.why = "fork() failed";
    return run;
  }
  if(pid == 0) { // the child
    close(fds[0]);
    Child_result r;
    const bool reset = reset_peak_memory();
    r.rss_start_kib = proc_status_kib("VmRSS");
    r.status = method.run(c, r);
    // the peak since the last reset, which a method may have made between its steps
    r.peak_kib = reset ? std::max(proc_status_kib("VmHWM"), r.steps_peak_kib) : 0.;
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    r.maxrss_kib = double(ru.ru_maxrss);
    if(!reset)
      r.peak_kib = r.maxrss_kib;
    if(measure && r.status == SMP::OK) {
      r.stats = SMP::compute_stretch_statistics(c.mesh, c.uv);
      r.has_stats = 1;
    }
    write_all(fds[1], &r, sizeof r);
    close(fds[1]);
    _exit(0); // no destructors, no flush of the parent's buffers
  }
  close(fds[1]);

  // the parent: read the figures, with a deadline
  std::size_t got = 0;
  char* p = reinterpret_cast<char*>(&run.r);
  bool killed = false;
  for(;;) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double left = hard_limit - elapsed;
    if(left <= 0.) {
      kill(pid, SIGKILL);
      killed = true;
      break;
    }
    struct pollfd pfd = {fds[0], POLLIN, 0};
    const int ready = poll(&pfd, 1, int(std::min(left, 1000.) * 1000.) + 1);
    if(ready < 0 && errno == EINTR)
      continue;
    if(ready <= 0)
      continue; // timeout of this poll: check the deadline
    const ssize_t k = read(fds[0], p + got, sizeof(Child_result) - got);
    if(k < 0 && errno == EINTR)
      continue;
    if(k <= 0)
      break; // end of file: the child exited
    got += std::size_t(k);
    if(got == sizeof(Child_result))
      break;
  }
  close(fds[0]);
  int wstatus = 0;
  while(waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) { }

  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(killed) {
    run.outcome = Outcome::KILLED;
    std::ostringstream s;
    s << "killed after " << std::setprecision(3) << elapsed << " s (hard limit " << hard_limit << " s)";
    run.why = s.str();
  } else if(got != sizeof(Child_result)) {
    run.outcome = Outcome::CRASHED;
    std::ostringstream s;
    if(WIFSIGNALED(wstatus))
      s << "crashed: signal " << WTERMSIG(wstatus) << " (" << strsignal(WTERMSIG(wstatus)) << ")";
    else
      s << "crashed: exit code " << WEXITSTATUS(wstatus);
    run.why = s.str();
  } else if(run.r.status != SMP::OK) {
    run.outcome = Outcome::FAILED;
    run.why = std::string("failed: ") + SMP::error_message(SMP::Error_code(run.r.status));
    if(run.r.note[0] != '\0')
      run.why += std::string(" (") + run.r.note + ")";
  } else {
    run.outcome = Outcome::OK;
  }
  return run;
}

// ------------------------------------------------------------------------------------------
// Meshes
// ------------------------------------------------------------------------------------------

struct Mesh_spec
{
  std::string path;
  int loops = 0;
  std::string name;
};

// A number given on the command line, or an error exit: atoi and atof would read "12abc" as 12
// and "x" as 0.
template <typename T>
T parse_number(const std::string& what, const std::string& text)
{
  try {
    return boost::lexical_cast<T>(text);
  } catch(const boost::bad_lexical_cast&) {
    std::cerr << "Error: " << what << ": '" << text << "' is not a number" << std::endl;
    std::exit(EXIT_FAILURE);
  }
}

Mesh_spec parse_mesh_spec(const std::string& arg)
{
  Mesh_spec s;
  s.path = arg;
  const std::size_t at = arg.rfind("@loop");
  if(at != std::string::npos) {
    s.path = arg.substr(0, at);
    s.loops = parse_number<int>(arg + " (@loopN)", arg.substr(at + 5));
  }
  s.name = fs::path(s.path).stem().string();
  if(s.loops > 0)
    s.name += "-loop" + std::to_string(s.loops);
  return s;
}

struct Mesh_info
{
  Mesh_spec spec;
  std::size_t vertices = 0, faces = 0, border_vertices = 0;
  double prepare_seconds = 0.;
  double baseline_mib = 0.;          // resident memory of the benchmark process with the mesh loaded
  double authalic_over_conformal = 0.; // (c): median over interior vertices of sum authalic / sum cotangent
  int runs = 1;
};

// The relative size of the two parts of the (c) weights: the blend is not scale invariant.
double authalic_over_conformal(const Mesh& mesh)
{
  std::vector<double> ratios;
  for(vertex_descriptor v : vertices(mesh)) {
    if(CGAL::is_border(v, mesh))
      continue;
    double conformal = 0., authalic = 0.;
    CGAL::Vertex_around_target_circulator<Mesh> vj(halfedge(v, mesh), mesh), end = vj;
    CGAL_For_all(vj, end) {
      const std::pair<double, double> w = Intrinsic::weights(mesh, v, vj);
      conformal += w.first;
      authalic += w.second;
    }
    if(conformal > 0. && std::isfinite(authalic))
      ratios.push_back(authalic / conformal);
  }
  if(ratios.empty())
    return 0.;
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  return ratios[ratios.size() / 2];
}

// ------------------------------------------------------------------------------------------
// Results
// ------------------------------------------------------------------------------------------

enum class State { NOT_RUN, OK, FAILED, SKIPPED, KILLED, CRASHED };

struct Cell
{
  State state = State::NOT_RUN;
  std::string why;               // for anything but OK
  std::vector<double> seconds;   // one per run
  Child_result first;            // the measured run
  double peak_mib = 0.;          // max over runs of the child's peak resident memory
  double above_mesh_mib = 0.;    // max over runs of (peak - resident size at the start)

  double median() const
  {
    std::vector<double> v = seconds;
    std::sort(v.begin(), v.end());
    if(v.empty())
      return std::nan("");
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  }
};

struct Options
{
  std::string out;
  int runs = 7;
  double budget = 300.;
  double hard_limit = 900.;
  std::string scratch;
  std::vector<std::string> only;
};

std::string fmt(double x, int precision = 3, bool fixed = false)
{
  if(!std::isfinite(x))
    return "-";
  std::ostringstream s;
  if(!fixed && std::abs(x) >= std::pow(10., precision) && std::abs(x) < 1e12) {
    s << std::fixed << std::setprecision(0) << x; // 1024, not 1.02e+03
    return s.str();
  }
  if(fixed)
    s << std::fixed;
  s << std::setprecision(precision) << x;
  return s.str();
}

std::string state_name(State s)
{
  switch(s) {
    case State::OK: return "ok";
    case State::FAILED: return "failed";
    case State::SKIPPED: return "skipped";
    case State::KILLED: return "killed";
    case State::CRASHED: return "crashed";
    default: return "not run";
  }
}

std::string csv_quote(const std::string& s)
{
  std::string r = "\"";
  for(char ch : s)
    r += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return r + "\"";
}

std::string now_string()
{
  const std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M:%S %Z", std::localtime(&t));
  return buf;
}

std::string load_average()
{
  std::ifstream in("/proc/loadavg");
  std::string a, b, c;
  in >> a >> b >> c;
  return a + " " + b + " " + c;
}

std::string build_description()
{
  std::ostringstream s;
  s << "compiler " <<
#if defined(__clang__)
    "clang "
#elif defined(__GNUC__)
    "g++ "
#endif
    << __VERSION__ << ", CGAL " << CGAL_VERSION_STR << ", Eigen " << EIGEN_WORLD_VERSION << "."
    << EIGEN_MAJOR_VERSION << "." << EIGEN_MINOR_VERSION <<
#ifdef NDEBUG
    ", NDEBUG"
#else
    ", assertions ON (not a release build!)"
#endif
#ifdef __OPTIMIZE__
    ", optimized"
#else
    ", NOT optimized"
#endif
    ;
  return s.str();
}

class Benchmark
{
public:
  Benchmark(const Options& options, std::vector<Method> methods)
    : m_options(options), m_methods(std::move(methods))
  { }

  bool run(const std::vector<Mesh_spec>& specs)
  {
    m_start_load = load_average();
    m_start_time = now_string();
    if(!m_options.out.empty())
      fs::create_directories(m_options.out);
    bool all_read = true;
    for(const Mesh_spec& spec : specs) {
      if(!run_mesh(spec)) {
        all_read = false;
        continue;
      }
      print_table(m_meshes.size() - 1, std::cout);
      write_files();
    }
    m_end_load = load_average();
    write_files();
    if(!m_options.out.empty())
      std::cerr << "results written to " << m_options.out << std::endl;
    return all_read;
  }

private:
  // ---------------------------------------------------------------- one mesh
  bool run_mesh(const Mesh_spec& spec)
  {
    const auto t0 = std::chrono::steady_clock::now();
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(spec.path, mesh) || faces(mesh).empty()) {
      std::cerr << "Error: cannot read a mesh from " << spec.path << std::endl;
      return false;
    }
    if(spec.loops > 0)
      CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(spec.loops));
    const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    if(bhd == Mesh::null_halfedge()) {
      std::cerr << "Error: " << spec.path << " has no border" << std::endl;
      return false;
    }
    UV_map uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv", Kernel::Point_2(0, 0)).first;

    Mesh_info info;
    info.spec = spec;
    info.vertices = num_vertices(mesh);
    info.faces = num_faces(mesh);
    for(halfedge_descriptor h : CGAL::halfedges_around_face(bhd, mesh)) {
      (void)h;
      ++info.border_vertices;
    }
    info.authalic_over_conformal = authalic_over_conformal(mesh);
    info.prepare_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    info.runs = info.vertices < 20000 ? 7 : info.vertices < 100000 ? 3 : 1;
    info.runs = std::max(1, std::min(info.runs, m_options.runs));
    malloc_trim(0); // give back what loading and subdivision freed: the children start from the mesh
    info.baseline_mib = proc_status_kib("VmRSS") / 1024.;
    std::cerr << "== " << info.spec.name << ": " << info.vertices << " vertices, " << info.faces
              << " faces (" << fmt(info.prepare_seconds) << " s to load" << (spec.loops ? " and subdivide" : "")
              << "), " << info.runs << " run(s) per method" << std::endl;

    m_meshes.push_back(info);
    m_cells.emplace_back(m_methods.size());
    std::vector<Cell>& cells = m_cells.back();

    std::vector<bool> active(m_methods.size(), false);
    for(std::size_t m = 0; m < m_methods.size(); ++m) {
      std::string why;
      if(should_skip(m, info.vertices, why)) {
        cells[m].state = State::SKIPPED;
        cells[m].why = why;
        std::cerr << "   " << m_methods[m].id << ": " << why << std::endl;
      } else {
        active[m] = true;
      }
    }

    Context context{mesh, bhd, uv, m_options.scratch};
    for(int r = 0; r < info.runs; ++r) {
      for(std::size_t m = 0; m < m_methods.size(); ++m) {
        if(!active[m])
          continue;
        Cell& cell = cells[m];
        const Run run = run_in_child(m_methods[m], context, r == 0, m_options.hard_limit);
        if(run.outcome != Outcome::OK) {
          cell.state = run.outcome == Outcome::KILLED ? State::KILLED
                     : run.outcome == Outcome::CRASHED ? State::CRASHED : State::FAILED;
          cell.why = run.why;
          if(r == 0)
            cell.first = run.r;
          active[m] = false;
          std::cerr << "   " << m_methods[m].id << ": " << run.why << std::endl;
          continue;
        }
        if(r == 0)
          cell.first = run.r;
        cell.state = State::OK;
        cell.seconds.push_back(run.r.seconds);
        cell.peak_mib = std::max(cell.peak_mib, run.r.peak_kib / 1024.);
        cell.above_mesh_mib = std::max(cell.above_mesh_mib, (run.r.peak_kib - run.r.rss_start_kib) / 1024.);
        std::cerr << "   " << std::left << std::setw(24) << m_methods[m].id << std::right << " run " << r + 1
                  << "/" << info.runs << ": " << fmt(run.r.seconds, 4) << " s, peak " << fmt(run.r.peak_kib / 1024., 4)
                  << " MiB" << std::endl;
        if(run.r.seconds > 60.)
          active[m] = false; // one run is enough for a long method (its median is that run)
      }
    }
    for(std::size_t m = 0; m < m_methods.size(); ++m)
      if(cells[m].state == State::OK)
        m_done[m].push_back({double(info.vertices), cells[m].median()});
      else if(cells[m].state == State::KILLED)
        m_killed_at[m] = double(info.vertices);
    return true;
  }

  // The skip rule: predict the time of one call from the largest mesh the method ran on,
  // t * (V / V_last)^g, with g measured between that mesh and the largest one at most half
  // its size (clamped to [1, 3]; 1.5 if there is no such mesh yet).
  bool should_skip(std::size_t m, std::size_t vertices, std::string& why) const
  {
    if(!m_options.only.empty() &&
       std::find(m_options.only.begin(), m_options.only.end(), m_methods[m].id) == m_options.only.end()) {
      why = "not selected (--methods)";
      return true;
    }
    auto killed = m_killed_at.find(m);
    if(killed != m_killed_at.end() && double(vertices) >= killed->second) {
      why = "skipped: killed at the hard limit on a mesh of " + std::to_string(std::size_t(killed->second)) +
            " vertices";
      return true;
    }
    auto done = m_done.find(m);
    if(done == m_done.end() || done->second.empty())
      return false;
    std::pair<double, double> last = done->second.front();
    for(const auto& p : done->second)
      if(p.first >= last.first)
        last = p;
    if(double(vertices) <= last.first)
      return false;
    const std::pair<double, double>* previous = nullptr;
    for(const auto& p : done->second)
      if(p.first <= 0.5 * last.first && (previous == nullptr || p.first > previous->first))
        previous = &p;
    double g = 1.5;
    std::string from = "assumed";
    if(previous != nullptr && previous->second > 0. && last.second > 0.) {
      g = std::log(last.second / previous->second) / std::log(last.first / previous->first);
      std::ostringstream s;
      s << "measured " << std::size_t(previous->first) << " -> " << std::size_t(last.first) << " vertices";
      from = s.str();
    }
    g = std::min(3., std::max(1., g));
    double predicted = last.second * std::pow(double(vertices) / last.first, g);
    if(m_methods[m].id == "d_sander") // it stops at its own cap
      predicted = std::min(predicted, sander_seconds);
    if(predicted <= m_options.budget || is_reference(m_methods[m].id))
      return false;
    std::ostringstream s;
    s << "skipped: predicted " << fmt(predicted, 3) << " s > budget " << m_options.budget << " s (" << fmt(last.second, 3)
      << " s at " << std::size_t(last.first) << " vertices, growth exponent " << fmt(g, 3) << " " << from << ")";
    why = s.str();
    return true;
  }

  // ---------------------------------------------------------------- output
  std::size_t method_index(const std::string& id) const
  {
    for(std::size_t m = 0; m < m_methods.size(); ++m)
      if(m_methods[m].id == id)
        return m;
    return std::size_t(-1);
  }

  double median_of(std::size_t mesh, const std::string& id) const
  {
    const std::size_t m = method_index(id);
    if(m == std::size_t(-1) || m_cells[mesh][m].state != State::OK)
      return std::nan("");
    return m_cells[mesh][m].median();
  }

  std::string skip_rule() const
  {
    std::ostringstream s;
    s << "Skip rule: time budget. A method is skipped on a mesh when the time of one call, predicted "
         "from the largest mesh it ran on as t * (V / V_last)^g, exceeds "
      << m_options.budget << " s; g is the growth exponent measured between that mesh and the largest one "
         "of at most half its size (clamped to [1, 3]). CGAL MVC, U^opt (eta = 1) and U^0 alone, the "
         "references of the quoted ratios, are run whatever the prediction. A run still going after "
      << m_options.hard_limit << " s is killed and the method is not run on larger meshes. Below 20k "
         "vertices every method runs 7 times, below 100k 3 times, above once; a method whose first run "
         "takes more than 60 s runs once.";
    return s.str();
  }

  void print_table(std::size_t k, std::ostream& out) const
  {
    const Mesh_info& info = m_meshes[k];
    const std::vector<Cell>& cells = m_cells[k];
    const double reference = median_of(k, "cgal_mvc");
    out << "## " << info.spec.name << "\n\n"
        << "`" << info.spec.path << "`" << (info.spec.loops ? " refined by " + std::to_string(info.spec.loops) +
                                               " Loop subdivision step(s) at run time" : std::string())
        << ": " << info.vertices << " vertices, " << info.faces << " faces, " << info.border_vertices
        << " border vertices. Time: median wall time of the parameterization call over " << info.runs
        << " run(s), each in a fresh child process forked after loading the mesh. Stretches normalized "
           "(1 = isometry up to scale); measures over all faces (L2 and Linf leave out faces degenerate in uv). "
           "Peak: peak resident memory of the child (the mesh it inherits included; the parent holds "
        << fmt(info.baseline_mib, 4) << " MiB with the mesh loaded); above mesh: that peak less the child's "
           "resident size at the start of the call.\n\n"
        << "| method | border | solver | time (s) | time / CGAL MVC | L2 stretch | Linf stretch | edge dist. | "
           "angle dist. (rad) | area dist. | flipped | degenerate | steps | peak (MiB) | above mesh (MiB) |\n"
        << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for(std::size_t m = 0; m < m_methods.size(); ++m) {
      const Method& method = m_methods[m];
      const Cell& c = cells[m];
      if(c.state == State::SKIPPED && c.why == "not selected (--methods)")
        continue;
      out << "| " << method.label << " | " << method.border << " | " << method.solver << " | ";
      if(c.state == State::OK) {
        const SMP::Stretch_statistics& s = c.first.stats;
        const double t = c.median();
        out << fmt(t, 3) << " | " << fmt(t / reference, 3) << " | " << fmt(s.l2_stretch, 4) << " | "
            << fmt(s.linf_stretch, 4) << " | " << fmt(s.edge_distortion, 4) << " | " << fmt(s.angle_distortion, 4)
            << " | " << fmt(s.area_distortion, 4) << " | " << s.flipped_faces << " | " << s.degenerate_uv_faces
            << " | " << (c.first.steps[0] ? c.first.steps : "-") << " | " << fmt(c.peak_mib, 4) << " | "
            << fmt(c.above_mesh_mib, 3) << " |\n";
      } else {
        out << c.why << " | | | | | | | | | | | | |\n";
      }
    }
    out << "\n(d) Sander et al. 2001 (the paper's reference), re-implemented in Sander_line_search.h: all vertices "
           "from the start (Sander et al. go coarse to fine on a progressive mesh), capped at "
        << sander_seconds << " s.\n";
    out << "(c): the authalic part of the blended weight is " << fmt(info.authalic_over_conformal, 3)
        << " times the conformal part (median over interior vertices): the blend depends on the units of the mesh.\n";
    const std::size_t ia = method_index("cgal_iterative_authalic");
    if(ia != std::size_t(-1) && cells[ia].state == State::OK)
      out << "(*) The time of CGAL Iterative_authalic includes the debug output that CGAL 5.5.1 hard-codes: every "
             "iteration printed (to a swallowed stream) and last_solve.off written (in a scratch directory) at "
             "every iteration.\n";
    const std::size_t fo = method_index("f_uopt");
    if(fo != std::size_t(-1) && cells[fo].state == State::OK && cells[fo].first.history_size > 0) {
      out << "U^h, eta = 1, L2 stretch by step:";
      for(int h = 0; h < cells[fo].first.history_size; ++h)
        out << " " << h << ": " << fmt(cells[fo].first.history_l2[h], 4) << (h + 1 < cells[fo].first.history_size ? "," : "");
      out << "\n";
      if(cells[fo].first.history_peak_kib[0] > 0.) {
        out << "U^h, eta = 1, peak resident memory (MiB, the mesh included) by step (step 0: the setup and U^0's "
               "solve; then the reweighting and the solve):";
        for(int h = 0; h < cells[fo].first.history_size; ++h)
          out << " " << h << ": " << fmt(cells[fo].first.history_peak_kib[h] / 1024., 4)
              << (h + 1 < cells[fo].first.history_size ? "," : "");
        out << "\n";
      }
    }
    out << std::endl;
  }

  void write_csv(std::ostream& out) const
  {
    out << "mesh,file,loop_subdivisions,vertices,faces,border_vertices,method_id,method,border,solver,state,runs,"
           "time_median_s,time_min_s,time_max_s,time_over_cgal_mvc,l2_stretch,linf_stretch,edge_distortion,"
           "angle_distortion,area_distortion,flipped_faces,degenerate_uv_faces,degenerate_3d_faces,steps,"
           "kept_step,steps_computed,peak_rss_mib,peak_above_mesh_mib,mesh_baseline_mib,note\n";
    for(std::size_t k = 0; k < m_meshes.size(); ++k) {
      const Mesh_info& info = m_meshes[k];
      const double reference = median_of(k, "cgal_mvc");
      for(std::size_t m = 0; m < m_methods.size(); ++m) {
        const Cell& c = m_cells[k][m];
        if(c.state == State::SKIPPED && c.why == "not selected (--methods)")
          continue;
        const Method& method = m_methods[m];
        const bool ok = c.state == State::OK;
        const SMP::Stretch_statistics& s = c.first.stats;
        std::string note = ok ? std::string(c.first.note) : c.why;
        if(method.id == "c_intrinsic")
          note += (note.empty() ? "" : "; ") + std::string("authalic/conformal weight ratio ") +
                  fmt(info.authalic_over_conformal, 4);
        const auto minmax = std::minmax_element(c.seconds.begin(), c.seconds.end());
        auto num = [&](double x) { return ok && std::isfinite(x) ? fmt(x, 6) : std::string(); };
        out << info.spec.name << "," << csv_quote(info.spec.path) << "," << info.spec.loops << "," << info.vertices
            << "," << info.faces << "," << info.border_vertices << "," << method.id << "," << csv_quote(method.label)
            << "," << csv_quote(method.border) << "," << csv_quote(method.solver) << "," << state_name(c.state) << ","
            << c.seconds.size() << "," << num(c.median()) << "," << (ok ? num(*minmax.first) : "") << ","
            << (ok ? num(*minmax.second) : "") << "," << num(c.median() / reference) << ","
            << num(s.l2_stretch) << "," << num(s.linf_stretch) << "," << num(s.edge_distortion) << ","
            << num(s.angle_distortion) << "," << num(s.area_distortion) << ","
            << (ok ? std::to_string(s.flipped_faces) : "") << "," << (ok ? std::to_string(s.degenerate_uv_faces) : "")
            << "," << (ok ? std::to_string(s.degenerate_3d_faces) : "") << "," << csv_quote(c.first.steps) << ",";
        if(ok && c.first.kept_step >= 0) {
          out << c.first.kept_step << "," << c.first.steps_computed;
        } else {
          out << ",";
        }
        out << "," << num(c.peak_mib) << "," << num(c.above_mesh_mib) << "," << fmt(info.baseline_mib, 6) << ","
            << csv_quote(note) << "\n";
      }
    }
  }

  void write_history_csv(std::ostream& out) const
  {
    out << "mesh,vertices,method_id,step,l2_stretch,linf_stretch,seconds_since_start,step_peak_rss_mib\n";
    for(std::size_t k = 0; k < m_meshes.size(); ++k)
      for(std::size_t m = 0; m < m_methods.size(); ++m) {
        const Cell& c = m_cells[k][m];
        if(c.state != State::OK)
          continue;
        for(int h = 0; h < c.first.history_size; ++h)
          out << m_meshes[k].spec.name << "," << m_meshes[k].vertices << "," << m_methods[m].id << "," << h << ","
              << fmt(c.first.history_l2[h], 8) << "," << fmt(c.first.history_linf[h], 8) << ","
              << fmt(c.first.history_seconds[h], 6) << "," << fmt(c.first.history_peak_kib[h] / 1024., 6) << "\n";
      }
  }

  // gnuplot data: one block per method (time and memory against vertices), separated by two
  // blank lines; the first line of a block is its title (for `title columnheader(1)`)
  void write_plot_data(const std::string& dir) const
  {
    std::ofstream time(dir + "/plot_time.dat"), memory(dir + "/plot_memory.dat");
    int blocks = 0;
    for(std::size_t m = 0; m < m_methods.size(); ++m) {
      std::vector<std::size_t> ks;
      for(std::size_t k = 0; k < m_meshes.size(); ++k)
        if(m_cells[k][m].state == State::OK)
          ks.push_back(k);
      if(ks.empty())
        continue;
      std::sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) { return m_meshes[a].vertices < m_meshes[b].vertices; });
      for(std::ofstream* f : {&time, &memory}) {
        if(blocks > 0)
          *f << "\n\n";
        *f << "\"" << m_methods[m].label << "\" value\n";
      }
      for(std::size_t k : ks) {
        time << m_meshes[k].vertices << " " << fmt(m_cells[k][m].median(), 6) << "\n";
        memory << m_meshes[k].vertices << " " << fmt(m_cells[k][m].peak_mib, 6) << "\n";
      }
      ++blocks;
    }
    // L2 stretch against the step, one block per mesh, for eta = 1 and eta = 0.5
    for(const std::string id : {"f_uopt", "uopt_eta05"}) {
      std::ofstream f(dir + "/plot_history_" + id + ".dat");
      const std::size_t m = method_index(id);
      int n = 0;
      for(std::size_t k = 0; m != std::size_t(-1) && k < m_meshes.size(); ++k) {
        const Cell& c = m_cells[k][m];
        if(c.state != State::OK || c.first.history_size == 0)
          continue;
        if(n++ > 0)
          f << "\n\n";
        f << "\"" << m_meshes[k].spec.name << " (" << m_meshes[k].vertices << " V)\" value\n";
        for(int h = 0; h < c.first.history_size; ++h)
          f << h << " " << fmt(c.first.history_l2[h], 8) << "\n";
      }
    }
  }

  void write_summary(std::ostream& out) const
  {
    out << "# Summary\n\n"
        << "Build: " << build_description() << ".\n"
        << "Run: started " << m_start_time << ", load average " << m_start_load << " at the start, "
        << (m_end_load.empty() ? std::string("still running") : m_end_load + " at the end")
        << " (the machine is shared: ratios measured side by side in one run are the figures to quote).\n\n"
        << skip_rule() << "\n\n";

    // ratios on every mesh
    out << "## Time ratios, side by side on each mesh\n\n"
        << "Medians of the wall time of the parameterization call; fixed-border methods share the "
           "unit-square arc-length border. U^0 one solve = the stretch minimizer with 0 steps "
           "(one factorization, solves for u and v).\n\n"
        << "| mesh | V | U^opt (s) | h | U^opt / CGAL MVC | U^1 / CGAL MVC | U^opt / U^0 one solve | "
           "U^opt / (b) Floater | U^opt / ARAP | U^opt / Iterative authalic |\n"
        << "|---|---|---|---|---|---|---|---|---|---|\n";
    for(std::size_t k = 0; k < m_meshes.size(); ++k) {
      const double u = median_of(k, "f_uopt");
      const std::size_t fo = method_index("f_uopt");
      out << "| " << m_meshes[k].spec.name << " | " << m_meshes[k].vertices << " | " << fmt(u, 3) << " | "
          << (m_cells[k][fo].state == State::OK ? m_cells[k][fo].first.steps : "-") << " | "
          << ratio(u, median_of(k, "cgal_mvc")) << " | " << ratio(median_of(k, "e_u1"), median_of(k, "cgal_mvc"))
          << " | " << ratio(u, median_of(k, "u0_minimizer")) << " | " << ratio(u, median_of(k, "b_floater")) << " | "
          << ratio(u, median_of(k, "cgal_arap"), k, "cgal_arap") << " | "
          << ratio(u, median_of(k, "cgal_iterative_authalic"), k, "cgal_iterative_authalic") << " |\n";
    }

    // quality beyond the paper: L2 stretch of the presets and the polish against CGAL's best
    auto l2_of = [&](std::size_t k, const std::string& id) {
      const std::size_t m = method_index(id);
      if(m == std::size_t(-1) || m_cells[k][m].state != State::OK || !m_cells[k][m].first.has_stats)
        return std::string(m == std::size_t(-1) ? "-" : state_name(m_cells[k][m].state));
      const SMP::Stretch_statistics& st = m_cells[k][m].first.stats;
      return fmt(st.l2_stretch, 4) + (st.flipped_faces ? " (" + std::to_string(st.flipped_faces) + " flips)" : "");
    };
    out << "\n## Quality beyond the paper: L2 stretch (flipped faces if any) and time ratios\n\n"
        << "| mesh | paper U^opt | LOWEST_STRETCH | LOWEST_STRETCH + fixed-border polish (100 Newton steps) | U^opt + free-border polish (5 Newton steps) | "
           "CGAL Iterative_authalic | LOWEST / paper time | fixed polish / paper time | free polish / CGAL MVC time |\n"
        << "|---|---|---|---|---|---|---|---|---|\n";
    for(std::size_t k = 0; k < m_meshes.size(); ++k)
      out << "| " << m_meshes[k].spec.name << " | " << l2_of(k, "f_uopt") << " | " << l2_of(k, "uopt_lowest") << " | "
          << l2_of(k, "lowest_polish") << " | " << l2_of(k, "uopt_free") << " | " << l2_of(k, "cgal_iterative_authalic")
          << " | " << ratio(median_of(k, "uopt_lowest"), median_of(k, "f_uopt"), k, "uopt_lowest") << " | "
          << ratio(median_of(k, "lowest_polish"), median_of(k, "f_uopt"), k, "lowest_polish") << " | "
          << ratio(median_of(k, "uopt_free"), median_of(k, "cgal_mvc"), k, "uopt_free") << " |\n";

    // the subdivision family: the base file that has refined versions
    std::map<int, std::size_t> level; // Loop steps -> mesh
    std::string base;
    for(std::size_t k = 0; k < m_meshes.size(); ++k)
      if(m_meshes[k].spec.loops > 0)
        base = m_meshes[k].spec.path;
    for(std::size_t k = 0; k < m_meshes.size(); ++k)
      if(!base.empty() && m_meshes[k].spec.path == base)
        level[m_meshes[k].spec.loops] = k;
    if(level.empty()) {
      out << "\n(No Loop-subdivided meshes in this run: no growth figures.)\n";
      return;
    }
    auto size_name = [&](std::size_t k) {
      const double v = double(m_meshes[k].vertices);
      return fmt(v / 1000., v < 100000 ? 2 : 3) + "k";
    };
    out << "\n## Figures to quote (" << fs::path(base).filename().string() << " and its Loop refinements)\n\n";
    auto line = [&](const std::string& what, const std::function<std::string(std::size_t)>& value) {
      out << "- " << what << ":";
      bool first = true;
      for(const auto& l : level) {
        out << (first ? " " : "; ") << size_name(l.second) << " (" << m_meshes[l.second].vertices << " V): "
            << value(l.second);
        first = false;
      }
      out << "\n";
    };
    line("U^opt time / CGAL MVC time (same border, same mesh)",
         [&](std::size_t k) { return ratio(median_of(k, "f_uopt"), median_of(k, "cgal_mvc")); });
    line("U^opt time / one factorization + solve of U^0 (stretch minimizer, 0 steps)",
         [&](std::size_t k) { return ratio(median_of(k, "f_uopt"), median_of(k, "u0_minimizer")); });
    line("U^opt time / (b) Floater U^0 through CGAL's Fixed_border_parameterizer_3",
         [&](std::size_t k) { return ratio(median_of(k, "f_uopt"), median_of(k, "b_floater")); });
    line("U^opt time / CGAL ARAP time",
         [&](std::size_t k) { return ratio(median_of(k, "f_uopt"), median_of(k, "cgal_arap"), k, "cgal_arap"); });
    line("U^opt time / CGAL Iterative_authalic time (its time includes its debug I/O)",
         [&](std::size_t k) {
           return ratio(median_of(k, "f_uopt"), median_of(k, "cgal_iterative_authalic"), k, "cgal_iterative_authalic");
         });
    line("U^opt time / U^opt time with the direct solver at every size",
         [&](std::size_t k) { return ratio(median_of(k, "f_uopt"), median_of(k, "uopt_direct"), k, "uopt_direct"); });
    line("U^opt time / U^opt called as CGAL's parameterize() body calls it (CGAL's vertex numbering)",
         [&](std::size_t k) { return ratio(median_of(k, "f_uopt"), median_of(k, "uopt_cgal_body"), k, "uopt_cgal_body"); });
    line("U^opt time on all cores / on one thread (number_of_threads(1))",
         [&](std::size_t k) {
           return ratio(median_of(k, "f_uopt"), median_of(k, "uopt_one_thread"), k, "uopt_one_thread");
         });
    line("U^opt steps", [&](std::size_t k) {
      const std::size_t fo = method_index("f_uopt");
      return m_cells[k][fo].state == State::OK ? std::string(m_cells[k][fo].first.steps) : std::string("-");
    });

    // growth between consecutive levels
    out << "\n### Growth of the time between consecutive refinements (x4 vertices: 4.0 is linear)\n\n| method |";
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for(auto it = level.begin(); it != level.end(); ++it) {
      auto next = std::next(it);
      if(next == level.end())
        break;
      pairs.push_back({it->second, next->second});
      out << " t(" << size_name(next->second) << ") / t(" << size_name(it->second) << ") |";
    }
    out << " exponent, last pair |\n|---|";
    for(std::size_t i = 0; i <= pairs.size(); ++i)
      out << "---|";
    out << "\n";
    for(std::size_t m = 0; m < m_methods.size(); ++m) {
      out << "| " << m_methods[m].label << " |";
      double last_exponent = std::nan("");
      for(const auto& p : pairs) {
        const double a = median_of(p.first, m_methods[m].id), b = median_of(p.second, m_methods[m].id);
        out << " " << ratio(b, a, p.second, m_methods[m].id) << " |";
        if(std::isfinite(a) && std::isfinite(b) && a > 0.)
          last_exponent = std::log(b / a) / std::log(double(m_meshes[p.second].vertices) / m_meshes[p.first].vertices);
      }
      out << " " << fmt(last_exponent, 3) << " |\n";
    }

    // memory at the largest level
    const std::size_t top = level.rbegin()->second;
    out << "\n### Peak memory on " << m_meshes[top].spec.name << " (" << m_meshes[top].vertices << " vertices)\n\n"
        << "Peak resident memory of the child process that runs one call (the mesh, loaded before the fork, "
           "included: "
        << fmt(m_meshes[top].baseline_mib, 4) << " MiB), and that peak less the resident size at the start of the call.\n\n"
        << "| method | peak (MiB) | above mesh (MiB) | time (s) |\n|---|---|---|---|\n";
    for(std::size_t m = 0; m < m_methods.size(); ++m) {
      const Cell& c = m_cells[top][m];
      if(c.state == State::SKIPPED && c.why == "not selected (--methods)")
        continue;
      out << "| " << m_methods[m].label << " | ";
      if(c.state == State::OK)
        out << fmt(c.peak_mib, 4) << " | " << fmt(c.above_mesh_mib, 4) << " | " << fmt(c.median(), 3) << " |\n";
      else
        out << c.why << " | | |\n";
    }
  }

  // a ratio, or why there is none
  std::string ratio(double a, double b, std::size_t k = std::size_t(-1), const std::string& id = std::string()) const
  {
    if(std::isfinite(a) && std::isfinite(b) && b > 0.)
      return fmt(a / b, 3);
    if(k != std::size_t(-1) && !id.empty()) {
      const std::size_t m = method_index(id);
      if(m != std::size_t(-1) && m_cells[k][m].state != State::OK)
        return state_name(m_cells[k][m].state);
    }
    return "-";
  }

  void write_files() const
  {
    if(m_options.out.empty())
      return;
    const std::string& dir = m_options.out;
    {
      std::ofstream all(dir + "/tables.md");
      all << "# Parameterizers side by side, one table per mesh\n\n" << skip_rule() << "\n\n";
      for(std::size_t k = 0; k < m_meshes.size(); ++k) {
        print_table(k, all);
        std::ofstream one(dir + "/" + m_meshes[k].spec.name + ".md");
        print_table(k, one);
      }
    }
    {
      std::ofstream csv(dir + "/results.csv");
      write_csv(csv);
    }
    {
      std::ofstream csv(dir + "/history.csv");
      write_history_csv(csv);
    }
    {
      std::ofstream md(dir + "/summary.md");
      write_summary(md);
    }
    write_plot_data(dir);
  }

  Options m_options;
  std::vector<Method> m_methods;
  std::vector<Mesh_info> m_meshes;
  std::vector<std::vector<Cell>> m_cells;                              // [mesh][method]
  std::map<std::size_t, std::vector<std::pair<double, double>>> m_done; // method -> (V, median time)
  std::map<std::size_t, double> m_killed_at;                            // method -> V
  std::string m_start_time, m_start_load, m_end_load;
};

// ------------------------------------------------------------------------------------------

int usage(const char* program)
{
  std::cerr << "usage: " << program << " [--out DIR] [--runs N] [--budget S] [--hard-limit S] [--scratch DIR] "
               "[--methods id,id,...] [--list] MESH[@loopN] ...\n"
               "       "
            << program << " mesh.off [runs]" << std::endl;
  return EXIT_FAILURE;
}

int main(int argc, char** argv)
{
  Options options;
  std::vector<std::string> positional;
  std::vector<Method> methods = all_methods();
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        std::cerr << "Error: " << a << " needs a value" << std::endl;
        std::exit(EXIT_FAILURE);
      }
      return argv[++i];
    };
    if(a == "--out")
      options.out = value();
    else if(a == "--runs")
      options.runs = std::max(1, parse_number<int>(a, value()));
    else if(a == "--budget")
      options.budget = parse_number<double>(a, value());
    else if(a == "--hard-limit")
      options.hard_limit = parse_number<double>(a, value());
    else if(a == "--scratch")
      options.scratch = value();
    else if(a == "--methods") {
      std::stringstream s(value());
      std::string id;
      while(std::getline(s, id, ','))
        options.only.push_back(id);
    } else if(a == "--list") {
      for(const Method& m : methods)
        std::cout << m.id << "\t" << m.label << "\n";
      return EXIT_SUCCESS;
    } else if(a == "-h" || a == "--help")
      return usage(argv[0]);
    else if(a.size() > 1 && a[0] == '-' && a[1] == '-')
      return usage(argv[0]);
    else
      positional.push_back(a);
  }
  // the older form: mesh.off runs
  if(positional.size() == 2 && !positional[1].empty() &&
     positional[1].find_first_not_of("0123456789") == std::string::npos && !fs::exists(positional[1])) {
    options.runs = std::max(1, parse_number<int>("runs", positional[1]));
    positional.pop_back();
  }
  if(positional.empty())
    return usage(argv[0]);
  for(const std::string& id : options.only)
    if(std::none_of(methods.begin(), methods.end(), [&](const Method& m) { return m.id == id; })) {
      std::cerr << "Error: unknown method " << id << " (see --list)" << std::endl;
      return EXIT_FAILURE;
    }

  std::string temporary;
  if(options.scratch.empty()) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/smp_benchmark.XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    if(mkdtemp(buf.data()) == nullptr) {
      std::cerr << "Error: cannot create a temporary directory" << std::endl;
      return EXIT_FAILURE;
    }
    options.scratch = temporary = buf.data();
  } else {
    fs::create_directories(options.scratch);
  }
  options.scratch = fs::absolute(options.scratch).string();

  std::vector<Mesh_spec> specs;
  for(const std::string& p : positional)
    specs.push_back(parse_mesh_spec(p));

  std::cerr << build_description() << std::endl;
  Benchmark benchmark(options, methods);
  const bool ok = benchmark.run(specs);
  std::cout << "Build: " << build_description() << "\n";

  if(!temporary.empty()) {
    std::error_code ec;
    fs::remove_all(temporary, ec);
  }
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

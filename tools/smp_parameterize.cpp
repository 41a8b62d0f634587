// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smp-parameterize: parameterizes a triangle mesh file and writes what a user looks at: an OBJ
// with texture coordinates, its MTL and checkerboard texture, a JSON report and pictures.
// Run without arguments for the options.

#include "render.h"
#include "smp_command_line.h"
#include "smp_input.h"
#include "smp_output.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Natural_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_ear_aware_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/make_disk_seam.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Surface_mesh_parameterization/parameterize_components.h>
#include <CGAL/Surface_mesh_parameterization/stretch_measures.h>
#include <CGAL/Surface_mesh_parameterization/stretch_minimizing_atlas.h>

#include <boost/program_options.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>                  Kernel;
typedef Kernel::Point_2                                 Point_2;
typedef Kernel::Point_3                                 Point_3;
typedef CGAL::Surface_mesh<Point_3>                     Mesh;
typedef Mesh::Vertex_index                              vertex_descriptor;
typedef Mesh::Halfedge_index                            halfedge_descriptor;
typedef Mesh::Face_index                                face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>  UV_map;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

namespace {

struct Options
{
  std::string input, output, method = "uopt", border = "square", preset = "paper";
  std::string start, update, rule; // empty: the preset's
  double eta = 1., polish_time = 0.;
  int iterations = 20, descent = -1, polish = 0, size = 800, up = 2, threads = 0; // descent < 0: the preset's
  bool cut = false, charts = false, pictures = true, quiet = false, free_border = false;
  bool atlas = false;
  double max_stretch = 1.05, gutter = 2.;
  int resolution = 1024;
};

[[noreturn]] void die(const std::string& message, int status = 1) { smp_tools::fail("smp-parameterize", message, status); }

Options parse(int argc, char** argv)
{
  namespace po = boost::program_options;
  Options o;
  std::string up = "z";
  bool no_pictures = false;
  po::options_description described("options");
  described.add_options()
    ("help,h", "this text")
    ("output,o", po::value(&o.output)->value_name("DIR"), "where to write the results (default: MESHNAME_uv)")
    ("method,m", po::value(&o.method)->value_name("M"),
     "uopt (default), u1, u0: this package's stretch minimization (U^opt, one step, the start only); "
     "for comparison, CGAL's mvc, dcm, dap (fixed border), lscm, arap (free border)")
    ("eta", po::value(&o.eta)->value_name("X"), "weight update exponent, 0 < X <= 1 (default 1)")
    ("iterations", po::value(&o.iterations)->value_name("N"), "cap on the steps of uopt (default 20)")
    ("border", po::value(&o.border)->value_name("B"),
     "square (default, CGAL's corners), ear-aware (square, corners that avoid flattened border faces), "
     "circle, natural (LSCM's border)")
    ("preset", po::value(&o.preset)->value_name("P"),
     "paper (default: the paper's method) or lowest (clamped cotangent start, edge update, descent "
     "steps: lower stretch for a few times the time; the manual gives the figures)")
    ("start", po::value(&o.start)->value_name("S"), "start weights of u0/u1/uopt: floater, mvc or cot (clamped cotangent)")
    ("update", po::value(&o.update)->value_name("U"), "stretch that divides the weights: vertex, symmetric or edge")
    ("rule", po::value(&o.rule)->value_name("R"), "when a step does not lower the stretch: stop or halve (eta)")
    ("descent", po::value(&o.descent)->value_name("N"),
     "then at most N cheap descent steps on Sander's stretch energy (flip-free; default: the "
     "preset's, 0 or 30)")
    ("polish", po::value(&o.polish)->value_name("N"), "then at most N Newton steps on Sander's stretch energy (flip-free)")
    ("polish-time", po::value(&o.polish_time)->value_name("S"), "time budget of the polish in seconds")
    ("free-border", po::bool_switch(&o.free_border), "let the polish move the border (never crossing itself)")
    ("threads", po::value(&o.threads)->value_name("N"), "threads of u0/u1/uopt on large meshes, and of the atlas (default 0: one per core)")
    ("cut", po::bool_switch(&o.cut), "open a closed genus-0 mesh along a seam first")
    ("charts", po::bool_switch(&o.charts), "parameterize each connected component into its own chart")
    ("atlas", po::bool_switch(&o.atlas),
     "any mesh (closed, any genus, several parts, non-manifold, polygons): cut into charts, each flattened "
     "with a free border, packed into the unit square; the OBJ keeps the input's vertices and faces")
    ("max-stretch", po::value(&o.max_stretch)->value_name("X"), "atlas: cut further every chart above this L2 stretch (default 1.05)")
    ("resolution", po::value(&o.resolution)->value_name("N"), "atlas: texels along a side of the texture (default 1024)")
    ("gutter", po::value(&o.gutter)->value_name("T"), "atlas: texels between charts (default 2)")
    ("size", po::value(&o.size)->value_name("PX"), "picture size in pixels (default 800)")
    ("up", po::value(&up)->value_name("A"), "the model's up axis in the pictures: x, y or z (default z)")
    ("no-pictures", po::bool_switch(&no_pictures), "write no PNG picture")
    ("quiet,q", po::bool_switch(&o.quiet), "no progress lines");
  const po::variables_map vm = smp_tools::parse_command_line(
      argc, argv, "smp-parameterize", described, o.input,
      "usage: smp-parameterize MESH [options]\n  MESH: a triangle mesh (.off, .obj, .ply or .stl), or any polygon mesh with --atlas\n");
  // the ranges the parser does not know
  auto finite = [](const std::string& option, double x) {
    if(!std::isfinite(x))
      die("option " + option + ": '" + std::to_string(x) + "' is not a number", 2);
  };
  auto whole_number = [](const std::string& option, int n, int low, int high, const std::string& unit) {
    if(n < low || n > high)
      die("option " + option + ": give a whole number " + unit + "from " + std::to_string(low) + " to " +
          std::to_string(high), 2);
  };
  for(const auto& [option, x] : {std::pair<const char*, double>{"--eta", o.eta}, {"--polish-time", o.polish_time},
                                 {"--max-stretch", o.max_stretch}, {"--gutter", o.gutter}})
    finite(option, x);
  if(vm.count("descent")) whole_number("--descent", o.descent, 0, 100000, "");
  whole_number("--polish", o.polish, 0, 100000, "");
  whole_number("--iterations", o.iterations, 0, 10000, "");
  whole_number("--threads", o.threads, 0, 1024, "");
  whole_number("--size", o.size, 64, 8192, "of pixels ");
  whole_number("--resolution", o.resolution, 16, 65536, "of texels ");
  if(vm.count("polish-time") && !(o.polish_time > 0.)) die("option --polish-time: give a positive number of seconds", 2);
  if(up != "x" && up != "y" && up != "z") die("option --up: give x, y or z", 2);
  o.up = up[0] - 'x';
  if(!(o.max_stretch >= 1.)) die("option --max-stretch: give a number of at least 1", 2);
  if(!(o.gutter >= 0. && o.gutter <= 64.)) die("option --gutter: give a number of texels from 0 to 64", 2);
  o.pictures = !no_pictures;

  const std::vector<std::string> methods = {"uopt", "u1", "u0", "mvc", "dcm", "dap", "lscm", "arap"};
  if(std::find(methods.begin(), methods.end(), o.method) == methods.end())
    die("unknown method '" + o.method + "' (uopt, u1, u0, mvc, dcm, dap, lscm, arap)", 2);
  if(o.border != "square" && o.border != "ear-aware" && o.border != "circle" && o.border != "natural")
    die("unknown border '" + o.border + "' (square, ear-aware, circle, natural)", 2);
  if(o.preset != "paper" && o.preset != "lowest")
    die("unknown preset '" + o.preset + "' (paper, lowest)", 2);
  if(o.start.empty()) o.start = o.preset == "lowest" ? "cot" : "floater";
  if(o.update.empty()) o.update = o.preset == "lowest" ? "edge" : "vertex";
  if(o.rule.empty()) o.rule = "stop";
  if(o.descent < 0) o.descent = o.preset == "lowest" ? int(SMP::lowest_stretch_descent_iterations) : 0;
  if(o.start != "floater" && o.start != "mvc" && o.start != "cot")
    die("unknown start '" + o.start + "' (floater, mvc, cot)", 2);
  if(o.update != "vertex" && o.update != "symmetric" && o.update != "edge")
    die("unknown update '" + o.update + "' (vertex, symmetric, edge)", 2);
  if(o.rule != "stop" && o.rule != "halve")
    die("unknown rule '" + o.rule + "' (stop, halve)", 2);
  if(o.polish_time > 0. && o.polish == 0)
    o.polish = 100000; // a time budget alone: as many steps as it allows
  if(o.free_border && o.polish == 0 && o.descent == 0)
    die("--free-border is a mode of the polish: give --descent N, --polish N or --polish-time S too", 2);
  if(!(o.eta > 0. && o.eta <= 1.))
    die("option --eta must be in (0, 1]", 2);
  if(o.atlas && (o.cut || o.charts))
    die("--atlas cuts and lays out every part itself: leave out --cut and --charts", 2);
  if(o.output.empty())
    o.output = fs::path(o.input).stem().string() + (o.atlas ? "_atlas" : "_uv");
  if(o.pictures) {
    const std::string missing = smp_tools::load_surface_renderer();
    if(!missing.empty()) die(missing + " (--no-pictures runs without it)");
  }
  return o;
}

// The border chosen on the command line, behind one type (one instantiation per method).
struct Chosen_border
{
  std::string kind = "square";
  std::string why; // reason of the last failure of the natural border

  template <typename UVMap, typename VIMap, typename VPMap>
  SMP::Error_code parameterize(Mesh& mesh, halfedge_descriptor bhd, UVMap uv, VIMap vi, VPMap vp)
  {
    if(kind == "ear-aware")
      return SMP::Square_border_ear_aware_parameterizer_3<Mesh>().parameterize(mesh, bhd, uv, vi, vp);
    if(kind == "circle")
      return SMP::Circular_border_arc_length_parameterizer_3<Mesh>().parameterize(mesh, bhd, uv, vi, vp);
    if(kind == "natural") {
      SMP::Natural_border_parameterizer_3<Mesh> natural;
      const SMP::Error_code e = natural.parameterize(mesh, bhd, uv, vi, vp);
      why = natural.why();
      return e;
    }
    return SMP::Square_border_arc_length_parameterizer_3<Mesh>().parameterize(mesh, bhd, uv, vi, vp);
  }
  bool is_border_convex() const { return kind != "natural"; }
};

typedef SMP::Shape_preserving_parameterizer_3<Mesh, Chosen_border>        Floater;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh, Chosen_border>  MVC;

struct Run
{
  SMP::Error_code status = SMP::OK;
  std::string message;
  std::vector<SMP::Stretch_minimizing_step> history;
  std::size_t kept_step = 0;
  std::size_t charts = 1;
  bool border_too_short = false; // of the component of `message` (--charts)
  std::size_t unmapped = 0;       // components left without a map (--charts)
  SMP::Stretch_minimizing_polish polish;
};

// What a border too short for the square's corners is told to do.
const char* const square_border_hint = "the square border needs 4 corners: add --border circle";

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Runs `p` on the mesh (one disk, or every component as a chart) and fills `run`.
template <typename Parameterizer>
void run_parameterizer(Mesh& mesh, halfedge_descriptor bhd, Parameterizer p, UV_map uv, bool charts, Run& run)
{
  if(charts) {
    std::vector<SMP::Chart> out;
    run.status = SMP::parameterize_components(mesh, p, uv, &out);
    run.charts = out.size();
    for(std::size_t c = 0; c < out.size(); ++c) {
      if(out[c].status == SMP::OK)
        continue;
      ++run.unmapped;
      if(run.message.empty()) {
        run.message = "component " + std::to_string(c) + ": " + SMP::error_message(out[c].status);
        run.border_too_short = out[c].status == SMP::ERROR_BORDER_TOO_SHORT;
      }
    }
  } else {
    run.status = SMP::parameterize(mesh, p, bhd, uv);
  }
}

// A closed mesh copied as a disk: cut along make_disk_seam()'s seam, seam vertices doubled.
Mesh cut_open(Mesh& closed)
{
  typedef Mesh::Property_map<Mesh::Edge_index, bool> Seam_edges;
  typedef Mesh::Property_map<vertex_descriptor, bool> Seam_vertices;
  typedef CGAL::Seam_mesh<Mesh, Seam_edges, Seam_vertices> Seam_mesh;
  Seam_edges se = closed.add_property_map<Mesh::Edge_index, bool>("e:smp_seam", false).first;
  Seam_vertices sv = closed.add_property_map<vertex_descriptor, bool>("v:smp_seam", false).first;
  Seam_mesh seam(closed, se, sv);
  boost::graph_traits<Seam_mesh>::halfedge_descriptor bhd;
  std::string why;
  const SMP::Error_code e = SMP::make_disk_seam(seam, bhd, &why);
  if(e != SMP::OK)
    die("cannot cut the mesh open: " + why);
  Mesh disk;
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), seam);
  const auto vpm = get(CGAL::vertex_point, seam);
  std::vector<vertex_descriptor> made;
  for(auto v : vertices(seam)) {
    put(index, v, int(made.size()));
    made.push_back(disk.add_vertex(get(vpm, v)));
  }
  for(auto f : faces(seam)) {
    std::vector<vertex_descriptor> corners;
    for(auto h : halfedges_around_face(halfedge(f, seam), seam))
      corners.push_back(made[get(index, target(h, seam))]);
    if(disk.add_face(corners) == Mesh::null_face())
      die("cutting the mesh open failed (is it a manifold surface?)");
  }
  closed.remove_property_map(se);
  closed.remove_property_map(sv);
  return disk;
}

// Stops unless `o.input` names a readable file of a format the tool reads.
void check_input_file(const Options& o)
{
  const std::string ext = fs::path(o.input).extension().string();
  std::string lower = ext;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if(lower != ".off" && lower != ".obj" && lower != ".ply" && lower != ".stl")
    die("unknown file format '" + ext + "' of " + o.input + " (read: .off, .obj, .ply, .stl)");
  if(!std::ifstream(o.input))
    die("cannot open " + o.input);
}

// The output folder, created if it is not there.
fs::path output_folder(const Options& o)
{
  std::error_code ec;
  fs::create_directories(o.output, ec);
  if(ec)
    die("cannot create the output folder " + o.output + ": " + ec.message());
  return fs::path(o.output);
}

void write_atomically(const fs::path& file, const std::string& text)
{
  std::string error;
  if(!smp_tools::write_atomically(file, text, error))
    die(error);
}

// NAME.obj (`obj`: its text, which uses material "checker" of NAME.mtl), its MTL and its
// checkerboard texture.
void write_textured_obj(const fs::path& dir, const std::string& name, const std::string& obj,
                        std::vector<std::string>& outputs)
{
  write_atomically(dir / (name + ".obj"), obj);
  outputs.push_back(name + ".obj");
  write_atomically(dir / (name + ".mtl"), "newmtl checker\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nmap_Kd checker.png\n");
  outputs.push_back(name + ".mtl");
  if(!smp_tools::write_checkerboard_png((dir / "checker.png").string(), 512, 16))
    die("cannot write " + (dir / "checker.png").string());
  outputs.push_back("checker.png");
}

// The report, its fields in the order written (a non-finite number is written as null).
typedef nlohmann::ordered_json Json;

// Ends `report` with the list of the files written, and writes it as report.json.
void write_report(const fs::path& dir, Json& report, const std::vector<std::string>& outputs)
{
  report["outputs"] = outputs;
  write_atomically(dir / "report.json", report.dump(2) + "\n");
}

// The uv layout by stretch (and by chart, for an atlas), and the surface with the checkerboard (`checks` squares a side)
// and with the stretch colours, from three views.
void write_pictures(const fs::path& dir, const std::string& name, const smp_tools::Textured_mesh& picture,
                    const Options& o, int checks, std::vector<std::string>& outputs)
{
  const std::string layout = name + "_uv_stretch.png";
  if(!smp_tools::write_uv_layout_png((dir / layout).string(), picture, o.size))
    die("cannot write " + layout);
  outputs.push_back(layout);
  if(!picture.face_chart.empty()) {
    const std::string charts = name + "_uv_charts.png";
    if(!smp_tools::write_uv_layout_png((dir / charts).string(), picture, o.size, true))
      die("cannot write " + charts);
    outputs.push_back(charts);
  }
  const struct { const char* view; double yaw, pitch; } views[] = {{"front", 0, 10}, {"side", 90, 10}, {"three_quarter", -40, 20}};
  for(const auto& view : views)
    for(bool checker : {true, false}) {
      const std::string file = name + (checker ? "_checker_" : "_stretch_") + view.view + ".png";
      const std::string error = smp_tools::render_surface_png((dir / file).string(), picture, o.size, o.size,
                                                              o.up, view.yaw, view.pitch, checker, checks);
      if(!error.empty())
        die("rendering " + file + ": " + error);
      outputs.push_back(file);
    }
}

} // namespace

#include "smp_atlas_command.h"

int run(int argc, char** argv)
{
  const Options o = parse(argc, argv);
  const auto start = std::chrono::steady_clock::now();

  if(o.atlas)
    return run_atlas(o);

  // ---- read and check
  check_input_file(o);
  Mesh mesh;
  std::string error;
  std::size_t isolated = 0;
  if(!smp_tools::read_mesh(o.input, mesh, error, isolated, ": add --atlas"))
    die(error);
  if(isolated > 0 && !o.quiet)
    std::cout << "removed " << isolated << " isolated vertices (of no face)" << std::endl;
  const double read_seconds = seconds_since(start);
  if(!CGAL::is_triangle_mesh(mesh))
    die(o.input + " is not a triangle mesh: add --atlas (it takes polygons), or triangulate it first");
  for(vertex_descriptor v : vertices(mesh)) {
    const Point_3& p = mesh.point(v);
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      die(o.input + " has a vertex with a non-finite coordinate");
  }
  auto cc = mesh.add_property_map<face_descriptor, std::size_t>("f:smp_cc").first;
  const std::size_t components = PMP::connected_components(mesh, cc);
  std::vector<halfedge_descriptor> loops;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(loops));
  const std::size_t input_vertices = num_vertices(mesh), input_faces = num_faces(mesh);
  if(components > 1 && !o.charts)
    die(o.input + " has " + std::to_string(components) + " connected components: add --atlas for a texture atlas, or --charts to map each component into its own chart");
  if(loops.empty() && !o.cut)
    die(o.input + " is a closed surface: add --atlas for a texture atlas, or --cut to open it along one seam (genus 0 only)");
  if(o.cut && o.charts)
    die("--cut and --charts do not go together: cut the components one at a time");
  if(!o.charts && !loops.empty()) {
    // one component with a border: a handle is refused by this package's methods, and CGAL's
    // fixed-border ones map it without a word (onto a disk, which it is not); V - E + F = 2 - 2g - b
    const long euler = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
    const long genus = (2 - long(loops.size()) - euler) / 2;
    if(genus > 0)
      die(o.input + " has a border and " + std::to_string(genus) + (genus == 1 ? " handle" : " handles") +
          ": add --atlas for a texture atlas (it cuts handles open); one chart needs a disk, with holes or not");
  }
  if(o.cut) {
    if(!loops.empty())
      die(o.input + " already has a border: --cut is for closed surfaces");
    mesh = cut_open(mesh);
  }

  // ---- parameterize
  UV_map uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0, 0)).first;
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  Chosen_border border;
  border.kind = o.border;
  // the methods of a fixed border (all but LSCM and ARAP) on a square one
  const bool square = (o.border == "square" || o.border == "ear-aware") && o.method != "lscm" && o.method != "arap";
  if(square && !o.charts) {
    const std::size_t edges = CGAL::halfedges_around_face(bhd, mesh).size();
    if(edges < 4)
      die(o.input + ": its border has " + std::to_string(edges) + " edges, and " + square_border_hint + " (or --atlas)");
  }
  Run run;
  auto progress = [&o, &run](const SMP::Stretch_minimizing_step& s) {
    if(!s.polish)
      run.history.push_back(s);
    if(!o.quiet)
      std::cout << (s.descent ? "descent step " : s.polish ? "polish step " : "step ") << s.step << "  L2 stretch " << std::setprecision(6) << s.l2_stretch << "  Linf "
                << s.linf_stretch << "  " << std::setprecision(3) << s.seconds << " s"
                << (s.screened ? "  (solved only far enough to show that it raises the stretch)" : "") << std::endl;
  };
  const auto t0 = std::chrono::steady_clock::now();
  const bool ours = o.method == "uopt" || o.method == "u1" || o.method == "u0";
  if(ours) {
    const unsigned int cap = o.method == "u0" ? 0u : o.method == "u1" ? 1u : unsigned(o.iterations);
    const SMP::Start_weights start = o.start == "mvc" ? SMP::Start_weights::MEAN_VALUE
                                   : o.start == "cot" ? SMP::Start_weights::CLAMPED_COTANGENT
                                                      : SMP::Start_weights::SHAPE_PRESERVING;
    const SMP::Stretch_update update = o.update == "edge" ? SMP::Stretch_update::EDGE
                                     : o.update == "symmetric" ? SMP::Stretch_update::SYMMETRIC
                                                               : SMP::Stretch_update::VERTEX;
    const SMP::Step_rule rule = o.rule == "halve" ? SMP::Step_rule::HALVE_ETA : SMP::Step_rule::STOP_AT_INCREASE;
    const unsigned int polish = o.method == "uopt" ? unsigned(o.polish) : 0u;
    const unsigned int descent = o.method == "uopt" ? unsigned(o.descent) : 0u;
    auto np = SMP::parameters::start_weights(start).stretch_update(update).step_rule(rule)
              .descent_iterations(descent).polish_iterations(polish).polish_time_budget(o.polish_time)
              .free_border(o.free_border).number_of_threads(unsigned(o.threads)).eta(o.eta)
              .number_of_iterations(cap).visitor(progress);
    SMP::Stretch_minimizing_parameterizer_3<Mesh, Floater> p(Floater(border), np);
    run_parameterizer(mesh, bhd, p, uv, o.charts, run);
    const SMP::Stretch_minimizing_report report = p.report(); // a copy: read it once
    run.kept_step = report.kept_step;
    run.polish = report.polish;
    if(run.message.empty()) run.message = report.message;
  } else if(o.method == "mvc") {
    run_parameterizer(mesh, bhd, MVC(border), uv, o.charts, run);
  } else if(o.method == "dcm") {
    run_parameterizer(mesh, bhd, SMP::Discrete_conformal_map_parameterizer_3<Mesh, Chosen_border>(border), uv, o.charts, run);
  } else if(o.method == "dap") {
    run_parameterizer(mesh, bhd, SMP::Discrete_authalic_parameterizer_3<Mesh, Chosen_border>(border), uv, o.charts, run);
  } else if(o.method == "lscm") {
    run_parameterizer(mesh, bhd, SMP::LSCM_parameterizer_3<Mesh>(), uv, o.charts, run);
  } else {
    run_parameterizer(mesh, bhd, SMP::ARAP_parameterizer_3<Mesh>(), uv, o.charts, run);
  }
  const double parameterize_seconds = seconds_since(t0);
  // --charts leaves the components that are no disk, as long as one is mapped
  const bool some_mapped = o.charts && run.unmapped < run.charts;
  if(run.status != SMP::OK && !(some_mapped && run.status == SMP::ERROR_NO_TOPOLOGICAL_DISC)) {
    std::string why = run.message.empty() ? border.why : run.message;
    // a component's message (run_parameterizer()) says its error itself
    if(run.unmapped > 0)
      die("parameterization failed: " + why +
          (square && run.border_too_short ? std::string(": ") + square_border_hint
           : run.status == SMP::ERROR_NO_TOPOLOGICAL_DISC ? ": no component is a disk: --atlas maps any" : ""));
    die(std::string("parameterization failed: ") + SMP::error_message(run.status) + (why.empty() ? "" : ": " + why));
  }
  if(run.unmapped > 0) // the components that are no disk, left by --charts: said even with -q
    std::cerr << "smp-parameterize: warning: " << run.unmapped << " of " << run.charts << " components not mapped ("
              << run.message << "): their faces keep uv (0, 0); --atlas maps every component" << std::endl;

  // ---- measure (the faces of the parameterized charts)
  const auto t1 = std::chrono::steady_clock::now();
  std::vector<face_descriptor> measured;
  for(face_descriptor f : faces(mesh)) {
    bool written = true;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      written = written && std::isfinite(uv[v].x()) && std::isfinite(uv[v].y());
    if(written) measured.push_back(f);
  }
  const SMP::Stretch_statistics stats = SMP::compute_stretch_statistics(measured, mesh, uv);
  smp_tools::Textured_mesh picture;
  {
    double a2 = 0., a3 = 0.;
    std::vector<SMP::Face_stretch> per_face;
    for(face_descriptor f : measured) {
      const halfedge_descriptor h = halfedge(f, mesh);
      const vertex_descriptor a = source(h, mesh), b = target(h, mesh), c = target(next(h, mesh), mesh);
      per_face.push_back(SMP::face_stretch(mesh.point(a), mesh.point(b), mesh.point(c), uv[a], uv[b], uv[c]));
      if(std::isfinite(per_face.back().l2) && per_face.back().area_3d > 0.) {
        a2 += std::abs(per_face.back().area_uv);
        a3 += per_face.back().area_3d;
      }
      picture.faces.push_back({int(a), int(b), int(c)});
      picture.corner_uv.push_back({{{uv[a].x(), uv[a].y()}, {uv[b].x(), uv[b].y()}, {uv[c].x(), uv[c].y()}}});
    }
    const double normalization = a3 > 0. ? std::sqrt(a2 / a3) : 1.;
    for(const SMP::Face_stretch& s : per_face)
      picture.face_stretch.push_back(std::isfinite(s.l2) ? s.l2 * normalization : 0.);
    for(vertex_descriptor v : vertices(mesh))
      picture.xyz.push_back({mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()});
  }
  const double measure_seconds = seconds_since(t1);

  // ---- write
  const auto t2 = std::chrono::steady_clock::now();
  const fs::path dir = output_folder(o);
  const std::string name = fs::path(o.input).stem().string();
  std::vector<std::string> outputs;
  {
    smp_tools::Text obj;
    obj << "# " << name << " parameterized by smp-parameterize (" << o.method << ")\nmtllib " << name << ".mtl\n";
    for(vertex_descriptor v : vertices(mesh))
      obj << "v " << mesh.point(v).x() << ' ' << mesh.point(v).y() << ' ' << mesh.point(v).z() << '\n';
    for(vertex_descriptor v : vertices(mesh))
      obj << "vt " << uv[v].x() << " " << uv[v].y() << "\n";
    obj << "usemtl checker\n";
    for(face_descriptor f : measured) {
      obj << "f";
      for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
        obj << " " << v.idx() + 1 << "/" << v.idx() + 1;
      obj << "\n";
    }
    write_textured_obj(dir, name, obj.str(), outputs);
  }
  const double write_seconds = seconds_since(t2);

  const auto t3 = std::chrono::steady_clock::now();
  if(o.pictures)
    write_pictures(dir, name, picture, o, 16, outputs);
  const double render_seconds = seconds_since(t3);

  // ---- report
  Json report;
  report["input"] = o.input;
  report["mesh"] = {{"vertices", input_vertices}, {"faces", input_faces}, {"isolated_vertices_removed", isolated},
                    {"boundaries", loops.size()},
                    {"components", components}, {"components_not_mapped", run.unmapped}, {"cut_open", o.cut}};
  report["method"] = o.method;
  report["options"] = {{"border", o.border}, {"preset", o.preset}, {"start", o.start}, {"update", o.update},
                       {"rule", o.rule}, {"eta", o.eta}, {"iterations", o.iterations}, {"descent", o.descent},
                       {"polish", o.polish}, {"polish_time", o.polish_time}, {"free_border", o.free_border},
                       {"charts", o.charts}};
  report["status"] = SMP::error_message(run.status);
  report["history"] = Json::array();
  for(const auto& s : run.history)
    report["history"].push_back({{"step", s.step}, {"l2_stretch", s.l2_stretch}, {"linf_stretch", s.linf_stretch},
                                 {"flipped_faces", s.flipped_faces}, {"degenerate_uv_faces", s.degenerate_uv_faces},
                                 {"solver_iterations", s.solver_iterations}, {"screened", s.screened},
                                 {"seconds", s.seconds}});
  report["kept_step"] = ours ? Json(run.kept_step) : Json(nullptr);
  report["polish"] = {{"ran", run.polish.ran()}, {"descent_iterations", run.polish.descent_iterations},
                      {"iterations", run.polish.iterations}, {"l2_before", run.polish.l2_before},
                      {"l2_after", run.polish.l2_after}, {"seconds", run.polish.seconds},
                      {"message", run.polish.message}};
  report["measures"] = {{"faces", stats.number_of_faces}, {"l2_stretch", stats.l2_stretch},
                        {"linf_stretch", stats.linf_stretch}, {"edge_distortion", stats.edge_distortion},
                        {"angle_distortion", stats.angle_distortion}, {"area_distortion", stats.area_distortion},
                        {"flipped_faces", stats.flipped_faces}, {"degenerate_uv_faces", stats.degenerate_uv_faces},
                        {"degenerate_3d_faces", stats.degenerate_3d_faces}};
  report["seconds"] = {{"read", read_seconds}, {"parameterize", parameterize_seconds}, {"measure", measure_seconds},
                       {"write", write_seconds}, {"pictures", render_seconds}};
  write_report(dir, report, outputs);

  if(!o.quiet)
    std::cout << o.method << ": L2 stretch " << std::setprecision(6) << stats.l2_stretch << ", Linf " << stats.linf_stretch
              << ", " << stats.flipped_faces << " flipped, " << stats.degenerate_uv_faces << " degenerate faces\n"
              << "wrote " << fs::absolute(dir).string() << "/{" << name << ".obj, report.json"
              << (o.pictures ? ", *.png" : "") << "}" << std::endl;
  return EXIT_SUCCESS;
}

int main(int argc, char** argv)
{
  return smp_tools::run_guarded("smp-parameterize", run, argc, argv);
}

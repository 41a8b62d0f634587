// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smp-remesh: remeshes a disk-like triangle mesh file with two of its parameterizations
// (remesh_with_parameterizations()) and writes the new mesh, a JSON report of its quality and,
// if asked, a picture of it.
// Run without arguments for the options.

#include "smp_command_line.h"
#include "smp_input.h"
#include "smp_output.h"
#include "smp_surface_distance.h"
#include "render.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/error_message.h>
#include <CGAL/Surface_mesh_parameterization/remesh_with_parameterizations.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/PLY.h>

#include <boost/program_options.hpp>

#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <new>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

namespace {

struct Options
{
  std::string input, output, report, picture, pair = "u0-uopt";
  long long vertices = 0;
  double eta = 1., curvature = 0.;
  int iterations = 20, threads = 0, size = 800, up = 2;
  bool quiet = false;
};

[[noreturn]] void die(const std::string& message, int status = 1) { smp_tools::fail("smp-remesh", message, status); }

Options parse(int argc, char** argv)
{
  namespace po = boost::program_options;
  Options o;
  std::string up = "z";
  po::options_description described("options");
  described.add_options()
    ("help,h", "this text")
    ("vertices,n", po::value(&o.vertices)->value_name("N"), "vertices of the new mesh (required)")
    ("output,o", po::value(&o.output)->value_name("OUT"), "the new mesh: .off, .obj or .ply (required)")
    ("pair", po::value(&o.pair)->value_name("P"),
     "the parameterizations {U', U''}: u0, u0-u1 or u0-uopt (default): the mesh is triangulated in U' = U^0 "
     "and sampled in U''")
    ("curvature", po::value(&o.curvature)->value_name("A"),
     "more vertices where the surface curves: the density goes as 1 + A k / mean(k), k the largest principal "
     "curvature (default 0: the surface sampled evenly)")
    ("report", po::value(&o.report)->value_name("JSON"), "the report (default: OUT with the extension .json)")
    ("eta", po::value(&o.eta)->value_name("X"), "weight update exponent of U^1 and U^opt, 0 < X <= 1 (default 1)")
    ("iterations", po::value(&o.iterations)->value_name("N"), "cap on the steps of U^opt (default 20)")
    ("threads", po::value(&o.threads)->value_name("N"), "threads of the parameterization (default 0: one per core)")
    ("picture", po::value(&o.picture)->value_name("PNG"), "a picture of the new mesh and its edges (three-quarter view)")
    ("size", po::value(&o.size)->value_name("PX"), "picture size in pixels (default 800)")
    ("up", po::value(&up)->value_name("A"), "the model's up axis in the picture: x, y or z (default z)")
    ("quiet,q", po::bool_switch(&o.quiet), "no summary line");
  const po::variables_map vm = smp_tools::parse_command_line(
      argc, argv, "smp-remesh", described, o.input,
      "usage: smp-remesh MESH --vertices N -o OUT [options]\n"
      "  MESH: a triangle mesh (.off, .obj, .ply or .stl), one disk, holes allowed\n");
  if(!vm.count("vertices") || o.vertices < 3 || o.vertices > (1LL << 29))
    die("give --vertices N, a whole number from 3 to 2^29", 2);
  if(o.output.empty())
    die("give the output mesh with -o OUT (.off, .obj or .ply)", 2);
  const std::string e = smp_tools::internal::lower_extension(o.output);
  if(e != ".off" && e != ".obj" && e != ".ply")
    die("the output mesh must end in .off, .obj or .ply: " + o.output, 2);
  if(o.pair != "u0" && o.pair != "u0-u1" && o.pair != "u0-uopt")
    die("option --pair: give u0, u0-u1 or u0-uopt", 2);
  if(!std::isfinite(o.eta) || !(o.eta > 0.) || o.eta > 1.)
    die("option --eta: give a number in (0, 1]", 2);
  if(!std::isfinite(o.curvature) || !(o.curvature >= 0.))
    die("option --curvature: give a number >= 0", 2);
  if(o.iterations < 1 || o.iterations > 10000)
    die("option --iterations: give a whole number from 1 to 10000", 2);
  if(o.threads < 0 || o.threads > 1024)
    die("option --threads: give a whole number from 0 to 1024", 2);
  if(!o.picture.empty() && smp_tools::internal::lower_extension(o.picture) != ".png")
    die("the picture must end in .png: " + o.picture, 2);
  if(o.size < 16 || o.size > 8192)
    die("option --size: give a whole number from 16 to 8192", 2);
  if(up != "x" && up != "y" && up != "z")
    die("option --up: give x, y or z", 2);
  o.up = up[0] - 'x';
  if(o.report.empty())
    o.report = fs::path(o.output).replace_extension(".json").string();
  if(!o.picture.empty()) {
    const std::string missing = smp_tools::load_surface_renderer();
    if(!missing.empty()) die(missing);
  }
  return o;
}

std::string mesh_text(const Mesh& mesh, const std::string& extension)
{
  std::ostringstream out;
  const auto np = CGAL::parameters::stream_precision(17);
  const bool ok = extension == ".obj" ? CGAL::IO::write_OBJ(out, mesh, np)
                : extension == ".ply" ? CGAL::IO::write_PLY(out, mesh, np)
                                     : CGAL::IO::write_OFF(out, mesh, np);
  if(!ok)
    die("cannot write the new mesh");
  return out.str();
}

int run(int argc, char** argv)
{
  const Options o = parse(argc, argv);
  Mesh mesh;
  std::string error;
  std::size_t isolated = 0;
  if(!smp_tools::read_mesh(o.input, mesh, error, isolated))
    die(error);
  if(!CGAL::is_triangle_mesh(mesh))
    die(o.input + " has faces that are not triangles: triangulate it first");

  const SMP::Remeshing_pair pair = o.pair == "u0" ? SMP::Remeshing_pair::U0
                                 : o.pair == "u0-u1" ? SMP::Remeshing_pair::U0_U1 : SMP::Remeshing_pair::U0_UOPT;
  namespace P = SMP::parameters;
  Mesh out;
  const SMP::Remeshing_report r = SMP::remesh_with_parameterizations(
      mesh, std::size_t(o.vertices), out,
      P::parameterization_pair(pair).eta(o.eta).number_of_iterations(std::size_t(o.iterations))
        .number_of_threads(unsigned(o.threads)).curvature_adaptation(o.curvature));
  if(r.status != SMP::OK)
    die("remeshing failed: " + std::string(SMP::error_message(r.status)) + ": " + r.message);

  const auto t = std::chrono::steady_clock::now();
  const double diagonal = smp_tools::bounding_box_diagonal(mesh);
  const double hausdorff = smp_tools::symmetric_hausdorff_distance(out, mesh, diagonal);
  const double mean_distance = smp_tools::symmetric_mean_distance(out, mesh);
  const double seconds_distances = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();

  nlohmann::ordered_json j;
  j["input"] = {{"file", o.input}, {"vertices", num_vertices(mesh)}, {"faces", num_faces(mesh)},
                {"isolated_vertices_removed", isolated}, {"bounding_box_diagonal", diagonal}};
  j["pair"] = o.pair;
  j["curvature_adaptation"] = o.curvature;
  j["vertices_asked"] = o.vertices;
  j["vertices"] = r.vertices;
  j["border_vertices"] = r.border_vertices;
  j["faces"] = r.faces;
  j["border_loops"] = r.border_loops;
  j["triangulation_l2_stretch"] = r.triangulation_l2_stretch;
  j["sampling_l2_stretch"] = r.sampling_l2_stretch;
  j["min_angle_degrees"] = r.min_angle;
  j["angles_at_least_30_degrees"] = r.angles_at_least_30;
  j["angle_histogram_10_degree_bins"] = r.angle_histogram;
  j["area_coefficient_of_variation"] = r.area_variation;
  j["wrong_faces"] = r.wrong_faces;
  j["hausdorff_distance"] = hausdorff;
  j["hausdorff_distance_over_diagonal"] = diagonal > 0. ? hausdorff / diagonal : 0.;
  j["mean_distance_over_diagonal"] = diagonal > 0. ? mean_distance / diagonal : 0.;
  j["seconds"] = {{"parameterization", r.seconds_parameterization}, {"sampling", r.seconds_sampling},
                  {"triangulation", r.seconds_triangulation}, {"remeshing", r.seconds}, {"distances", seconds_distances}};

  // the mesh first: a report is never left beside a mesh that was not written
  if(!smp_tools::write_atomically(o.output, mesh_text(out, smp_tools::internal::lower_extension(o.output)), error) ||
     !smp_tools::write_atomically(o.report, j.dump(2) + "\n", error))
    die(error);
  if(!o.picture.empty()) {
    smp_tools::Textured_mesh picture;
    std::vector<int> index(out.num_vertices(), -1); // removed vertices included
    for(const auto v : out.vertices()) {
      index[v.idx()] = int(picture.xyz.size());
      picture.xyz.push_back({out.point(v).x(), out.point(v).y(), out.point(v).z()});
    }
    for(const auto f : out.faces()) {
      std::array<int, 3> corners{};
      int k = 0;
      for(const auto v : vertices_around_face(out.halfedge(f), out))
        corners[std::size_t(k++)] = index[v.idx()];
      picture.faces.push_back(corners);
      picture.corner_uv.push_back({});
    }
    const std::string failure = smp_tools::render_surface_png(o.picture, picture, o.size, o.size, o.up, -40., 20., false, 0, true);
    if(!failure.empty())
      die("rendering " + o.picture + ": " + failure);
  }
  if(r.wrong_faces > 0)
    std::cerr << "smp-remesh: warning: " << r.wrong_faces << " triangles cross another or are turned against the "
              << "surface (a part too thin for this vertex count: ask for more vertices)" << std::endl;
  if(!o.quiet)
    std::cout << "smp-remesh: " << r.vertices << " vertices (" << r.border_vertices << " on " << r.border_loops
              << " border loops), " << r.faces << " triangles; angles >= 30 degrees: " << 100. * r.angles_at_least_30
              << "%, smallest " << r.min_angle << "; area variation " << r.area_variation << "; Hausdorff "
              << hausdorff << "; " << r.seconds << " s\nwrote " << o.output << ", " << o.report << std::endl;
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  return smp_tools::run_guarded("smp-remesh", run, argc, argv);
}

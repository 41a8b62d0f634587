// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// smp-parameterize as a user meets it: on a small mesh, the OBJ reread with CGAL is the
// library's result, the JSON report parses and agrees, the pictures have the asked size and
// are not blank; each error a user will hit gives one line and a non-zero exit; the tools' plain
// OFF reader gives what CGAL's reader gives.

#include "smp_test_util.h"
#include "smp_input.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Stretch_minimizing_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cairo.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

typedef CGAL::Simple_cartesian<double>      Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;
typedef SMP::Stretch_minimizing_parameterizer_3<Mesh> Smp_parameterizer;
namespace fs = std::filesystem;

struct Result
{
  int status = -1;
  std::string out, err;
};

// The bytes of `file` (none if it cannot be read).
std::string file_text(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs `tool` (smp-parameterize by default) with `args`, capturing its output.
Result run(const std::string& args, const std::string& tool = SMP_TOOL)
{
  const std::string out = "tool_stdout.txt", err = "tool_stderr.txt";
  const int raw = std::system((tool + " " + args + " > " + out + " 2> " + err).c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = file_text(out);
  r.err = file_text(err);
  return r;
}

// An error: non-zero exit, exactly one line on stderr that mentions `word`.
void check_error(const std::string& what, const std::string& args, const std::string& word,
                 const std::string& tool = SMP_TOOL)
{
  const Result r = run(args, tool);
  const std::size_t lines = std::size_t(std::count(r.err.begin(), r.err.end(), '\n'));
  SMP_CHECK(r.status != 0 && r.status != -1, what << ": exit status " << r.status);
  SMP_CHECK(lines == 1 && r.err.find(word) != std::string::npos, what << ": stderr was '" << r.err << "'");
}

// A torus of 6 x 6 quads, each cut into two triangles, less the two of one quad: one border
// of four edges, one handle.
void write_holed_torus(const std::string& file)
{
  const int n = 6;
  std::ofstream out(file);
  out << "OFF\n" << n * n << " " << 2 * n * n - 2 << " 0\n";
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      const double a = 2. * CGAL_PI * i / n, b = 2. * CGAL_PI * j / n;
      out << (2. + std::cos(b)) * std::cos(a) << " " << (2. + std::cos(b)) * std::sin(a) << " " << std::sin(b) << "\n";
    }
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      if(i == 0 && j == 0) continue;
      const int v00 = i * n + j, v10 = ((i + 1) % n) * n + j, v01 = i * n + (j + 1) % n, v11 = ((i + 1) % n) * n + (j + 1) % n;
      out << "3 " << v00 << " " << v10 << " " << v11 << "\n3 " << v00 << " " << v11 << " " << v01 << "\n";
    }
}

// A binary little-endian PLY of the vertices (0, 0, 0), (1, 0, 0), (0, 1, 0), of properties
// `extra` (header lines) then x, y, z, and one face whose list of ints is `face` (its count then
// its items, 4 bytes each).
void write_triangle_ply(const std::string& file, const std::string& extra, const std::string& face)
{
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" << extra
      << "property float x\nproperty float y\nproperty float z\nelement face 1\n"
         "property list int int vertex_indices\nend_header\n";
  const std::string zero(4, '\0'), one("\x00\x00\x80\x3f", 4); // 0.f and 1.f
  out << zero << zero << zero << one << zero << zero << zero << one << zero << face;
}

// An ASCII PLY of three vertices x y z, the lines `vertices`, and one element `element` (face,
// tristrips) of a list of types `list` (count type, item type), the line `item`.
void write_ascii_triangle_ply(const std::string& file, const std::string& element, const std::string& list,
                              const std::string& vertices, const std::string& item)
{
  std::ofstream(file) << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                      << "element " << element << " 1\nproperty list " << list << " vertex_indices\nend_header\n"
                      << vertices << item;
}

// Size and spread of the pixel values of a PNG.
bool png_facts(const std::string& file, int& width, int& height, double& spread)
{
  cairo_surface_t* s = cairo_image_surface_create_from_png(file.c_str());
  if(cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return false;
  }
  width = cairo_image_surface_get_width(s);
  height = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  double sum = 0., sum2 = 0.;
  std::size_t n = 0;
  for(int y = 0; y < height; ++y)
    for(int x = 0; x < width; ++x) {
      const double g = data[y * stride + 4 * x + 1]; // green channel
      sum += g;
      sum2 += g * g;
      ++n;
    }
  spread = std::sqrt(std::max(0., sum2 / n - (sum / n) * (sum / n)));
  cairo_surface_destroy(s);
  return true;
}

// The texture of the OBJ: 512 x 512, 16 checks a side of a light and a dark colour, the light
// one at the bottom left (uv 0, 0).
void check_checkerboard(const std::string& file)
{
  cairo_surface_t* s = cairo_image_surface_create_from_png(file.c_str());
  const bool read = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS;
  SMP_CHECK(read && cairo_image_surface_get_width(s) == 512 && cairo_image_surface_get_height(s) == 512,
            file << ": not a 512 x 512 PNG");
  if(read && cairo_image_surface_get_width(s) == 512 && cairo_image_surface_get_height(s) == 512) {
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    std::size_t wrong = 0;
    for(int y = 0; y < 512; ++y)
      for(int x = 0; x < 512; ++x) {
        const bool dark = (x / 32 + (511 - y) / 32) % 2 == 1;
        const std::uint32_t pixel = reinterpret_cast<const std::uint32_t*>(data + std::size_t(y) * stride)[x];
        wrong += (pixel & 0xffffffu) != (dark ? 0x283c78u : 0xebebe1u); // (40, 60, 120), (235, 235, 225)
      }
    SMP_CHECK(wrong == 0, file << ": " << wrong << " pixels off the checkerboard");
  }
  cairo_surface_destroy(s);
}

void check_outputs()
{
  const std::string input = smp_test::data_file("nefertiti.off");
  fs::remove_all("out_nefertiti");
  const Result r = run(input + " -o out_nefertiti --size 200 --eta 0.5 --iterations 7 --threads 2");
  SMP_CHECK(r.status == 0, "tool failed: " << r.err);
  SMP_CHECK(r.out.find("step 1") != std::string::npos, "no progress line: " << r.out);
  SMP_CHECK(run(input + " -o out_quiet -q --no-pictures").out.empty(), "--quiet still prints");
  SMP_CHECK(!fs::exists("out_quiet/nefertiti_uv_stretch.png") && fs::exists("out_quiet/nefertiti.obj"), "--no-pictures");

  // the library's result with the same options
  Mesh expected;
  CGAL::IO::read_polygon_mesh(input, expected);
  auto uv = expected.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  SMP::Stretch_minimizing_parameterizer_3<Mesh> p(SMP::parameters::eta(0.5).number_of_iterations(7));
  SMP_CHECK(SMP::parameterize(expected, p, CGAL::Polygon_mesh_processing::longest_border(expected).first, uv) == SMP::OK,
            "library run failed");

  // the OBJ: same vertices, and texture coordinates equal to the library's to 1e-12
  std::ifstream obj("out_nefertiti/nefertiti.obj");
  std::vector<std::array<double, 3> > v;
  std::vector<std::array<double, 2> > vt;
  std::size_t f = 0;
  std::string line;
  bool mtl = false;
  while(std::getline(obj, line)) {
    std::istringstream in(line);
    std::string key;
    in >> key;
    if(key == "v") { std::array<double, 3> x; in >> x[0] >> x[1] >> x[2]; v.push_back(x); }
    else if(key == "vt") { std::array<double, 2> x; in >> x[0] >> x[1]; vt.push_back(x); }
    else if(key == "f") ++f;
    else if(key == "mtllib") mtl = true;
  }
  SMP_CHECK(mtl && fs::exists("out_nefertiti/nefertiti.mtl") && fs::exists("out_nefertiti/checker.png"), "MTL or texture missing");
  check_checkerboard("out_nefertiti/checker.png");
  SMP_CHECK(v.size() == num_vertices(expected) && vt.size() == v.size() && f == num_faces(expected),
            "OBJ has " << v.size() << " v, " << vt.size() << " vt, " << f << " f");
  double err = 0.;
  std::size_t k = 0;
  for(Mesh::Vertex_index w : vertices(expected)) {
    if(k >= vt.size()) break;
    err = std::max(err, std::hypot(vt[k][0] - uv[w].x(), vt[k][1] - uv[w].y()));
    ++k;
  }
  SMP_CHECK(err < 1e-12, "OBJ texture coordinates differ from the library's by " << err);
  // and CGAL reads the OBJ back as the same surface
  Mesh reread;
  SMP_CHECK(CGAL::IO::read_polygon_mesh("out_nefertiti/nefertiti.obj", reread) && num_faces(reread) == num_faces(expected),
            "CGAL cannot read the OBJ back");

  // the JSON report
  boost::property_tree::ptree json;
  try {
    boost::property_tree::read_json("out_nefertiti/report.json", json);
  } catch(const std::exception& e) {
    SMP_CHECK(false, "report.json does not parse: " << e.what());
    return;
  }
  SMP_CHECK(json.get<std::size_t>("mesh.vertices") == num_vertices(expected) && json.get<std::size_t>("mesh.boundaries") == 1,
            "mesh facts in the report");
  SMP_CHECK(json.get<std::string>("method") == "uopt" && json.get<double>("options.eta") == 0.5, "options in the report");
  SMP_CHECK(json.get_child("history").size() == p.report().history.size(), "history length in the report");
  SMP_CHECK(json.get<std::size_t>("kept_step") == p.report().kept_step, "kept step in the report");
  SMP_CHECK(std::abs(json.get<double>("measures.l2_stretch") - p.report().kept().l2_stretch) < 1e-8, "L2 in the report");
  SMP_CHECK(json.get<int>("measures.flipped_faces") == 0, "flips in the report");

  // the pictures
  std::size_t pictures = 0;
  for(const auto& entry : fs::directory_iterator("out_nefertiti"))
    if(entry.path().extension() == ".png" && entry.path().filename() != "checker.png") {
      int w = 0, h = 0;
      double spread = 0.;
      SMP_CHECK(png_facts(entry.path().string(), w, h, spread), entry.path() << " is not a PNG");
      SMP_CHECK(w == 200 && h == 200, entry.path() << " is " << w << " x " << h);
      SMP_CHECK(spread > 10., entry.path() << " looks blank (spread " << spread << ")");
      ++pictures;
    }
  SMP_CHECK(pictures == 7, pictures << " pictures");

  // the other methods and borders run too
  for(const char* args : {"-m mvc --border circle", "-m lscm", "-m u1 --border ear-aware", "-m u0 --start mvc",
                          "--preset lowest", "--start cot --update symmetric --rule halve", "--polish 5",
                          "--polish-time 0.5 --free-border", "--descent 10 --free-border"}) {
    const Result o = run(input + " -q --no-pictures -o out_methods " + args);
    SMP_CHECK(o.status == 0, args << ": " << o.err);
  }
  // the preset and the polish reach the report as the library gives them
  fs::remove_all("out_polish");
  SMP_CHECK(run(input + " -q --no-pictures -o out_polish --preset lowest --polish 5 --free-border").status == 0, "polish run");
  Smp_parameterizer polished(SMP::parameters::preset(SMP::Stretch_minimizing_preset::LOWEST_STRETCH,
                             SMP::parameters::polish_iterations(5u, SMP::parameters::free_border(true))));
  SMP_CHECK(SMP::parameterize(expected, polished, CGAL::Polygon_mesh_processing::longest_border(expected).first, uv) == SMP::OK &&
            polished.report().polish.ran(), "library polish failed");
  {
    boost::property_tree::ptree json;
    boost::property_tree::read_json("out_polish/report.json", json);
    SMP_CHECK(json.get<bool>("polish.ran") && json.get<std::size_t>("polish.iterations") == polished.report().polish.iterations &&
              json.get<std::size_t>("polish.descent_iterations") == polished.report().polish.descent_iterations &&
              std::abs(json.get<double>("polish.l2_after") - polished.report().l2_stretch()) < 1e-9 &&
              std::abs(json.get<double>("measures.l2_stretch") - polished.report().l2_stretch()) < 1e-9,
              "report.json polish: " << json.get<double>("polish.l2_after") << " vs " << polished.report().l2_stretch());
    SMP_CHECK(json.get<std::string>("options.start") == "cot" && json.get<std::string>("options.rule") == "stop" &&
              json.get<unsigned>("options.descent") == SMP::lowest_stretch_descent_iterations,
              "report.json options of the preset");
  }

  // a closed mesh with --cut, several components with --charts
  SMP_CHECK(run(smp_test::data_file("bear.off") + " -q --no-pictures --cut -o out_bear").status == 0, "--cut on bear");
}

void check_errors()
{
  check_error("no such file", "does_not_exist.off", "cannot open");
  std::ofstream("not_a_mesh.off") << "this is not an OFF file\n";
  check_error("unreadable file", "not_a_mesh.off", "cannot read");
  std::ofstream("mesh.xyz") << "0 0 0\n";
  check_error("unknown format", "mesh.xyz", "format");
  std::ofstream("quads.off") << "OFF\n6 2 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n4 0 1 4 3\n4 1 2 5 4\n";
  check_error("quads", "quads.off", "triangle");
  check_error("closed mesh", smp_test::data_file("bear.off"), "--atlas");
  std::ofstream("two.off") << "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n";
  check_error("two components", "two.off", "--atlas");
  // two triangles on the same side of one edge: a soup, not a polygon mesh
  std::ofstream("soup.off") << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n";
  check_error("not a polygon mesh", "soup.off", "--atlas");
  // a border of three edges (an octahedron less a face): the square border needs four corners
  const std::string octahedron_points = "1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n",
                    octahedron_faces = "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n";
  std::ofstream("three_edge_border.off") << "OFF\n6 7 0\n" << octahedron_points << octahedron_faces;
  fs::remove_all("out_three_edges");
  check_error("three-edge border, square", "three_edge_border.off -o out_three_edges", "--border circle");
  check_error("three-edge border, CGAL's mean value map", "three_edge_border.off -m mvc -o out_three_edges", "--border circle");
  SMP_CHECK(!fs::exists("out_three_edges"), "an output written for a border the square cannot take");
  SMP_CHECK(run("three_edge_border.off --border circle -q -o out_three_edges").status == 0,
            "a three-edge border on a circle is refused");
  // the same with --charts: a component of a three-edge border beside one of a square
  std::ofstream("three_edge_component.off") << "OFF\n10 9 0\n" << octahedron_points << "5 0 0\n6 0 0\n6 1 0\n5 1 0\n"
                                             << octahedron_faces << "3 6 7 8\n3 6 8 9\n";
  check_error("three-edge border of a component", "three_edge_component.off --charts", "--border circle");
  SMP_CHECK(run("three_edge_component.off --charts --border circle -q -o out_three_edges").status == 0,
            "components, one of a three-edge border, on circles are refused");
  write_holed_torus("holed_torus.off");
  check_error("a border and a handle", "holed_torus.off", "--atlas");
  check_error("a border and a handle, CGAL's mean value map", "holed_torus.off -m mvc", "--atlas");
  check_error("a border and a handle, the only component of --charts", "holed_torus.off --charts", "--atlas");
  check_error("eta out of range", smp_test::data_file("nefertiti.off") + " --eta 2", "eta");
  check_error("iterations not a number", smp_test::data_file("nefertiti.off") + " --iterations many", "iterations");
  check_error("threads not a whole number", smp_test::data_file("nefertiti.off") + " --threads 1.5", "threads");
  check_error("unknown method", smp_test::data_file("nefertiti.off") + " -m best", "method");
  check_error("unknown option", smp_test::data_file("nefertiti.off") + " --fast", "option");
  check_error("unknown preset", smp_test::data_file("nefertiti.off") + " --preset best", "preset");
  check_error("unknown update", smp_test::data_file("nefertiti.off") + " --update face", "update");
  check_error("free border alone", smp_test::data_file("nefertiti.off") + " --free-border", "--polish");
  check_error("negative polish time", smp_test::data_file("nefertiti.off") + " --polish-time -1", "polish-time");
  check_error("descent not a whole number", smp_test::data_file("nefertiti.off") + " --descent -3", "descent");
  check_error("atlas with --cut", smp_test::data_file("bear.off") + " --atlas --cut", "--cut");
  check_error("atlas stretch bound below 1", smp_test::data_file("bear.off") + " --atlas --max-stretch 0.9", "max-stretch");
  check_error("atlas gutter not a number", smp_test::data_file("bear.off") + " --atlas --gutter wide", "gutter");
  check_error("atlas resolution too small", smp_test::data_file("bear.off") + " --atlas --resolution 4", "resolution");
  check_error("atlas of an unreadable file", "not_a_mesh.off --atlas", "cannot read");
  check_error("natural border folds", smp_test::data_file("three_peaks.off") + " --border natural --no-pictures -o out_fold", "one-to-one");
  std::ofstream("nan.off") << "OFF\n4 2 0\n0 0 0\n1 0 0\nnan 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  const Result nan = run("nan.off -o out_nan");
  SMP_CHECK(nan.status != 0 && std::count(nan.err.begin(), nan.err.end(), '\n') == 1, "NaN coordinate: " << nan.status << " " << nan.err);
  check_error("atlas with a NaN coordinate", "nan.off --atlas -o out_nan_atlas", "nan.off");
  SMP_CHECK(!fs::exists("out_nan_atlas/nan.obj"), "no OBJ written for a NaN coordinate");
  // headers that announce more elements than the file holds (CGAL's readers would reserve them)
  std::ofstream("huge.off") << "OFF\n2000000000 2000000000 0\n0 0 0\n";
  check_error("OFF header beyond the file", "huge.off", "announces");
  std::ofstream("huge.ply") << "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\n"
                               "property float y\nproperty float z\nend_header\n0 0 0\n";
  check_error("PLY header beyond the file", "huge.ply --atlas", "announces");
  // found by the fuzz harness: CGAL reads an element's count as an unsigned integer, "-1.5" as
  // the largest one, and skips the items of an element it does not know one by one (a hang)
  std::ofstream("negative_element.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                           "property float y\nproperty float z\nelement junk -1.5\nend_header\n0 0 0\n1 0 0\n0 1 0\n";
  check_error("PLY element of a negative count", "negative_element.ply --atlas", "announces");
  // a list whose count the file cannot hold: CGAL 5.5.1 resizes the list to it before reading it
  const std::string beyond("\xff\xff\xff\x7f", 4), zero(4, '\0'), one("\x01\0\0\0", 4), two("\x02\0\0\0", 4);
  write_triangle_ply("list_count.ply", "", beyond + zero + one + two);
  check_error("binary PLY list of a count beyond the file", "list_count.ply --atlas", "list announces");
  write_ascii_triangle_ply("list_count_ascii.ply", "face", "int int", "0 0 0\n1 0 0\n0 1 0\n", "-3 0 1 2\n");
  check_error("ASCII PLY list of a negative count", "list_count_ascii.ply --atlas", "list announces");
  // found by the fuzz harness: a property of a type CGAL does not know takes no byte of the body
  // (CGAL skips it), so the list after it starts earlier than its place in the header says
  write_triangle_ply("unknown_type.ply", "property float3 w\n", beyond + zero + one);
  check_error("binary PLY list after a property of an unknown type", "unknown_type.ply --atlas", "list announces");
  // found by the fuzz harness: with no end_header, CGAL's reader reads the body from the end of
  // the stream, lists of counts it never read (a binary PLY: no byte of it read as a count)
  {
    std::ofstream open_header("no_end_header.ply", std::ios::binary);
    open_header << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty list int int vertex_indices\n"
                << std::string("\xff\xff\xff\x7f\0\0\0\0", 8);
  }
  check_error("PLY header without end_header", "no_end_header.ply --atlas", "end_header");
  // CGAL's reader reads on from a failed stream (values it never wrote, list counts among them):
  // after an ASCII value it cannot read, and past the end of a body shorter than its elements
  write_ascii_triangle_ply("nan_ascii.ply", "face", "uchar int", "0 0 0\nnan 0 0\n0 1 0\n", "3 0 1 2\n");
  check_error("ASCII PLY value that is not a number", "nan_ascii.ply --atlas", "not a number");
  write_ascii_triangle_ply("short_ascii.ply", "face", "uchar int", "0 0 0\n1 0 0\n0 1 0\n", "3 0 1\n");
  check_error("ASCII PLY body shorter than its elements", "short_ascii.ply --atlas", "ends before");
  // a count of a byte type read as a short and narrowed: 200 is -56 items
  write_ascii_triangle_ply("narrowed_count.ply", "face", "char int", "0 0 0\n1 0 0\n0 1 0\n", "200 0 1 2\n");
  check_error("ASCII PLY count narrowed to a negative byte", "narrowed_count.ply --atlas", "announces -56");
  {
    std::ofstream cut("short_binary.ply", std::ios::binary);
    cut << "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
           "property float z\nelement face 2\nproperty list int int vertex_indices\nend_header\n";
    cut << std::string(36, '\0') << std::string("\x03\0\0\0\0\0\0\0\x01\0\0\0\x02\0\0\0", 16);
  }
  check_error("binary PLY body shorter than its elements", "short_binary.ply --atlas", "ends before");
  // found by the fuzz harness: CGAL 5.5.1's PLY reader adds a property to an element that is not there
  std::ofstream("property_first.ply") << "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\n"
                                         "property float y\nend_header\n0 0\n";
  check_error("PLY property before any element", "property_first.ply --atlas", "property");
  // found by the fuzz harness: CGAL reads the second line as the format whatever it holds, so a
  // header ends at a line whose first word is end_header, from the third line on
  std::ofstream("end_header_second.ply") << "ply\nend_header format ascii 1.0\nproperty float x\nelement vertex 1\n"
                                            "property float y\nend_header\n0 0\n";
  check_error("PLY property before any element, after a second line that starts with end_header",
              "end_header_second.ply --atlas", "property");
  // found by the fuzz harness: CGAL 5.5.1 converts a face's numbers to unsigned integers unchecked
  std::ofstream("negative_count.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-1.5 0 1 2\n";
  check_error("OFF face of a negative vertex count", "negative_count.off --atlas", "face 0");
  std::ofstream("bad_index.off") << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n";
  check_error("OFF face of a fractional index", "bad_index.off", "face 0");
  // found by the fuzz harness: CGAL 5.5.1's read_polygon_mesh() reads past its points for such an index
  std::ofstream("bad_index.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 9\n";
  check_error("OBJ face index out of range", "bad_index.obj", "cannot read");
  // a point set (trimesh's points_emptyface.ply is one): read, but nothing to parameterize
  std::ofstream("points_only.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 0\nproperty list uchar int vertex_indices\n"
                                      "end_header\n0 0 0\n1 0 0\n0 1 0\n";
  check_error("a point set", "points_only.ply --atlas", "no polygon");
}

// The faces of an OBJ file the tool wrote, as written.
std::vector<std::string> obj_faces(const std::string& file)
{
  std::ifstream obj(file);
  std::vector<std::string> faces;
  for(std::string line; std::getline(obj, line);)
    if(line.rfind("f ", 0) == 0) faces.push_back(line);
  return faces;
}

// A PLY file of 6 vertices on a 3 x 2 grid (x, y, z and a property the reader skips) and one
// triangle strip with a restart (-1) and a repeated last vertex, in binary of either byte order.
void write_binary_strips(const std::string& file, bool big_endian)
{
  std::ofstream out(file, std::ios::binary);
  out << "ply\nformat " << (big_endian ? "binary_big_endian" : "binary_little_endian")
      << " 1.0\ncomment strips\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
         "property float confidence\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n";
  auto put = [&](std::uint32_t bits) {
    for(int k = 0; k < 4; ++k) {
      const int shift = big_endian ? 8 * (3 - k) : 8 * k;
      out.put(char((bits >> shift) & 0xff));
    }
  };
  auto put_float = [&](float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, 4);
    put(bits);
  };
  for(int v = 0; v < 6; ++v) {
    put_float(float(v / 2));
    put_float(float(v % 2));
    put_float(0.f);
    put_float(0.5f);
  }
  const std::vector<std::int32_t> strip = {0, 1, 2, 3, -1, 2, 3, 4, 5, 5};
  put(std::uint32_t(strip.size()));
  for(std::int32_t i : strip)
    put(std::uint32_t(i));
}

// Triangle strips (PLY element tristrips: Stanford's igea.ply is stored so), which CGAL's PLY
// reader does not read: unrolled into triangles of one orientation, ASCII and binary of both
// byte orders; a bad strip gets a message.
void check_ply_triangle_strips()
{
  typedef std::vector<std::vector<std::size_t> > Polygons;
  Polygons triangles;
  std::string error;
  const std::size_t restart = std::numeric_limits<std::uint32_t>::max(); // -1 read as unsigned
  SMP_CHECK(smp_tools::internal::unroll_triangle_strips({{0, 1, 2, 3, restart, 3, 3, 4}, {1, 2}}, 5, triangles, error) &&
              triangles == Polygons({{0, 1, 2}, {2, 1, 3}}),
            "unrolled strips: " << triangles.size() << " triangles");
  triangles.clear();
  SMP_CHECK(!smp_tools::internal::unroll_triangle_strips({{0, 1, 5}}, 5, triangles, error) &&
              error.find("out of range") != std::string::npos,
            "a strip index out of range: '" << error << "'");

  std::ofstream("strips.ply") << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                 "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                                 "end_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2 3\n";
  Result r = run("strips.ply --atlas -q --no-pictures -o out_strips");
  SMP_CHECK(r.status == 0, "ASCII strips: " << r.err);
  SMP_CHECK(obj_faces("out_strips/strips.obj") == std::vector<std::string>({"f 1/1 2/2 3/3", "f 3/4 2/5 4/6"}),
            "ASCII strips: " << obj_faces("out_strips/strips.obj").size() << " faces written");
  const std::vector<std::string> grid = {"f 1/1 2/2 3/3", "f 3/4 2/5 4/6", "f 3/7 4/8 5/9", "f 5/10 4/11 6/12"};
  for(bool big_endian : {false, true}) {
    const std::string name = big_endian ? "strips_be" : "strips_le";
    write_binary_strips(name + ".ply", big_endian);
    r = run(name + ".ply --atlas -q --no-pictures -o out_" + name);
    SMP_CHECK(r.status == 0, name << ": " << r.err);
    SMP_CHECK(obj_faces("out_" + name + "/" + name + ".obj") == grid,
              name << ": " << obj_faces("out_" + name + "/" + name + ".obj").size() << " faces written");
  }
  r = run("strips_le.ply -q --no-pictures -o out_strips_disk"); // a disk: parameterized as one
  SMP_CHECK(r.status == 0, "strips of a disk, without --atlas: " << r.err);

  write_ascii_triangle_ply("strips_bad_index.ply", "tristrips", "int int", "0 0 0\n1 0 0\n0 1 0\n", "4 0 1 2 7\n");
  check_error("a strip index out of range", "strips_bad_index.ply --atlas", "out of range");
  write_ascii_triangle_ply("strips_bytes.ply", "tristrips", "uchar uchar", "0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n");
  check_error("strips of 8-bit indices", "strips_bytes.ply --atlas", "triangle strips");
}

// An OBJ file whose long lines go on after a backslash (as Rhino writes them), with indices
// counted from the end and texture and normal indices: read as the polygons they spell.
void check_obj_continued_lines()
{
  std::ofstream("continued.obj") << "# continued lines\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n"
                                    "f 1 2 \\\n 5\nf -4 -3 \\\r\n -1\nf 3/1/1 4/2/2 5/3/3\nf -2 -5 -1\n";
  const Result r = run("continued.obj --atlas -q --no-pictures -o out_continued");
  SMP_CHECK(r.status == 0, "continued lines: " << r.err);
  const std::vector<std::string> faces = obj_faces("out_continued/continued.obj");
  const std::vector<std::string> expected = {"f 1/1 2/2 5/3", "f 2/4 3/5 5/6", "f 3/7 4/8 5/9", "f 4/10 1/11 5/12"};
  SMP_CHECK(faces == expected, "continued lines: " << faces.size() << " faces written");
}

// An OBJ file with polylines (`l`), points (`p`) and merging groups (`mg`) beside its faces, as
// modellers write loose edges (CGAL's reader refuses `l` and `mg` statements): its faces are read,
// the rest left out. A face index out of range, or a file of lines and points only, is refused
// with a message that says so.
void check_obj_other_statements()
{
  const std::string points = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 0.5 1\n";
  std::ofstream("mixed.obj") << "# lines, points and faces\n" << points
                             << "l 1 2 3 4 1\n  l 1 5\np 5\nmg 1 0.5\nmaplib a.map\nf 1 2 5\nf 2 3 5\n"
                                "l 3 5\nf 3 4 5\r\nf 4 1 5\nl\t4 5";
  const Result r = run("mixed.obj --atlas -q --no-pictures -o out_mixed");
  SMP_CHECK(r.status == 0, "OBJ with lines: " << r.err);
  const std::vector<std::string> faces = obj_faces("out_mixed/mixed.obj");
  const std::vector<std::string> expected = {"f 1/1 2/2 5/3", "f 2/4 3/5 5/6", "f 3/7 4/8 5/9", "f 4/10 1/11 5/12"};
  SMP_CHECK(faces == expected, "OBJ with lines: " << faces.size() << " faces written");
  // a statement that only starts like a polyline is no polyline
  std::ofstream("lod.obj") << points << "lx 1 2\nf 1 2 5\n";
  check_error("OBJ unknown statement", "lod.obj --atlas -o out_lod", "line 6");
  std::ofstream("lines_only.obj") << points << "l 1 2 3\np 4\n";
  check_error("OBJ of lines only", "lines_only.obj --atlas -o out_lines_only", "no polygon");
  std::ofstream("index_out.obj") << points << "l 1 2\nf 1 2 5\nf 2 3 9\n";
  check_error("OBJ face index out of range", "index_out.obj --atlas -o out_index_out", "line 8");
  std::ofstream("index_after_continued.obj") << points << "f 1 2 \\\n 5\nf 2 3 9\n"; // lines counted in the file
  check_error("OBJ face index out of range after a continued line", "index_after_continued.obj --atlas -o out_index_out",
              "line 8");
  std::ofstream("index_zero.obj") << points << "f 1 2 5\nf 0 3 5\n";
  check_error("OBJ face index 0", "index_zero.obj --atlas -o out_index_zero", "line 7");
  SMP_CHECK(!fs::exists("out_index_out") && !fs::exists("out_index_zero") && !fs::exists("out_lod"),
            "an output written for an OBJ file that cannot be read");
}

// An ASCII STL file whose first line is "solid", a tab and its name (as assimp's sphereWithHole.stl):
// CGAL's reader takes it for a binary file and reads garbage; read as ASCII. A binary STL file
// that announces more triangles than it holds is refused.
void check_stl_headers()
{
  std::ofstream("tab.stl") << "solid\ttab\n"
                              "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
                              "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
                              "endsolid tab\n";
  const Result r = run("tab.stl --atlas -q --no-pictures -o out_tab");
  SMP_CHECK(r.status == 0, "STL with a tab after solid: " << r.err);
  SMP_CHECK(obj_faces("out_tab/tab.obj").size() == 2, "STL with a tab after solid: faces written");
  std::string v; // a vertex line of the OBJ file, of the input's coordinates
  std::ifstream obj("out_tab/tab.obj");
  bool in_range = true;
  while(std::getline(obj, v))
    if(v.rfind("v ", 0) == 0) {
      std::istringstream xyz(v.substr(2));
      double x = -1., y = -1., z = -1.;
      xyz >> x >> y >> z;
      in_range = in_range && x >= 0. && x <= 1. && y >= 0. && y <= 1. && z == 0.;
    }
  SMP_CHECK(in_range, "STL with a tab after solid: vertices not the file's");
  std::string binary(80, 'x'); // a header, a count of 1000 triangles, and two of them
  const std::uint32_t count = 1000;
  for(int k = 0; k < 4; ++k)
    binary.push_back(char((count >> (8 * k)) & 0xff));
  const float triangles[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
  for(const auto& t : triangles) {
    binary.append(reinterpret_cast<const char*>(t), sizeof(t));
    binary.append(2, '\0');
  }
  std::ofstream("short.stl", std::ios::binary) << binary;
  check_error("binary STL shorter than its count", "short.stl --atlas -o out_short", "1000 triangles");
  SMP_CHECK(!fs::exists("out_short"), "an output written for a binary STL file shorter than its count");
}

// A vertex of no face is left out (CGAL's parameterization wants a valid polygon mesh), and
// said so; no temporary file is left in the output folder.
void check_isolated_vertex()
{
  std::ofstream("isolated.off") << "OFF\n6 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0.2\n9 9 9\n"
                                   "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n";
  const Result r = run("isolated.off --no-pictures -o out_isolated");
  SMP_CHECK(r.status == 0 && r.out.find("removed 1 isolated") != std::string::npos, r.status << ": " << r.err);
  boost::property_tree::ptree json;
  try {
    boost::property_tree::read_json("out_isolated/report.json", json);
    SMP_CHECK(json.get<std::size_t>("mesh.isolated_vertices_removed") == 1 && json.get<std::size_t>("mesh.vertices") == 5,
              "isolated vertex in the report");
  } catch(const std::exception& e) {
    SMP_CHECK(false, "report.json: " << e.what());
  }
  for(const auto& entry : fs::directory_iterator("out_isolated"))
    SMP_CHECK(entry.path().extension() != ".part", entry.path() << " left behind");
}

// --charts on a closed tetrahedron beside a disk: the disk is mapped, the tetrahedron cannot be
// (no border to fix), and that is said, on stderr and in the report, with what maps it.
void check_unmapped_component()
{
  std::ofstream("closed_and_disk.off") << "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 0\n6 0 0\n6 1 0\n5 1 0\n"
                                          "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 4 5 6\n3 4 6 7\n";
  const Result r = run("closed_and_disk.off --charts -q --no-pictures -o out_closed_and_disk");
  SMP_CHECK(r.status == 0 && r.err.find("1 of 2 components") != std::string::npos &&
            r.err.find("--atlas") != std::string::npos, r.status << ": '" << r.err << "'");
  boost::property_tree::ptree json;
  try {
    boost::property_tree::read_json("out_closed_and_disk/report.json", json);
    SMP_CHECK(json.get<std::size_t>("mesh.components_not_mapped") == 1, "unmapped component in the report");
  } catch(const std::exception& e) {
    SMP_CHECK(false, "report.json: " << e.what());
  }
}

// --atlas on what the disk path refuses (quads, a closed mesh, two parts): the OBJ keeps the
// input's vertices and faces in order, a vt per corner in the unit square, and report.json
// agrees with it.
void check_atlas()
{
  std::ofstream("atlas_mix.off") << "OFF\n10 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n"
                                    "5 0 0\n6 0 0\n5 1 0\n5 0 0\n4 0 1 4 3\n4 1 2 5 4\n3 6 7 8\n3 9 7 8\n";
  for(const std::string& mesh : {std::string("atlas_mix.off"), smp_test::data_file("bear.off")}) {
    const std::string dir = "out_atlas_" + fs::path(mesh).stem().string();
    const Result r = run(mesh + " --atlas -q --no-pictures -o " + dir);
    SMP_CHECK(r.status == 0, mesh << ": " << r.err);
    if(r.status != 0) continue;
    // the input as a soup, and the OBJ read back line by line
    std::vector<Kernel::Point_3> points;
    std::vector<std::vector<std::size_t> > polygons;
    CGAL::IO::read_polygon_soup(mesh, points, polygons);
    std::ifstream obj(dir + "/" + fs::path(mesh).stem().string() + ".obj");
    std::size_t v = 0, vt = 0, f = 0, bad = 0;
    for(std::string line; std::getline(obj, line);) {
      std::istringstream in(line);
      std::string tag;
      in >> tag;
      if(tag == "v") {
        double x, y, z;
        in >> x >> y >> z;
        bad += v >= points.size() || Kernel::Point_3(x, y, z) != points[v];
        ++v;
      } else if(tag == "vt") {
        double s, t;
        in >> s >> t;
        bad += !(s >= 0. && s <= 1. && t >= 0. && t <= 1.);
        ++vt;
      } else if(tag == "f") {
        std::size_t k = 0;
        for(std::string corner; in >> corner; ++k) {
          const std::size_t index = std::stoul(corner.substr(0, corner.find('/')));
          bad += f >= polygons.size() || k >= polygons[f].size() || index != polygons[f][k] + 1 ||
                 corner.find('/') == std::string::npos;
        }
        bad += f >= polygons.size() || k != polygons[f].size();
        ++f;
      }
    }
    std::size_t corners = 0;
    for(const auto& p : polygons) corners += p.size();
    SMP_CHECK(bad == 0 && v == points.size() && f == polygons.size() && vt == corners,
              mesh << ": OBJ " << v << " v, " << vt << " vt, " << f << " f, " << bad << " wrong");
    boost::property_tree::ptree json;
    boost::property_tree::read_json(dir + "/report.json", json);
    SMP_CHECK(json.get<std::string>("method") == "atlas" && json.get<std::size_t>("mesh.polygons") == polygons.size() &&
              json.get<unsigned>("atlas.flipped_faces") == 0 && json.get<double>("atlas.l2_stretch") <= 1.05 &&
              json.get<double>("atlas.utilization") > 0., mesh << ": report.json");
    SMP_CHECK(!fs::exists(dir + "/report.json.part"), "no temporary file left");
  }
  // --threads reaches the atlas, whose result does not depend on it
  {
    const std::string bear = smp_test::data_file("bear.off");
    const Result r = run(bear + " --atlas -q --no-pictures --threads 1 -o out_atlas_bear_1");
    SMP_CHECK(r.status == 0, "atlas on one thread: " << r.err);
    const std::string one = file_text("out_atlas_bear_1/bear.obj");
    SMP_CHECK(!one.empty() && one == file_text("out_atlas_bear/bear.obj"), "atlas on one thread: another OBJ");
  }
  // the pictures of an atlas: the uv layout by stretch and by chart too
  const Result r = run("atlas_mix.off --atlas -q --size 120 -o out_atlas_pictures");
  SMP_CHECK(r.status == 0 && fs::exists("out_atlas_pictures/atlas_mix_uv_charts.png") &&
            fs::exists("out_atlas_pictures/atlas_mix_uv_stretch.png") &&
            fs::exists("out_atlas_pictures/atlas_mix_checker_front.png"), "atlas pictures: " << r.err);
}

// smp-remesh: the mesh and its report, and the errors a user meets (none leaves a file).
void check_remesh()
{
  const std::string nefertiti = smp_test::data_file("nefertiti.off");
  fs::remove_all("out_remesh");
  fs::create_directory("out_remesh");
  const Result r = run(nefertiti + " -n 1500 -o out_remesh/nefertiti.off", SMP_REMESH_TOOL);
  SMP_CHECK(r.status == 0, "smp-remesh: exit status " << r.status << ", " << r.err);
  Mesh m;
  SMP_CHECK(CGAL::IO::read_polygon_mesh("out_remesh/nefertiti.off", m) && m.is_valid(false) && CGAL::is_triangle_mesh(m) &&
            m.number_of_vertices() >= 1470 && m.number_of_vertices() <= 1530,
            "smp-remesh: the new mesh has " << m.number_of_vertices() << " vertices for 1500");
  const std::string report = file_text("out_remesh/nefertiti.json");
  SMP_CHECK(report.find("\"vertices\": " + std::to_string(m.number_of_vertices())) != std::string::npos &&
            report.find("\"hausdorff_distance\"") != std::string::npos &&
            report.find("\"mean_distance_over_diagonal\"") != std::string::npos &&
            report.find("\"wrong_faces\": 0") != std::string::npos,
            "smp-remesh: the report is not the mesh's: " << report.substr(0, 300));
  SMP_CHECK(run(nefertiti + " -n 800 --curvature 1 -q -o out_remesh/curved.off", SMP_REMESH_TOOL).status == 0 &&
                file_text("out_remesh/curved.json").find("\"curvature_adaptation\": 1.0") != std::string::npos,
            "smp-remesh --curvature 1: no such report: " << file_text("out_remesh/curved.json").substr(0, 300));
  SMP_CHECK(run(nefertiti + " -n 800 --pair u0 -q -o out_remesh/nefertiti_u0.obj --report out_remesh/u0.json",
                SMP_REMESH_TOOL).status == 0 && fs::exists("out_remesh/nefertiti_u0.obj") && fs::exists("out_remesh/u0.json"),
            "smp-remesh: an OBJ with its report elsewhere");
  int w = 0, h = 0;
  double spread = 0.;
  SMP_CHECK(run(nefertiti + " -n 800 -q -o out_remesh/pictured.off --picture out_remesh/pictured.png --size 200 --up y",
                SMP_REMESH_TOOL).status == 0 && png_facts("out_remesh/pictured.png", w, h, spread) && w == 200 && h == 200 &&
            spread > 10., "smp-remesh: the picture is " << w << " x " << h << ", spread " << spread);
  const std::string out = " -o out_remesh/failed.off";
  check_error("remesh: no vertex count", nefertiti + out, "--vertices", SMP_REMESH_TOOL);
  check_error("remesh: 2 vertices", nefertiti + " -n 2" + out, "--vertices", SMP_REMESH_TOOL);
  check_error("remesh: too few vertices for the border", nefertiti + " -n 4" + out, "border", SMP_REMESH_TOOL);
  check_error("remesh: no output", nefertiti + " -n 100", "-o", SMP_REMESH_TOOL);
  check_error("remesh: output format", nefertiti + " -n 100 -o out_remesh/failed.xyz", ".off", SMP_REMESH_TOOL);
  check_error("remesh: unknown pair", nefertiti + " -n 100 --pair best" + out, "pair", SMP_REMESH_TOOL);
  check_error("remesh: eta out of range", nefertiti + " -n 100 --eta 2" + out, "eta", SMP_REMESH_TOOL);
  check_error("remesh: negative curvature adaptation", nefertiti + " -n 100 --curvature -1" + out, "curvature", SMP_REMESH_TOOL);
  check_error("remesh: curvature adaptation not a number", nefertiti + " -n 100 --curvature nan" + out, "curvature", SMP_REMESH_TOOL);
  check_error("remesh: picture format", nefertiti + " -n 100 --picture out_remesh/failed.jpg" + out, ".png", SMP_REMESH_TOOL);
  check_error("remesh: picture axis", nefertiti + " -n 100 --picture out_remesh/failed.png --up w" + out, "--up", SMP_REMESH_TOOL);
  check_error("remesh: closed mesh", smp_test::data_file("bear.off") + " -n 100" + out, "border", SMP_REMESH_TOOL);
  check_error("remesh: two components", "two.off -n 100" + out, "components", SMP_REMESH_TOOL);
  check_error("remesh: quads", "quads.off -n 100" + out, "triangle", SMP_REMESH_TOOL);
  check_error("remesh: not a polygon mesh", "soup.off -n 100" + out, "non-manifold", SMP_REMESH_TOOL);
  SMP_CHECK(run("soup.off -n 100" + out, SMP_REMESH_TOOL).err.find("--atlas") == std::string::npos,
            "smp-remesh names an option it does not have");
  check_error("remesh: unreadable file", "not_a_mesh.off -n 100" + out, "cannot read", SMP_REMESH_TOOL);
  check_error("remesh: a NaN coordinate", "nan.off -n 100" + out, "nan.off", SMP_REMESH_TOOL);
  std::size_t left = 0;
  for(const auto& e : fs::directory_iterator("out_remesh"))
    left += e.path().filename().string().find("failed") != std::string::npos || e.path().extension() == ".part";
  SMP_CHECK(left == 0, "smp-remesh: " << left << " files left by the failed runs");
}

// The surface renderer is a module loaded at run time: a tool without it stops before it
// writes anything when pictures are asked for, and runs in full without them. A tool's command
// is a launcher of its program (in libexec/ beside it in the build tree): without the program, it
// says so.
void check_missing_renderer()
{
  fs::remove_all("lone");
  fs::create_directories("lone/libexec");
  for(const std::string tool : {std::string(SMP_TOOL), std::string(SMP_REMESH_TOOL)})
    fs::copy_file(tool, fs::path("lone") / fs::path(tool).filename());
  const std::string parameterize = "lone/" + fs::path(SMP_TOOL).filename().string();
  const std::string remesh = "lone/" + fs::path(SMP_REMESH_TOOL).filename().string();
  const std::string nefertiti = smp_test::data_file("nefertiti.off");
  check_error("no program", nefertiti + " --no-pictures -o lone/out", "cannot start", parameterize);
  check_error("remesh: no program", nefertiti + " -n 300 -o lone/remeshed.off", "cannot start", remesh);
  for(const std::string tool : {std::string(SMP_TOOL), std::string(SMP_REMESH_TOOL)}) {
    const fs::path program = fs::path(tool).parent_path() / "libexec" / fs::path(tool).filename();
    fs::copy_file(program, fs::path("lone/libexec") / program.filename());
  }
  check_error("no renderer", nefertiti + " -o lone/out", "renderer", parameterize);
  check_error("no renderer, atlas", nefertiti + " --atlas -o lone/out_atlas", "renderer", parameterize);
  check_error("remesh: no renderer", nefertiti + " -n 300 -o lone/remeshed.off --picture lone/remeshed.png",
              "renderer", remesh);
  SMP_CHECK(!fs::exists("lone/out") && !fs::exists("lone/out_atlas") && !fs::exists("lone/remeshed.off"),
            "a run that had no renderer wrote something");
  SMP_CHECK(run(nefertiti + " -q --no-pictures -o lone/out", parameterize).status == 0 &&
            fs::exists("lone/out/nefertiti.obj"), "no run without the renderer and without pictures");
  SMP_CHECK(run(nefertiti + " -n 300 -q -o lone/remeshed.off", remesh).status == 0 && fs::exists("lone/remeshed.off"),
            "smp-remesh: no run without the renderer and without a picture");
}

// The tools' plain OFF reader gives CGAL's points and polygons, and leaves every other OFF file
// to CGAL's reader (read_soup() then gives what CGAL's reader gives).
void check_plain_off()
{
  typedef std::vector<Kernel::Point_3> Points;
  typedef std::vector<std::vector<std::size_t> > Polygons;
  auto same_as_cgal = [](const std::string& file, bool plain) {
    Points cgal_points, points;
    Polygons cgal_polygons, polygons;
    const bool cgal_read = CGAL::IO::read_polygon_soup(file, cgal_points, cgal_polygons, CGAL::parameters::verbose(false));
    SMP_CHECK(smp_tools::internal::read_plain_off(file, points, polygons) == plain,
              file << (plain ? " is not" : " is") << " read as a plain OFF file");
    std::string error;
    points.clear();
    polygons.clear();
    const bool read = smp_tools::read_soup(file, points, polygons, error);
    SMP_CHECK(!cgal_read || (read && points == cgal_points && polygons == cgal_polygons),
              file << ": not CGAL's points and polygons (" << error << ")");
  };
  for(const auto& entry : fs::directory_iterator(SMP_TEST_DATA_DIR))
    if(entry.path().extension() == ".off")
      same_as_cgal(entry.path().string(), true);

  // variants of a small file: each line as given, with "\n" or "\r\n" line ends
  const std::vector<std::string> plain_lines = {"OFF", "5 3 0", "0 0 0", "1 0 0", "1 1 0", "0 1 0.5",
                                                "0.5 0.5 1e-3", "3 0 1 4", "3 1 2 4", "4 2 3 0 4"};
  auto write = [](const std::string& name, const std::vector<std::string>& lines, const char* end) {
    std::ofstream out(name, std::ios::binary);
    for(const std::string& l : lines) out << l << end;
    return name;
  };
  same_as_cgal(write("plain_lf.off", plain_lines, "\n"), true);
  same_as_cgal(write("plain_crlf.off", plain_lines, "\r\n"), true);
  std::vector<std::string> blank = plain_lines;
  blank.insert(blank.begin() + 2, "");
  blank.insert(blank.begin() + 5, " \t");
  blank.insert(blank.end(), {"", "  "});
  same_as_cgal(write("plain_blank.off", blank, "\n"), true);
  std::vector<std::string> no_edges = plain_lines;
  no_edges[1] = "5 3";
  same_as_cgal(write("plain_no_edges.off", no_edges, "\n"), true);
  // faces that run on over the next lines (OFF is a sequence of numbers; some writers break a
  // face's line), which CGAL's reader refuses: the polygons of the file with one face a line
  std::vector<std::string> split_faces = plain_lines;
  split_faces[7] = "3 0";
  split_faces.insert(split_faces.begin() + 8, {"1", "  4 "});
  split_faces[11] = "4 2 3";
  split_faces.insert(split_faces.end(), {"", "0 4"});
  Points points, split_points;
  Polygons polygons, split_polygons;
  SMP_CHECK(smp_tools::internal::read_plain_off(write("plain_split.off", split_faces, "\n"), split_points, split_polygons) &&
                smp_tools::internal::read_plain_off("plain_lf.off", points, polygons) && split_points == points &&
                split_polygons == polygons,
            "faces split over lines: not the polygons of one face a line");
  // files left to CGAL's reader: another keyword, a comment, colours, a sign, an index out of
  // range, a short face, a short vertex, a line after the last face
  const std::vector<std::pair<std::size_t, std::string> > others = {
    {0, "COFF"}, {1, "5 3 0 # counts"}, {2, "0 0 0 0.5 0.5 0.5 1"}, {3, "+1 0 0"}, {7, "3 0 1 4 255 0 0"},
    {7, "3 0 1 9"}, {9, "4 2 3 0"}, {4, "1 1"}};
  for(std::size_t k = 0; k < others.size(); ++k) {
    std::vector<std::string> lines = plain_lines;
    lines[others[k].first] = others[k].second;
    same_as_cgal(write("other_" + std::to_string(k) + ".off", lines, "\n"), false);
  }
  std::vector<std::string> comment = plain_lines;
  comment.insert(comment.begin() + 2, "# a comment");
  same_as_cgal(write("other_comment.off", comment, "\n"), false);
  std::vector<std::string> trailing = plain_lines;
  trailing.push_back("3 0 1 2");
  same_as_cgal(write("other_trailing.off", trailing, "\n"), false);
}

int main()
{
  check_plain_off();
  check_outputs();
  check_unmapped_component();
  check_errors();
  check_obj_continued_lines();
  check_obj_other_statements();
  check_stl_headers();
  check_ply_triangle_strips();
  check_isolated_vertex();
  check_atlas();
  check_remesh();
  check_missing_renderer();
  return smp_test::summary();
}

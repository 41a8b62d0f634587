// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the tools read a mesh file (OFF, OBJ, PLY, STL: CGAL's readers, by the file's extension;
// a plain ASCII OFF file by read_plain_off(), faster; a PLY file of triangle strips by
// smp_ply_strips.h; an OBJ file's polylines left out, which CGAL's reader refuses),
// shared with the fuzz harness so that it tests what users run. A file that cannot be read
// gives a message, never an exception: an OFF or PLY file is checked first where CGAL 5.5.1's
// readers would misbehave (see check_off() and smp_ply_check.h), and an exception from a reader
// (out of memory included) becomes a message.

#ifndef SMP_TOOLS_SMP_INPUT_H
#define SMP_TOOLS_SMP_INPUT_H

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Surface_mesh.h>

#include "smp_ply_check.h"
#include "smp_ply_strips.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <sstream>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

namespace smp_tools {

namespace internal {

inline std::string lower_extension(const std::string& file)
{
  std::string e = std::filesystem::path(file).extension().string();
  for(char& c : e)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// A whole number of at least 0.
inline bool whole(double x) { return std::isfinite(x) && x >= 0. && x == std::floor(x); }

// A token that is a whole number of at least 0 (as `value`).
inline bool whole_number(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end != token.c_str() && *end == 0 && whole(value);
}

// The tokens of the next line that holds any (comments removed); false at the end.
inline bool next_tokens(std::istream& in, std::vector<std::string>& tokens)
{
  std::string line;
  tokens.clear();
  while(tokens.empty() && std::getline(in, line)) {
    line.erase((std::min)(line.find('#'), line.size()));
    std::istringstream fields(line);
    for(std::string token; fields >> token;)
      tokens.push_back(token);
  }
  return !tokens.empty();
}

// An ASCII OFF file: counts that the file can hold (CGAL reserves them), and face lines (CGAL
// reads one face a line) of whole numbers: a vertex count, then as many vertex indices below
// the number of vertices (CGAL 5.5.1 converts them from double to an unsigned integer without
// a check). What this does not look at, the reader checks.
inline bool check_off(std::istream& in, std::uintmax_t bytes, std::string& error)
{
  // [keyword [dimension, after nOFF]] vertices faces [edges], on whole lines
  std::vector<std::string> header, tokens;
  auto first_count = [&header]() -> std::size_t {
    if(header.empty() || header[0].find("OFF") == std::string::npos)
      return 0;
    return header[0].find('n') != std::string::npos ? 2 : 1;
  };
  while((header.empty() || header.size() < first_count() + 2) && next_tokens(in, tokens))
    header.insert(header.end(), tokens.begin(), tokens.end());
  if(header.size() > 1 && header[1] == "BINARY")
    return true;
  const std::size_t first = first_count();
  double vertices = 0., faces = 0.;
  if(header.size() < first + 2 || !whole_number(header[first], vertices) || !whole_number(header[first + 1], faces)) {
    error = "no OFF header of whole vertex and face counts";
    return false;
  }
  if(vertices + faces > static_cast<double>(bytes)) {
    std::ostringstream m;
    m << "the header announces " << vertices + faces << " elements in " << bytes << " bytes";
    error = m.str();
    return false;
  }
  // the body, in one pass without tokens (it is as long as the file): the vertex lines are
  // only counted, the face lines read as numbers, as CGAL reads them
  std::string line;
  std::vector<double> numbers;
  auto next_line = [&]() {
    while(std::getline(in, line)) {
      line.erase((std::min)(line.find('#'), line.size()));
      if(line.find_first_not_of(" \t\r") != std::string::npos)
        return true;
    }
    return false;
  };
  for(double v = 0.; v < vertices; ++v)
    if(!next_line())
      return true;
  for(double f = 0.; f < faces && next_line(); ++f) {
    numbers.clear();
    const char* at = line.c_str();
    for(char* end = nullptr;; at = end) {
      const double x = std::strtod(at, &end);
      if(end == at)
        break;
      numbers.push_back(x);
    }
    bool ok = !numbers.empty() && whole(numbers[0]) && numbers[0] < double(numbers.size());
    for(std::size_t k = 1; ok && k <= std::size_t(numbers[0]); ++k)
      ok = whole(numbers[k]) && numbers[k] < vertices;
    if(!ok) {
      error = "face " + std::to_string(std::size_t(f)) + " is not a vertex count and as many vertex indices";
      return false;
    }
  }
  return true;
}

// The fields of a line of a plain OFF file: numbers separated by blanks (spaces and tabs).
class Off_line
{
public:
  explicit Off_line(const std::string& line) : at_(line.data()), end_(line.data() + line.size()) {}

  // the next field as a T (finite, for a double); false if it is not one
  template <typename T>
  bool next(T& value)
  {
    skip_blanks();
    const std::from_chars_result r = std::from_chars(at_, end_, value);
    if(r.ec != std::errc() || r.ptr == at_)
      return false;
    at_ = r.ptr;
    if constexpr(std::is_floating_point<T>::value)
      return std::isfinite(value);
    return true;
  }

  // whether only blanks are left
  bool done()
  {
    skip_blanks();
    return at_ == end_;
  }

private:
  void skip_blanks()
  {
    while(at_ != end_ && (*at_ == ' ' || *at_ == '\t')) ++at_;
  }

  const char* at_;
  const char* end_;
};

// The plain ASCII OFF file that most programs write: "OFF" alone on the first line, the vertex,
// face (and edge) counts on the second, then one vertex of three finite coordinates a line and
// one face a line (a count of at least 3, then as many indices of vertices, which may run on
// over the next lines), blank lines anywhere. Read line by line with std::from_chars, it takes
// a fraction of the time of CGAL's reader (whose points and polygons it gives: test_tool checks
// it). Any other file (not
// .off, comments, colours, normals, another keyword, a non-finite coordinate, an index out of
// range, ...) gives false, `points` and `polygons` then unspecified: CGAL's reader reads it.
template <typename Point>
bool read_plain_off(const std::string& file, std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  if(lower_extension(file) != ".off")
    return false;
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  std::ifstream in(file, std::ios::binary);
  if(ec || !in)
    return false;
  std::string line;
  // the next line that is not blank
  auto next_line = [&in, &line]() {
    while(std::getline(in, line)) {
      if(!line.empty() && line.back() == '\r')
        line.pop_back();
      if(!Off_line(line).done())
        return true;
    }
    return false;
  };
  if(!next_line() || line != "OFF" || !next_line())
    return false;
  std::size_t vertices = 0, faces = 0, edges = 0;
  Off_line counts(line);
  if(!counts.next(vertices) || !counts.next(faces) || !(counts.done() || (counts.next(edges) && counts.done())))
    return false;
  if(vertices > bytes || faces > bytes) // each takes a line: the file cannot hold them
    return false;
  points.clear();
  polygons.clear();
  points.reserve(vertices);
  polygons.reserve(faces);
  for(std::size_t v = 0; v < vertices; ++v) {
    double x, y, z;
    if(!next_line())
      return false;
    Off_line fields(line);
    if(!fields.next(x) || !fields.next(y) || !fields.next(z) || !fields.done())
      return false;
    points.emplace_back(x, y, z);
  }
  for(std::size_t f = 0; f < faces; ++f) {
    std::size_t size = 0;
    if(!next_line())
      return false;
    Off_line fields(line);
    if(!fields.next(size) || size < 3 || size > bytes)
      return false;
    // grown as its indices are read: a count is only as good as the indices that follow it
    std::vector<std::size_t> polygon;
    polygon.reserve((std::min)(size, std::size_t(64)));
    for(std::size_t index = 0; polygon.size() < size; polygon.push_back(index)) {
      // a face that runs on over the next lines (OFF is a sequence of numbers; some writers
      // break a face's line) goes on at the next line that is not blank
      while(!fields.next(index)) {
        if(!fields.done() || !next_line())
          return false;
        fields = Off_line(line);
      }
      if(index >= vertices)
        return false;
    }
    if(!fields.done())
      return false;
    polygons.push_back(std::move(polygon));
  }
  return !next_line();
}

// The character after the word "solid" that begins an ASCII STL file (after white space, as
// CGAL's reader skips it), '\n' if the file ends there; '\0' if the file does not begin so.
inline char stl_after_solid(std::istream& in)
{
  char c = ' ';
  while(in.get(c) && std::isspace(static_cast<unsigned char>(c))) {}
  std::string word(1, c);
  for(int i = 0; i < 5 && in.get(c); ++i)
    word.push_back(c);
  if(word.size() == 5 && word == "solid")
    return '\n';
  return word.size() == 6 && word.compare(0, 5, "solid") == 0 && std::isspace(static_cast<unsigned char>(word[5]))
             ? word[5]
             : '\0';
}

// False, with a message, if a binary STL file (one that does not begin with the word "solid")
// announces more triangles than its `bytes` hold: CGAL's reader would read on past them.
inline bool check_stl(std::istream& in, std::uintmax_t bytes, std::string& error)
{
  if(stl_after_solid(in) != '\0' || bytes < 84)
    return true; // ASCII, or a binary file too short for a count, which CGAL's reader refuses
  unsigned char count[4] = {0, 0, 0, 0};
  in.clear();
  in.seekg(80);
  in.read(reinterpret_cast<char*>(count), 4);
  const std::uintmax_t triangles = std::uintmax_t(count[0]) | std::uintmax_t(count[1]) << 8 |
                                   std::uintmax_t(count[2]) << 16 | std::uintmax_t(count[3]) << 24;
  if(84 + 50 * triangles <= bytes)
    return true;
  error = "the binary STL header announces " + std::to_string(triangles) + " triangles, of " +
          std::to_string(84 + 50 * triangles) + " bytes, in " + std::to_string(bytes) + " bytes";
  return false;
}

// False, with a message, if an OFF, PLY or STL file would make CGAL's reader misbehave (see
// check_off(), smp_ply_check.h and check_stl()); other files pass.
inline bool check_before_reading(const std::string& file, std::string& error)
{
  const std::string e = lower_extension(file);
  if(e != ".off" && e != ".ply" && e != ".stl")
    return true;
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  std::ifstream in(file, std::ios::binary);
  if(ec || !in)
    return true; // the reader says what is wrong
  if(e == ".off" ? check_off(in, bytes, error) : e == ".ply" ? check_ply(in, bytes, error) : check_stl(in, bytes, error))
    return true;
  error = "cannot read " + file + ": " + error;
  return false;
}

// The text of an ASCII STL file whose word "solid" is followed by white space other than a space
// or a line's end (a tab, as some writers put before the name), with a space there instead, in
// `text`: CGAL's reader takes such a file for a binary one. False for any other file.
inline bool stl_text_for_cgal(const std::string& file, std::string& text)
{
  if(lower_extension(file) != ".stl")
    return false;
  std::ifstream in(file, std::ios::binary);
  const char after = stl_after_solid(in);
  if(after == '\0' || after == ' ' || after == '\n' || after == '\r')
    return false;
  in.clear();
  in.seekg(0);
  text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  text[text.find("solid") + 5] = ' ';
  return true;
}

// Whether an OBJ statement (by its keyword, the first word of its line) holds no polygon and is
// refused by CGAL's reader: polylines (`l`, as modellers write loose edges), merging groups
// (`mg`) and texture map libraries (`maplib`).
inline bool obj_statement_left_out(const std::string& keyword)
{
  return keyword == "l" || keyword == "mg" || keyword == "maplib";
}

// The text of an OBJ file as CGAL's reader takes it, in `text`: the lines that go on after a
// backslash at their end (as some modellers write long faces) joined, and the statements of
// obj_statement_left_out() emptied (their lines kept, so that lines keep their numbers). False
// if there is nothing to change (or the file cannot be read): CGAL's reader then takes the
// file as it is.
inline bool obj_text_for_cgal(const std::string& file, std::string& text)
{
  if(lower_extension(file) != ".obj")
    return false;
  std::ifstream in(file, std::ios::binary);
  // a first pass looks for a continued line or a statement to leave out, a block at a time
  bool found = false, line_start = true; // line_start: the line's first word is not over yet
  std::string word;
  char last = '\0', before = '\0';
  std::vector<char> block(1 << 16);
  while(!found && in) {
    in.read(block.data(), std::streamsize(block.size()));
    for(std::streamsize i = 0; i < in.gcount() && !found; ++i) {
      const char c = block[std::size_t(i)];
      if(c == '\n') {
        found = (last == '\\' || (last == '\r' && before == '\\')) || (line_start && obj_statement_left_out(word));
        line_start = true;
        word.clear();
      } else if(line_start) {
        if(c == ' ' || c == '\t' || c == '\r') {
          if(!word.empty()) {
            found = obj_statement_left_out(word);
            line_start = false;
          }
        } else if(word.size() < 8) {
          word.push_back(c);
        } else {
          line_start = false;
        }
      }
      before = last;
      last = c;
    }
  }
  if(!found && !(line_start && obj_statement_left_out(word)))
    return false;
  in.clear();
  in.seekg(0);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.clear();
  text.reserve(raw.size());
  // line by line: a continued line joined to the next (its newlines kept at its end, so that the
  // next statement keeps its line number), its first word read
  for(std::size_t i = 0; i < raw.size();) {
    std::string line;
    std::size_t newlines = 0;
    for(; i < raw.size(); ++i) {
      if(raw[i] == '\\') {
        const std::size_t end = i + 1 < raw.size() && raw[i + 1] == '\r' ? i + 2 : i + 1;
        if(end < raw.size() && raw[end] == '\n') {
          line.push_back(' ');
          ++newlines;
          i = end;
          continue;
        }
      }
      if(raw[i] == '\n') {
        ++i;
        ++newlines;
        break;
      }
      line.push_back(raw[i]);
    }
    const std::size_t first = line.find_first_not_of(" \t");
    const std::size_t after = first == std::string::npos ? first : line.find_first_of(" \t\r", first);
    const std::string keyword = first == std::string::npos ? std::string() : line.substr(first, after - first);
    if(!obj_statement_left_out(keyword))
      text += line;
    text.append(newlines, '\n');
  }
  return true;
}

// `bytes` with those that are not printable ASCII (another encoding, a binary file) as \xNN.
inline std::string printable(const std::string& bytes)
{
  static const char hex[] = "0123456789abcdef";
  std::string shown;
  for(const char c : bytes) {
    const unsigned char u = static_cast<unsigned char>(c);
    shown += std::isprint(u) ? std::string(1, c) : std::string("\\x") + hex[u >> 4] + hex[u & 15];
  }
  return shown;
}

// Why CGAL's reader refused the OBJ text `in` (a file, or its text from obj_text_for_cgal(),
// whose lines keep their numbers), from its first statement that is not one of the format's,
// or its first face with an index that is not a vertex's (0, or beyond the vertices: counted
// from 1, from the end if negative), or the want of any face: "line N: ..."; empty if none of
// these is found.
inline std::string obj_read_error(std::istream& in)
{
  static const char* const keywords[] = {
      "v", "vt", "vn", "vp", "f", "l", "p", "o", "g", "s", "mg", "usemtl", "mtllib", "usemap", "maplib",
      "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end",
      "con", "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech",
      "bsp", "bzp", "cdc", "cdp", "res", "surf_1", "q0_1", "q1_1", "curv2d_1", "surf_2", "q0_2", "q1_2", "curv2d_2"};
  std::string line;
  std::size_t number = 0, vertices = 0, faces = 0;
  // (line, index) of the first index beyond the vertices before it (a reference forward, which
  // CGAL's reader takes), and of the largest index: either may be beyond the file's vertices
  std::pair<std::size_t, long long> forward(0, 0), largest(0, 0);
  while(std::getline(in, line)) {
    const std::size_t at = ++number;
    std::istringstream words(line);
    std::string keyword;
    if(!(words >> keyword) || keyword[0] == '#')
      continue;
    if(std::find_if(std::begin(keywords), std::end(keywords), [&keyword](const char* k) { return keyword == k; }) ==
       std::end(keywords))
      return "line " + std::to_string(at) + ": '" + printable(keyword.substr(0, 32)) +
             "' is not a statement of the OBJ format";
    if(keyword == "v") {
      ++vertices;
    } else if(keyword == "f") {
      ++faces;
      std::string corner;
      while(words >> corner) {
        long long index = 0;
        const std::string digits = corner.substr(0, corner.find('/'));
        const auto parsed = std::from_chars(digits.data(), digits.data() + digits.size(), index);
        if(parsed.ec != std::errc() || parsed.ptr != digits.data() + digits.size())
          return "line " + std::to_string(at) + ": the face corner '" + printable(corner.substr(0, 32)) +
                 "' has no vertex index";
        if(index == 0 || (index < 0 && -(index + 1) >= static_cast<long long>(vertices))) // -index > vertices
          return "line " + std::to_string(at) + ": the face index " + digits + " is not that of a vertex";
        if(index > 0 && forward.first == 0 && std::size_t(index) > vertices)
          forward = {at, index};
        if(index > largest.second)
          largest = {at, index};
      }
    }
  }
  for(const auto& beyond : {forward, largest})
    if(beyond.second > 0 && std::size_t(beyond.second) > vertices)
      return "line " + std::to_string(beyond.first) + ": the face index " + std::to_string(beyond.second) +
             " is beyond the file's " + std::to_string(vertices) + " vertices";
  if(faces == 0)
    return "no polygon: no face statement (f) among its " + std::to_string(number) + " lines";
  return std::string();
}

// The polygons of `file`: a plain OFF file read by read_plain_off(), any other by CGAL's reader
// once check_before_reading() lets it (an OBJ file with continued lines, joined first; a PLY
// file of triangle strips, in which CGAL finds no polygon, by smp_ply_strips.h); an exception
// becomes false and a message.
template <typename Point>
bool read_polygons(const std::string& file, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons, std::string& error)
{
  try {
    if(read_plain_off(file, points, polygons))
      return true;
    points.clear();
    polygons.clear();
    if(!check_before_reading(file, error))
      return false;
    std::string text;
    bool read = false;
    if(obj_text_for_cgal(file, text)) {
      std::istringstream in(text);
      read = CGAL::IO::read_OBJ(in, points, polygons, CGAL::parameters::verbose(false));
    } else if(stl_text_for_cgal(file, text)) {
      std::istringstream in(text);
      read = CGAL::IO::read_STL(in, points, polygons, CGAL::parameters::verbose(false));
    } else {
      read = CGAL::IO::read_polygon_soup(file, points, polygons, CGAL::parameters::verbose(false));
    }
    // CGAL's reader takes an index 0 (and makes it one beyond the points)
    const auto outside = [&points](const std::vector<std::size_t>& polygon) {
      return std::any_of(polygon.begin(), polygon.end(), [&points](std::size_t v) { return v >= points.size(); });
    };
    if(lower_extension(file) == ".obj" && (!read || std::any_of(polygons.begin(), polygons.end(), outside))) {
      // the text CGAL's reader was given: a continued line is one there
      std::istringstream joined(text);
      std::ifstream original(file, std::ios::binary);
      const std::string why = obj_read_error(text.empty() ? static_cast<std::istream&>(original) : joined);
      if(!why.empty())
        error = "cannot read " + file + ": " + why;
      return false;
    }
    if(read && polygons.empty() && lower_extension(file) == ".ply" && ply_has_triangle_strips(file))
      return read_ply_triangle_strips(file, points, polygons, error);
    return read;
  } catch(const std::bad_alloc&) {
    error = "out of memory while reading " + file;
  } catch(const std::exception& e) {
    error = "cannot read " + file + ": " + e.what();
  }
  return false;
}

} // namespace internal

// The polygons of `file`, as they are (no repair). False, with a message, if none can be read.
template <typename Point>
bool read_soup(const std::string& file, std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons,
               std::string& error)
{
  const bool ok = internal::read_polygons(file, points, polygons, error);
  if(ok && !polygons.empty())
    return true;
  if(error.empty())
    error = ok ? file + " holds no polygon (" + std::to_string(points.size()) + " points)" : "cannot read polygons from " + file;
  return false;
}

// The polygon mesh of `file`, without its isolated vertices (CGAL's parameterization wants a
// valid polygon mesh, and a vertex of no face has nothing to map); `isolated` receives how
// many were removed. False, with a message, if it is not a polygon mesh (or has no face);
// `soup_hint` ends the message of a soup that is not a mesh (what the calling tool offers).
// Read as a soup whose indices are checked, then made a mesh: CGAL 5.5.1's read_polygon_mesh()
// reads past its array of points for an index out of range.
template <typename Point>
bool read_mesh(const std::string& file, CGAL::Surface_mesh<Point>& mesh, std::string& error, std::size_t& isolated,
               const std::string& soup_hint = "")
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  isolated = 0;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!read_soup(file, points, polygons, error))
    return false;
  for(const auto& polygon : polygons)
    for(std::size_t v : polygon)
      if(v >= points.size()) {
        error = "cannot read " + file + ": a face has a vertex index out of range";
        return false;
      }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    error = "cannot read a polygon mesh from " + file +
            " (a soup with non-manifold edges, or an inconsistent orientation" + soup_hint + ")";
    return false;
  }
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  isolated = PMP::remove_isolated_vertices(mesh);
  if(isolated > 0)
    mesh.collect_garbage();
  return true;
}

} // namespace smp_tools

#endif // SMP_TOOLS_SMP_INPUT_H

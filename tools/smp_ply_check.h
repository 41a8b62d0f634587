// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef SMP_TOOLS_SMP_PLY_CHECK_H
#define SMP_TOOLS_SMP_PLY_CHECK_H

// What the tools check in a PLY file before CGAL 5.5.1's reader reads it, where that reader
// would misbehave: counts in the header that the file cannot hold (it reserves them, and skips
// the items of an element it does not read one by one), a property before any element, a
// header with no end (it then reads the body from the stream's end, counts of values it never
// read), and lists whose count the rest of the file cannot hold (it resizes a list to its count
// before reading its items, so that a file of a few bytes can make it fill gigabytes).

#include <cstdint>
#include <cstdlib>
#include <istream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace smp_tools {
namespace internal {

// How one property of a PLY element that CGAL reads is stored: a scalar of `bytes` bytes, or a
// list of items of `bytes` bytes after an integer count of `count_bytes` bytes (signed or not).
struct Ply_property_layout
{
  bool list = false;
  int count_bytes = 0;
  bool count_signed = false;
  int bytes = 0;
};

struct Ply_element_layout
{
  std::uintmax_t count = 0;
  std::vector<Ply_property_layout> properties;
};

// How a PLY scalar type is stored: its bytes (0 if CGAL does not know it), whether it is signed
// and whether it is an integer.
struct Ply_type
{
  int bytes = 0;
  bool is_signed = false;
  bool integer = false;
};

inline Ply_type ply_type(const std::string& name)
{
  struct Named { const char* name; Ply_type type; };
  static const Named types[] = {
      {"char", {1, true, true}},     {"int8", {1, true, true}},     {"uchar", {1, false, true}},
      {"uint8", {1, false, true}},   {"short", {2, true, true}},    {"int16", {2, true, true}},
      {"ushort", {2, false, true}},  {"uint16", {2, false, true}},  {"int", {4, true, true}},
      {"int32", {4, true, true}},    {"uint", {4, false, true}},    {"uint32", {4, false, true}},
      {"float", {4, true, false}},   {"float32", {4, true, false}}, {"double", {8, true, false}},
      {"float64", {8, true, false}}};
  for(const Named& t : types)
    if(name == t.name)
      return t.type;
  return Ply_type();
}

// The lists of the body of a PLY file (from `in`'s position; `left` bytes), as laid out by
// `elements`: false, with a message, if a list announces more items than the rest of the file
// can hold (or a negative number of them). Stops without complaint where the file ends early:
// the reader says what is wrong there.
inline bool check_ply_lists(std::istream& in, std::uintmax_t left, bool ascii, bool big_endian,
                            const std::vector<Ply_element_layout>& elements, std::string& error)
{
  const std::uintmax_t body = left;
  auto refuse = [&](double count) {
    std::ostringstream m;
    m << "a PLY list announces " << count << " items in a body of " << body << " bytes";
    error = m.str();
    return false;
  };
  std::istreambuf_iterator<char> at(in), end;
  std::string token;
  auto space = [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; };
  auto next_token = [&](bool keep) { // false at the end of the file; `token` holds it if `keep`
    token.clear();
    while(at != end && space(*at)) ++at;
    if(at == end) return false;
    for(; at != end && !space(*at); ++at)
      if(keep) token.push_back(*at);
    return true;
  };
  auto skip_bytes = [&](std::uintmax_t n) {
    if(n > left) return false;
    for(std::uintmax_t k = 0; k < n; ++k) ++at;
    left -= n;
    return true;
  };
  for(const Ply_element_layout& element : elements) {
    bool scalars_only = true;
    std::uintmax_t item_bytes = 0;
    for(const Ply_property_layout& p : element.properties) {
      scalars_only = scalars_only && !p.list;
      item_bytes += std::uintmax_t(p.bytes);
    }
    if(scalars_only && !ascii) { // nothing to check: skipped whole
      if(item_bytes > 0 && element.count > left / item_bytes) return true;
      if(!skip_bytes(element.count * item_bytes)) return true;
      continue;
    }
    for(std::uintmax_t item = 0; item < element.count; ++item)
      for(const Ply_property_layout& p : element.properties) {
        double count = 0.;
        if(ascii) {
          if(!next_token(p.list)) return true;
          if(!p.list) continue;
          char* stop = nullptr;
          count = std::strtod(token.c_str(), &stop);
          if(stop == token.c_str()) return true;
          if(!(count >= 0.) || count > double(body)) return refuse(count);
          for(double k = 0.; k < count; ++k)
            if(!next_token(false)) return true;
          continue;
        }
        if(!p.list) {
          if(!skip_bytes(std::uintmax_t(p.bytes))) return true;
          continue;
        }
        if(left < std::uintmax_t(p.count_bytes)) return true;
        std::uint64_t bits = 0;
        for(int k = 0; k < p.count_bytes; ++k, ++at) {
          const std::uint64_t byte = static_cast<unsigned char>(*at);
          bits |= byte << (8 * (big_endian ? p.count_bytes - 1 - k : k));
        }
        left -= std::uintmax_t(p.count_bytes);
        const bool negative = p.count_signed && (bits >> (8 * p.count_bytes - 1)) != 0;
        if(negative) return refuse(-1.);
        if(bits > left / std::uint64_t(p.bytes)) return refuse(double(bits));
        if(!skip_bytes(bits * std::uint64_t(p.bytes))) return true;
      }
  }
  return true;
}

// A PLY header, then its body's lists (see check_ply_lists()). Read as CGAL reads it: the
// signature and the format on the first two lines, whatever they hold, then one keyword a line
// up to end_header.
inline bool check_ply(std::istream& in, std::uintmax_t bytes, std::string& error)
{
  std::string line, format;
  double announced = 0.;
  bool element = false, ended = false;
  std::vector<Ply_element_layout> elements;
  for(int number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line);
    std::string word, name;
    std::size_t count = 0; // read as CGAL reads it: "-1" is the largest count
    if(number == 2)
      fields >> word >> format;
    if(number <= 2 || !(fields >> word))
      continue;
    if(word == "end_header") {
      ended = true;
      break;
    }
    if(word == "element") {
      element = true;
      elements.emplace_back();
      if(fields >> name >> count) {
        announced += double(count);
        elements.back().count = count;
      }
    } else if(word == "property" && !element) {
      error = "a PLY property comes before any element";
      return false;
    } else if(word == "property") {
      // CGAL reads only the properties of a known type (and lists of an integer count): the
      // others take no byte of the body
      Ply_property_layout p;
      std::string type, name, item_type;
      if(!(fields >> type >> name))
        continue;
      if(type == "list" && fields >> item_type) {
        const Ply_type count = ply_type(name);
        if(!count.integer)
          continue;
        p.list = true;
        p.count_bytes = count.bytes;
        p.count_signed = count.is_signed;
        p.bytes = ply_type(item_type).bytes;
      } else if(type != "list") {
        p.bytes = ply_type(type).bytes;
      }
      if(p.bytes > 0)
        elements.back().properties.push_back(p);
    }
  }
  if(announced > static_cast<double>(bytes)) {
    std::ostringstream m;
    m << "the header announces " << announced << " elements in " << bytes << " bytes";
    error = m.str();
    return false;
  }
  if(!ended) { // CGAL's reader would read the body from a stream at its end: counts it never read
    error = "the PLY header has no end_header line";
    return false;
  }
  const bool ascii = format == "ascii", big_endian = format == "binary_big_endian";
  if(!(ascii || big_endian || format == "binary_little_endian"))
    return true;
  const std::streamoff header = in.tellg();
  if(header < 0 || std::uintmax_t(header) > bytes)
    return true;
  return check_ply_lists(in, bytes - std::uintmax_t(header), ascii, big_endian, elements, error);
}

} // namespace internal
} // namespace smp_tools

#endif // SMP_TOOLS_SMP_PLY_CHECK_H

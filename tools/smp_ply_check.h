// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef SMP_TOOLS_SMP_PLY_CHECK_H
#define SMP_TOOLS_SMP_PLY_CHECK_H

// What the tools check in a PLY file before CGAL 5.5.1's reader reads it, where that reader
// would misbehave: counts in the header that the file cannot hold (it reserves them, and skips
// the items of an element it does not read one by one), a property before any element, a
// header with no end, a body that ends early or an ASCII value that its stream fails to read (it
// then reads on from a failed stream: values it never wrote, as counts of lists too), and lists
// whose count the rest of the file cannot hold (it resizes a list to its count before reading
// its items, so that a file of a few bytes can make it fill gigabytes).

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <istream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace smp_tools {
namespace internal {

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

// How one property of a PLY element that CGAL reads is stored: a value of type `item`, or, for a
// list, an integer count of type `count` then that many values of type `item`.
struct Ply_property_layout
{
  bool list = false;
  Ply_type count, item;
};

struct Ply_element_layout
{
  std::uintmax_t count = 0;
  std::vector<Ply_property_layout> properties;
};

// The value of the ASCII token `token` read as CGAL's reader reads a value of type `type` into
// `value`; false if that read would fail (then the reader's stream is failed, and every later
// value it reads is a variable never written: a list's count among them). An integer: digits
// after an optional sign (no sign for an unsigned type), within the range of the type, or of a
// short for a byte, which CGAL reads as a short and narrows. A floating point number: the
// characters the standard reader takes, the whole token, finite.
inline bool ply_ascii_value(const std::string& token, const Ply_type& type, double& value)
{
  if(token.empty())
    return false;
  char* stop = nullptr;
  if(type.integer) {
    const std::size_t digits = token[0] == '+' || token[0] == '-' ? 1 : 0;
    if(digits == token.size() || token.find_first_not_of("0123456789", digits) != std::string::npos ||
       (!type.is_signed && token[0] == '-'))
      return false;
    value = std::strtod(token.c_str(), &stop);
    const int bits = 8 * (type.bytes < 2 ? 2 : type.bytes);
    const double high = type.is_signed ? std::ldexp(1., bits - 1) - 1. : std::ldexp(1., bits) - 1.;
    const double low = type.is_signed ? -std::ldexp(1., bits - 1) : 0.;
    return value >= low && value <= high;
  }
  if(token.find_first_not_of("0123456789+-.eE") != std::string::npos)
    return false;
  value = std::strtod(token.c_str(), &stop);
  return stop == token.c_str() + token.size() && std::isfinite(value);
}

// The body of a PLY file (from `in`'s position; `left` bytes), as laid out by `elements`: false,
// with a message, if it ends before its elements do, if a list announces more items than the
// rest of the file can hold (or a negative number of them), or if an ASCII value is not one
// CGAL's reader reads as a value of its type (see ply_ascii_value()). In each of these cases
// CGAL 5.5.1's reader would read values it never wrote, as counts of lists too.
inline bool check_ply_body(std::istream& in, std::uintmax_t left, bool ascii, bool big_endian,
                           const std::vector<Ply_element_layout>& elements, std::string& error)
{
  const std::uintmax_t body = left;
  auto refuse = [&](double count) {
    std::ostringstream m;
    m << "a PLY list announces " << count << " items in a body of " << body << " bytes";
    error = m.str();
    return false;
  };
  auto ends_early = [&]() {
    error = "the PLY body ends before its elements do";
    return false;
  };
  std::istreambuf_iterator<char> at(in), end;
  std::string token;
  auto not_a_value = [&]() {
    std::string shown;
    for(char c : token.substr(0, 24)) shown.push_back(c > ' ' && c < 127 ? c : '?');
    error = "a PLY value that is not a number of its type: '" + shown + "'";
    return false;
  };
  auto space = [](char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; };
  auto next_token = [&]() { // false at the end of the file
    token.clear();
    while(at != end && space(*at)) ++at;
    if(at == end) return false;
    for(; at != end && !space(*at); ++at)
      token.push_back(*at);
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
      item_bytes += std::uintmax_t(p.item.bytes);
    }
    if(scalars_only && !ascii) { // nothing to check but its size: skipped whole
      if(item_bytes > 0 && element.count > left / item_bytes) return ends_early();
      skip_bytes(element.count * item_bytes);
      continue;
    }
    for(std::uintmax_t item = 0; item < element.count; ++item)
      for(const Ply_property_layout& p : element.properties) {
        if(ascii) {
          double value = 0.;
          if(!next_token()) return ends_early();
          if(!ply_ascii_value(token, p.list ? p.count : p.item, value)) return not_a_value();
          if(!p.list) continue;
          if(p.count.bytes == 1) // CGAL narrows what it read to the count's type
            value = p.count.is_signed ? double(std::int8_t(int(value))) : double(std::uint8_t(int(value)));
          if(!(value >= 0.) || value > double(body)) return refuse(value);
          for(double k = 0.; k < value; ++k) {
            if(!next_token()) return ends_early();
            double item_value = 0.;
            if(!ply_ascii_value(token, p.item, item_value)) return not_a_value();
          }
          continue;
        }
        if(!p.list) {
          if(!skip_bytes(std::uintmax_t(p.item.bytes))) return ends_early();
          continue;
        }
        if(left < std::uintmax_t(p.count.bytes)) return ends_early();
        std::uint64_t bits = 0;
        for(int k = 0; k < p.count.bytes; ++k, ++at) {
          const std::uint64_t byte = static_cast<unsigned char>(*at);
          bits |= byte << (8 * (big_endian ? p.count.bytes - 1 - k : k));
        }
        left -= std::uintmax_t(p.count.bytes);
        const bool negative = p.count.is_signed && (bits >> (8 * p.count.bytes - 1)) != 0;
        if(negative) return refuse(-1.);
        if(bits > left / std::uint64_t(p.item.bytes)) return refuse(double(bits));
        skip_bytes(bits * std::uint64_t(p.item.bytes));
      }
  }
  return true;
}

// A PLY header, then its body (see check_ply_body()). Read as CGAL reads it: the
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
        p.list = true;
        p.count = ply_type(name);
        p.item = ply_type(item_type);
        if(!p.count.integer)
          continue;
      } else if(type != "list") {
        p.item = ply_type(type);
      }
      if(p.item.bytes > 0)
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
  return check_ply_body(in, bytes - std::uintmax_t(header), ascii, big_endian, elements, error);
}

} // namespace internal
} // namespace smp_tools

#endif // SMP_TOOLS_SMP_PLY_CHECK_H

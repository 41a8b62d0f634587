// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "render.h"

#include <cairo.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>

namespace smp_tools {

namespace {

// Writes `surface` to `file` through a temporary name, so that a failure never leaves a PNG
// that looks complete.
bool write_png_atomically(cairo_surface_t* surface, const std::string& file)
{
  const std::string temporary = file + ".part";
  if(cairo_surface_write_to_png(surface, temporary.c_str()) == CAIRO_STATUS_SUCCESS &&
     std::rename(temporary.c_str(), file.c_str()) == 0)
    return true;
  std::remove(temporary.c_str());
  return false;
}

} // namespace

bool write_rgba_png(const std::string& file, const std::vector<unsigned char>& rgba, int width, int height)
{
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  if(cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    return false;
  cairo_surface_flush(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for(int y = 0; y < height; ++y) {
    const unsigned char* src = &rgba[std::size_t(height - 1 - y) * width * 4];
    std::uint32_t* dst = reinterpret_cast<std::uint32_t*>(data + std::size_t(y) * stride);
    for(int x = 0; x < width; ++x) // opaque, so premultiplication changes nothing
      dst[x] = 0xff000000u | (std::uint32_t(src[4 * x]) << 16) | (std::uint32_t(src[4 * x + 1]) << 8) | src[4 * x + 2];
  }
  cairo_surface_mark_dirty(surface);
  const bool ok = write_png_atomically(surface, file);
  cairo_surface_destroy(surface);
  return ok;
}

std::array<double, 3> stretch_color(double s)
{
  if(!(s > 0.) || !std::isfinite(s))
    return {0., 0., 0.};
  // position on a log scale: 0 at stretch 1, 1/3 at about 1.6, 2/3 at about 2.5, 1 at 4 and above
  const double t = std::clamp(std::log(std::max(s, 1.)) / std::log(4.), 0., 1.);
  static const double stops[4][3] = {{0.45, 0.65, 0.90}, {0.95, 0.90, 0.55}, {0.95, 0.50, 0.15}, {0.55, 0.05, 0.05}};
  const double x = t * 3.;
  const int i = std::min(int(x), 2);
  const double f = x - i;
  return {stops[i][0] * (1 - f) + stops[i + 1][0] * f, stops[i][1] * (1 - f) + stops[i + 1][1] * f,
          stops[i][2] * (1 - f) + stops[i + 1][2] * f};
}

bool write_checkerboard_png(const std::string& file, int size, int checks)
{
  // two colours: an image of palette indices, a fraction of the bytes of RGBA to compress (it
  // is written on every run, pictures or not, as the texture of the OBJ)
  std::vector<unsigned char> index(std::size_t(size) * std::size_t(size));
  for(int y = 0; y < size; ++y) // PNG rows go top to bottom
    for(int x = 0; x < size; ++x)
      index[std::size_t(y) * std::size_t(size) + std::size_t(x)] = checker_is_dark(x, size - 1 - y, size, checks);
  const std::array<unsigned char, 3> light = checker_color(false), dark = checker_color(true);
  const unsigned char palette[6] = {light[0], light[1], light[2], dark[0], dark[1], dark[2]};
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(size);
  image.height = png_uint_32(size);
  image.format = PNG_FORMAT_RGB_COLORMAP;
  image.colormap_entries = 2;
  const std::string temporary = file + ".part";
  const bool ok = png_image_write_to_file(&image, temporary.c_str(), 0, index.data(), size, palette) != 0;
  png_image_free(&image);
  if(ok && std::rename(temporary.c_str(), file.c_str()) == 0)
    return true;
  std::remove(temporary.c_str());
  return false;
}

std::array<double, 3> chart_color(int chart)
{
  // hues a golden angle apart, a lighter and a darker shade in turn
  const double h = std::fmod(0.618033988749895 * double(chart), 1.) * 6., v = chart % 2 ? 0.95 : 0.75, s = 0.55;
  const int i = int(h) % 6;
  const double f = h - std::floor(h), p = v * (1. - s), q = v * (1. - s * f), t = v * (1. - s * (1. - f));
  switch(i) {
    case 0: return {v, t, p};
    case 1: return {q, v, p};
    case 2: return {p, v, t};
    case 3: return {p, q, v};
    case 4: return {t, p, v};
    default: return {v, p, q};
  }
}

bool write_uv_layout_png(const std::string& file, const Textured_mesh& mesh, int size, bool by_chart)
{
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size, size);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  // fit the uv bounding box, y up
  double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
  for(const auto& f : mesh.corner_uv)
    for(const auto& q : f) {
      xmin = std::min(xmin, q[0]); xmax = std::max(xmax, q[0]);
      ymin = std::min(ymin, q[1]); ymax = std::max(ymax, q[1]);
    }
  const double margin = 0.04 * size, extent = std::max(xmax - xmin, ymax - ymin);
  const double scale = extent > 0. ? (size - 2 * margin) / extent : 1.;
  auto px = [&](const std::array<double, 2>& q) { return margin + (q[0] - xmin) * scale; };
  auto py = [&](const std::array<double, 2>& q) { return size - margin - (q[1] - ymin) * scale; };
  const bool edges = mesh.faces.size() < 20000; // edges of dense meshes would only darken the picture
  cairo_set_line_width(cr, 0.25);
  for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& q = mesh.corner_uv[f];
    cairo_move_to(cr, px(q[0]), py(q[0]));
    cairo_line_to(cr, px(q[1]), py(q[1]));
    cairo_line_to(cr, px(q[2]), py(q[2]));
    cairo_close_path(cr);
    const auto c = by_chart && f < mesh.face_chart.size() ? chart_color(mesh.face_chart[f])
                 : stretch_color(f < mesh.face_stretch.size() ? mesh.face_stretch[f] : 1.);
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    if(edges) {
      cairo_fill_preserve(cr);
      cairo_set_source_rgba(cr, 0, 0, 0, 0.35);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  }
  cairo_destroy(cr);
  const bool ok = write_png_atomically(surface, file);
  cairo_surface_destroy(surface);
  return ok;
}

} // namespace smp_tools

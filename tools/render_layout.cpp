// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The pictures of render.h drawn with Cairo, in the renderer's module (render_surface.cpp) with
// the surface renderer: Cairo and the libraries it brings (fontconfig, freetype, X11's) are then
// loaded only by the runs that draw pictures.

#include "render.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

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

// write_uv_layout_png() of render.h
bool draw_uv_layout_png(const std::string& file, const Textured_mesh& mesh, int size, bool by_chart)
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

} // namespace smp_tools

// The module's entry point for the uv layouts, looked up by name (an unmangled C name).
extern "C" __attribute__((visibility("default"))) smp_tools::Write_uv_layout_function smp_tools_write_uv_layout_png()
{
  return &smp_tools::draw_uv_layout_png;
}

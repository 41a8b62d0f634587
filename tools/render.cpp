// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include "render.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace smp_tools {

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

} // namespace smp_tools

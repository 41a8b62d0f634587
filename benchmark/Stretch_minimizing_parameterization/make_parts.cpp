// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes a mesh of many separate small parts, as game assets and CAD models have: PARTS curved
// patches of 3 x 3 vertices (8 triangles each), of random sizes (a fixed seed: the same file
// every time), side by side in rows of 100. For the atlas's packing of thousands of charts
// (scripts/compare-xatlas.sh):
//
//   make_parts PARTS OUT

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <random>
#include <vector>

int main(int argc, char** argv)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  const long parts = argc == 3 ? std::atol(argv[1]) : 0;
  if(parts <= 0) {
    std::cerr << "usage: make_parts PARTS OUT" << std::endl;
    return 2;
  }
  std::mt19937 random(1);
  std::uniform_real_distribution<double> side(0.3, 1.5), bump(0.05, 0.1);
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  for(long p = 0; p < parts; ++p) {
    const double x0 = 3. * double(p % 100), y0 = 3. * double(p / 100);
    const double sx = side(random), sy = side(random);
    const std::size_t first = points.size();
    for(int j = 0; j < 3; ++j)
      for(int i = 0; i < 3; ++i) // a bowl: height growing with the distance to the middle vertex
        points.emplace_back(x0 + 0.5 * i * sx, y0 + 0.5 * j * sy, bump(random) * double((i - 1) * (i - 1) + (j - 1) * (j - 1)));
    for(std::size_t j = 0; j < 2; ++j)
      for(std::size_t i = 0; i < 2; ++i) {
        const std::size_t a = first + 3 * j + i;
        triangles.push_back({a, a + 1, a + 4});
        triangles.push_back({a, a + 4, a + 3});
      }
  }
  if(!CGAL::IO::write_polygon_soup(argv[2], points, triangles, CGAL::parameters::stream_precision(17))) {
    std::cerr << "make_parts: cannot write " << argv[2] << std::endl;
    return 1;
  }
  return 0;
}

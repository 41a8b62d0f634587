// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Pictures of a parameterized triangle mesh, written as PNG: the uv layout coloured by stretch
// (Cairo), the checkerboard texture itself, and the surface rendered off-screen (OSMesa, Mesa's
// software OpenGL) with the checkerboard or with a stretch colour map. Kept free of CGAL so that
// it compiles fast in a translation unit of its own. What Cairo or OSMesa draws lives in a
// module of its own (render_layout.cpp, render_surface.cpp), loaded on first use: OSMesa brings
// LLVM and Cairo a dozen libraries, whose loading would otherwise cost every run of the tools,
// pictures or not, a noticeable startup time. The checkerboard is written with libpng alone.

#ifndef SMP_TOOLS_RENDER_H
#define SMP_TOOLS_RENDER_H

#include <array>
#include <string>
#include <vector>

namespace smp_tools {

// A triangle soup with one uv per face corner (seams and charts need several uv per vertex).
struct Textured_mesh
{
  std::vector<std::array<double, 3> > xyz;         // vertex positions
  std::vector<std::array<int, 3> > faces;          // vertex indices
  std::vector<std::array<std::array<double, 2>, 3> > corner_uv; // uv per face corner
  std::vector<double> face_stretch;                // normalized L2 stretch per face (<= 0: degenerate)
  std::vector<int> face_chart;                     // chart per face (an atlas), or empty
};

// Colour of a stretch value: 1 (no stretch) is blue, 1.6 pale yellow, 2.5 orange, 4 and above
// dark red; degenerate faces (value <= 0 or not finite) are black.
std::array<double, 3> stretch_color(double stretch);

// Writes RGBA rows stored bottom-up (OpenGL's order) as an opaque PNG. False on failure (nothing
// is left then). In the module only (render_layout.cpp).
bool write_rgba_png(const std::string& file, const std::vector<unsigned char>& rgba, int width, int height);

// The checkerboard of the texture, `checks` squares a side on `size` x `size` texels: whether
// texel (x, y), y counted upwards (uv (0, 0) at the bottom left, in a light square), is dark.
inline bool checker_is_dark(int x, int y, int size, int checks)
{
  return ((x * checks / size) + (y * checks / size)) % 2 == 1;
}

// The RGB colour of a light or a dark square of the checkerboard.
inline std::array<unsigned char, 3> checker_color(bool dark)
{
  return dark ? std::array<unsigned char, 3>{{40, 60, 120}} : std::array<unsigned char, 3>{{235, 235, 225}};
}

// Writes a size x size checkerboard with `checks` squares per side. Returns false on failure.
bool write_checkerboard_png(const std::string& file, int size, int checks);

// Colour of a chart: neighbouring numbers get distant hues.
std::array<double, 3> chart_color(int chart);

// Draws the uv layout in the unit square, faces filled by stretch colour, or by chart colour if
// `by_chart` (and `mesh.face_chart` is given). False on failure, or if the module that draws it
// cannot be loaded (see load_surface_renderer()).
bool write_uv_layout_png(const std::string& file, const Textured_mesh& mesh, int size, bool by_chart = false);

// Renders the surface with model axis `up` (0: x, 1: y, 2: z) upwards, seen from `yaw` degrees
// around it (at 0 the viewer is on the -y side of the model for z up, on the +z side otherwise)
// and `pitch` degrees above, either textured by the checkerboard (`checks` per unit of uv) or
// coloured by stretch (light grey without `mesh.face_stretch`), with the triangles' edges drawn
// if `edges`. Returns an empty string on success, else what went wrong (the module that renders
// could not be loaded, for one).
std::string render_surface_png(const std::string& file, const Textured_mesh& mesh, int width, int height,
                               int up, double yaw, double pitch, bool checkerboard, int checks, bool edges = false);

// Loads the module that draws the uv layouts and renders the surfaces if it is not yet loaded:
// an empty string if it is there, else why not. The tools call it before they start, so that a
// missing module stops them before they write anything.
std::string load_surface_renderer();

// The signature of render_surface_png(), which the module exports as
// `smp_tools_render_surface_png` (render_surface.cpp).
typedef std::string (*Render_surface_function)(const std::string&, const Textured_mesh&, int, int, int, double,
                                               double, bool, int, bool);

// The signature of write_uv_layout_png(), which the module exports as
// `smp_tools_write_uv_layout_png` (render_layout.cpp).
typedef bool (*Write_uv_layout_function)(const std::string&, const Textured_mesh&, int, bool);

} // namespace smp_tools

#endif // SMP_TOOLS_RENDER_H

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The surface renderer of render.h, built as a module that the tools load on first use
// (render_module.cpp), so that OSMesa and LLVM are loaded only by the runs that draw pictures.

#include "render.h"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

namespace {

using namespace smp_tools;

struct Vec { double x, y, z; };
Vec operator-(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec cross(const Vec& a, const Vec& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

std::string render_surface(const std::string& file, const Textured_mesh& mesh, int width, int height, int up,
                           double yaw, double pitch, bool checkerboard, int checks, bool edges)
{
  std::vector<unsigned char> buffer(std::size_t(width) * height * 4);
  std::unique_ptr<std::remove_pointer<OSMesaContext>::type, void (*)(OSMesaContext)> context(
    OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr), OSMesaDestroyContext);
  if(!context)
    return "cannot create an OSMesa context";
  if(!OSMesaMakeCurrent(context.get(), buffer.data(), GL_UNSIGNED_BYTE, width, height))
    return "cannot bind the OSMesa buffer";

  // centre and radius of the model
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(const auto& p : mesh.xyz)
    for(int i = 0; i < 3; ++i) { lo[i] = std::min(lo[i], p[i]); hi[i] = std::max(hi[i], p[i]); }
  const double c[3] = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  double radius = 0.;
  for(const auto& p : mesh.xyz)
    radius = std::max(radius, std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2])));
  if(!(radius > 0.))
    return "the mesh has no extent";

  // smooth normals: area-weighted face normals summed at the vertices
  std::vector<Vec> normal(mesh.xyz.size(), Vec{0, 0, 0});
  for(const auto& f : mesh.faces) {
    const Vec a{mesh.xyz[f[0]][0], mesh.xyz[f[0]][1], mesh.xyz[f[0]][2]};
    const Vec b{mesh.xyz[f[1]][0], mesh.xyz[f[1]][1], mesh.xyz[f[1]][2]};
    const Vec d{mesh.xyz[f[2]][0], mesh.xyz[f[2]][1], mesh.xyz[f[2]][2]};
    const Vec n = cross(b - a, d - a);
    for(int v : f) { normal[v].x += n.x; normal[v].y += n.y; normal[v].z += n.z; }
  }

  glViewport(0, 0, width, height);
  glClearColor(0.94f, 0.94f, 0.94f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double aspect = double(width) / height, near_plane = radius, far_plane = 5. * radius;
  const double half = 0.42 * near_plane; // field of view that frames the sphere at distance 2.6 r
  glFrustum(-half * aspect, half * aspect, -half, half, near_plane, far_plane);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const GLfloat light_position[4] = {0.3f, 0.5f, 1.f, 0.f}; // in eye space: from the viewer
  const GLfloat ambient[4] = {0.35f, 0.35f, 0.35f, 1.f}, diffuse[4] = {0.75f, 0.75f, 0.75f, 1.f};
  glLightfv(GL_LIGHT0, GL_POSITION, light_position);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glTranslated(0, 0, -2.6 * radius);
  glRotated(pitch, 1, 0, 0);
  glRotated(yaw, 0, 1, 0);
  if(up == 2)      // z up, -y towards the viewer
    glRotated(-90, 1, 0, 0);
  else if(up == 0) // x up, +z towards the viewer
    glRotated(90, 0, 0, 1);
  glTranslated(-c[0], -c[1], -c[2]);

  GLuint texture = 0;
  if(checkerboard) {
    const int size = 512;
    std::vector<unsigned char> texels(std::size_t(size) * size * 3);
    for(int y = 0; y < size; ++y)
      for(int x = 0; x < size; ++x) {
        const std::array<unsigned char, 3> color = checker_color(checker_is_dark(x, y, size, checks));
        std::copy(color.begin(), color.end(), &texels[(std::size_t(y) * size + x) * 3]);
      }
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
  }

  if(edges) { // the faces pushed back, so that their edges are drawn over them
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.f, 1.f);
  }
  glBegin(GL_TRIANGLES);
  for(std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if(checkerboard) {
      glColor3d(1, 1, 1);
    } else if(mesh.face_stretch.empty()) {
      glColor3d(0.85, 0.85, 0.82);
    } else {
      const auto col = stretch_color(f < mesh.face_stretch.size() ? mesh.face_stretch[f] : 1.);
      glColor3d(col[0], col[1], col[2]);
    }
    for(int k = 0; k < 3; ++k) {
      const int v = mesh.faces[f][k];
      if(checkerboard)
        glTexCoord2d(mesh.corner_uv[f][k][0], mesh.corner_uv[f][k][1]);
      glNormal3d(normal[v].x, normal[v].y, normal[v].z);
      glVertex3d(mesh.xyz[v][0], mesh.xyz[v][1], mesh.xyz[v][2]);
    }
  }
  glEnd();
  if(edges) {
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHTING);
    glColor3d(0.15, 0.15, 0.2);
    glBegin(GL_LINES);
    for(const auto& f : mesh.faces)
      for(int k = 0; k < 3; ++k)
        for(int v : {f[k], f[(k + 1) % 3]})
          glVertex3d(mesh.xyz[v][0], mesh.xyz[v][1], mesh.xyz[v][2]);
    glEnd();
  }
  glFinish();
  if(texture != 0)
    glDeleteTextures(1, &texture);
  if(glGetError() != GL_NO_ERROR)
    return "OpenGL reported an error";
  if(!write_rgba_png(file, buffer, width, height))
    return "cannot write " + file;
  return std::string();
}

} // namespace

// The module's one entry point: the renderer, looked up by name (an unmangled C name).
extern "C" __attribute__((visibility("default"))) smp_tools::Render_surface_function smp_tools_render_surface_png()
{
  return &render_surface;
}

// Copyright (c) 2026 The Stretch_minimizing_parameterization authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// render_surface_png() and write_uv_layout_png() of render.h: load the renderer module
// (render_surface.cpp, render_layout.cpp) on first use. The module is looked for beside the
// executable (the build tree), then where the install puts it relative to the executable, then
// by the dynamic loader's own search.

#include "render.h"

#include <dlfcn.h>

#include <filesystem>
#include <system_error>

namespace smp_tools {

namespace {

struct Loaded_renderer
{
  Render_surface_function render = nullptr;
  Write_uv_layout_function layout = nullptr;
  std::string error;
};

Loaded_renderer load_renderer()
{
  Loaded_renderer result;
  std::error_code ec;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
  std::vector<std::string> candidates;
  if(!ec) {
    candidates.push_back((executable.parent_path() / SMP_RENDER_MODULE).string());
    candidates.push_back((executable.parent_path() / SMP_RENDER_MODULE_FROM_PROGRAM / SMP_RENDER_MODULE).string());
  }
  candidates.push_back(SMP_RENDER_MODULE);
  for(const std::string& file : candidates) {
    if(&file != &candidates.back() && !std::filesystem::exists(file, ec))
      continue;
    void* module = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if(module == nullptr) {
      const char* why = dlerror();
      if(result.error.empty()) // the first failure says most (a library the module needs, say)
        result.error = "cannot load the surface renderer: " + std::string(why ? why : file);
      continue;
    }
    typedef Render_surface_function (*Render_entry)();
    typedef Write_uv_layout_function (*Layout_entry)();
    const Render_entry render = reinterpret_cast<Render_entry>(dlsym(module, "smp_tools_render_surface_png"));
    const Layout_entry layout = reinterpret_cast<Layout_entry>(dlsym(module, "smp_tools_write_uv_layout_png"));
    if(render == nullptr || layout == nullptr) {
      if(result.error.empty())
        result.error = file + " is not the surface renderer (no smp_tools_render_surface_png or smp_tools_write_uv_layout_png)";
      dlclose(module);
      continue;
    }
    result.render = render(); // the module stays loaded until the process ends
    result.layout = layout();
    result.error.clear();
    return result;
  }
  return result;
}

const Loaded_renderer& renderer()
{
  static const Loaded_renderer loaded = load_renderer();
  return loaded;
}

} // namespace

std::string load_surface_renderer()
{
  return renderer().error;
}

std::string render_surface_png(const std::string& file, const Textured_mesh& mesh, int width, int height,
                               int up, double yaw, double pitch, bool checkerboard, int checks, bool edges)
{
  if(renderer().render == nullptr)
    return renderer().error;
  return renderer().render(file, mesh, width, height, up, yaw, pitch, checkerboard, checks, edges);
}

bool write_uv_layout_png(const std::string& file, const Textured_mesh& mesh, int size, bool by_chart)
{
  return renderer().layout != nullptr && renderer().layout(file, mesh, size, by_chart);
}

} // namespace smp_tools

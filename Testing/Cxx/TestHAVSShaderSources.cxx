/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSShaderSources.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// Every generated shader source is valid GLSL, checked with glslangValidator
// (Khronos' reference compiler) — also the interlock path, which needs a GPU
// with fragment-shader interlock to run (NVIDIA) and so cannot be rendered
// here. The framebuffer-fetch draw shader is not checked this way
// (glslang does not know EXT_shader_framebuffer_fetch on desktop GL); Mesa
// compiles it in every rendering test. Negative control: a broken source must
// be rejected, so that a missing or permissive validator cannot pass the test.
#include "havsTestChecks.h"
#include "havsTestImages.h"

#include "vtkHAVSShaders.h"
#include "vtkHAVSVolumeMapper.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace
{
bool Validate(const std::string& source, const std::string& name, const std::string& stage)
{
  const std::string path = havstest::OutputDir() + "/" + name + "." + stage;
  std::ofstream(path) << source;
  const std::string command = "glslangValidator " + path + " > " + path + ".log 2>&1";
  const bool ok = std::system(command.c_str()) == 0;
  if (!ok)
  {
    std::ifstream log(path + ".log");
    std::cerr << name << ":\n" << log.rdbuf() << std::endl;
  }
  return ok;
}
}

int TestHAVSShaderSources(int, char*[])
{
  if (!havstest::Check(std::system("glslangValidator --version > /dev/null 2>&1") == 0,
        "glslangValidator is installed (Debian package glslang-tools)"))
  {
    return EXIT_FAILURE;
  }
  havstest::Check(!Validate("#version 450 core\nvoid main() { undefined(); }\n", "broken", "frag"),
    "negative control: a broken shader is rejected");

  int checked = 0;
  auto check = [&](const std::string& source, const std::string& name, const char* stage)
  {
    havstest::Check(Validate(source, name, stage), name + " compiles");
    ++checked;
  };
  check(vtkHAVSShaders::FaceVertexShader(), "face", "vert");
  check(vtkHAVSShaders::QuadVertexShader(), "quad", "vert");
  check(vtkHAVSShaders::ListDrawShader(), "list_draw", "frag");
  check(vtkHAVSShaders::ExtremumDrawShader(), "extremum_draw", "frag");
  check(vtkHAVSShaders::ExtremumResolveShader(), "extremum_resolve", "frag");
  check(vtkHAVSShaders::CompositeShader(), "composite", "frag");
  check(vtkHAVSShaders::CoverageVertexShader(), "coverage", "vert");
  check(vtkHAVSShaders::CoverageShader(), "coverage", "frag");
  // The table's compute shader at the smallest and the largest table (1 and
  // 1023 intervals: its shared memory at the 32 KB GL guarantees).
  check(vtkHAVSShaders::TableComputeShader(1, 64), "table_1", "comp");
  check(vtkHAVSShaders::TableComputeShader(1023, 64), "table_1023", "comp");
  check(vtkHAVSShaders::CellProjectionVertexShader(), "cell_projection", "vert");
  check(vtkHAVSShaders::CellProjectionShader(false), "cell_projection", "frag");
  check(vtkHAVSShaders::CellProjectionShader(true), "cell_projection_opaque", "frag");
  check(vtkHAVSShaders::RayCastPeelShader(), "ray_cast_peel", "frag");
  check(vtkHAVSShaders::RayCastShader(false), "ray_cast", "frag");
  check(vtkHAVSShaders::RayCastShader(true), "ray_cast_opaque", "frag");
  for (int blend : { 1, 2, 4 })
  {
    check(
      vtkHAVSShaders::RayCastShader(true, blend), "ray_cast_blend" + std::to_string(blend), "frag");
  }
  check(vtkHAVSShaders::RayCastTileVertexShader(), "ray_cast_tile", "vert");
  for (int blend : { 1, 2, 4 })
  {
    check(vtkHAVSShaders::CellProjectionShader(true, blend),
      "cell_projection_blend" + std::to_string(blend), "frag");
  }
  check(vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFragmentLists, 1, true),
    "list_resolve_vote", "frag");
  check(vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFragmentLists, 1, false),
    "list_resolve", "frag");
  for (int k : { 1, 2, 3, 6, 13, 14 })
  {
    check(vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFramebufferFetch, k, false),
      "fetch_resolve_k" + std::to_string(k), "frag");
  }
  for (int k : { 1, 2, 3, 6, 14, 15, 32, 64 })
  {
    const std::string suffix = "_k" + std::to_string(k);
    check(vtkHAVSShaders::InterlockDrawShader(k, vtkHAVSShaders::InterlockARB),
      "interlock_draw" + suffix, "frag");
    check(vtkHAVSShaders::InterlockClearShader(k), "interlock_clear" + suffix, "frag");
    check(vtkHAVSShaders::ResolveShader(
            vtkHAVSVolumeMapper::KBufferPathFragmentShaderInterlock, k, false),
      "interlock_resolve" + suffix, "frag");
  }
  // Every combination of the per-fragment features compiled in or out
  // (counter, tagging, opaque cut), on each path's draw and resolve (the
  // framebuffer-fetch draw is not checked: glslangValidator has no
  // EXT_shader_framebuffer_fetch for desktop GLSL; it shares the library).
  for (int mask = 0; mask < 8; ++mask)
  {
    vtkHAVSShaders::Features f;
    f.CountViolations = (mask & 1) != 0;
    f.Tagging = (mask & 2) != 0;
    f.Opaque = (mask & 4) != 0;
    const std::string suffix = "_features" + std::to_string(mask);
    check(
      vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFramebufferFetch, 2, false, f),
      "fetch_resolve" + suffix, "frag");
    check(vtkHAVSShaders::InterlockDrawShader(6, vtkHAVSShaders::InterlockARB, f),
      "interlock_draw" + suffix, "frag");
    check(vtkHAVSShaders::ListDrawShader(f), "list_draw" + suffix, "frag");
    check(vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFragmentLists, 1, true, f),
      "list_resolve" + suffix, "frag");
  }
  // Cell scalars (vtkHAVSCellOptics: the segments, the extremum resolve and
  // the additive blend read the cell optics) on every pass that has them.
  {
    vtkHAVSShaders::Features f;
    f.CellScalars = true;
    check(vtkHAVSShaders::ExtremumResolveShader(true), "extremum_resolve_cells", "frag");
    check(vtkHAVSShaders::ExtremumDrawShader(f), "extremum_draw_cells", "frag");
    for (int blend : { 0, 1, 2, 4 })
    {
      const std::string suffix = "_cells_blend" + std::to_string(blend);
      check(vtkHAVSShaders::CellProjectionShader(true, blend, true), "cell_projection" + suffix,
        "frag");
      check(vtkHAVSShaders::RayCastShader(true, blend, true), "ray_cast" + suffix, "frag");
    }
    for (int k : { 2, 6 })
    {
      const std::string suffix = "_cells_k" + std::to_string(k);
      check(vtkHAVSShaders::InterlockDrawShader(k, vtkHAVSShaders::InterlockARB, f),
        "interlock_draw" + suffix, "frag");
      check(vtkHAVSShaders::ResolveShader(
              vtkHAVSVolumeMapper::KBufferPathFramebufferFetch, k, false, f),
        "fetch_resolve" + suffix, "frag");
    }
    check(vtkHAVSShaders::ListDrawShader(f), "list_draw_cells", "frag");
    check(vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFragmentLists, 1, true, f),
      "list_resolve_cells", "frag");
  }
  // The isosurfaces (the blend, the mixed mode), unshaded and shaded: the
  // cell mappers' (fields) and HAVS's fragment lists (gradients in the
  // entries, the face vertex shader's gradient attribute).
  for (int iso : { 1, 2 })
  {
    for (bool shade : { false, true })
    {
      const std::string suffix = "_iso" + std::to_string(iso) + (shade ? "_shaded" : "");
      check(vtkHAVSShaders::CellProjectionShader(true, 0, false, 1, iso, shade),
        "cell_projection" + suffix, "frag");
      check(
        vtkHAVSShaders::RayCastShader(true, 0, false, 2, iso, shade), "ray_cast" + suffix, "frag");
      vtkHAVSShaders::Features f;
      f.IsoSurfaces = iso;
      f.IsoShade = shade ? 2 : 0;
      check(vtkHAVSShaders::ListDrawShader(f), "list_draw" + suffix, "frag");
      check(
        vtkHAVSShaders::ResolveShader(vtkHAVSVolumeMapper::KBufferPathFragmentLists, 1, true, f),
        "list_resolve" + suffix, "frag");
    }
  }
  check(vtkHAVSShaders::FaceVertexShader(false, true), "face_shaded", "vert");
  // The features left out are really out of the source (no fetch, no atomic).
  vtkHAVSShaders::Features none;
  none.CountViolations = none.Tagging = none.Opaque = false;
  const std::string lean = vtkHAVSShaders::FetchDrawShader(2, none);
  havstest::Check(lean.find("#define HAVS_COUNT_VIOLATIONS 0") != std::string::npos &&
      lean.find("#define HAVS_TAGGING 0") != std::string::npos &&
      lean.find("#define HAVS_OPAQUE 0") != std::string::npos,
    "a shader without the features says so in its defines");
  std::cout << checked << " shader sources checked with glslangValidator" << std::endl;
  return havstest::Result();
}

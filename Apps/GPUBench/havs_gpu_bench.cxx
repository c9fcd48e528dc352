/*=========================================================================

  Project:   vtkHAVS
  Module:    havs_gpu_bench.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench: the mappers' frames on a GPU, with no VTK (issues 16, 47).
//
//   havs_gpu_bench CASE_DIR... [--frames N] [--paths NAMES] [--control]
//                  [--max-difference D] [--csv FILE] [--save-images DIR]
//
// Reads frame cases (README.md beside this file: written by
// `havs_benchmark --dump-case DIR`, their large arrays made again by
// havs_gpu_cases where the case was carried without them), makes an OpenGL
// 4.5 core context through EGL (the device platform, else Mesa's surfaceless
// one, else the default display; libEGL is opened at run time, every GL
// function comes from eglGetProcAddress, so the program needs nothing but a
// driver) and draws each case through every path its mapper has on this GPU:
//   - HAVS: framebuffer fetch, the fragment-shader interlock (ARB or NV; on
//     llvmpipe, which shades a pixel's fragments in primitive order, its
//     layout without a guard), fragment lists;
//   - the cell projection: its cells in the exact visibility order;
//   - the ray caster: peel and cast;
// and the trivial shader of the raster bound of the same faces; a table case
// (mapper table): the pre-integrated table's compute build, against the CPU's
// (havsGPUTable.cxx). Prints per
// path the median frame time (clear, draw, resolve), the draw alone, tets/s,
// fragments/s, the ratio to the raster bound, and the image's error against
// the mapper's own float result (where captured: --max-difference, default
// 2/255) and against the exact reference stored with the case (MISSION.md's
// bound: RMSE < 5e-4, max < 0.01, folded pixels left out and counted). A path
// that misses either fails the run; a path this GPU cannot run is reported as
// not run, never as passed. --control draws each part's wrong order (README.md):
// its images must then miss. --save-images DIR writes each path's float image
// (RGBA, bottom row first) as DIR/<case>_<path number>.f32.
#include "havsGPUBench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace
{
using namespace havsgpu;

/// An image's error against another (RMSE and max over the RGBA components).
struct Error
{
  bool Known = false;
  double RMSE = 0, Max = 0;
  long long LeftOut = 0; ///< pixels left out (folded)
};

Error Compare(const std::vector<float>& image, const std::vector<float>& truth,
  const std::vector<uint8_t>& folded, size_t pixels)
{
  Error e;
  if (truth.size() != 4 * pixels || image.size() != 4 * pixels)
  {
    return e;
  }
  e.Known = true;
  double sum = 0;
  size_t counted = 0;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (p < folded.size() && folded[p])
    {
      ++e.LeftOut;
      continue;
    }
    for (int k = 0; k < 4; ++k)
    {
      const float v = image[4 * p + k];
      const double d = std::isfinite(v) ? std::abs(v - truth[4 * p + k]) : 1e30;
      sum += d * d;
      e.Max = std::max(e.Max, d);
    }
    counted += 4;
  }
  e.RMSE = std::sqrt(sum / std::max<size_t>(1, counted));
  return e;
}

struct Timing
{
  double Frame = 0, Draw = 0;
  unsigned long long Fragments = 0;
  Error VsMapper, VsExact;
};

Timing Run(const Case& c, Path& p, int frames, const std::string& saveAs)
{
  Timing t;
  GLuint query = 0;
  gl.GenQueries(1, &query);
  std::vector<double> frame, draw;
  for (int f = -2; f < frames; ++f) // two warm-up frames
  {
    gl.Finish();
    const double t0 = Now();
    p.Clear();
    gl.Finish();
    const double t1 = Now();
    if (f == 0)
    {
      gl.BeginQuery(GL_SAMPLES_PASSED, query);
    }
    p.Draw();
    if (f == 0)
    {
      gl.EndQuery(GL_SAMPLES_PASSED);
    }
    gl.Finish();
    const double t2 = Now();
    p.Resolve();
    gl.Finish();
    const double t3 = Now();
    if (f >= 0)
    {
      frame.push_back(t3 - t0);
      draw.push_back(t2 - t1);
    }
  }
  GLuint64 samples = 0;
  gl.GetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
  t.Fragments = samples;
  t.Frame = Median(frame);
  t.Draw = Median(draw);
  if (p.Image)
  {
    const std::vector<float> image = p.Image();
    if (!saveAs.empty())
    {
      std::ofstream(saveAs, std::ios::binary)
        .write(reinterpret_cast<const char*>(image.data()),
          static_cast<std::streamsize>(image.size() * sizeof(float)));
    }
    const size_t pixels = static_cast<size_t>(c.Width) * c.Height;
    t.VsMapper = Compare(image, c.Result, {}, pixels);
    t.VsExact = Compare(image, c.Exact, c.Folded, pixels);
  }
  return t;
}

std::string Figure(const Error& e, bool rmse)
{
  if (!e.Known)
  {
    return "-";
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.2e", rmse ? e.RMSE : e.Max);
  return text;
}

/// One case: its paths made, run, reported; the number of failures.
int RunCase(const std::string& path, const Options& o, const Device& device, std::ofstream* csv)
{
  std::string dir = path;
  while (dir.size() > 1 && dir.back() == '/')
  {
    dir.pop_back();
  }
  const std::string name = dir.substr(dir.find_last_of('/') + 1);
  Case c;
  if (!ReadCase(dir, c))
  {
    return 1;
  }
  if (c.Mapper == "table")
  {
    return RunTableCase(c, o, csv);
  }
  Paths paths;
  bool made = false;
  if (c.Mapper == "havs")
    made = MakeKBufferPaths(c, o, device, paths);
  else if (c.Mapper == "cellprojection")
    made = MakeCellProjectionPaths(c, o, device, paths);
  else if (c.Mapper == "raycast")
    made = MakeRayCastPaths(c, o, device, paths);
  else
    Fail("unknown mapper '" + c.Mapper + "' in " + dir);
  std::printf("\n## %s: %s, %d x %d, %lld tetrahedra, table %d x %d x %d%s%s%s\n", name.c_str(),
    c.Mapper.c_str(), c.Width, c.Height, c.Cells, c.TableSize[0], c.TableSize[1], c.TableSize[2],
    c.Keys.count("k") ? (", k = " + c.Keys["k"]).c_str() : "",
    c.Exact.empty() ? ", NO exact reference stored" : "",
    o.Control ? ", CONTROL (README.md: must fail)" : "");
  if (!made)
  {
    std::printf("FAILED: the case's paths could not be made\n");
    return 1;
  }
  gl.Disable(GL_DEPTH_TEST);
  gl.Disable(GL_BLEND);
  gl.Disable(GL_CULL_FACE);
  gl.Disable(GL_SCISSOR_TEST);
  gl.Viewport(0, 0, c.Width, c.Height);

  std::vector<Timing> timings;
  double rasterDraw = 0;
  for (Path& p : paths.Run)
  {
    std::string saveAs;
    if (!o.SaveImages.empty())
    {
      saveAs = o.SaveImages + "/" + name + "_" + std::to_string(&p - paths.Run.data()) + ".f32";
      std::printf("image of %s: %s\n", p.Name.c_str(), saveAs.c_str());
    }
    timings.push_back(Run(c, p, o.Frames, saveAs));
    if (p.RasterBound)
    {
      rasterDraw = timings.back().Draw;
    }
  }
  std::printf("\n| path | frame ms (median of %d) | draw ms | Mtets/s | Mfragments/s | × raster "
              "bound | RMSE vs mapper | max vs mapper | RMSE vs exact | max vs exact | verdict "
              "|\n|---|---|---|---|---|---|---|---|---|---|---|\n",
    o.Frames);
  int failures = 0;
  for (size_t i = 0; i < paths.Run.size(); ++i)
  {
    const Path& p = paths.Run[i];
    const Timing& t = timings[i];
    char ratio[32] = "-";
    if (rasterDraw > 0 && !p.RasterBound)
    {
      std::snprintf(ratio, sizeof(ratio), "%.2f", t.Frame / rasterDraw);
    }
    std::string verdict = "timed";
    if (p.Image)
    {
      const bool mapperOk = !t.VsMapper.Known || t.VsMapper.Max <= o.MaxDifference;
      const bool exactOk = !t.VsExact.Known || (t.VsExact.RMSE < 5e-4 && t.VsExact.Max < 0.01);
      verdict = mapperOk && exactOk ? (t.VsExact.Known ? "exact" : "as the mapper (no reference)")
                                    : (exactOk ? "FAILED (mapper)" : "FAILED (exact bound)");
      failures += mapperOk && exactOk ? 0 : 1;
    }
    std::printf("| %s | %.2f | %.2f | %.2f | %.1f | %s | %s | %s | %s | %s | %s |\n",
      p.Name.c_str(), 1e3 * t.Frame, 1e3 * t.Draw, 1e-6 * c.Cells / std::max(1e-9, t.Draw),
      1e-6 * t.Fragments / std::max(1e-9, t.Draw), ratio, Figure(t.VsMapper, true).c_str(),
      Figure(t.VsMapper, false).c_str(), Figure(t.VsExact, true).c_str(),
      Figure(t.VsExact, false).c_str(), verdict.c_str());
    if (csv)
    {
      *csv << name << "," << c.Mapper << "," << c.Width << "," << c.Keys["k"] << ",\"" << p.Name
           << "\"," << 1e3 * t.Frame << "," << 1e3 * t.Draw << "," << c.Cells << "," << t.Fragments
           << "," << (t.VsMapper.Known ? t.VsMapper.RMSE : NAN) << ","
           << (t.VsMapper.Known ? t.VsMapper.Max : NAN) << ","
           << (t.VsExact.Known ? t.VsExact.RMSE : NAN) << ","
           << (t.VsExact.Known ? t.VsExact.Max : NAN) << "," << t.VsExact.LeftOut << "," << verdict
           << "," << (o.Control ? 1 : 0) << "\n";
      csv->flush();
    }
  }
  if (c.Keys.count("havs_table_resolution"))
  {
    // The case was made with the settings of the thesis' Table 4.3.
    std::printf("beside: Callahan's thesis, Table 4.3 (HAVS, 512², 128³ table, early ray "
                "termination off, GPU time only): 1.1 to 3.4 M tets/s\n");
  }
  if (!c.Folded.empty() && !timings.empty())
  {
    std::printf("left out of the exact comparison: %lld pixels whose rays cross folded cells\n",
      timings.front().VsExact.LeftOut);
  }
  for (const std::string& s : paths.NotRun)
  {
    std::printf("not run on this GPU: %s\n", s.c_str());
  }
  const GLenum error = gl.GetError();
  if (error != GL_NO_ERROR)
  {
    std::printf("GL error 0x%x\n", error);
    ++failures;
  }
  std::printf("%s\n",
    failures == 0 ? "every path drew the exact image"
                  : "FAILED: a path's image misses the bound (or a GL error)");
  return failures;
}
}

int main(int argc, char* argv[])
{
  if (argc < 2 || argv[1][0] == '-')
  {
    std::printf("usage: havs_gpu_bench CASE_DIR... [--frames N] [--paths NAMES] [--control] "
                "[--max-difference D] [--csv FILE] [--save-images DIR]\n  NAMES: any of fetch, "
                "interlock, lists, "
                "raster, cells, rays (default: all)\n");
    return argc < 2 ? EXIT_FAILURE : EXIT_SUCCESS;
  }
  Options o;
  std::vector<std::string> dirs;
  std::string csvPath;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--frames")
      o.Frames = std::max(1, std::atoi(next().c_str()));
    else if (a == "--paths")
      o.Paths = next();
    else if (a == "--control" || a == "--reverse-order")
      o.Control = true;
    else if (a == "--max-difference")
      o.MaxDifference = std::atof(next().c_str());
    else if (a == "--csv")
      csvPath = next();
    else if (a == "--save-images")
      o.SaveImages = next();
    else if (!a.empty() && a[0] == '-')
    {
      std::fprintf(stderr, "havs_gpu_bench: unknown option %s\n", a.c_str());
      return EXIT_FAILURE;
    }
    else
      dirs.push_back(a);
  }
  Device device;
  const bool context = MakeContext(device);
  for (const std::string& d : device.Diagnostics)
  {
    std::printf("EGL: %s\n", d.c_str());
  }
  if (!context)
  {
    std::printf("FAILED: no OpenGL 4.3 core context through EGL (above: what was tried)\n");
    return EXIT_FAILURE;
  }
  std::printf("GPU: %s (%s), OpenGL %s; EGL %s %s on %s%s\n", device.Renderer.c_str(),
    device.Vendor.c_str(), device.Version.c_str(), device.EGLVendor.c_str(),
    device.EGLVersion.c_str(), device.Platform.c_str(),
    device.EGLDevice.empty() ? "" : (" (" + device.EGLDevice + ")").c_str());
  std::printf("paths this GPU offers: framebuffer fetch %s, ARB interlock %s, NV interlock %s, "
              "fragment lists yes (GL 4.3)%s\n",
    device.Fetch ? "yes" : "no", device.InterlockARB ? "yes" : "no",
    device.InterlockNV ? "yes" : "no",
    device.Llvmpipe ? "; llvmpipe: the interlock layout runs without a guard" : "");
  std::ofstream csv;
  if (!csvPath.empty())
  {
    const bool exists = std::ifstream(csvPath).good();
    csv.open(csvPath, std::ios::app);
    if (!exists)
    {
      csv << "case,mapper,size,k,path,frame_ms,draw_ms,tets,fragments,rmse_mapper,max_mapper,"
             "rmse_exact,max_exact,folded_px,verdict,control\n";
    }
  }
  int failures = 0;
  for (const std::string& dir : dirs)
  {
    failures += RunCase(dir, o, device, csvPath.empty() ? nullptr : &csv);
  }
  std::printf("\n%s\n",
    failures == 0 ? "havs_gpu_bench: every path of every case drew the exact image"
                  : "havs_gpu_bench: FAILED");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

/*=========================================================================

  Project:   vtkHAVS
  Module:    havsGPUTable.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// havs_gpu_bench's table cases (issue 45): vtkHAVSGLTableBuilder's compute
// pass on its own, with no VTK, from the inputs havs_gpu_cases made.
#include "havsGPUBench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace havsgpu
{

int RunTableCase(const Case& c, const Options& o, std::ofstream* csv)
{
  const std::string name = c.Dir.substr(c.Dir.find_last_of('/') + 1);
  const int ns = c.TableSize[0], nl = c.TableSize[2];
  std::vector<float> samples, steps, layers, cpu;
  std::vector<int32_t> tableSamples;
  if (!ReadArray(c.Dir + "/samples.f32", samples) || !ReadArray(c.Dir + "/steps.f32", steps) ||
    !ReadArray(c.Dir + "/table_samples.i32", tableSamples) ||
    !ReadArray(c.Dir + "/layers.f32", layers) || !ReadArray(c.Dir + "/table.f32", cpu) ||
    static_cast<int>(tableSamples.size()) != ns || static_cast<int>(layers.size()) != nl ||
    cpu.size() != static_cast<size_t>(ns) * ns * nl * 4)
  {
    std::printf("FAILED: %s: the table case's inputs (havs_gpu_cases makes them) are missing or "
                "of other sizes\n",
      name.c_str());
    return 1;
  }
  if (o.Control)
  {
    // The functions mirrored: sample k becomes fineCount - 1 - k.
    const int fine = static_cast<int>(samples.size() / 4);
    std::vector<float> mirrored(samples.size());
    for (int k = 0; k < fine; ++k)
    {
      std::copy_n(&samples[4 * (fine - 1 - k)], 4, &mirrored[4 * k]);
    }
    samples.swap(mirrored);
    std::reverse(steps.begin(), steps.end());
    std::vector<int32_t> flipped(ns);
    for (int i = 0; i < ns; ++i)
    {
      flipped[i] = fine - 1 - tableSamples[ns - 1 - i];
    }
    tableSamples.swap(flipped);
  }
  const GLuint program = ComputeProgram(c, "table.comp");
  if (!program)
  {
    std::printf("FAILED: %s: the table's compute shader\n", name.c_str());
    return 1;
  }
  const GLuint buffers[4] = { Buffer(GL_SHADER_STORAGE_BUFFER, samples),
    Buffer(GL_SHADER_STORAGE_BUFFER, steps), Buffer(GL_SHADER_STORAGE_BUFFER, tableSamples),
    Buffer(GL_SHADER_STORAGE_BUFFER, layers) };
  for (GLuint i = 0; i < 4; ++i)
  {
    gl.BindBufferBase(GL_SHADER_STORAGE_BUFFER, i, buffers[i]);
  }
  GLuint texture = 0;
  gl.GenTextures(1, &texture);
  gl.BindTexture(GL_TEXTURE_3D, texture);
  gl.TexStorage3D(GL_TEXTURE_3D, 1, GL_RGBA32F, ns, ns, nl);
  gl.BindImageTexture(0, texture, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl.UseProgram(program);
  GLuint queries[2];
  gl.GenQueries(2, queries);
  std::vector<double> compute, gpu;
  for (int f = -1; f < o.Frames; ++f) // one warm-up build
  {
    gl.Finish();
    const double t0 = Now();
    gl.QueryCounter(queries[0], GL_TIMESTAMP);
    gl.DispatchCompute(static_cast<GLuint>(ns), static_cast<GLuint>(nl), 2);
    gl.QueryCounter(queries[1], GL_TIMESTAMP);
    gl.Finish();
    const double t1 = Now();
    GLuint64 begin = 0, end = 0;
    gl.GetQueryObjectui64v(queries[0], GL_QUERY_RESULT, &begin);
    gl.GetQueryObjectui64v(queries[1], GL_QUERY_RESULT, &end);
    if (f >= 0)
    {
      compute.push_back(t1 - t0);
      gpu.push_back(1e-9 * static_cast<double>(end - begin));
    }
  }
  gl.MemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
  std::vector<float> built(cpu.size());
  const double r0 = Now();
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.GetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_FLOAT, built.data());
  const double read = Now() - r0;
  double largest = 0.0;
  for (size_t i = 0; i < built.size(); ++i)
  {
    const double d = std::fabs(static_cast<double>(built[i]) - cpu[i]);
    largest = std::max(largest, std::isfinite(d) ? d : INFINITY);
  }
  const double bound = 5e-6;
  const bool equal = largest <= bound;
  const double cpuMs = std::atof(ReadText(c.Dir + "/cpu_table_ms.txt").c_str());
  const double wallMs = 1e3 * Median(compute), gpuMs = 1e3 * Median(gpu);
  std::printf("\n## %s: table %d x %d x %d, %zu fine samples%s\n", name.c_str(), ns, ns, nl,
    samples.size() / 4, o.Control ? ", CONTROL (the functions mirrored: must fail)" : "");
  std::printf("| build | ms (median of %d) | GPU ms (timer query) | read back ms | CPU build ms "
              "(havs_gpu_cases) | CPU / GPU | largest difference from the CPU's | verdict |\n"
              "|---|---|---|---|---|---|---|---|\n",
    o.Frames);
  const std::string verdict = o.Control ? (equal ? "FAILED (control equal)" : "control misses")
                                        : (equal ? "equal" : "FAILED (differs)");
  std::printf("| compute shader | %.3f | %.3f | %.3f | %.2f | %.2f | %.2e (bound %.0e) | %s |\n",
    wallMs, gpuMs, 1e3 * read, cpuMs, cpuMs / std::max(1e-9, wallMs), largest, bound,
    verdict.c_str());
  if (csv)
  {
    *csv << name << ",table," << ns << ",,\"table compute\"," << wallMs << "," << gpuMs << ","
         << static_cast<long long>(ns) * ns * nl << ",0,nan," << largest << ",nan,nan,0," << verdict
         << "," << (o.Control ? 1 : 0) << "\n";
    csv->flush();
  }
  gl.DeleteQueries(2, queries);
  gl.UseProgram(0);
  gl.BindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl.DeleteTextures(1, &texture);
  gl.DeleteBuffers(4, buffers);
  gl.DeleteProgram(program);
  const GLenum error = gl.GetError();
  if (error != GL_NO_ERROR)
  {
    std::printf("GL error 0x%x\n", error);
    return 1;
  }
  // (A control that misses fails the run, as the frames' controls do:
  // run_gpu_bundle.sh counts one that passes as the failure.)
  return equal ? 0 : 1;
}
}

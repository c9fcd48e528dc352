/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLFrameCapture.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLFrameCapture
 * @brief   Writes what the GPU drew in one frame, for the stand-alone GPU program.
 *
 * A benchmark aid (vtkHAVSMapperBase::SetCaptureDirectory, the
 * benchmark's `--dump-case DIR`): after a frame drawn through the
 * framebuffer-fetch or the interlock k-buffer, writes into a directory
 * (the format: Apps/GPUBench/README.md)
 *
 *   case.txt        size, k, counts, table size, facing, and every active
 *                   uniform of the draw program ("uniform draw NAME TYPE
 *                   COUNT VALUES")
 *   points.f32      the vertex buffer as drawn (3 floats per vertex, boundary
 *                   vertices included), scalars.f32 (1 float per vertex),
 *                   indices.u32 (the faces in draw order)
 *   table.f32       the pre-integration table (RGBA floats, s_front fastest)
 *   result.f32      the frame's float result (RGBA, bottom row first)
 *   *.vert, *.frag  the project's shaders as the mapper generates them, for
 *                   every path (fetch; interlock ARB, NV and none) and the
 *                   trivial shader of the raster bound
 *
 * Apps/GPUBench/havs_gpu_bench reads it with no VTK and draws the same frame
 * through EGL (on NVIDIA with the interlock). Frames with plane sections,
 * opaque geometry or another blend are not captured (an error says so).
 * The cell projection and the ray caster write their own cases with the
 * helpers below.
 */
#ifndef vtkHAVSGLFrameCapture_h
#define vtkHAVSGLFrameCapture_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkType.h" // For vtkIdType

#include <cstddef> // For size_t
#include <string>  // For std::string
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLPassContext;
class vtkTextureObject;

class vtkHAVSGLFrameCapture
{
public:
  /**
   * Writes the case of the frame just drawn with `context` (its result still
   * in the targets) into `directory` (made if missing); `cells`: the cells
   * the frame drew. False, with `error` set, when it cannot.
   */
  static bool Write(const std::string& directory, vtkHAVSGLPassContext& context, vtkIdType cells,
    std::string& error);

  ///@{
  /// Helpers of every mapper's capture.
  /// Every active non-sampler uniform of the GL program `handle`, a line each:
  /// "uniform PROGRAM NAME TYPE COUNT VALUES..." (PROGRAM: `programName`).
  static std::string UniformLines(const std::string& programName, unsigned int handle);
  /// The first lines of case.txt: the format, the mapper, the size, the table's size.
  static std::string Header(
    const std::string& mapper, int width, int height, const int tableSize[3]);
  /// The table texture's RGBA floats (s_front fastest); its size in `size`.
  static std::vector<float> ReadTable(vtkTextureObject* table, int size[3]);
  static bool WriteBytes(const std::string& path, const void* data, size_t bytes);
  template <typename T>
  static bool WriteArray(const std::string& path, const std::vector<T>& values)
  {
    return WriteBytes(path, values.data(), values.size() * sizeof(T));
  }
  static bool WriteText(const std::string& path, const std::string& text);
  /// Makes `directory` (false, with `error` set, when it cannot).
  static bool MakeDirectory(const std::string& directory, std::string& error);
  ///@}
};

VTK_ABI_NAMESPACE_END
#endif

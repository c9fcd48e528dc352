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
 * A benchmark aid (vtkOpenGLHAVSVolumeMapper::SetCaptureDirectory, the
 * benchmark's `--dump-case DIR`): after a frame drawn through the
 * framebuffer-fetch or the interlock k-buffer, writes into a directory
 *
 *   case.txt        size, k, counts, table size, facing, and every active
 *                   uniform of the draw program (name, type, values)
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
 */
#ifndef vtkHAVSGLFrameCapture_h
#define vtkHAVSGLFrameCapture_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkType.h" // For vtkIdType

#include <string> // For std::string

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLPassContext;

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
};

VTK_ABI_NAMESPACE_END
#endif

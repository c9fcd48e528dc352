/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLCapabilities.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file    vtkHAVSGLCapabilities.h
 * @brief   What the current OpenGL context offers the k-buffer paths.
 *
 * Queries of the context current on the calling thread: version, extensions,
 * the fragment-shader interlock flavour. HAVS_EMULATE_INTERLOCK=1 on llvmpipe
 * runs the interlock path without the interlock: llvmpipe shades each tile in
 * one thread, a pixel's fragments one at a time in primitive order, so the
 * storage-buffer k-buffer is race-free there without it; this tests the
 * path's layout, clear and resolve on a machine without an interlock GPU.
 * Ignored anywhere else.
 */
#ifndef vtkHAVSGLCapabilities_h
#define vtkHAVSGLCapabilities_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSShaders.h" // For InterlockKind

VTK_ABI_NAMESPACE_BEGIN

namespace vtkHAVSGLCapabilities
{
/// Whether the context has the extension.
bool HasExtension(const char* name);
/// Whether the context's version is at least major.minor.
bool HasVersion(int major, int minor);
/// Whether HAVS_EMULATE_INTERLOCK=1 asks for the emulated interlock and this is llvmpipe.
bool InterlockEmulated();
/**
 * Faces one piece of a big draw holds (0: no pieces): a software rasterizer
 * (llvmpipe) bins every queued triangle into scenes it keeps for reuse, and
 * one draw of millions of faces left it holding about 360 bytes a
 * tetrahedron after the frame (1M tets, 512^2), against 23 with its
 * rasterization synchronous (LP_NUM_THREADS=0). There 2^18 faces, drawn
 * through a DrawThrottle; on a GPU no pieces. HAVS_FACES_PER_FINISH (a
 * number, 0: none) overrides it.
 */
long long FacesPerFinish();

/**
 * Keeps at most two pieces of a draw queued: Before() waits for the piece
 * drawn two pieces earlier (a fence), After() fences the piece just drawn.
 * The rasterizer works on one piece while the next is binned.
 */
class DrawThrottle
{
public:
  DrawThrottle() = default;
  ~DrawThrottle();
  DrawThrottle(const DrawThrottle&) = delete;
  DrawThrottle& operator=(const DrawThrottle&) = delete;
  void Before();
  void After();

private:
  void* Fences[2] = { nullptr, nullptr }; // GLsync
  int Next = 0;
};
/// The interlock the context has (ARB, NV), else InterlockNone.
vtkHAVSShaders::InterlockKind AvailableInterlock();
}

VTK_ABI_NAMESPACE_END
#endif

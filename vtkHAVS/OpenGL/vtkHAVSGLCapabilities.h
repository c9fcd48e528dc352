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

#include <functional> // For std::function

VTK_ABI_NAMESPACE_BEGIN

namespace vtkHAVSGLCapabilities
{
/// Whether the context has the extension.
bool HasExtension(const char* name);
/// Whether the context's version is at least major.minor.
bool HasVersion(int major, int minor);
/// Whether the context's GL_RENDERER names `name` (e.g. llvmpipe).
bool RendererIs(const char* name);
/// Whether HAVS_EMULATE_INTERLOCK=1 asks for the emulated interlock and this is llvmpipe.
bool InterlockEmulated();
/**
 * Faces one piece of a big draw holds (0: no pieces): a software rasterizer
 * (llvmpipe) bins every queued triangle into scenes it keeps for reuse, and
 * one draw of millions of faces left it holding about 360 bytes a
 * tetrahedron after the frame (1M tets, 512^2), against 23 with its
 * rasterization synchronous (LP_NUM_THREADS=0). There 2^18 faces; on a GPU
 * no pieces. HAVS_FACES_PER_FINISH (a number, 0: none) overrides it.
 */
long long FacesPerFinish();

/**
 * Draws units [first, last) (cells, faces) in pieces of `perPiece` units
 * (0: one piece), at most two pieces queued: before each piece it waits for
 * the fence of the piece two earlier, so the rasterizer works on one piece
 * while the next is binned. `draw(begin, end)` issues one piece's draw.
 */
void DrawInPieces(long long first, long long last, long long perPiece,
  const std::function<void(long long, long long)>& draw);
/// The interlock the context has (ARB, NV), else InterlockNone.
vtkHAVSShaders::InterlockKind AvailableInterlock();
}

VTK_ABI_NAMESPACE_END
#endif

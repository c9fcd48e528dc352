/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSInterlockKBuffer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSInterlockKBuffer
 * @brief   The k-buffer in a per-pixel storage buffer, guarded by an ordered interlock.
 *
 * Each pixel owns InterlockPixelStride(k) vec4 slots of a storage buffer
 * (the colour, then the entries in pairs). The draw shader's read-modify-write
 * runs inside ARB_ or NV_fragment_shader_interlock in ordered mode, so a
 * pixel's fragments update it one at a time in primitive order (the
 * k-buffer's requirement; NVIDIA has it, llvmpipe has not). k <= 64. On
 * llvmpipe, HAVS_EMULATE_INTERLOCK=1 runs the path without the interlock
 * (see vtkHAVSGLCapabilities) to test its layout, clear and resolve.
 */
#ifndef vtkHAVSInterlockKBuffer_h
#define vtkHAVSInterlockKBuffer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSGLObjects.h" // For vtkHAVSGLBuffer
#include "vtkHAVSKBuffer.h"
#include "vtkHAVSOpenGL.h" // For GLuint

#include <cstddef> // For size_t

VTK_ABI_NAMESPACE_BEGIN

class vtkOpenGLRenderWindow;

class vtkHAVSInterlockKBuffer : public vtkHAVSKBuffer
{
public:
  static vtkHAVSInterlockKBuffer* New();
  vtkTypeMacro(vtkHAVSInterlockKBuffer, vtkHAVSKBuffer);

  /// Whether the current context of `window` runs this path.
  static bool IsSupported(vtkOpenGLRenderWindow* window);

  int GetPath() const override;
  int GetMaximumK() const override;
  bool Allocate(vtkHAVSGLPassContext& context) override;
  bool Clear(vtkHAVSGLPassContext& context) override;
  bool Draw(vtkHAVSGLPassContext& context) override;
  bool Resolve(vtkHAVSGLPassContext& context) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkHAVSInterlockKBuffer() = default;
  ~vtkHAVSInterlockKBuffer() override = default;

private:
  vtkHAVSInterlockKBuffer(const vtkHAVSInterlockKBuffer&) = delete;
  void operator=(const vtkHAVSInterlockKBuffer&) = delete;

  vtkHAVSGLBuffer PixelEntries; ///< the per-pixel entries (its version: its size)
};

VTK_ABI_NAMESPACE_END
#endif

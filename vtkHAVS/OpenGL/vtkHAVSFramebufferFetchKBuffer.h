/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFramebufferFetchKBuffer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFramebufferFetchKBuffer
 * @brief   The k-buffer in colour attachments, read with framebuffer fetch.
 *
 * The colour and the k entries (eye distance, code) live in 1 + (k+1)/2
 * RGBA32F colour attachments that the draw shader reads (inout,
 * EXT_shader_framebuffer_fetch: coherent and ordered per primitive within a
 * draw call, so the read-modify-write needs no lock) and writes back. k <= 14
 * with 8 draw buffers. Mesa's llvmpipe has it; NVIDIA has not.
 */
#ifndef vtkHAVSFramebufferFetchKBuffer_h
#define vtkHAVSFramebufferFetchKBuffer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSKBuffer.h"
#include "vtkSmartPointer.h"  // For vtkSmartPointer
#include "vtkTextureObject.h" // For vtkSmartPointer<vtkTextureObject>

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;

class vtkHAVSFramebufferFetchKBuffer : public vtkHAVSKBuffer
{
public:
  static vtkHAVSFramebufferFetchKBuffer* New();
  vtkTypeMacro(vtkHAVSFramebufferFetchKBuffer, vtkHAVSKBuffer);

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
  vtkHAVSFramebufferFetchKBuffer() = default;
  ~vtkHAVSFramebufferFetchKBuffer() override = default;

private:
  vtkHAVSFramebufferFetchKBuffer(const vtkHAVSFramebufferFetchKBuffer&) = delete;
  void operator=(const vtkHAVSFramebufferFetchKBuffer&) = delete;

  std::vector<vtkSmartPointer<vtkTextureObject>> Targets; // colour, then entry pairs
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  int K = 0;
  int Size[2] = { 0, 0 };
};

VTK_ABI_NAMESPACE_END
#endif

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSVolumeMapper.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkOpenGLHAVSVolumeMapper
 * @brief   The OpenGL layer of vtkHAVSVolumeMapper (its object-factory override).
 *
 * vtkHAVSVolumeMapper::New() returns this class once the vtkHAVS::OpenGL
 * module is initialized (vtk_module_autoinit; `import vtkhavs` in Python).
 * It draws what the GL-free mapper asks for, one frame at a time:
 *
 *   upload      what changed: points and scalars (per mesh), the faces in
 *               draw order (per order), sections (per plane change), the
 *               table (per build) — vtkHAVSGLMesh, vtkHAVSGLTable
 *   capture     the opaque depth of VTK's framebuffer (vtkHAVSGLFrameTargets)
 *   draw        the faces through the k-buffer path (vtkHAVSKBuffer: framebuffer
 *               fetch, interlock or fragment lists), or the extremum pass, or
 *               the raster-bound pass
 *   resolve     the remaining entries in depth order into the float result
 *   read back   the order-violation count (when asked), the float result (when kept)
 *   composite   the premultiplied result over VTK's framebuffer
 *
 * Resources live in one window at a time; a frame in another window moves
 * them there, and a window deleted while it holds them takes them with it.
 */
#ifndef vtkOpenGLHAVSVolumeMapper_h
#define vtkOpenGLHAVSVolumeMapper_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkHAVSVolumeMapper.h"
#include "vtkNew.h" // For vtkNew

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSExtremumPass;
class vtkHAVSFragmentListKBuffer;
class vtkHAVSFramebufferFetchKBuffer;
class vtkHAVSGLFrameTargets;
class vtkHAVSGLMapperResources;
class vtkHAVSGLMesh;
class vtkHAVSGLTable;
class vtkHAVSInterlockKBuffer;
class vtkHAVSKBuffer;
class vtkHAVSRasterBoundPass;
class vtkOpenGLRenderWindow;

class VTKHAVSOPENGL_EXPORT vtkOpenGLHAVSVolumeMapper : public vtkHAVSVolumeMapper
{
public:
  static vtkOpenGLHAVSVolumeMapper* New();
  vtkTypeMacro(vtkOpenGLHAVSVolumeMapper, vtkHAVSVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  bool IsKBufferPathSupported(vtkRenderWindow* window, int path) override;

protected:
  vtkOpenGLHAVSVolumeMapper();
  ~vtkOpenGLHAVSVolumeMapper() override;

  int ChooseKBufferPath(vtkRenderer* renderer, int requested) override;
  int GetMaximumK(int path) override;
  bool DrawFrame(vtkRenderer* renderer, const FrameRequest& request, FrameResult& result) override;
  bool CompositeKeptResult(vtkRenderer* renderer) override;

private:
  vtkOpenGLHAVSVolumeMapper(const vtkOpenGLHAVSVolumeMapper&) = delete;
  void operator=(const vtkOpenGLHAVSVolumeMapper&) = delete;

  /// Uploads what changed since the last frame in this window; `result` says what was.
  bool Upload(const FrameRequest& request, FrameResult& result);
  vtkHAVSKBuffer* GetKBuffer(int path);

  vtkNew<vtkHAVSGLMesh> GLMesh;
  vtkNew<vtkHAVSFramebufferFetchKBuffer> FetchKBuffer;
  vtkNew<vtkHAVSInterlockKBuffer> InterlockKBuffer;
  vtkNew<vtkHAVSFragmentListKBuffer> ListKBuffer;
  struct GLObjects; // releases the mesh and k-buffers above
  // The window, the table, the targets; declared after the objects its Own
  // releases, so that it is destroyed before them.
  vtkNew<vtkHAVSGLMapperResources> Resources;
  vtkNew<vtkHAVSExtremumPass> Extremum;
  vtkNew<vtkHAVSRasterBoundPass> RasterBound;
};

VTK_ABI_NAMESPACE_END
#endif

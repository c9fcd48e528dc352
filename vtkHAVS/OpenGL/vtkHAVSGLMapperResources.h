/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLMapperResources.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLMapperResources
 * @brief   What each of the three GL mappers holds in its window the same way.
 *
 * The window the mapper draws in (its context made current at the start of
 * a frame; the resources of an earlier window released first), a watch on
 * that window's deletion (a window that goes away while the mapper is not
 * among its props, so that nobody tells the mapper to release, takes the
 * resources with it), the pre-integration table on the GPU
 * (vtkHAVSGLTable, uploaded when its version changes) and the frame's
 * targets (vtkHAVSGLFrameTargets: the result, the opaque depth, the kept
 * result). The mapper's own GPU objects are released through the callback
 * given to SetReleaseCallback, with the context current.
 */
#ifndef vtkHAVSGLMapperResources_h
#define vtkHAVSGLMapperResources_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkNew.h" // For vtkNew
#include "vtkObject.h"

#include <functional> // For std::function

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLFrameTargets;
class vtkHAVSGLTable;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkWindow;

class vtkHAVSGLMapperResources : public vtkObject
{
public:
  static vtkHAVSGLMapperResources* New();
  vtkTypeMacro(vtkHAVSGLMapperResources, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// What releases the mapper's own GPU objects (called with the context current).
  void SetReleaseCallback(std::function<void(vtkOpenGLRenderWindow*)> release)
  {
    this->ReleaseOwn = std::move(release);
  }

  /**
   * The renderer's OpenGL window, its context current and everything of an
   * earlier window released; nullptr, with an error through `mapper` naming
   * `mapperName`, when it is not an OpenGL window or has no OpenGL 4.3
   * (storage buffers, images), which `needs` says what for.
   */
  vtkOpenGLRenderWindow* Prepare(
    vtkRenderer* renderer, vtkObject* mapper, const char* mapperName, const char* needs);

  /// Releases everything in `window` (nullptr: in whichever window holds it).
  void Release(vtkWindow* window);

  vtkOpenGLRenderWindow* GetWindow() const { return this->Window; }
  vtkHAVSGLTable* GetTable() { return this->Table; }
  vtkHAVSGLFrameTargets* GetTargets() { return this->Targets; }

protected:
  vtkHAVSGLMapperResources();
  ~vtkHAVSGLMapperResources() override;

private:
  vtkHAVSGLMapperResources(const vtkHAVSGLMapperResources&) = delete;
  void operator=(const vtkHAVSGLMapperResources&) = delete;

  void OnWindowDeleted(vtkObject* window, unsigned long, void*);

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned long WindowDeleteObserver = 0;
  vtkNew<vtkHAVSGLTable> Table;
  vtkNew<vtkHAVSGLFrameTargets> Targets;
  std::function<void(vtkOpenGLRenderWindow*)> ReleaseOwn;
};

VTK_ABI_NAMESPACE_END
#endif

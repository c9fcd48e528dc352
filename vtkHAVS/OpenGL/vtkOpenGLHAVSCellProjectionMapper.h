/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkOpenGLHAVSCellProjectionMapper.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkOpenGLHAVSCellProjectionMapper
 * @brief   OpenGL layer of vtkHAVSCellProjectionMapper (its object-factory override).
 *
 * Per mesh: the points (vertex buffer), the cells' planes and fields
 * (vtkHAVSCellGeometry, storage buffer 4). Per frame: the faces of the cells
 * in the cell order (index buffer) and the tetrahedron of each drawn position
 * (storage buffer 5); one draw call, back faces culled, front-to-back
 * blending of premultiplied segments into the float result
 * (vtkHAVSGLFrameTargets, which also captures the opaque depth and
 * composites the result over VTK's framebuffer). The table is vtkHAVSGLTable,
 * the shaders vtkHAVSKBufferShaders::CellProjection*Shader. Needs OpenGL 4.3.
 */
#ifndef vtkOpenGLHAVSCellProjectionMapper_h
#define vtkOpenGLHAVSCellProjectionMapper_h

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkNew.h"              // For vtkNew

#include <vector> // For std::vector

class vtkHAVSGLFrameTargets;
class vtkHAVSGLTable;
class vtkOpenGLRenderWindow;

class VTKHAVSOPENGL_EXPORT vtkOpenGLHAVSCellProjectionMapper : public vtkHAVSCellProjectionMapper
{
public:
  static vtkOpenGLHAVSCellProjectionMapper* New();
  vtkTypeMacro(vtkOpenGLHAVSCellProjectionMapper, vtkHAVSCellProjectionMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkOpenGLHAVSCellProjectionMapper();
  ~vtkOpenGLHAVSCellProjectionMapper() override;

  bool DrawCells(vtkRenderer* renderer, const CellFrame& frame, double* drawSeconds) override;
  const std::vector<float>* GetKeptResult(int size[2]) override;

private:
  vtkOpenGLHAVSCellProjectionMapper(const vtkOpenGLHAVSCellProjectionMapper&) = delete;
  void operator=(const vtkOpenGLHAVSCellProjectionMapper&) = delete;

  void PrepareWindow(vtkOpenGLRenderWindow* window);
  void OnWindowDeleted(vtkObject* window, unsigned long, void*);
  void Upload(const CellFrame& frame);
  /// The near plane's section (triangles and their cells); returns its triangle count.
  int UploadSection(const CellFrame& frame);

  vtkOpenGLRenderWindow* Window = nullptr;
  unsigned long WindowDeleteObserver = 0;
  vtkNew<vtkHAVSGLTable> GLTable;
  vtkNew<vtkHAVSGLFrameTargets> Targets;
  unsigned int VertexArray = 0;
  unsigned int PointBuffer = 0;
  unsigned int IndexBuffer = 0;
  unsigned int CellBuffer = 0;
  unsigned int OrderBuffer = 0;
  unsigned int SectionArray = 0;
  unsigned int SectionPointBuffer = 0;
  unsigned int SectionCellBuffer = 0;
  int SectionTriangles = 0;
  vtkMTimeType UploadedGeometry = 0;
  vtkMTimeType UploadedTable = 0;
  vtkMTimeType UploadedOrder = 0;
  vtkMTimeType UploadedSection = 0;
  size_t UploadedCells = 0; // tetrahedra in the index buffer (12 indices each)
};

#endif

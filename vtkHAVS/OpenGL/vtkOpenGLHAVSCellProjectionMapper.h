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
 * the shaders vtkHAVSShaders::CellProjection*Shader. Needs OpenGL 4.3.
 */
#ifndef vtkOpenGLHAVSCellProjectionMapper_h
#define vtkOpenGLHAVSCellProjectionMapper_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCellProjectionMapper.h"
#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkNew.h"              // For vtkNew

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLMapperResources;
class vtkShaderProgram;

class VTKHAVSOPENGL_EXPORT vtkOpenGLHAVSCellProjectionMapper : public vtkHAVSCellProjectionMapper
{
public:
  static vtkOpenGLHAVSCellProjectionMapper* New();
  vtkTypeMacro(vtkOpenGLHAVSCellProjectionMapper, vtkHAVSCellProjectionMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkOpenGLHAVSCellProjectionMapper();
  ~vtkOpenGLHAVSCellProjectionMapper() override;

  bool DrawCells(vtkRenderer* renderer, const CellFrame& frame, double* drawSeconds) override;

private:
  vtkOpenGLHAVSCellProjectionMapper(const vtkOpenGLHAVSCellProjectionMapper&) = delete;
  void operator=(const vtkOpenGLHAVSCellProjectionMapper&) = delete;

  /// The mesh's points and cells, the order's faces and cells: each when its version changed.
  void Upload(const CellFrame& frame);
  /// Every uniform of the frame's program (the view, the planes, the table).
  void SetUniforms(vtkShaderProgram* program, const CellFrame& frame);
  /// The frame just drawn with `program` (its result still in the targets)
  /// as a frame case in CaptureDirectory (Apps/GPUBench/README.md); false,
  /// with `error` set, when the frame cannot be represented or written.
  bool WriteCase(
    const CellFrame& frame, vtkShaderProgram* program, size_t patternCells, std::string& error);

  vtkNew<vtkHAVSGLMapperResources> Resources; // the window, the table, the targets
  struct GLObjects;                           // the mapper's own buffers (vtkHAVSGLObjects)
  GLObjects* GL = nullptr;                    // (owned and released by Resources)
};

VTK_ABI_NAMESPACE_END
#endif

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLTableBuilder.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLTableBuilder
 * @brief   Builds the pre-integrated table on the GPU (a compute shader).
 *
 * Issue 45's candidate "the table built on the GPU": the same windowed
 * quadrature as vtkHAVSPreIntegrationTable::Build, from the inputs the CPU
 * computes (vtkHAVSPreIntegrationTable::Quadrature: the functions sampled on
 * the fine grid, a few thousand values), in single precision, one work group
 * per (j = |b - f|, length layer, direction) (vtkHAVSTableCS.glsl). The
 * entries are written to a 3D RGBA32F image and read back into the CPU's
 * table (whose other users, cell visibility and the automatic resolution's
 * probes, read it there); vtkHAVSMapperBase::PreIntegrationOnGPU builds the
 * mappers' tables with it (vtkHAVSPreIntegrationTable::SetEntryBuilder).
 *
 * VTK's vtkShaderProgram has no compute stage before VTK 9.3, so the program
 * is made with GL's own calls. OpenGL 4.3 (compute shaders, storage buffers,
 * image stores); at most 1024 table scalars (the shared memory of two
 * windows' composites, 32 KB).
 */
#ifndef vtkHAVSGLTableBuilder_h
#define vtkHAVSGLTableBuilder_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSGLObjects.h"           // For vtkHAVSGLBuffer
#include "vtkHAVSOpenGLModule.h"        // For export macro
#include "vtkHAVSPreIntegrationTable.h" // For vtkHAVSPreIntegrationTable::Quadrature
#include "vtkObject.h"
#include "vtkSmartPointer.h"  // For vtkSmartPointer
#include "vtkTextureObject.h" // For vtkSmartPointer<vtkTextureObject>

VTK_ABI_NAMESPACE_BEGIN

class vtkOpenGLRenderWindow;
class vtkWindow;

class VTKHAVSOPENGL_EXPORT vtkHAVSGLTableBuilder : public vtkObject
{
public:
  static vtkHAVSGLTableBuilder* New();
  vtkTypeMacro(vtkHAVSGLTableBuilder, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Builds every entry of the table `inputs` describe into `table`
   * (vtkHAVSPreIntegrationTable::GetTable()'s layout) in `window`, its
   * context current. False, with an error the first time, where the context
   * cannot (no OpenGL 4.3, the shader does not compile, more than 1024 table
   * scalars): the caller builds the table itself.
   */
  bool Build(vtkOpenGLRenderWindow* window, const vtkHAVSPreIntegrationTable::Quadrature& inputs,
    float* table);

  /// Seconds of the last Build(): the compute pass alone (to glFinish), and its read-back.
  vtkGetMacro(LastComputeSeconds, double);
  vtkGetMacro(LastReadSeconds, double);

  /// The work groups' size (HAVS_LOCAL of vtkHAVSTableCS.glsl).
  static constexpr int LocalSize = 64;

  /// Releases the program, the buffers and the image (`window`'s context current).
  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkHAVSGLTableBuilder() = default;
  ~vtkHAVSGLTableBuilder() override;

private:
  vtkHAVSGLTableBuilder(const vtkHAVSGLTableBuilder&) = delete;
  void operator=(const vtkHAVSGLTableBuilder&) = delete;

  bool MakeProgram(int cells);

  unsigned int Program = 0; // a GLuint
  int ProgramCells = 0;     // the HAVS_CELLS it was compiled for
  bool Failed = false;      // the program failed once in this context: not tried again
  vtkHAVSGLBuffer Samples, Steps, TableSamples, Layers;
  vtkSmartPointer<vtkTextureObject> Image;
  vtkOpenGLRenderWindow* Window = nullptr;
  double LastComputeSeconds = 0.0;
  double LastReadSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSGLTable.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSGLTable
 * @brief   The pre-integrated table and the 1D transfer function on the GPU.
 *
 * The 3D table of vtkHAVSPreIntegrationTable (front scalar, back scalar,
 * length -> premultiplied RGBA, trilinear) and its 1D transfer function (for
 * maximum and minimum intensity), uploaded once per table build.
 * SetUniforms() gives a program the table's sampler and texel mapping.
 */
#ifndef vtkHAVSGLTable_h
#define vtkHAVSGLTable_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h" // For vtkSmartPointer<vtkOpenGLBufferObject>
#include "vtkSmartPointer.h"       // For vtkSmartPointer
#include "vtkTextureObject.h"      // For vtkSmartPointer<vtkTextureObject>

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSIsoSurfaces;
class vtkHAVSPreIntegrationTable;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkWindow;

class vtkHAVSGLTable : public vtkObject
{
public:
  static vtkHAVSGLTable* New();
  vtkTypeMacro(vtkHAVSGLTable, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetContext(vtkOpenGLRenderWindow* window) { this->Window = window; }

  /// Uploads the table, the 1D function and the additive nodes.
  void Upload(vtkHAVSPreIntegrationTable* table);
  /// Uploads `table` unless its `version` (a modification time) is the one
  /// uploaded last; returns whether it uploaded.
  bool Update(vtkHAVSPreIntegrationTable* table, vtkMTimeType version);

  vtkTextureObject* GetTable() { return this->Table; }
  vtkTextureObject* GetTransferFunction1D() { return this->TransferFunction1D; }
  /// The additive blend's (g, G) nodes (vtkHAVSPreIntegrationTable::GetAdditive1D).
  vtkTextureObject* GetAdditive1D() { return this->Additive1D; }
  /**
   * Cell scalars: the functions at each cell value (vtkHAVSCellOptics, two
   * RGBA texels a value), a buffer texture; a placeholder of one value when
   * the table has none, so that a program's havsCellOptics always has one.
   */
  vtkTextureObject* GetCellOptics() { return this->CellOptics; }
  /// Whether the table uploaded last has cell optics (the passes draw cell codes).
  bool HasCellOptics() const { return this->CellValues > 0; }

  /// havsTable, havsScalarTexel, havsLengthTexel, havsInvMaxLength,
  /// havsLengthLogScale, havsInvLogRange (table active), havsCellOptics
  /// (when GetCellOptics() is active), and the isosurfaces' havsIsoCount,
  /// havsIsoValues, havsIsoColors (the shaders compile them in with HAVS_ISO).
  void SetUniforms(vtkShaderProgram* program);

  /// The frame's isosurfaces (the mapper's, set every frame; nullptr: none).
  void SetIsoSurfaces(const vtkHAVSIsoSurfaces* iso) { this->IsoSurfaces = iso; }

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkHAVSGLTable() = default;
  ~vtkHAVSGLTable() override = default;

private:
  vtkHAVSGLTable(const vtkHAVSGLTable&) = delete;
  void operator=(const vtkHAVSGLTable&) = delete;

  vtkOpenGLRenderWindow* Window = nullptr;
  vtkSmartPointer<vtkTextureObject> Table;
  vtkSmartPointer<vtkTextureObject> TransferFunction1D;
  vtkSmartPointer<vtkTextureObject> Additive1D;
  vtkSmartPointer<vtkTextureObject> CellOptics;
  vtkSmartPointer<vtkOpenGLBufferObject> CellOpticsBuffer;
  size_t CellValues = 0;
  vtkMTimeType UploadedVersion = 0;
  int ScalarResolution = 0;
  int LengthResolution = 0;
  double MaxLength = 1.0;
  double LengthLogScale = 0.0; ///< 0: a linear length axis
  const vtkHAVSIsoSurfaces* IsoSurfaces = nullptr;
};

VTK_ABI_NAMESPACE_END
#endif

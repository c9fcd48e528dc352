/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellVisibility.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSCellVisibility
 * @brief   Which cells the transfer function leaves fully transparent.
 *
 * Plain C++, no OpenGL. A tetrahedron whose scalars span [min, max] is
 * invisible when the pre-integration table gives nothing, colour and opacity,
 * for the longest segment from the table node at or below min to the node at
 * or above max: its opacity is then zero over an interval holding every value
 * the cell takes and every value the GPU's interpolation between table nodes
 * can read for it (a segment's opacity only grows with its length, and a
 * sub-interval of a transparent interval is transparent). Cells with a
 * non-finite scalar stay visible.
 *
 * The faces between a visible and an invisible cell then act as boundary
 * faces (vtkHAVSFaceOrderPolicy gathers them wound out of the visible cell,
 * and the boundary tagging makes the gap behind them empty); faces with no
 * visible cell are not drawn. Dropping them is exact: the segments they
 * bounded contribute nothing. Any visibility order of all the cells stays one
 * of the visible cells, so the exact orders keep working unchanged.
 *
 * Update() runs in parallel (vtkSMPTools) and only where the mesh or the
 * table changed; a transfer-function edit recomputes it without touching
 * the mesh on the GPU.
 */
#ifndef vtkHAVSCellVisibility_h
#define vtkHAVSCellVisibility_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"

#include <cstdint> // For uint8_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSMesh;
class vtkHAVSPreIntegrationTable;

class VTKHAVSCORE_EXPORT vtkHAVSCellVisibility : public vtkObject
{
public:
  static vtkHAVSCellVisibility* New();
  vtkTypeMacro(vtkHAVSCellVisibility, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Recomputes the visibility of the mesh's cells under `table` when either
   * was rebuilt since the last call (tableVersion: when the table was
   * built). Returns true when the set of visible cells changed.
   */
  bool Update(
    vtkHAVSMesh* mesh, const vtkHAVSPreIntegrationTable* table, vtkMTimeType tableVersion);

  /**
   * A cell counts as invisible when the table's opacity for the longest
   * segment over its scalar range (as above) is at most this. 0, the default:
   * only cells the transfer function leaves fully transparent, and the image
   * stays exact. Above 0, nearly transparent cells are dropped too: faster,
   * not exact (the tests' control).
   */
  void SetOpacityThreshold(double threshold);
  vtkGetMacro(OpacityThreshold, double);

  /// Forgets the last result (the next Update() computes again).
  void Invalidate();

  /**
   * Per grid cell id (the ids vtkHAVSFaceSet::GetFaceCells() uses): 1 visible,
   * 0 invisible; cells that are not drawn tetrahedra are 0.
   */
  const std::vector<uint8_t>& GetVisible() const { return this->Visible; }

  /// Drawn tetrahedra the transfer function hides, and all drawn tetrahedra.
  vtkGetMacro(NumberOfInvisibleCells, vtkIdType);
  vtkGetMacro(NumberOfCells, vtkIdType);

  /// Seconds the last recomputation took.
  vtkGetMacro(LastSeconds, double);

  /// Changes each time the set of visible cells does.
  vtkMTimeType GetVisibilityVersion() const { return this->VisibilityTime.GetMTime(); }

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSCellVisibility() = default;
  ~vtkHAVSCellVisibility() override = default;

private:
  vtkHAVSCellVisibility(const vtkHAVSCellVisibility&) = delete;
  void operator=(const vtkHAVSCellVisibility&) = delete;

  double OpacityThreshold = 0.0;
  std::vector<uint8_t> Visible;
  vtkIdType NumberOfInvisibleCells = 0;
  vtkIdType NumberOfCells = 0;
  double LastSeconds = 0.0;
  vtkMTimeType MeshVersion = 0;
  vtkMTimeType ScalarVersion = 0;
  vtkMTimeType TableVersion = 0;
  vtkTimeStamp VisibilityTime;
};

VTK_ABI_NAMESPACE_END
#endif

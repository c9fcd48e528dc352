/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellProjectionMapper.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSCellProjectionMapper
 * @brief   View-independent cell projection in the exact cell order, pre-integrated.
 *
 * The third mapper of vtkHAVS, after Weiler, Kraus and Ertl, "Hardware-Based
 * View-Independent Cell Projection" (2002, seed 001), with the pre-integrated
 * segments and the exact order of Röttger, Guthe, Schieber and Ertl (2004,
 * seed 004): every tetrahedron's faces are drawn in the exact front-to-back
 * cell order (vtkHAVSVisibilityOrder: MPVO with the boundary layers or the
 * convexification), back faces culled; per fragment of a front face the
 * shader finds where the ray leaves the cell (the nearest of the cell's
 * other face planes, perspective or parallel, in model coordinates), the
 * scalars at both ends from the cell's linear field, the segment from the
 * shared pre-integration table, and fixed-function blending composites it
 * front to back. No k-buffer, no per-pixel storage; per view the CPU makes
 * the order only (vtkHAVSCellGeometry is built once per mesh), and only when
 * the view's key changed (GetLastOrderReused()). The order-independent blends
 * (maximum, minimum intensity, additive) draw the cells unsorted: no per-view
 * CPU work at all.
 *
 * Same inputs, scalars, mesh and table as the other mappers (vtkHAVSMapperBase,
 * whose Render() calls RenderView()),
 * the volume's matrix, perspective and parallel cameras, opaque geometry in
 * the scene, up to 6 clipping planes (each fragment's segment clipped to
 * them: the ray starts inside a cell where a plane cuts it, no section to
 * draw). The camera inside the mesh: where the near plane cuts it the GL
 * clip removes the front faces, so the near plane's section
 * (vtkHAVSPlaneSection, each triangle with its cell) is drawn first, the rays
 * starting on it. Not available: early ray termination (blending has none).
 * A cycle break has no k-buffer to absorb it: the cells taken out of order
 * are counted (GetLastCycleBreaks()).
 *
 * Abstract: New() gives the graphics layer's override
 * (vtkOpenGLHAVSCellProjectionMapper), as vtkHAVSVolumeMapper does.
 */
#ifndef vtkHAVSCellProjectionMapper_h
#define vtkHAVSCellProjectionMapper_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMapperBase.h"
#include "vtkHAVSVisibilityOrder.h" // For ViewKey
#include "vtkNew.h"                 // For vtkNew

#include <cstdint>    // For uint32_t
#include <functional> // For std::function
#include <string>     // For std::string
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSCellProjectionMapper : public vtkHAVSMapperBase
{
public:
  /// The graphics layer's override (vtkOpenGLHAVSCellProjectionMapper); nullptr without one.
  static vtkHAVSCellProjectionMapper* New();
  vtkTypeMacro(vtkHAVSCellProjectionMapper, vtkHAVSMapperBase);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum CellOrders
  {
    CellOrderMPVO = 0,    ///< exact (default)
    CellOrderCentroid = 1 ///< cells by centroid distance: not exact (for comparison)
  };
  ///@{
  /// The cell order; MPVO by default.
  vtkSetClampMacro(CellOrder, int, CellOrderMPVO, CellOrderCentroid);
  vtkGetMacro(CellOrder, int);
  void SetCellOrderToMPVO() { this->SetCellOrder(CellOrderMPVO); }
  void SetCellOrderToCentroid() { this->SetCellOrder(CellOrderCentroid); }
  ///@}

  ///@{
  /// How MPVO orders across the gaps of a non-convex mesh (vtkHAVSVisibilityOrder's
  /// NonConvexMethods); default the boundary layers.
  vtkSetClampMacro(NonConvexMethod, int, 0, 2);
  vtkGetMacro(NonConvexMethod, int);
  ///@}

  // Blend modes (vtkHAVSMapperBase): composite (default, in the exact cell
  // order), and the order-independent ones, drawn unsorted with no per-view
  // work on the CPU at all: maximum and minimum intensity (the extremal
  // scalar along the ray in the mesh, coloured by the transfer function's
  // colour and opacity, as vtkHAVSVolumeMapper and VTK's ray casters), and
  // additive (VTK's ADDITIVE_BLEND in the limit of small samples: the
  // integral of tau(s) s along the ray, s normalized to the scalar range,
  // clamped to 1, grey with opacity 1 where the ray crosses the mesh; a sum
  // of per-sample terms, hence order-independent).

  ///@{
  /// Testing aid (a negative control): the ray leaves each cell through the
  /// farthest forward face plane instead of the nearest. Off by default.
  vtkSetMacro(WrongExitForTesting, bool);
  vtkGetMacro(WrongExitForTesting, bool);
  ///@}

  ///@{
  /// Testing aid (a negative control): the isosurfaces from the scalars that
  /// composite frames use. In isosurface frames the scalars where a cell's
  /// stretch enters and leaves it come from the faces' corners where the
  /// pixel centre's exact ray meets them, in double, so the two cells of a
  /// face agree on its scalar and an isovalue is crossed once. With this on,
  /// the cell's field at the float crossing points gives them: values a
  /// rounding apart across a face, crossed in both cells or in neither (a
  /// shader variant without the double code). Off by default.
  vtkSetMacro(FloatIsoStretchesForTesting, bool);
  vtkGetMacro(FloatIsoStretchesForTesting, bool);
  ///@}

  ///@{
  /// Testing aid (a negative control): the cells drawn in the reverse of the
  /// chosen order (back to front under front-to-back blending). Off by default.
  vtkSetMacro(ReverseOrderForTesting, bool);
  vtkGetMacro(ReverseOrderForTesting, bool);
  ///@}

  ///@{
  /// Testing aid: the unsorted blends draw the cells in a fixed random
  /// permutation instead of the mesh's order (their image must not change).
  vtkSetMacro(ShuffleOrderForTesting, bool);
  vtkGetMacro(ShuffleOrderForTesting, bool);
  ///@}

  /// Whether the last frame reused the previous frame's cell order and its
  /// upload (the same view key, vtkHAVSVisibilityOrder::ViewKey: a
  /// transfer-function edit or a redraw does not sort again).
  vtkGetMacro(LastOrderReused, bool);

  ///@{
  /// The last frame: cells drawn, cells taken out of order to break cycles,
  /// seconds of the order and of the draw (with the GPU finished only when
  /// MeasureStageTimes is on).
  vtkGetMacro(LastCellsDrawn, vtkIdType);
  vtkGetMacro(LastCycleBreaks, vtkIdType);
  vtkGetMacro(LastOrderSeconds, double);
  vtkGetMacro(LastDrawSeconds, double);
  vtkSetMacro(MeasureStageTimes, bool);
  vtkGetMacro(MeasureStageTimes, bool);
  vtkBooleanMacro(MeasureStageTimes, bool);
  ///@}

  /// What the graphics layer draws in one frame.
  struct CellFrame
  {
    const vtkHAVSViewFrame* View = nullptr;
    vtkHAVSMesh* Mesh = nullptr;
    vtkHAVSPreIntegrationTable* Table = nullptr;
    vtkMTimeType TableVersion = 0;
    const std::vector<float>* Cells = nullptr;         ///< vtkHAVSCellGeometry, per tetrahedron
    const std::vector<uint32_t>* Tetrahedra = nullptr; ///< 4 point ids each (the mesh's)
    const std::vector<uint32_t>* Mirrored = nullptr;   ///< vtkHAVSCellGeometry::ComputeMirrored
    vtkMTimeType GeometryVersion = 0;                  ///< of Points, Cells, Tetrahedra, Mirrored
    const std::vector<uint32_t>* Order = nullptr;      ///< tetrahedra, front to back
    vtkMTimeType OrderVersion = 0;                     ///< changes whenever Order does
    int Blend = 0;                                     ///< the blend mode
    vtkHAVSFramePlanes* Planes = nullptr; ///< the clipping planes, the near plane's section
    bool Opaque = false;                  ///< opaque geometry may end the rays
    bool KeepResult = false;
    bool WrongExit = false;
    bool FloatIsoStretches = false;
    bool MeasureStages = false;
    /// Makes Cells again when they were freed after an upload and the GPU
    /// needs them (its buffers were released).
    std::function<void()> RestoreCells;
  };

protected:
  vtkHAVSCellProjectionMapper();
  ~vtkHAVSCellProjectionMapper() override;

  void ResetLastFrame() override;
  void AddMemoryParts(std::vector<vtkHAVSMemory::Part>& parts) const override;
  vtkHAVSMemory::Part GetLargestGPUBufferNeed() const override;
  void MeshPrepared(int update, bool rebuilt) override;
  void RenderView(vtkRenderer* renderer, vtkVolume* volume, const vtkHAVSViewFrame& view) override;

  /// The graphics layer: draws one frame (false, with an error, when it cannot).
  virtual bool DrawCells(vtkRenderer* renderer, const CellFrame& frame, double* drawSeconds);

private:
  vtkHAVSCellProjectionMapper(const vtkHAVSCellProjectionMapper&) = delete;
  void operator=(const vtkHAVSCellProjectionMapper&) = delete;

  void CentroidOrder(const vtkHAVSViewFrame& view);
  /// The cells' planes and fields (and faces) from the mesh (MeshPrepared, RestoreCells).
  void ComputeCells();
  /// The frame's cell order (made again only when its key changed); nullptr on failure.
  const std::vector<uint32_t>* MakeOrder(const vtkHAVSViewFrame& view);

  int CellOrder = CellOrderMPVO;
  int NonConvexMethod = 1; // vtkHAVSVisibilityOrder::NonConvexBoundaryLayers
  bool WrongExitForTesting = false;
  bool FloatIsoStretchesForTesting = false;
  bool ReverseOrderForTesting = false;
  bool ShuffleOrderForTesting = false;
  bool MeasureStageTimes = false;
  bool LastOrderReused = false;
  vtkIdType LastCellsDrawn = 0;
  vtkIdType LastCycleBreaks = 0;
  double LastOrderSeconds = 0.0;
  double LastDrawSeconds = 0.0;

  vtkNew<vtkHAVSVisibilityOrder> Order;
  bool OrderBuilt = false;
  std::vector<float> Cells; // freed once uploaded (CellFrame::RestoreCells)
  bool CellsComputed = false;
  std::vector<uint32_t> Mirrored; // one bit a tetrahedron: its faces' windings
  vtkTimeStamp GeometryTime;      // the cells' geometry (what the order depends on)
  vtkTimeStamp FieldTime;         // the cells' geometry or fields (what the GPU holds)
  std::vector<uint32_t> Centroid; // the centroid cell order
  std::vector<uint32_t> Drawn;    // the frame's cell order
  vtkHAVSVisibilityOrder::ViewKey OrderKey;
  bool OrderKeyValid = false;
  bool OrderReversed = false;
  vtkIdType KeptCycleBreaks = 0;
  vtkTimeStamp OrderTime;
};

VTK_ABI_NAMESPACE_END
#endif

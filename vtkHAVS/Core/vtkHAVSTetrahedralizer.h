/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTetrahedralizer.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSTetrahedralizer
 * @brief   Any vtkDataSet as the tetrahedral grid the vtkHAVS mappers draw.
 *
 * A grid of tetrahedra only is used as it is. Anything else (hexahedra,
 * wedges, pyramids, voxels, polyhedra, quadratic and higher-order cells;
 * structured, rectilinear and image data) is split into tetrahedra by VTK's
 * vtkDataSetTriangleFilter (tetrahedra only): linear cells through the
 * ordered triangulator, which orders each cell's points by id, so two cells
 * that share a quadrilateral face split it along the same diagonal and the
 * tetrahedra meet face to face (no cracks); structured grids with the
 * alternating voxel split that is compatible across neighbours; non-linear
 * cells by VTK's own split of their nodes, except quadratic tetrahedra:
 * VTK splits their faces by point order, which neighbours need not share
 * (measured: cracks between quadratic tetrahedra), so they are cut here
 * into the canonical eight (the four corners and the inner octahedron along
 * one diagonal): every face into its four sub-triangles, the same from both
 * sides. Point and cell data travel with the points and cells, so cell
 * scalars stay exact per cell. Cells of dimension below 3 are left out and
 * counted.
 */
#ifndef vtkHAVSTetrahedralizer_h
#define vtkHAVSTetrahedralizer_h

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkSmartPointer.h"   // For vtkSmartPointer
#include "vtkType.h"           // For vtkIdType

#include <functional> // For std::function

class vtkCompositeDataSet;
class vtkDataSet;
class vtkUnstructuredGrid;

class VTKHAVSCORE_EXPORT vtkHAVSTetrahedralizer
{
public:
  /// What Tetrahedralize() did.
  struct Report
  {
    bool Tessellated = false;          ///< false: the input was used as it is
    vtkIdType InputCells = 0;          ///< cells of the input
    vtkIdType SplitCells = 0;          ///< 3D cells that were not tetrahedra, split
    vtkIdType QuadraticTetrahedra = 0; ///< of which quadratic tetrahedra (the canonical split)
    vtkIdType LowerDimensionCells = 0; ///< vertices, lines, polygons: left out
    vtkIdType InvalidCells = 0; ///< cells with a point id out of range: left out before the split
    vtkIdType OutputTetrahedra = 0;
    double Seconds = 0.0;
  };

  /// Whether `data` is a vtkUnstructuredGrid of VTK_TETRA cells only.
  static bool IsTetrahedral(vtkDataSet* data);

  /**
   * The tetrahedral grid of `data` (the input itself when IsTetrahedral()).
   * nullptr for a null input.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralize(vtkDataSet* data, Report* report);

  /**
   * The leaves of a multiblock or partitioned data set as one unstructured
   * grid (points not merged: blocks that touch keep their own points), so
   * that one face order runs across all blocks and blocks that interleave in
   * depth composite correctly. Leaves without cells or for which `keep`
   * (when given) says no are left out and counted in `skipped`. The point
   * and cell arrays kept are those every appended leaf has (vtkAppendFilter);
   * the active scalars of the first leaf stay active. nullptr when no leaf
   * is left.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> AppendBlocks(vtkCompositeDataSet* blocks,
    const std::function<bool(vtkDataSet*)>& keep, vtkIdType* skipped, vtkIdType* appended);
};

#endif

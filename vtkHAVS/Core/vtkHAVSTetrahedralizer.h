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
 * sides; Lagrange and Bezier tetrahedra of order p likewise (VTK's split of
 * them cracks too: measured at order 3), on their nodes' lattice of p
 * segments per edge by Freudenthal's triangulation, whose faces are the
 * regular lattice triangulation; 19-node pyramids likewise (VTK's split
 * cracks too: measured), on the lattice of two segments per edge of their
 * corners, edges' and base's middle nodes (the faces' middle nodes and the
 * centre unused): a triangular face into the quadratic tetrahedron's four
 * sub-triangles. Point and cell data travel with the points and cells, so cell
 * scalars stay exact per cell. Cells of dimension below 3 are left out and
 * counted.
 *
 * Higher-order subdivision (level n >= 1; 0, the default, is the split
 * above): every non-linear hexahedron, tetrahedron and wedge (quadratic,
 * bi/triquadratic, Lagrange, Bezier, any order) and pyramid (quadratic,
 * triquadratic) is first refined uniformly in its
 * parametric space, 2^n segments along each edge, each new point placed and
 * its point data interpolated through the cell's own interpolation
 * (vtkCell::EvaluateLocation), so curved cells become curved. The pieces are
 * linear hexahedra, wedges (then split by the ordered triangulator, whose
 * choice of a quadrilateral's diagonal depends on the global point ids only,
 * the same from both sides) and tetrahedra (the canonical eight, recursively:
 * a triangular face has one lattice triangulation). A point on a shared edge
 * or face is the same point from both cells: points are merged by a key of
 * the parent cell's corner ids and their integer lattice weights. Quadratic
 * and triquadratic pyramids likewise: their lattice is the tetrahedral-
 * octahedral one (upright and inverted pyramids, tetrahedra between them;
 * on the base the hexahedron's refined face, on a triangular face the
 * tetrahedron's). Lagrange and Bezier pyramids, which VTK 9.2 has no cell
 * class for (no shape functions: vtkGenericCell makes them empty cells), are
 * taken as the linear pyramid of their five corners, counted: at level 0 as
 * it is, at levels n >= 1 refined on the same lattice (so their faces'
 * points are their refined neighbours', no cracks), flat.
 */
#ifndef vtkHAVSTetrahedralizer_h
#define vtkHAVSTetrahedralizer_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkSmartPointer.h"   // For vtkSmartPointer
#include "vtkType.h"           // For vtkIdType

#include <functional> // For std::function
#include <vector>     // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkCompositeDataSet;
class vtkDataArray;
class vtkDataSet;
class vtkUnstructuredGrid;

class VTKHAVSCORE_EXPORT vtkHAVSTetrahedralizer
{
public:
  /// What Tetrahedralize() did.
  struct Report
  {
    bool Tessellated = false; ///< false: the input was used as it is
    vtkIdType InputCells = 0; ///< cells of the input
    vtkIdType SplitCells = 0; ///< 3D cells that were not tetrahedra, split
    /// of which quadratic, Lagrange or Bezier tetrahedra (split on their nodes' lattice)
    vtkIdType QuadraticTetrahedra = 0;
    vtkIdType LowerDimensionCells = 0; ///< vertices, lines, polygons: left out
    vtkIdType InvalidCells = 0; ///< cells with a point id out of range: left out before the split
    vtkIdType OutputTetrahedra = 0;
    double Seconds = 0.0;
    int HigherOrderSubdivision = 0;        ///< the level used
    vtkIdType RefinedCells = 0;            ///< non-linear cells refined (level >= 1)
    vtkIdType UnrefinedNonLinearCells = 0; ///< non-linear cells not refined
    /// Lagrange and Bezier pyramids, taken as the linear pyramid of their corners
    vtkIdType CornerPyramids = 0;
    vtkIdType AddedPoints = 0; ///< points the refinement added
  };

  /**
   * Where the tetrahedral grid's values come from (Tetrahedralize(), when
   * asked): a new time step on the same mesh maps its scalars through it
   * instead of splitting the cells again. The grid's first InputPoints points
   * are the input's, with the same ids; each further point p is the input's
   * points StencilIds[StencilOffsets[q] …  StencilOffsets[q + 1]) (q = p -
   * InputPoints) weighted by StencilWeights (the cell's interpolation at the
   * point); each tetrahedron t lies in the input's cell Cells[t].
   */
  struct SourceMap
  {
    bool Valid = false;
    vtkIdType InputPoints = 0;
    std::vector<vtkIdType> StencilOffsets; ///< one per added point, and the end
    std::vector<vtkIdType> StencilIds;
    std::vector<double> StencilWeights;
    std::vector<vtkIdType> Cells;
    /// The grid's point values of the input's `points` array, or cell values of its `cells` array.
    vtkSmartPointer<vtkDataArray> MapPointArray(vtkDataArray* points) const;
    vtkSmartPointer<vtkDataArray> MapCellArray(vtkDataArray* cells) const;
  };

  /// The largest subdivision level (2^6 = 64 segments per edge).
  static constexpr int MaximumHigherOrderSubdivision = 6;

  /**
   * How refined cells are split (a testing hook; only SplitOrdered is
   * crack-free): SplitLocalOrder cuts every piece into tetrahedra by its
   * local lattice order (a quadrilateral's diagonal chosen per cell) and, at
   * level 0, leaves Lagrange and Bezier tetrahedra and 19-node pyramids to
   * VTK's own split;
   * SplitUnmerged gives every refined cell its own new points.
   */
  enum SubdivisionSplit
  {
    SplitOrdered = 0,
    SplitLocalOrder = 1,
    SplitUnmerged = 2
  };

  /// Whether `data` is a vtkUnstructuredGrid of VTK_TETRA cells only.
  static bool IsTetrahedral(vtkDataSet* data);

  /**
   * The tetrahedral grid of `data` (the input itself when IsTetrahedral()).
   * nullptr for a null input. `higherOrderSubdivision` (clamped to 0 …
   * MaximumHigherOrderSubdivision): see the class description. `map`
   * (optional) is filled when the input was tessellated (Valid stays false
   * when it was used as it is).
   */
  static vtkSmartPointer<vtkUnstructuredGrid> Tetrahedralize(vtkDataSet* data, Report* report,
    int higherOrderSubdivision = 0, int split = SplitOrdered, SourceMap* map = nullptr);

  /**
   * The non-linear 3D cells of `data` refined at `level` into linear
   * hexahedra, wedges and tetrahedra (see the class description); other
   * cells as they are. The input's points keep their ids; new points follow.
   * nullptr when `data` is not an unstructured grid, `level` < 1 or no cell
   * was refined.
   */
  static vtkSmartPointer<vtkUnstructuredGrid> RefineHigherOrderCells(vtkDataSet* data, int level,
    Report* report, int split = SplitOrdered, SourceMap* map = nullptr);

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

VTK_ABI_NAMESPACE_END
#endif

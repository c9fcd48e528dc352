/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSFaceSet.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSFaceSet
 * @brief   The unique triangular faces of a tetrahedral grid, boundary flagged.
 *
 * HAVS draws these faces, not the cells (Callahan, Ikits, Comba and Silva
 * 2005, section 4.1). Build() takes the VTK_TETRA cells of a vtkUnstructuredGrid (ghost cells
 * marked duplicate or hidden are left out, as another piece draws them; other cells
 * are counted as skipped; degenerate tetrahedra, with repeated points or a
 * volume within the rounding of its own computation (|6 V| <= 16 eps |a| |b| |d|,
 * the edges from the first point: scale- and shape-free, so a needle 1e6
 * times longer than wide is kept), are counted and dropped, and so
 * are duplicate tetrahedra, the same four points as an earlier cell, one
 * copy kept: a mesh's cell written twice is one cell) and stores
 * each face once: a face of one tetrahedron is a boundary face, of two an
 * internal one, of more a non-manifold one (counted, kept as internal).
 * Boundary faces are wound so that (p1 - p0) x (p2 - p0) points out of the
 * mesh, away from the cell's fourth vertex, decided in double precision from
 * the coordinates: an inverted cell cannot flip it. Internal faces keep their
 * ids ascending.
 *
 * Faces are found by a bucket sort: each face use is filed under its smallest
 * point id, each bucket is sorted, and equal runs are one face. Every pass
 * runs through vtkSMPTools; faces come out ordered by their sorted ids, so the
 * result does not depend on the thread count.
 */
#ifndef vtkHAVSFaceSet_h
#define vtkHAVSFaceSet_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkTimeStamp.h"    // For BuildTime

#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkPoints;
class vtkUnstructuredGrid;

class VTKHAVSCORE_EXPORT vtkHAVSFaceSet : public vtkObject
{
public:
  static vtkHAVSFaceSet* New();
  vtkTypeMacro(vtkHAVSFaceSet, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The relative bound below which a tetrahedron is dropped as degenerate: its
   * smallest height (the distance of a point to the opposite face, along that
   * face's normal n) at most this share of the mesh's extent along n (the sum
   * over the axes of |n_k| times the used tetrahedra's bounding-box extent:
   * what float coordinates resolve in that direction, so that a mesh 1e6
   * times longer than wide keeps its cells). Default
   * DefaultMinimumRelativeThickness, 2^-20 (about 9.5e-7: 8 units in the last
   * place of a float; the GPU draws with float coordinates and depths and
   * cannot tell such a cell's faces apart). Such a cell adds at most its
   * thickness times the largest extinction over |cos| of the ray's angle to
   * its faces; in bulk (thousands of mutually intersecting slivers, as a
   * broken mesher writes) it would otherwise break the order its faces are
   * drawn in. The real data sets' thinnest cells are over 1.8e-5 of their
   * diagonal (loxpost; the blunt fin 2.5e-5): none is dropped. 0 keeps every
   * cell of non-zero volume (the rounding rule of double alone). Read by
   * Build().
   */
  static constexpr double DefaultMinimumRelativeThickness = 9.5367431640625e-07;
  vtkSetClampMacro(MinimumRelativeThickness, double, 0.0, 1.0);
  vtkGetMacro(MinimumRelativeThickness, double);
  ///@}

  /**
   * Extracts the faces. Returns false, with an error, for a null grid, a grid
   * without points, too many points for 32-bit ids, or no usable tetrahedron;
   * every array is then empty (the cell counts still say what was found).
   */
  bool Build(vtkUnstructuredGrid* grid);

  ///@{
  /**
   * Faces stored, of which boundary and non-manifold (more than two
   * tetrahedra); tetrahedra used; other cells skipped; degenerate
   * tetrahedra dropped.
   */
  vtkIdType GetNumberOfFaces() const { return static_cast<vtkIdType>(this->BoundaryFlags.size()); }
  vtkGetMacro(NumberOfBoundaryFaces, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldFaces, vtkIdType);
  vtkGetMacro(NumberOfTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfSkippedCells, vtkIdType);
  vtkGetMacro(NumberOfDegenerateTetrahedra, vtkIdType);
  /// Of the degenerate tetrahedra, those of non-zero volume thinner than
  /// MinimumRelativeThickness.
  vtkGetMacro(NumberOfThinTetrahedra, vtkIdType);
  /// Of the degenerate tetrahedra, those with a point id repeated: pieces of
  /// collapsed cells (a wedge with two corners merged, as a clip through a
  /// vertex leaves), which any tetrahedralization of such cells gives.
  vtkGetMacro(NumberOfCollapsedTetrahedra, vtkIdType);
  vtkGetMacro(NumberOfDuplicateTetrahedra, vtkIdType);
  /// Cells with a point id out of range (< 0 or >= the number of points, as a
  /// corrupt file gives): skipped, their points never read.
  vtkGetMacro(NumberOfInvalidCells, vtkIdType);
  /// Ghost cells (duplicate or hidden, vtkGhostType) left out: another piece draws them.
  vtkGetMacro(NumberOfGhostCells, vtkIdType);
  ///@}

  /// Three point ids per face.
  const std::vector<uint32_t>& GetFaceVertices() const { return this->FaceVertices; }
  /// One per face: 1 for a boundary face, 0 for an internal one.
  const std::vector<uint8_t>& GetBoundaryFlags() const { return this->BoundaryFlags; }
  /**
   * Three floats per face: the centroid in model coordinates minus
   * GetCentroidOrigin() (the centre of the points' bounds), so that the floats
   * keep their precision far from the origin. Add the origin back, in double,
   * for the model-space centroid. Made at the first call after Build() (only
   * the centroid sort reads them; the exact orders and the ray caster never
   * do, and need not hold their 12 bytes a face); not thread-safe.
   */
  const std::vector<float>& GetCentroids() const;
  const double* GetCentroidOrigin() const { return this->CentroidOrigin; }

  /// Four point ids per used tetrahedron (skipped and degenerate cells left out).
  const std::vector<uint32_t>& GetTetrahedra() const { return this->Tetrahedra; }
  /// The grid's cell id of each used tetrahedron.
  const std::vector<uint32_t>& GetTetrahedronCells() const { return this->TetrahedronCells; }

  /// No cell on that side of a face (the outside of a boundary face).
  static constexpr uint32_t NoCell = 0xFFFFFFFFu;
  /**
   * Two grid cell ids per face: the cell on the side its winding's normal
   * (p1 - p0) x (p2 - p0) points to, then the cell on the other side; NoCell
   * where there is none (a boundary face's first entry: its normal points
   * out). A fragment of a face seen from the normal's side lies in front of
   * the second cell; seen from the other side, in front of the first. Cell
   * scalars are carried by these.
   */
  const std::vector<uint32_t>& GetFaceCells() const { return this->FaceCells; }

  /// Per point of the grid (numberOfPoints), 1 where a used tetrahedron has it, else 0.
  std::vector<uint8_t> GetPointUse(vtkIdType numberOfPoints) const;

  /**
   * Whether the mesh is one convex body: its boundary is one closed,
   * connected, 2-manifold surface that is locally convex at every edge (the
   * far vertex of each neighbouring boundary face lies on the inner side of
   * the face's plane, up to 1e-9 of the bounds' diagonal), and no face is
   * non-manifold. A closed, connected, embedded surface that is locally
   * convex everywhere bounds a convex body (Hadamard), so a ray meets it at
   * most twice: once in, once out, and boundary tagging cannot change the
   * image. Decided once per Build() in O(boundary faces log boundary faces).
   */
  bool IsConvex() const { return this->Convex; }

  /// The longest edge of the used tetrahedra, in model coordinates.
  vtkGetMacro(LongestEdge, double);

  /// Modified at each Build(), successful or not.
  vtkMTimeType GetBuildTime() const { return this->BuildTime.GetMTime(); }

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSFaceSet() = default;
  ~vtkHAVSFaceSet() override = default;

private:
  vtkHAVSFaceSet(const vtkHAVSFaceSet&) = delete;
  void operator=(const vtkHAVSFaceSet&) = delete;

  void Clear();

  std::vector<uint32_t> FaceVertices;
  std::vector<uint8_t> BoundaryFlags;
  mutable std::vector<float> Centroids;   // made by GetCentroids()
  vtkSmartPointer<vtkPoints> BuiltPoints; // the points the faces were built on (shared)
  std::vector<uint32_t> Tetrahedra;
  std::vector<uint32_t> TetrahedronCells;
  std::vector<uint32_t> FaceCells;
  bool Convex = false;
  vtkIdType NumberOfBoundaryFaces = 0;
  vtkIdType NumberOfNonManifoldFaces = 0;
  vtkIdType NumberOfTetrahedra = 0;
  vtkIdType NumberOfSkippedCells = 0;
  vtkIdType NumberOfDegenerateTetrahedra = 0;
  vtkIdType NumberOfCollapsedTetrahedra = 0;
  vtkIdType NumberOfThinTetrahedra = 0;
  double MinimumRelativeThickness = DefaultMinimumRelativeThickness;
  vtkIdType NumberOfInvalidCells = 0;
  vtkIdType NumberOfDuplicateTetrahedra = 0;
  vtkIdType NumberOfGhostCells = 0;
  double LongestEdge = 0.0;
  double CentroidOrigin[3] = { 0.0, 0.0, 0.0 };
  vtkTimeStamp BuildTime;
};

VTK_ABI_NAMESPACE_END
#endif

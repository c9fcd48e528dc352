/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRayCastMesh.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSRayCastMesh
 * @brief   The compact per-tetrahedron layout a GPU ray caster walks: planes, field, neighbours.
 *
 * Plain C++, no OpenGL (vtkHAVSRayCastMapper; Bernardon, Pagot, Comba and
 * Silva 2005 after Weiler et al. 2003, seed 002). Per tetrahedron, in the
 * mesh's model coordinates (the points already shifted to the mesh's centre
 * by vtkHAVSMesh, so that the floats keep their precision):
 * - its four outward face planes and its linear scalar field, 20 floats
 *   (vtkHAVSCellGeometry, computed in double precision); plane j is the face
 *   opposite vertex j;
 * - its four face neighbours, 4 int32: Neighbours[4 t + j] is the
 *   tetrahedron across face j, -1 on the mesh's boundary.
 * That is 96 bytes per tetrahedron (the seed's layout: 144, Weiler's: 160).
 * Also the boundary faces a ray enters by: their 3 point ids, wound
 * counter-clockwise seen from outside (back-face culling keeps the entries),
 * and the tetrahedron behind each.
 *
 * Neighbours are found by the faces' sorted point ids (the mesh's own
 * connectivity, as vtkHAVSFaceSet): a face shared by two tetrahedra links
 * them, a face of one is boundary. A face shared by more than two (a
 * non-manifold mesh) links its first two and leaves the others boundary.
 */
#ifndef vtkHAVSRayCastMesh_h
#define vtkHAVSRayCastMesh_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes

#include <cstddef> // For size_t
#include <cstdint> // For uint32_t, int32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSRayCastMesh
{
public:
  /// Bytes of a tetrahedron's cell record: four face planes and the field (20 floats).
  static constexpr size_t CellRecordBytes = 20 * sizeof(float);
  /// Bytes per tetrahedron on the GPU: the cell record (80), neighbours (16).
  static constexpr size_t BytesPerTetrahedron = CellRecordBytes + 4 * sizeof(int32_t);

  /**
   * Builds the layout from `points` (3 floats each, model coordinates),
   * `scalars` (1 per point, normalized), `tets` (4 point ids each); with
   * `cellScalars` (1 per tetrahedron) each field is that constant.
   */
  void Build(const std::vector<float>& points, const std::vector<float>& scalars,
    const std::vector<uint32_t>& tets, const std::vector<float>* cellScalars = nullptr);

  /// The fields only (a new time step on the same mesh): planes and neighbours kept.
  void UpdateFields(const std::vector<float>& points, const std::vector<float>& scalars,
    const std::vector<uint32_t>& tets, const std::vector<float>* cellScalars = nullptr);

  /**
   * The neighbour table of `tets` (4 entries per tetrahedron, -1 on the
   * boundary, face j opposite vertex j); returns the number of boundary faces.
   */
  static size_t ComputeNeighbours(const std::vector<uint32_t>& tets, std::vector<int32_t>& out);

  size_t GetNumberOfTetrahedra() const { return this->Neighbours.size() / 4; }
  const std::vector<float>& GetCells() const { return this->Cells; }
  const std::vector<int32_t>& GetNeighbours() const { return this->Neighbours; }
  /// 3 point ids per boundary face, wound outward.
  const std::vector<uint32_t>& GetBoundaryFaces() const { return this->BoundaryFaces; }
  /// The tetrahedron behind each boundary face.
  const std::vector<uint32_t>& GetBoundaryCells() const { return this->BoundaryCells; }
  size_t GetNumberOfBoundaryFaces() const { return this->BoundaryCells.size(); }

  /**
   * Testing aid (a negative control): each tetrahedron's neighbours rotated
   * by one face (the walk then leaves through a face into the wrong cell).
   */
  void BreakNeighboursForTesting();

  /// Frees the cell records (80 bytes a tetrahedron) once the GPU holds them;
  /// UpdateFields() makes them again. Neighbours and boundary are kept.
  void ReleaseCells();

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

private:
  std::vector<float> Cells;
  std::vector<int32_t> Neighbours;
  std::vector<uint32_t> BoundaryFaces;
  std::vector<uint32_t> BoundaryCells;
};

VTK_ABI_NAMESPACE_END
#endif

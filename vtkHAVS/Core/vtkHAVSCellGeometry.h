/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSCellGeometry.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSCellGeometry
 * @brief   Per tetrahedron, what view-independent cell projection reads: face planes, scalar
 * gradient.
 *
 * Plain C++, no OpenGL (vtkHAVSCellProjectionMapper; Weiler, Kraus and Ertl
 * 2002, seed 001). For each tetrahedron, in the mesh's model coordinates:
 * its four face planes (unit outward normal n and offset d, n.x + d > 0
 * outside; plane j is the face opposite vertex j) and the linear scalar
 * field through its vertices (g.x + c, the normalized scalar), 20 floats;
 * and its four faces as 12 point ids, face j wound counter-clockwise seen
 * from outside, so that back-face culling keeps the faces a ray enters by.
 * Computed once per mesh, in double precision, with vtkSMPTools.
 */
#ifndef vtkHAVSCellGeometry_h
#define vtkHAVSCellGeometry_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSCellGeometry
{
public:
  static constexpr int FloatsPerCell = 20; ///< 4 planes, then the gradient and offset

  /**
   * `points` (3 floats each), `scalars` (1 per point), `tets` (4 point ids
   * each) in; `cells` (FloatsPerCell per tetrahedron) and `faces` (12 point
   * ids per tetrahedron) out. With `cellScalars` (1 per tetrahedron: cell
   * data), each field is that constant instead (gradient 0).
   */
  static void Compute(const std::vector<float>& points, const std::vector<float>& scalars,
    const std::vector<uint32_t>& tets, std::vector<float>& cells, std::vector<uint32_t>& faces,
    const std::vector<float>* cellScalars = nullptr);
};

VTK_ABI_NAMESPACE_END
#endif

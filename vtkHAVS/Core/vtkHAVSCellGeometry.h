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
 * and, where asked, its four faces as 12 point ids, face j wound
 * counter-clockwise seen from outside, so that back-face culling keeps the
 * faces a ray enters by. Face j's corners are vertices (j+1, j+2, j+3) mod 4,
 * the last two swapped for even j on a mirrored tetrahedron (negative volume
 * in its vertex order) and for odd j on another (FaceCorners): one bit a
 * tetrahedron (ComputeMirrored) says every winding, so a shader can wind the
 * faces from the point ids alone. Computed once per mesh, in double
 * precision, with vtkSMPTools.
 *
 * On the GPU the records go in up to MaximumRecordBuffers storage buffers, each
 * at most the mapper's LargestGPUBuffer bytes (shaders address a buffer with
 * 32-bit byte offsets: one buffer holds 26.8 million tetrahedra's records):
 * RecordBuffers() says how many, CellsPerRecordBuffer() how many records each
 * holds (the last the rest), LargestRecordBufferNeed() the least that the
 * largest of them can be.
 */
#ifndef vtkHAVSCellGeometry_h
#define vtkHAVSCellGeometry_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro

#include <cstddef> // For size_t
#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSCellGeometry
{
public:
  static constexpr int FloatsPerCell = 20; ///< 4 planes, then the gradient and offset
  static constexpr size_t RecordBytes = FloatsPerCell * sizeof(float);
  static constexpr size_t MaximumRecordBuffers = 4;

  /// The records a buffer of at most `largestBuffer` bytes holds (at least 1).
  static size_t CellsPerRecordBuffer(size_t largestBuffer)
  {
    return largestBuffer / RecordBytes > 0 ? largestBuffer / RecordBytes : 1;
  }
  /// The buffers `cells` records take under `largestBuffer` bytes each (at least 1;
  /// more than MaximumRecordBuffers: the mesh is refused).
  static size_t RecordBuffers(size_t cells, size_t largestBuffer)
  {
    const size_t per = CellsPerRecordBuffer(largestBuffer);
    return cells > per ? (cells + per - 1) / per : 1;
  }
  /// The bytes of the largest record buffer of `cells` records at best: spread
  /// over MaximumRecordBuffers buffers.
  static size_t LargestRecordBufferNeed(size_t cells)
  {
    return RecordBytes * ((cells + MaximumRecordBuffers - 1) / MaximumRecordBuffers);
  }

  /**
   * `points` (3 floats each), `scalars` (1 per point), `tets` (4 point ids
   * each) in; `cells` (FloatsPerCell per tetrahedron) and, unless nullptr,
   * `faces` (12 point ids per tetrahedron) out. With `cellScalars` (1 per
   * tetrahedron: cell data), each field is that constant instead (gradient 0).
   */
  static void Compute(const std::vector<float>& points, const std::vector<float>& scalars,
    const std::vector<uint32_t>& tets, std::vector<float>& cells, std::vector<uint32_t>* faces,
    const std::vector<float>* cellScalars = nullptr);

  /// Bit t % 32 of word t / 32 of `bits`: tetrahedron t is mirrored (Mirrored()).
  static void ComputeMirrored(const std::vector<float>& points, const std::vector<uint32_t>& tets,
    std::vector<uint32_t>& bits);
  /// Whether x[0..3] has negative volume (x1 - x0, x2 - x0, x3 - x0 left-handed).
  static bool Mirrored(const double x[4][3]);
  /// Face j's corners, counter-clockwise seen from outside.
  static void FaceCorners(int j, bool mirrored, int& a, int& b, int& c)
  {
    const bool swapped = (j % 2 == 0) == mirrored;
    a = (j + 1) % 4;
    b = (j + (swapped ? 3 : 2)) % 4;
    c = (j + (swapped ? 2 : 3)) % 4;
  }
};

VTK_ABI_NAMESPACE_END
#endif

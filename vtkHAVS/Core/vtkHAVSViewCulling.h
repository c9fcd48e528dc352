/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSViewCulling.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSViewCulling
 * @brief   Which cells a frame cannot see: outside the view frustum or cut away.
 *
 * Plain C++, no OpenGL. A tetrahedron is culled when its four points lie on
 * the outer side of one plane: one of the view frustum's six (a zoomed-in
 * view) or one of the clipping planes (the discarded side). Every face of
 * such a cell lies entirely outside that plane, so none of its fragments
 * would reach the image (the rasterizer clips them, or the clipping test
 * discards them): not drawing them leaves the image as it is, and no face
 * needs to become a boundary face. A face shared with a kept cell lies
 * outside too and is drawn with it (harmless).
 *
 * Update() runs in parallel (vtkSMPTools) only for new planes or a new
 * mesh; when the mesh's bounding box lies inside every plane it touches no
 * cell (none can be culled).
 */
#ifndef vtkHAVSViewCulling_h
#define vtkHAVSViewCulling_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"

#include <array>   // For std::array
#include <cstdint> // For uint8_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSMesh;

class VTKHAVSCORE_EXPORT vtkHAVSViewCulling : public vtkObject
{
public:
  static vtkHAVSViewCulling* New();
  vtkTypeMacro(vtkHAVSViewCulling, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The planes of a frame in the mesh's model coordinates (vtkHAVSMesh's
   * shifted points): the view frustum's six from the model -> clip matrix
   * (row-major), then `clipping` (a point is kept where dot(xyz, p) + w >= 0).
   */
  static std::vector<std::array<double, 4>> FrustumPlanes(const double modelToClip[16]);

  /**
   * Culls the mesh's cells against `planes` (as FrustumPlanes gives, plus any
   * clipping planes). Returns true when the set of culled cells changed.
   */
  bool Update(vtkHAVSMesh* mesh, const std::vector<std::array<double, 4>>& planes);

  /// Per grid cell id (as vtkHAVSFaceSet::GetFaceCells()): 1 culled, 0 kept.
  const std::vector<uint8_t>& GetCulled() const { return this->Culled; }
  vtkGetMacro(NumberOfCulledCells, vtkIdType);
  vtkGetMacro(LastSeconds, double);
  /// Changes each time the set of culled cells does.
  vtkMTimeType GetCullingVersion() const { return this->CullingTime.GetMTime(); }

  /// True when all four points lie where dot(xyz, p) + w < 0 for `plane`.
  static bool Outside(const float* const points[4], const double plane[4]);

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSViewCulling() = default;
  ~vtkHAVSViewCulling() override = default;

private:
  vtkHAVSViewCulling(const vtkHAVSViewCulling&) = delete;
  void operator=(const vtkHAVSViewCulling&) = delete;

  std::vector<uint8_t> Culled;
  vtkIdType NumberOfCulledCells = 0;
  double LastSeconds = 0.0;
  vtkMTimeType MeshVersion = 0;
  std::vector<std::array<double, 4>> LastPlanes;
  vtkTimeStamp CullingTime;
};

VTK_ABI_NAMESPACE_END
#endif

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSPlaneSection.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSPlaneSection
 * @brief   The cross-section of a tetrahedral mesh with a plane, as triangles.
 *
 * Plain C++, no OpenGL. Each tetrahedron that the plane cuts contributes a
 * triangle (one vertex on one side) or a quadrilateral split in two (two on
 * each side); each section point lies on a cut edge, its scalar interpolated
 * linearly along the edge, so the section carries the exact scalar of the
 * mesh on the plane (the scalar is linear in each tetrahedron). The sections
 * of neighbouring tetrahedra share their cut edges: the section is a
 * watertight partition of the mesh's intersection with the plane.
 *
 * vtkHAVSVolumeMapper draws these sections where the near plane or a
 * clipping plane cuts the mesh, as the fragments where the rays enter (or
 * leave) the clipped volume: no face of the mesh lies there.
 *
 * Points are in the mapper's model coordinates (floats, shifted); the plane
 * is given in the same coordinates (a, b, c, d: a x + b y + c z + d = 0).
 * Runs in parallel through vtkSMPTools; the output order does not depend on
 * the thread count.
 */
#ifndef vtkHAVSPlaneSection_h
#define vtkHAVSPlaneSection_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"

#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSPlaneSection : public vtkObject
{
public:
  static vtkHAVSPlaneSection* New();
  vtkTypeMacro(vtkHAVSPlaneSection, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Cuts the tetrahedra (4 point ids each) with the plane. `points` holds 3
   * floats per point, `scalars` one per point. Fills `sectionPoints` (9 floats
   * per triangle) and `sectionScalars` (3 per triangle); returns the number
   * of triangles. `sectionCells`, when given, gets the tetrahedron (its index
   * in `tetrahedra`) of each triangle.
   */
  vtkIdType Compute(const std::vector<uint32_t>& tetrahedra, const std::vector<float>& points,
    const std::vector<float>& scalars, const double plane[4], std::vector<float>& sectionPoints,
    std::vector<float>& sectionScalars, std::vector<uint32_t>* sectionCells = nullptr);

  /// Seconds the last Compute() took.
  vtkGetMacro(LastSeconds, double);

  /**
   * Whether the plane separates the corners of the box (xmin, xmax, ymin,
   * ymax, zmin, zmax): false when the whole box lies on one side.
   */
  static bool CutsBox(const double plane[4], const double bounds[6]);

protected:
  vtkHAVSPlaneSection() = default;
  ~vtkHAVSPlaneSection() override = default;

private:
  vtkHAVSPlaneSection(const vtkHAVSPlaneSection&) = delete;
  void operator=(const vtkHAVSPlaneSection&) = delete;

  double LastSeconds = 0.0;
};

VTK_ABI_NAMESPACE_END
#endif

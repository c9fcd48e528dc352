/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSStandardViews.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSStandardViews
 * @brief   The 14 standard views of a mesh: 6 axis directions, 8 cube diagonals.
 *
 * As in Callahan's timings (thesis Table 4.5) and MISSION.md's measure of
 * "exact": view i < 6 looks along -axis (x, -x, y, -y, z, -z: the eye on that
 * side), views 6 … 13 from the cube diagonals (±1, ±1, ±1). Perspective, a
 * 30 degree view angle, the bounding sphere filling the view, the clipping
 * range just around it.
 */
#ifndef vtkHAVSStandardViews_h
#define vtkHAVSStandardViews_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSValidationModule.h" // For export macro
#include "vtkObject.h"

VTK_ABI_NAMESPACE_BEGIN

class vtkCamera;
class vtkDataSet;

class VTKHAVSVALIDATION_EXPORT vtkHAVSStandardViews : public vtkObject
{
public:
  static vtkHAVSStandardViews* New();
  vtkTypeMacro(vtkHAVSStandardViews, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  static constexpr int NumberOfViews = 14;

  /// The direction from the centre to the eye of view i (not normalized).
  static void GetDirection(int view, double direction[3]);

  /// Places `camera` for view i of `data`.
  static void PlaceCamera(vtkCamera* camera, vtkDataSet* data, int view);

protected:
  vtkHAVSStandardViews() = default;
  ~vtkHAVSStandardViews() override = default;

private:
  vtkHAVSStandardViews(const vtkHAVSStandardViews&) = delete;
  void operator=(const vtkHAVSStandardViews&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRasterBoundPass.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSRasterBoundPass
 * @brief   Benchmark aid: the ordered faces with a trivial shader, nothing else.
 *
 * The same faces in the same order as a k-buffer frame, through a fragment
 * shader that only adds a constant (additive blending into the result, which
 * is never composited): the time of the rasterization alone, the lower bound
 * of any face-based method on the machine
 * (vtkHAVSVolumeMapper::FaceRasterBoundMode).
 */
#ifndef vtkHAVSRasterBoundPass_h
#define vtkHAVSRasterBoundPass_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkObject.h"

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLPassContext;

class vtkHAVSRasterBoundPass : public vtkObject
{
public:
  static vtkHAVSRasterBoundPass* New();
  vtkTypeMacro(vtkHAVSRasterBoundPass, vtkObject);

  bool Draw(vtkHAVSGLPassContext& context);

protected:
  vtkHAVSRasterBoundPass() = default;
  ~vtkHAVSRasterBoundPass() override = default;

private:
  vtkHAVSRasterBoundPass(const vtkHAVSRasterBoundPass&) = delete;
  void operator=(const vtkHAVSRasterBoundPass&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif

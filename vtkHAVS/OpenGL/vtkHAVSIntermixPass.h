/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSIntermixPass.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSIntermixPass
 * @brief   VTK's render steps with translucent geometry intermixed into the
 *          HAVS volumes: set it as the renderer's pass.
 *
 * vtkRenderStepsPass (camera, lights, opaque, translucent, volumetric,
 * overlay) whose translucent step peels the translucent actors into layers
 * (vtkHAVSTranslucentLayers, GetLayers()) instead of drawing them, and whose
 * volumetric step draws the volumes (VTK's vtkVolumetricPass), a HAVS
 * volume that intermixes (vtkHAVSMapperBase::IntermixTranslucentGeometry,
 * the composite or isosurface blend) compositing the layers at their depths
 * within itself:
 *
 * @code{.cpp}
 * vtkNew<vtkHAVSIntermixPass> pass;
 * renderer->SetPass(pass);
 * @endcode
 *
 * Where no volume of the renderer intermixes, the layers are composited over
 * the window before the volumes (VTK's order: the volumes over the
 * translucent scene, which the layers give exactly, sorted per pixel). One
 * volume per renderer takes them (the first drawn); the other volumes are
 * composited over the result as a whole, as VTK composites volumes.
 */
#ifndef vtkHAVSIntermixPass_h
#define vtkHAVSIntermixPass_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN
#include "vtkHAVSOpenGLModule.h" // For export macro
#include "vtkNew.h"              // For vtkNew
#include "vtkRenderStepsPass.h"

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSTranslucentLayers;
class vtkRenderState;
class vtkRenderer;

class VTKHAVSOPENGL_EXPORT vtkHAVSIntermixPass : public vtkRenderStepsPass
{
public:
  static vtkHAVSIntermixPass* New();
  vtkTypeMacro(vtkHAVSIntermixPass, vtkRenderStepsPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The translucent step: the peeled layers of the last frame.
  vtkHAVSTranslucentLayers* GetLayers() { return this->Layers; }

  /// Whether a visible volume of `renderer` has a HAVS mapper that intermixes
  /// (any HAVS mapper when `intermixing` is false).
  static bool HasIntermixingVolume(vtkRenderer* renderer, bool intermixing = true);
  /// Whether a visible prop of `s` (not a volume) has translucent polygonal geometry.
  static bool HasTranslucentGeometry(const vtkRenderState* s);

  /**
   * The steps without the camera pass (lights, opaque, the peel, the volumes,
   * overlay): for a host whose own camera pass delegates to this pass's
   * steps (the ParaView plugin puts them in place of ParaView's default pass).
   */
  void RenderSteps(const vtkRenderState* s);

protected:
  vtkHAVSIntermixPass();
  ~vtkHAVSIntermixPass() override;

private:
  vtkHAVSIntermixPass(const vtkHAVSIntermixPass&) = delete;
  void operator=(const vtkHAVSIntermixPass&) = delete;

  vtkNew<vtkHAVSTranslucentLayers> Layers;
};

VTK_ABI_NAMESPACE_END
#endif

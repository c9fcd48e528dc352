/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSExtremumPass.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSExtremumPass
 * @brief   Maximum and minimum intensity projection: no k-buffer, no order.
 *
 * Draw(): every face fragment writes its scalar into the result with GL_MAX
 * blending (the minimum as the maximum of 1 - s), so the order of the faces
 * does not matter. Resolve(): each pixel's extremal scalar coloured from the
 * 1D transfer function (colour and opacity), as VTK's ray casters do.
 * ResolveResult() is that resolve for any result target (also the
 * additive blend's, for vtkOpenGLHAVSCellProjectionMapper).
 */
#ifndef vtkHAVSExtremumPass_h
#define vtkHAVSExtremumPass_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkObject.h"

VTK_ABI_NAMESPACE_BEGIN

class vtkHAVSGLFrameTargets;
class vtkHAVSGLPassContext;
class vtkHAVSGLTable;
class vtkOpenGLRenderWindow;

class vtkHAVSExtremumPass : public vtkObject
{
public:
  static vtkHAVSExtremumPass* New();
  vtkTypeMacro(vtkHAVSExtremumPass, vtkObject);

  bool Draw(vtkHAVSGLPassContext& context);
  bool Resolve(vtkHAVSGLPassContext& context);

  enum ResolveKind
  {
    ResolveMaximum,  ///< result (s, covered): colour and opacity of s
    ResolveMinimum,  ///< result (1 - s, covered): colour and opacity of s
    ResolveAdditive, ///< result (sum, covered): grey clamp(sum), opacity 1
  };
  /**
   * Resolves `targets`' result in place (the table uploaded and active).
   * False when the program could not be built.
   */
  static bool ResolveResult(vtkOpenGLRenderWindow* window, vtkHAVSGLFrameTargets* targets,
    vtkHAVSGLTable* table, ResolveKind kind);
  /**
   * The same for a mapper's blend mode (vtkVolumeMapper's BlendModes: maximum,
   * minimum or additive; composite needs no resolve and returns true).
   */
  static bool ResolveBlend(vtkOpenGLRenderWindow* window, vtkHAVSGLFrameTargets* targets,
    vtkHAVSGLTable* table, int blendMode);

protected:
  vtkHAVSExtremumPass() = default;
  ~vtkHAVSExtremumPass() override = default;

private:
  vtkHAVSExtremumPass(const vtkHAVSExtremumPass&) = delete;
  void operator=(const vtkHAVSExtremumPass&) = delete;
};

VTK_ABI_NAMESPACE_END
#endif

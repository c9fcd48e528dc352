/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSLevelOfDetailController.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSLevelOfDetailController
 * @brief   How many internal faces the next frame draws, so that it takes the
 *          time the renderer allocates.
 *
 * Plain C++, no OpenGL. The thesis' rule |I| <- |I| * target / last (Callahan
 * 2005, chapter 5), damped: the fraction f of the internal faces drawn becomes
 * f * (target / last)^Gain, left as it is while the last frame took within
 * Deadband (relative) of the target. With a frame time a + b f (the boundary
 * faces' fixed part a, the internal faces' b f), the step's derivative at the
 * fixed point is 1 - Gain (1 - a / target), between 0 and 1 for a Gain in
 * (0, 1]: the fraction converges without overshooting, so it never
 * oscillates; the dead band keeps noise from moving it once there. Full
 * quality (f = 1) whenever the budget allows: when the last full frame took
 * no more than the target, or the step reaches 1.
 */
#ifndef vtkHAVSLevelOfDetailController_h
#define vtkHAVSLevelOfDetailController_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkObject.h"

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSLevelOfDetailController : public vtkObject
{
public:
  static vtkHAVSLevelOfDetailController* New();
  vtkTypeMacro(vtkHAVSLevelOfDetailController, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The step's exponent (0.7 by default; 1 is the thesis' undamped rule) and
  /// the relative dead band around the target (0.1 by default).
  vtkSetClampMacro(Gain, double, 0.0, 4.0);
  vtkGetMacro(Gain, double);
  vtkSetClampMacro(Deadband, double, 0.0, 1.0);
  vtkGetMacro(Deadband, double);
  ///@}

  /**
   * The smallest fraction above 0 a step goes to (default 0.01): a step
   * below it while the frames are too slow gives 0, and a step up from 0 (or
   * from below it) starts there. The image reduction's controller sets the
   * smallest share of the detail its image can draw.
   */
  vtkSetClampMacro(SmallestFraction, double, 1.0e-8, 1.0);
  vtkGetMacro(SmallestFraction, double);

  /**
   * The fraction of the internal faces the next frame draws (0: the boundary
   * faces only; 1: all) for a frame budget of `targetSeconds`.
   */
  double Choose(double targetSeconds);

  /// The frame drawn at `fraction` took `seconds`.
  void FrameDrawn(double fraction, double seconds);

  /// Forgets every frame (a new mesh): the next Choose() gives 1.
  void Reset();

  ///@{
  /// The last frame recorded, and the last full-quality frame's time (-1: none).
  vtkGetMacro(LastFraction, double);
  vtkGetMacro(LastSeconds, double);
  vtkGetMacro(FullSeconds, double);
  ///@}

protected:
  vtkHAVSLevelOfDetailController() = default;
  ~vtkHAVSLevelOfDetailController() override = default;

private:
  vtkHAVSLevelOfDetailController(const vtkHAVSLevelOfDetailController&) = delete;
  void operator=(const vtkHAVSLevelOfDetailController&) = delete;

  double Gain = 0.7;
  double Deadband = 0.1;
  double SmallestFraction = 0.01;
  double LastFraction = 1.0;
  double LastSeconds = -1.0;
  double FullSeconds = -1.0;
};

VTK_ABI_NAMESPACE_END
#endif

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSImageMetrics.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSImageMetrics
 * @brief   Error between two premultiplied RGBA images in [0, 1].
 *
 * The one comparison used by the tests, the demo and the benchmark: RMSE over
 * all channels, PSNR (peak 1), the largest absolute channel error, and the
 * share of pixels with a channel off by more than 1/255 and 4/255. A
 * non-finite value counts as an error of 1. DifferenceImage() paints the
 * per-pixel largest error in false colour (black 0, blue, green, yellow, red
 * at >= Scale).
 */
#ifndef vtkHAVSImageMetrics_h
#define vtkHAVSImageMetrics_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSValidationModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class vtkFloatArray;
class vtkUnsignedCharArray;

class VTKHAVSVALIDATION_EXPORT vtkHAVSImageMetrics : public vtkObject
{
public:
  static vtkHAVSImageMetrics* New();
  vtkTypeMacro(vtkHAVSImageMetrics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Compares two 4-component arrays of the same size. Returns false (and
   * sets every metric to its worst) when they do not match in size.
   */
  bool Compare(vtkFloatArray* a, vtkFloatArray* b);

  /// The same on raw RGBA floats (`pixels` * 4 values each).
  bool Compare(const float* a, const float* b, vtkIdType pixels);
  /// The same on RGBA vectors; false (every metric at its worst) when their sizes differ.
  bool Compare(const std::vector<float>& a, const std::vector<float>& b);

  ///@{
  /**
   * Leave out the pixels with the largest error, this many (default 0): for
   * comparisons that must tolerate a known number of rasterization-edge
   * pixels, which the test then states and counts.
   */
  vtkSetClampMacro(IgnoreWorstPixels, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(IgnoreWorstPixels, vtkIdType);
  ///@}

  vtkGetMacro(RMSE, double);
  vtkGetMacro(PSNR, double);
  vtkGetMacro(MaxAbsError, double);
  vtkGetMacro(FractionOver1, double);
  vtkGetMacro(FractionOver4, double);

  ///@{
  /// The error that maps to full red in DifferenceImage (default 16/255).
  vtkSetMacro(Scale, double);
  vtkGetMacro(Scale, double);
  ///@}

  /**
   * False-colour image (RGB, 3 components) of the per-pixel largest channel
   * error between a and b.
   */
  void DifferenceImage(vtkFloatArray* a, vtkFloatArray* b, vtkUnsignedCharArray* rgb);

protected:
  vtkHAVSImageMetrics() = default;
  ~vtkHAVSImageMetrics() override = default;

private:
  vtkHAVSImageMetrics(const vtkHAVSImageMetrics&) = delete;
  void operator=(const vtkHAVSImageMetrics&) = delete;

  double RMSE = 0.0;
  double PSNR = 0.0;
  double MaxAbsError = 0.0;
  double FractionOver1 = 0.0;
  double FractionOver4 = 0.0;
  double Scale = 16.0 / 255.0;
  vtkIdType IgnoreWorstPixels = 0;
};

VTK_ABI_NAMESPACE_END
#endif

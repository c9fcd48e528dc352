/*=========================================================================

  Project:   vtkHAVS
  Module:    havsTestImages.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @file havsTestImages.h
 * @brief Images in the vtkHAVS tests: read-backs, the one image metric, PNG files.
 *
 * Every comparison goes through vtkHAVSImageMetrics (Compare() here only adapts
 * std::vector images to it).
 */
#ifndef havsTestImages_h
#define havsTestImages_h

#include <cstddef>
#include <string>
#include <vector>

class vtkAbstractVolumeMapper;
class vtkRenderWindow;
class vtkUnsignedCharArray;

namespace havstest
{
/// Directory where tests write images and logs, from HAVS_TEST_OUTPUT_DIR.
std::string OutputDir();
/// Directory of the baseline images, from HAVS_BASELINE_DIR.
std::string BaselineDir();

/// Reads the window's RGBA (float, [0,1]) after a render.
std::vector<float> ReadRGBA(vtkRenderWindow* window);
/// The kept float result (KeepFloatResultOn before rendering) of a
/// vtkHAVSVolumeMapper, vtkHAVSCellProjectionMapper or vtkHAVSRayCastMapper; empty without one.
std::vector<float> FloatResult(vtkAbstractVolumeMapper* mapper);

/// vtkHAVSImageMetrics' figures of a comparison.
struct ImageDifference
{
  double RMSE = 0;
  double Max = 0;
  double FractionOver1 = 0; ///< share of pixels with a channel off by more than 1/255
  double FractionOver4 = 0; ///< … by more than 4/255
};
/// vtkHAVSImageMetrics::Compare of two RGBA images, the ignoreWorst pixels
/// with the largest error left out (1e30 everywhere when the sizes differ).
ImageDifference Compare(
  const std::vector<float>& a, const std::vector<float>& b, size_t ignoreWorst = 0);

/// True when every value is finite (for float results, not 8-bit read-backs).
bool AllFinite(const std::vector<float>& values);

/// Writes RGBA floats as PNG into the output directory.
void WritePNG(const std::vector<float>& rgba, int width, int height, const std::string& name);
/// Writes a 3-component unsigned char image as PNG into the output directory.
void WriteRGB(vtkUnsignedCharArray* rgb, int width, int height, const std::string& name);
/// Reads a PNG as RGBA floats; empty on failure.
std::vector<float> ReadPNG(const std::string& path, int* width, int* height);
}

#endif

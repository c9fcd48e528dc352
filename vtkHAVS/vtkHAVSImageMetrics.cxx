/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSImageMetrics.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSImageMetrics.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkHAVSImageMetrics);

namespace
{
double ChannelError(float a, float b)
{
  const double e = std::fabs(double(a) - double(b));
  return std::isfinite(e) ? e : 1.0;
}
}

//------------------------------------------------------------------------------
bool vtkHAVSImageMetrics::Compare(vtkFloatArray* a, vtkFloatArray* b)
{
  if (!a || !b || a->GetNumberOfComponents() != 4 || b->GetNumberOfComponents() != 4 ||
    a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    this->RMSE = this->MaxAbsError = this->FractionOver1 = this->FractionOver4 = 1.0;
    this->PSNR = 0.0;
    return false;
  }
  return this->Compare(a->GetPointer(0), b->GetPointer(0), a->GetNumberOfTuples());
}

//------------------------------------------------------------------------------
bool vtkHAVSImageMetrics::Compare(const float* a, const float* b, vtkIdType pixels)
{
  double sum = 0.0, worst = 0.0;
  vtkIdType over1 = 0, over4 = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    double pixelWorst = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      const double e = ChannelError(a[4 * p + c], b[4 * p + c]);
      sum += e * e;
      pixelWorst = std::max(pixelWorst, e);
    }
    worst = std::max(worst, pixelWorst);
    over1 += pixelWorst > 1.0 / 255.0 ? 1 : 0;
    over4 += pixelWorst > 4.0 / 255.0 ? 1 : 0;
  }
  const double n = std::max<vtkIdType>(pixels, 1);
  this->RMSE = std::sqrt(sum / (4.0 * n));
  this->PSNR = this->RMSE > 0.0 ? -20.0 * std::log10(this->RMSE) : INFINITY;
  this->MaxAbsError = worst;
  this->FractionOver1 = over1 / n;
  this->FractionOver4 = over4 / n;
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSImageMetrics::DifferenceImage(
  vtkFloatArray* a, vtkFloatArray* b, vtkUnsignedCharArray* rgb)
{
  const vtkIdType pixels = a && b ? std::min(a->GetNumberOfTuples(), b->GetNumberOfTuples()) : 0;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(pixels);
  // Colour ramp: black, blue, green, yellow, red.
  static const double ramp[5][3] = { { 0, 0, 0 }, { 0, 0, 1 }, { 0, 1, 0 }, { 1, 1, 0 },
    { 1, 0, 0 } };
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    double e = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      e = std::max(e, ChannelError(a->GetValue(4 * p + c), b->GetValue(4 * p + c)));
    }
    const double t = std::min(e / this->Scale, 1.0) * 4.0;
    const int i = std::min(static_cast<int>(t), 3);
    const double f = t - i;
    for (int c = 0; c < 3; ++c)
    {
      const double v = (1 - f) * ramp[i][c] + f * ramp[i + 1][c];
      rgb->SetValue(3 * p + c, static_cast<unsigned char>(255.0 * v + 0.5));
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSImageMetrics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RMSE: " << this->RMSE << "\n";
  os << indent << "PSNR: " << this->PSNR << "\n";
  os << indent << "MaxAbsError: " << this->MaxAbsError << "\n";
  os << indent << "FractionOver1: " << this->FractionOver1 << "\n";
  os << indent << "FractionOver4: " << this->FractionOver4 << "\n";
  os << indent << "Scale: " << this->Scale << "\n";
}

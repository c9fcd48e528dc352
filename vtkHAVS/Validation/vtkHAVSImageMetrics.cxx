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

VTK_ABI_NAMESPACE_BEGIN

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
  std::vector<double> squares(static_cast<size_t>(std::max<vtkIdType>(pixels, 0)), 0.0);
  std::vector<double> worst(squares.size(), 0.0);
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    for (int c = 0; c < 4; ++c)
    {
      const double e = ChannelError(a[4 * p + c], b[4 * p + c]);
      squares[p] += e * e;
      worst[p] = std::max(worst[p], e);
    }
  }
  // The IgnoreWorstPixels pixels with the largest error are left out.
  std::vector<uint8_t> kept(squares.size(), 1);
  const vtkIdType ignored = std::min(this->IgnoreWorstPixels, pixels);
  if (ignored > 0)
  {
    std::vector<vtkIdType> byError(squares.size());
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      byError[p] = p;
    }
    std::partial_sort(byError.begin(), byError.begin() + ignored, byError.end(),
      [&](vtkIdType x, vtkIdType y) { return worst[x] > worst[y]; });
    for (vtkIdType i = 0; i < ignored; ++i)
    {
      kept[byError[i]] = 0;
    }
  }
  double sum = 0.0, maximum = 0.0;
  vtkIdType over1 = 0, over4 = 0, count = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    if (!kept[p])
    {
      continue;
    }
    sum += squares[p];
    maximum = std::max(maximum, worst[p]);
    over1 += worst[p] > 1.0 / 255.0 ? 1 : 0;
    over4 += worst[p] > 4.0 / 255.0 ? 1 : 0;
    ++count;
  }
  const double n = static_cast<double>(std::max<vtkIdType>(count, 1));
  this->RMSE = std::sqrt(sum / (4.0 * n));
  this->PSNR = this->RMSE > 0.0 ? -20.0 * std::log10(this->RMSE) : INFINITY;
  this->MaxAbsError = maximum;
  this->FractionOver1 = over1 / n;
  this->FractionOver4 = over4 / n;
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSImageMetrics::Compare(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size() || a.empty() || a.size() % 4 != 0)
  {
    this->RMSE = this->MaxAbsError = this->FractionOver1 = this->FractionOver4 = 1e30;
    this->PSNR = 0.0;
    return false;
  }
  return this->Compare(a.data(), b.data(), static_cast<vtkIdType>(a.size() / 4));
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
  os << indent << "IgnoreWorstPixels: " << this->IgnoreWorstPixels << "\n";
}

VTK_ABI_NAMESPACE_END

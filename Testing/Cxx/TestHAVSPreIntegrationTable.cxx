/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSPreIntegrationTable.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSPreIntegrationTable against closed forms and the adaptive reference:
// - constant opacity and colour: every entry is 1 - exp(-tau L), c * alpha;
// - opacity linear over the range, constant colour: alpha = 1 - exp(-L (tau_f + tau_b) / 2);
// - a property with midpoints, sharpness and HSV colour: random lookups
//   against IntegrateSegment within a stated bound at 128^3, with a negative
//   control (an 8^3 table must miss the bound);
// - IntegrateSegment composes: (f -> b, L) = (f -> m, L/2) over (m -> b, L/2);
// - the windowed composites (issue 45): every entry of 41 x 41 x 17 tables
//   (linear and logarithmic length axes) equals the table's quadrature of
//   that one segment (IntegrateSubSteps) to 1e-6; controls: the neighbouring
//   layer's length, and half the sub-steps, must miss;
// - the logarithmic length axis: short segments against IntegrateSegment;
//   long, optically thick ones (200 to 1e5 units) against a brute-force
//   integral, with a negative control (the former mean-colour rule);
// - NeedsRebuild follows the property; degenerate inputs stay finite.
#include "havsTestChecks.h"
#include "havsTestProperties.h"

#include "vtkColorTransferFunction.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <random>
#include <utility>

namespace
{
vtkSmartPointer<vtkVolumeProperty> Fancy()
{
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkColorTransferFunction> color;
  color->SetColorSpaceToHSV();
  color->AddRGBPoint(0.0, 0.0, 0.0, 1.0, 0.3, 0.8);
  color->AddRGBPoint(0.4, 0.0, 1.0, 0.0);
  color->AddRGBPoint(1.0, 1.0, 0.2, 0.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(0.35, 0.6, 0.7, 0.2);
  opacity->AddPoint(0.6, 0.1);
  opacity->AddPoint(1.0, 0.9);
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(0.5);
  return property;
}

double MaxLookupError(vtkVolumeProperty* property, int resolution, double maxLength)
{
  vtkNew<vtkHAVSPreIntegrationTable> table;
  table->SetScalarResolution(resolution);
  table->SetLengthResolution(resolution);
  const double range[2] = { 0.0, 1.0 };
  table->Build(property, 0, range, maxLength);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 400; ++i)
  {
    const double sf = u(random), sb = u(random), len = u(random) * maxLength;
    double got[4], want[4];
    table->Lookup(sf, sb, len, got);
    vtkHAVSPreIntegrationTable::IntegrateSegment(property, 0, sf, sb, len, want);
    for (int c = 0; c < 4; ++c)
    {
      worst = std::max(worst, std::fabs(got[c] - want[c]));
    }
  }
  return worst;
}

/// Independent brute force of a segment's integral straight from the
/// property's functions: midpoint rule with the exact exponential per step
/// (of optical depth <= 1e-3 at the step's start, and <= length / 2e5),
/// long double accumulation, stopping once the transmittance is below 1e-15
/// (nothing behind can show). Its error is < 1e-8 on the segments below
/// (checked against steps four times smaller when it was written).
void BruteForce(vtkVolumeProperty* property, double sf, double sb, double length, double rgba[4])
{
  const double unit = property->GetScalarOpacityUnitDistance();
  auto tau = [&](double s) { return property->GetScalarOpacity()->GetValue(s) / unit; };
  long double color[3] = { 0, 0, 0 }, transmittance = 1;
  double t = 0.0;
  while (t < length && transmittance > 1e-15L)
  {
    const double tau0 = tau(sf + (sb - sf) * t / length);
    const double h = std::min({ length / 2e5, 1e-3 / std::max(tau0, 1e-300), length - t });
    const double s = sf + (sb - sf) * (t + 0.5 * h) / length;
    double c[3];
    property->GetRGBTransferFunction()->GetColor(s, c);
    const long double alpha = -std::expm1(-static_cast<long double>(tau(s)) * h);
    for (int k = 0; k < 3; ++k)
    {
      color[k] += transmittance * alpha * c[k];
    }
    transmittance *= 1 - alpha;
    t += h;
  }
  for (int k = 0; k < 3; ++k)
  {
    rgba[k] = static_cast<double>(color[k]);
  }
  rgba[3] = static_cast<double>(1 - transmittance);
}

/// The negative control: the table's sub-steps (4 per table interval of a
/// 128 table) composited with the rule the table used before issue 20's fix,
/// the tau-weighted mean colour times the sub-step's opacity, which an opaque
/// sub-step (long segments) gets wrong by half its colour change.
void MeanColorRule(vtkVolumeProperty* property, double sf, double sb, double length, double rgba[4])
{
  const double unit = property->GetScalarOpacityUnitDistance();
  const int n = std::max(1, static_cast<int>(std::lround(std::fabs(sb - sf) * 127 * 4)));
  double color[3] = { 0, 0, 0 }, transmittance = 1.0, ca[3], cb[3];
  double ta = property->GetScalarOpacity()->GetValue(sf) / unit;
  property->GetRGBTransferFunction()->GetColor(sf, ca);
  for (int j = 1; j <= n; ++j)
  {
    const double s = sf + (sb - sf) * j / n;
    const double tb = property->GetScalarOpacity()->GetValue(s) / unit;
    property->GetRGBTransferFunction()->GetColor(s, cb);
    const double attenuation = std::exp(-0.5 * (ta + tb) * length / n);
    if (ta + tb > 0.0)
    {
      for (int k = 0; k < 3; ++k)
      {
        color[k] += transmittance * (1.0 - attenuation) * (ca[k] * ta + cb[k] * tb) / (ta + tb);
      }
    }
    transmittance *= attenuation;
    ta = tb;
    std::copy(cb, cb + 3, ca);
  }
  std::copy(color, color + 3, rgba);
  rgba[3] = 1.0 - transmittance;
}

double MaxDifference(const double a[4], const double b[4])
{
  double worst = 0.0;
  for (int c = 0; c < 4; ++c)
  {
    worst = std::max(worst, std::fabs(a[c] - b[c]));
  }
  return worst;
}
}

int TestHAVSPreIntegrationTable(int, char*[])
{
  const double range[2] = { 0.0, 1.0 };
  vtkNew<vtkHAVSPreIntegrationTable> table;
  table->SetScalarResolution(32);
  table->SetLengthResolution(32);

  // Constant: tau = 0.5 / 0.25 = 2.
  auto constant = havstest::MakeConstantProperty(0.2, 0.6, 0.9, 0.5, 0.25);
  havstest::Check(table->Build(constant, 0, range, 1.5), "constant builds");
  double worst = 0.0;
  const float* t = table->GetTable();
  for (int l = 0; l < 32; ++l)
  {
    const double alpha = 1.0 - std::exp(-2.0 * 1.5 * l / 31.0);
    for (int i = 0; i < 32 * 32; ++i)
    {
      const float* e = t + 4 * (static_cast<size_t>(l) * 32 * 32 + i);
      worst = std::max<double>({ worst, std::fabs(double(e[3]) - alpha),
        std::fabs(double(e[0]) - 0.2 * alpha), std::fabs(double(e[2]) - 0.9 * alpha) });
    }
  }
  std::cout << "constant: max error " << worst << std::endl;
  havstest::Check(worst < 1e-5, "constant entries equal the closed form");

  // Linear opacity 0 -> 1 over the range, unit distance 1, constant colour.
  auto ramp = havstest::MakeConstantProperty(0.2, 0.6, 0.9, 1.0, 1.0);
  ramp->GetScalarOpacity()->RemoveAllPoints();
  ramp->GetScalarOpacity()->AddPoint(0.0, 0.0);
  ramp->GetScalarOpacity()->AddPoint(1.0, 1.0);
  table->Build(ramp, 0, range, 2.0);
  worst = 0.0;
  for (int l = 0; l < 32; l += 3)
  {
    for (int b = 0; b < 32; b += 3)
    {
      for (int f = 0; f < 32; f += 3)
      {
        const double len = 2.0 * l / 31.0;
        const double alpha = 1.0 - std::exp(-len * (f / 31.0 + b / 31.0) / 2.0);
        const float* e = t + 4 * ((static_cast<size_t>(l) * 32 + b) * 32 + f);
        worst = std::max<double>(
          { worst, std::fabs(double(e[3]) - alpha), std::fabs(double(e[1]) - 0.6 * alpha) });
      }
    }
  }
  std::cout << "linear ramp: max error " << worst << std::endl;
  havstest::Check(worst < 1e-4, "linear ramp entries equal the closed form");

  // A property with midpoints, sharpness and HSV interpolation.
  auto fancy = Fancy();
  const double fine = MaxLookupError(fancy, 128, 1.0);
  const double finer = MaxLookupError(fancy, 256, 1.0);
  const double coarse = MaxLookupError(fancy, 8, 1.0);
  std::cout << "lookup vs IntegrateSegment: 8^3 " << coarse << ", 128^3 " << fine << ", 256^3 "
            << finer << std::endl;
  const double bound = 0.01;
  havstest::Check(fine < bound, "128^3 table within 0.01 of the adaptive integral");
  havstest::Check(finer < fine, "a finer table is closer");
  havstest::Check(coarse > bound, "negative control: an 8^3 table misses the bound");

  // Composition of the reference.
  double whole[4], front[4], back[4];
  vtkHAVSPreIntegrationTable::IntegrateSegment(fancy, 0, 0.1, 0.9, 0.8, whole);
  vtkHAVSPreIntegrationTable::IntegrateSegment(fancy, 0, 0.1, 0.5, 0.4, front);
  vtkHAVSPreIntegrationTable::IntegrateSegment(fancy, 0, 0.5, 0.9, 0.4, back);
  double composed = 0.0;
  for (int c = 0; c < 4; ++c)
  {
    composed = std::max(composed, std::fabs(whole[c] - (front[c] + (1 - front[3]) * back[c])));
  }
  havstest::Check(composed < 1e-5, "IntegrateSegment composes front to back");

  // The windowed composites against the quadrature of each segment alone.
  // 41 scalars, 4 sub-steps: the fine grid has steps of 1/160, on which
  // Fancy's nodes (0.35, 0.4, 0.6) lie, so no node is added to it.
  for (const double maxLength : { 1.0, 1e3 })
  {
    const int ns = 41, nl = 17, sub = 4;
    vtkNew<vtkHAVSPreIntegrationTable> windowed;
    windowed->SetScalarResolution(ns);
    windowed->SetLengthResolution(nl);
    windowed->SetSubdivisionsPerInterval(sub);
    windowed->Build(fancy, 0, range, maxLength);
    double worstEntry = 0.0, worstNeighbour = 0.0, worstHalf = 0.0;
    for (int l = 1; l < nl; ++l)
    {
      const double length = windowed->LengthAt(static_cast<double>(l) / (nl - 1));
      const double next =
        windowed->LengthAt(static_cast<double>(std::min(l + 1, nl - 1)) / (nl - 1));
      for (int b = 0; b < ns; ++b)
      {
        for (int f = 0; f < ns; ++f)
        {
          const double sf = static_cast<double>(f) / (ns - 1),
                       sb = static_cast<double>(b) / (ns - 1);
          const int n = std::max(1, std::abs(b - f) * sub);
          double alone[4], neighbour[4], half[4];
          vtkHAVSPreIntegrationTable::IntegrateSubSteps(fancy, 0, sf, sb, length, n, alone);
          const float* e = windowed->GetTable() + 4 * ((static_cast<size_t>(l) * ns + b) * ns + f);
          for (int c = 0; c < 4; ++c)
          {
            worstEntry = std::max(worstEntry, std::fabs(e[c] - alone[c]));
          }
          if (l + 1 < nl && (f + b + l) % 7 == 0)
          {
            vtkHAVSPreIntegrationTable::IntegrateSubSteps(fancy, 0, sf, sb, next, n, neighbour);
            vtkHAVSPreIntegrationTable::IntegrateSubSteps(
              fancy, 0, sf, sb, length, std::max(1, n / 2), half);
            for (int c = 0; c < 4; ++c)
            {
              worstNeighbour = std::max(worstNeighbour, std::fabs(e[c] - neighbour[c]));
              worstHalf = std::max(worstHalf, std::fabs(e[c] - half[c]));
            }
          }
        }
      }
    }
    std::cout << "windowed composites, max length " << maxLength
              << (windowed->GetLengthLogScale() > 0.0 ? " (logarithmic)" : " (linear)")
              << ": each segment alone " << worstEntry << "; controls: the next layer "
              << worstNeighbour << ", half the sub-steps " << worstHalf << std::endl;
    havstest::Check(worstEntry < 1e-6, "windowed entries equal each segment's own quadrature");
    havstest::Check(worstNeighbour > 1e-3, "control: the next layer's length misses");
    havstest::Check(worstHalf > 1e-5, "control: half the sub-steps miss");
  }

  // NeedsRebuild.
  table->Build(fancy, 0, range, 1.0);
  havstest::Check(!table->NeedsRebuild(fancy, 0, range, 1.0), "fresh table needs no rebuild");
  fancy->GetRGBTransferFunction()->AddRGBPoint(0.7, 1, 1, 1);
  havstest::Check(table->NeedsRebuild(fancy, 0, range, 1.0), "colour edit needs a rebuild");
  table->Build(fancy, 0, range, 1.0);
  fancy->SetScalarOpacityUnitDistance(0.7);
  havstest::Check(table->NeedsRebuild(fancy, 0, range, 1.0), "unit distance edit needs a rebuild");
  table->Build(fancy, 0, range, 1.0);
  const double range2[2] = { 0.0, 2.0 };
  havstest::Check(table->NeedsRebuild(fancy, 0, range2, 1.0), "range change needs a rebuild");
  table->SetScalarResolution(16);
  havstest::Check(table->NeedsRebuild(fancy, 0, range, 1.0), "size change needs a rebuild");

  // Degenerate inputs: defined, finite.
  const double flat[2] = { 0.5, 0.5 };
  havstest::Check(table->Build(fancy, 0, flat, 1.0), "degenerate range builds");
  const double nanRange[2] = { std::numeric_limits<double>::quiet_NaN(), 1.0 };
  havstest::Check(!table->Build(fancy, 0, nanRange, 1.0), "NaN range fails");
  havstest::Check(!table->Build(nullptr, 0, range, 1.0), "null property fails");
  table->Build(fancy, 0, range, 0.0);
  bool finite = true;
  for (size_t i = 0; i < 16 * 16 * 16 * 4; ++i)
  {
    finite = finite && std::isfinite(table->GetTable()[i]);
  }
  havstest::Check(finite, "tables stay finite");

  // The logarithmic length axis: the longest length (1e6) spans about 1e6
  // optical lengths of `fancy` (tau_max 1.3); segments of 0.1 to 30 (where
  // the opacity changes) against the adaptive integral. Control: what a
  // linear axis of the same size returns there (the interpolation between 0
  // and its first step, 7874). Longer, optically thick segments below.
  {
    vtkNew<vtkHAVSPreIntegrationTable> longest;
    longest->Build(fancy, 0, range, 1e6);
    std::cout << "longest length 1e6: length axis scale " << longest->GetLengthLogScale()
              << std::endl;
    havstest::Check(longest->GetLengthLogScale() > 0.0, "a logarithmic axis where needed");
    havstest::Check(std::fabs(longest->LengthAt(longest->LengthCoordinate(123.0)) - 123.0) < 1e-9,
      "LengthAt inverts LengthCoordinate");
    double worstLog = 0.0, worstLinear = 0.0;
    const double step = 1e6 / (longest->GetLengthResolution() - 1);
    for (double length : { 0.1, 0.5, 2.0, 7.0, 30.0 })
    {
      for (double sf : { 0.1, 0.45, 0.9 })
      {
        const double sb = 1.0 - sf;
        double looked[4], exact[4], atStep[4];
        longest->Lookup(sf, sb, length, looked);
        vtkHAVSPreIntegrationTable::IntegrateSegment(fancy, 0, sf, sb, length, exact);
        vtkHAVSPreIntegrationTable::IntegrateSegment(fancy, 0, sf, sb, step, atStep);
        for (int c = 0; c < 4; ++c)
        {
          worstLog = std::max(worstLog, std::fabs(looked[c] - exact[c]));
          const double linear = length < step ? atStep[c] * length / step : atStep[c];
          worstLinear = std::max(worstLinear, std::fabs(linear - exact[c]));
        }
      }
    }
    std::cout << "longest length 1e6: worst error " << worstLog
              << " (a linear axis: " << worstLinear << ")" << std::endl;
    havstest::Check(worstLog < 2e-3, "logarithmic axis: short segments within 2e-3");
    havstest::Check(worstLinear > 0.1, "control: a linear axis misses them by > 0.1");
    // Where the axis is linear it stays so (every table of the tests above).
    vtkNew<vtkHAVSPreIntegrationTable> ordinary;
    ordinary->Build(fancy, 0, range, 1.0);
    havstest::Check(ordinary->GetLengthLogScale() == 0.0, "a linear axis where it suffices");
  }

  // Long, optically thick segments (issue 20): 200 to 1e5 units on the
  // logarithmic axis, where one scalar sub-step of the quadrature is itself
  // opaque (a sub-step composites its ends' colours weighted by where the
  // light it emits is seen from, see CompositeStep), for `fancy` and a
  // smooth ramp, against the brute force. The scalars are on the table's
  // nodes (the quadrature's error, not the scalar interpolation's): within
  // 2e-3 (fancy) and 2e-4 (smooth); IntegrateSegment (the reference
  // renderer's) within 1e-5. Controls: the former mean-colour rule on the
  // table's sub-steps misses both bounds. Off the nodes the lookup's error
  // (printed) is the interpolation between scalar nodes too (up to 0.01 for
  // `fancy`, whose colour has a kink at 0.7 and its steepest opacity at 0.1).
  {
    auto smooth = havstest::MakeRampProperty(0.0, 1.0, 0.8, 1.0);
    for (vtkVolumeProperty* property : { static_cast<vtkVolumeProperty*>(fancy), smooth.Get() })
    {
      const bool isSmooth = property == smooth;
      vtkNew<vtkHAVSPreIntegrationTable> thick;
      thick->Build(property, 0, range, 1e6);
      const int n = thick->GetScalarResolution() - 1;
      double worstTable = 0.0, worstIntegral = 0.0, worstMean = 0.0, worstOff = 0.0;
      for (double length : { 200.0, 3000.0, 1e5 })
      {
        for (const auto& pair : { std::make_pair(0.45, 0.55), std::make_pair(0.1, 0.9),
               std::make_pair(0.9, 0.1), std::make_pair(0.02, 0.6), std::make_pair(0.7, 0.3) })
        {
          double brute[4], looked[4], integral[4], mean[4];
          BruteForce(property, pair.first, pair.second, length, brute);
          thick->Lookup(pair.first, pair.second, length, looked);
          worstOff = std::max(worstOff, MaxDifference(looked, brute));
          const double sf = std::round(pair.first * n) / n, sb = std::round(pair.second * n) / n;
          BruteForce(property, sf, sb, length, brute);
          thick->Lookup(sf, sb, length, looked);
          vtkHAVSPreIntegrationTable::IntegrateSegment(property, 0, sf, sb, length, integral);
          MeanColorRule(property, sf, sb, length, mean);
          worstTable = std::max(worstTable, MaxDifference(looked, brute));
          worstIntegral = std::max(worstIntegral, MaxDifference(integral, brute));
          worstMean = std::max(worstMean, MaxDifference(mean, brute));
        }
      }
      const double bound = isSmooth ? 2e-4 : 2e-3;
      std::cout << (isSmooth ? "smooth" : "fancy")
                << " thick segments (200 to 1e5) vs brute force: table " << worstTable
                << " (off the scalar nodes " << worstOff << "), IntegrateSegment " << worstIntegral
                << ", control (mean-colour rule) " << worstMean << "; bound " << bound << std::endl;
      havstest::Check(worstTable < bound, "thick segments: the table within the bound");
      havstest::Check(worstIntegral < 1e-5, "thick segments: IntegrateSegment within 1e-5");
      havstest::Check(worstMean > bound, "control: the mean-colour rule misses the bound");
    }
  }

  // Timing of the default size (no assertion).
  vtkNew<vtkHAVSPreIntegrationTable> big;
  big->Build(fancy, 0, range, 1.0);
  std::cout << "128^3 table build: " << big->GetLastBuildSeconds() << " s" << std::endl;
  return havstest::Result();
}

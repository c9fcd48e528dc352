/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTableResolution.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTableResolution.h"

#include "vtkHAVSPreIntegrationTable.h"
#include "vtkObjectFactory.h"
#include "vtkTimerLog.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

vtkStandardNewMacro(vtkHAVSTableResolution);

//------------------------------------------------------------------------------
double vtkHAVSTableResolution::MeasureError(
  vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property, int component) const
{
  const int ns = table->GetScalarResolution();
  const int nl = table->GetLengthResolution();
  const float* values = table->GetTable();
  const double* range = table->GetScalarRange();
  const double span = range[1] - range[0];
  const double maxLength = table->GetMaxLength();
  if (!values || ns < 2 || nl < 2 || !(maxLength > 0.0))
  {
    return 0.0;
  }

  // Probes, in normalized coordinates (front, back, length), where trilinear
  // interpolation errs most, a quarter each:
  // - beside the functions' nodes (their kinks make the table's kinks), on one
  //   axis or on both;
  // - near the diagonal (front and back within a cell: short scalar spans,
  //   where a kink between them bends the entry most);
  // - in the cells whose corners differ most;
  // - anywhere.
  // Positions inside a cell are random: a kink's error peaks where it lies.
  std::vector<double> nodes;
  if (span > 0.0)
  {
    vtkHAVSPreIntegrationTable::GetFunctionNodes(property, component, nodes);
    for (double& x : nodes)
    {
      x = (x - range[0]) / span;
    }
    nodes.erase(
      std::remove_if(nodes.begin(), nodes.end(), [](double x) { return !(x >= 0.0 && x <= 1.0); }),
      nodes.end());
  }
  std::mt19937 random(20261202u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell = 1.0 / (ns - 1);
  auto clamp01 = [](double x) { return std::min(std::max(x, 0.0), 1.0); };
  auto nearNode = [&]()
  {
    return nodes.empty()
      ? unit(random)
      : clamp01(
          nodes[std::min(static_cast<size_t>(unit(random) * nodes.size()), nodes.size() - 1)] +
          (unit(random) - 0.5) * 2.0 * cell);
  };

  auto entry = [&](int f, int b, int l, int c)
  { return values[((static_cast<size_t>(l) * ns + b) * ns + f) * 4 + c]; };
  std::uniform_int_distribution<int> pickScalar(0, ns - 2);
  std::uniform_int_distribution<int> pickLength(0, nl - 2);
  using Cell = std::array<int, 3>;
  const int quarter = std::max(this->ProbeCount / 4, 1);
  std::vector<std::pair<double, Cell>> spread(std::max(16 * quarter, 1024));
  for (auto& sp : spread)
  {
    const Cell cl = { pickScalar(random), pickScalar(random), pickLength(random) };
    double largest = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      double lo = 1e30, hi = -1e30;
      for (int corner = 0; corner < 8; ++corner)
      {
        const double v =
          entry(cl[0] + (corner & 1), cl[1] + ((corner >> 1) & 1), cl[2] + ((corner >> 2) & 1), c);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      largest = std::max(largest, hi - lo);
    }
    sp = { largest, cl };
  }
  std::partial_sort(spread.begin(), spread.begin() + quarter, spread.end(),
    [](const auto& x, const auto& y) { return x.first > y.first; });

  std::vector<std::array<double, 3>> probes;
  probes.reserve(this->ProbeCount);
  for (int p = 0; p < this->ProbeCount; ++p)
  {
    const int kind = p % 4;
    std::array<double, 3> t;
    t[2] = unit(random);
    if (kind == 0)
    {
      t[0] = nearNode();
      const double which = unit(random);
      t[1] = which < 0.4
        ? nearNode()
        : (which < 0.7 ? clamp01(t[0] + (unit(random) - 0.5) * 2.0 * cell) : unit(random));
      if (unit(random) < 0.5)
      {
        std::swap(t[0], t[1]);
      }
    }
    else if (kind == 1)
    {
      t[0] = unit(random);
      t[1] = clamp01(t[0] + (unit(random) - 0.5) * 2.0 * cell);
    }
    else if (kind == 2)
    {
      const Cell& cl = spread[(p / 4) % quarter].second;
      t = { (cl[0] + unit(random)) * cell, (cl[1] + unit(random)) * cell,
        (cl[2] + unit(random)) / (nl - 1) };
    }
    else
    {
      t[0] = unit(random);
      t[1] = unit(random);
    }
    probes.push_back(t);
  }

  double error = 0.0;
  for (const auto& t : probes)
  {
    const double sf = range[0] + span * clamp01(t[0]);
    const double sb = range[0] + span * clamp01(t[1]);
    const double length = maxLength * clamp01(t[2]);
    double looked[4], exact[4];
    table->Lookup(sf, sb, length, looked);
    vtkHAVSPreIntegrationTable::IntegrateSegment(property, component, sf, sb, length, exact);
    for (int c = 0; c < 4; ++c)
    {
      error = std::max(error, std::abs(looked[c] - exact[c]));
    }
  }
  return error;
}

//------------------------------------------------------------------------------
bool vtkHAVSTableResolution::Build(vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property,
  int component, const double scalarRange[2], double maxLength, int maxScalarResolution,
  int maxLengthResolution)
{
  const double start = vtkTimerLog::GetUniversalTime();
  this->BuildTime.Modified();
  this->BuiltMaxima[0] = maxScalarResolution;
  this->BuiltMaxima[1] = maxLengthResolution;
  this->LastCandidates = 0;
  this->LastError = 0.0;
  const int largest = std::max(maxScalarResolution, maxLengthResolution);
  int n = std::min(this->SmallestResolution, largest);
  bool ok = true;
  for (;;)
  {
    table->SetScalarResolution(std::min(n, maxScalarResolution));
    table->SetLengthResolution(std::min(n, maxLengthResolution));
    ok = table->Build(property, component, scalarRange, maxLength);
    ++this->LastCandidates;
    const bool last = n >= largest;
    if (!ok)
    {
      break;
    }
    this->LastError = this->MeasureError(table, property, component);
    if (last || this->LastError <= this->ErrorBound)
    {
      break;
    }
    n = std::min(2 * n, largest);
  }
  this->LastSeconds = vtkTimerLog::GetUniversalTime() - start;
  return ok;
}

//------------------------------------------------------------------------------
bool vtkHAVSTableResolution::NeedsRebuild(const vtkHAVSPreIntegrationTable* table,
  vtkVolumeProperty* property, int component, const double scalarRange[2], double maxLength,
  int maxScalarResolution, int maxLengthResolution) const
{
  return maxScalarResolution != this->BuiltMaxima[0] ||
    maxLengthResolution != this->BuiltMaxima[1] ||
    const_cast<vtkHAVSTableResolution*>(this)->GetMTime() > this->BuildTime ||
    table->NeedsRebuild(property, component, scalarRange, maxLength);
}

//------------------------------------------------------------------------------
void vtkHAVSTableResolution::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorBound: " << this->ErrorBound << "\n";
  os << indent << "ProbeCount: " << this->ProbeCount << "\n";
  os << indent << "SmallestResolution: " << this->SmallestResolution << "\n";
  os << indent << "LastError: " << this->LastError << "\n";
  os << indent << "LastCandidates: " << this->LastCandidates << "\n";
  os << indent << "LastSeconds: " << this->LastSeconds << "\n";
}

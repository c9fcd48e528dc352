/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSTableResolution.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSTableResolution.h"

#include "vtkColorTransferFunction.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <random>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSTableResolution);

//------------------------------------------------------------------------------
void vtkHAVSTableResolution::IntegrateProbes(
  vtkVolumeProperty* property, int component, Probe* probes, int count)
{
  if (count <= 0)
  {
    return;
  }
  // VTK's function objects are not promised to be thread-safe: each chunk of
  // probes evaluates its own deep copies of the component's functions (made
  // here, serially), which give the same values to the bit.
  const int chunks = std::max(1, std::min(count, vtkSMPTools::GetEstimatedNumberOfThreads()));
  std::vector<vtkSmartPointer<vtkVolumeProperty>> copies(chunks);
  for (auto& copy : copies)
  {
    copy = vtkSmartPointer<vtkVolumeProperty>::New();
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->DeepCopy(property->GetScalarOpacity(component));
    copy->SetScalarOpacity(0, opacity);
    if (property->GetColorChannels(component) == 1)
    {
      vtkNew<vtkPiecewiseFunction> gray;
      gray->DeepCopy(property->GetGrayTransferFunction(component));
      copy->SetColor(0, gray);
    }
    else
    {
      vtkNew<vtkColorTransferFunction> color;
      color->DeepCopy(property->GetRGBTransferFunction(component));
      copy->SetColor(0, color);
    }
    copy->SetScalarOpacityUnitDistance(0, property->GetScalarOpacityUnitDistance(component));
  }
  vtkSMPTools::For(0, chunks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType chunk = begin; chunk < end; ++chunk)
      {
        vtkVolumeProperty* own = copies[chunk];
        const int from = static_cast<int>(static_cast<long long>(count) * chunk / chunks);
        const int to = static_cast<int>(static_cast<long long>(count) * (chunk + 1) / chunks);
        for (int p = from; p < to; ++p)
        {
          // At most 256 sub-steps (Richardson-extrapolated: about 1e-6 on a
          // ramp): functions with many kinks (ParaView's presets) would
          // refine each probe long.
          vtkHAVSPreIntegrationTable::IntegrateSegment(
            own, 0, probes[p].Front, probes[p].Back, probes[p].Length, probes[p].Exact, 256);
        }
      }
    });
}

//------------------------------------------------------------------------------
double vtkHAVSTableResolution::MeasureError(
  vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property, int component) const
{
  std::vector<Probe> probes;
  return this->MeasureError(table, property, component, probes);
}

//------------------------------------------------------------------------------
double vtkHAVSTableResolution::MeasureError(vtkHAVSPreIntegrationTable* table,
  vtkVolumeProperty* property, int component, std::vector<Probe>& probes) const
{
  const int nl = table->GetLengthResolution();
  const double* range = table->GetScalarRange();
  const double span = range[1] - range[0];
  const double maxLength = table->GetMaxLength();
  const double unitDistance = property ? property->GetScalarOpacityUnitDistance(component) : 0.0;
  if (!table->GetTable() || nl < 2 || !(maxLength > 0.0) || !(unitDistance > 0.0))
  {
    return 0.0;
  }
  // Segments drawn uniformly (fixed seed, see below); each one's error is divided by its
  // length in unit distances, at least one length step of the table (below
  // it the entries are nearly linear in the length, and both vanish at 0).
  std::mt19937 random(20261202u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Lengths drawn uniformly along the table's own length axis (linear or
  // logarithmic): on a logarithmic axis, uniform lengths would nearly all be
  // long, saturated segments that any table gets right.
  const double shortest = table->LengthAt(1.0 / (nl - 1));
  // The segments, drawn serially (one random sequence). The same segments as
  // the kept probes (the same draws, and a length axis that maps them to the
  // same lengths) keep their integrals; from the first that differs on, the
  // probes are integrated again.
  if (static_cast<int>(probes.size()) != this->ProbeCount)
  {
    probes.assign(this->ProbeCount, Probe());
  }
  int first = this->ProbeCount; // the first probe to integrate
  for (int p = 0; p < this->ProbeCount; ++p)
  {
    const double sf = range[0] + span * unit(random);
    const double sb = range[0] + span * unit(random);
    const double length = table->LengthAt(unit(random));
    Probe& probe = probes[p];
    if (first == this->ProbeCount &&
      (probe.Front != sf || probe.Back != sb || probe.Length != length))
    {
      first = p;
    }
    probe.Front = sf;
    probe.Back = sb;
    probe.Length = length;
  }
  IntegrateProbes(property, component, probes.data() + first, this->ProbeCount - first);
  double sum = 0.0;
  for (const Probe& probe : probes)
  {
    double looked[4];
    table->Lookup(probe.Front, probe.Back, probe.Length, looked);
    double error = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      error = std::max(error, std::abs(looked[c] - probe.Exact[c]));
    }
    sum += error * unitDistance / std::max(probe.Length, shortest);
  }
  return sum / this->ProbeCount;
}

//------------------------------------------------------------------------------
bool vtkHAVSTableResolution::Build(vtkHAVSPreIntegrationTable* table, vtkVolumeProperty* property,
  int component, const double scalarRange[2], double maxLength, int maxScalarResolution,
  int maxLengthResolution)
{
  const double start = vtkTimerLog::GetUniversalTime();
  // The search starts from the last choice unless this object's settings or
  // the largest sizes changed since (then from the smallest).
  const bool fresh = this->LastChoice == 0 || maxScalarResolution != this->BuiltMaxima[0] ||
    maxLengthResolution != this->BuiltMaxima[1] || this->GetMTime() > this->BuildTime;
  this->BuildTime.Modified();
  this->BuiltMaxima[0] = maxScalarResolution;
  this->BuiltMaxima[1] = maxLengthResolution;
  this->LastCandidates = 0;
  this->LastError = 0.0;
  const int largest = std::max(maxScalarResolution, maxLengthResolution);
  const int smallest = std::min(this->SmallestResolution, largest);
  int n = fresh ? smallest : std::min(std::max(this->LastChoice, smallest), largest);
  bool ok = true;
  bool descending = !fresh;  // the last choice may be larger than needed now
  int upper = 0;             // going down: the size above the one tried (0: none)
  double upperError = 0.0;   // and its error
  bool rebuilding = false;   // building `upper` again: the half size missed
  std::vector<Probe> probes; // integrated once for every candidate

  for (;;)
  {
    table->SetScalarResolution(std::min(n, maxScalarResolution));
    table->SetLengthResolution(std::min(n, maxLengthResolution));
    ok = table->Build(property, component, scalarRange, maxLength);
    ++this->LastCandidates;
    if (!ok)
    {
      break;
    }
    if (rebuilding)
    {
      this->LastError = upperError;
      break;
    }
    const double error = this->MeasureError(table, property, component, probes);
    this->LastError = error;
    if (error <= this->ErrorBound)
    {
      // The measure falls with the square of the resolution: going down
      // from the last choice, the half size is tried where it is predicted
      // (4 times the error) to meet the bound too.
      if (descending && n / 2 >= smallest && 4.0 * error <= this->ErrorBound)
      {
        upper = n;
        upperError = error;
        n /= 2;
        continue;
      }
      break;
    }
    if (upper > 0)
    {
      // The half size missed after all: back to the size above, built again.
      n = upper;
      rebuilding = true;
      continue;
    }
    descending = false;
    if (n >= largest)
    {
      break;
    }
    // Where even the next size would miss the bound by half again, skip it.
    n = std::min(error > 6.0 * this->ErrorBound ? 4 * n : 2 * n, largest);
  }
  this->LastChoice = n;
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
  os << indent << "LastChoice: " << this->LastChoice << "\n";
}

VTK_ABI_NAMESPACE_END

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSPreIntegrationTable.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSPreIntegrationTable.h"

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPTools.h"
#include "vtkTimerLog.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <numeric> // For std::gcd

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSPreIntegrationTable);

namespace
{
/// Extinction and colour of the property at one scalar.
struct OpticalSample
{
  double Tau;
  double Color[3];
};

OpticalSample Evaluate(vtkVolumeProperty* property, int component, double s)
{
  OpticalSample out;
  const double unit = property->GetScalarOpacityUnitDistance(component);
  out.Tau = std::max(0.0, property->GetScalarOpacity(component)->GetValue(s)) / unit;
  vtkHAVSPreIntegrationTable::EvaluateColor(property, component, s, out.Color);
  return out;
}

/// The sub-step's end weights ca / x (front) and cb / x (back) before the
/// extinctions: their series below x = 1e-3 (where 1 - (1 - A) / x cancels;
/// truncation < 2e-14 relative), else the closed form.
inline void StepWeights(
  double depth, double inverseDepth, double attenuation, double& front, double& back)
{
  const double x = depth;
  if (x < 1e-3)
  {
    front = 0.5 - x * (1.0 / 6 - x * (1.0 / 24 - x * (1.0 / 120)));
    back = 0.5 - x * (1.0 / 3 - x * (1.0 / 8 - x * (1.0 / 30)));
  }
  else
  {
    const double r = (1.0 - attenuation) * inverseDepth;
    front = 1.0 - r;
    back = r - attenuation;
  }
}

/// The sub-step's colour (premultiplied, seen through `transmittance`) from
/// its weights (StepWeights) and ends a (front) and b (back).
inline void StepColor(const OpticalSample& a, const OpticalSample& b, double front, double back,
  double attenuation, double transmittance, double color[3])
{
  const double wa = front * a.Tau;
  const double wb = back * b.Tau;
  const double w = wa + wb;
  if (w > 0.0)
  {
    const double k = transmittance * (1.0 - attenuation) / w;
    for (int c = 0; c < 3; ++c)
    {
      color[c] += k * (wa * a.Color[c] + wb * b.Color[c]);
    }
  }
}

/// Composites one sub-step between samples a and b of optical depth `depth`
/// (its mean extinction times its length; attenuation = exp(-depth);
/// inverseDepth = 1 / depth, from the callers' reciprocals: a multiplication
/// here, not a division).
/// Extinction and colour are linear inside; the attenuation is exact for
/// the mean extinction kappa. Within the sub-step the light emitted at
/// depth t kappa is seen through exp(-kappa t); with the emission tau c
/// linear, that weighs the ends by tau_a ca and tau_b cb, where
///   ca = 1 - (1 - A) / x,   cb = (1 - A) / x - A   (x = depth, A = attenuation)
/// are kappa times the integrals of (1 - t/h) exp(-kappa t) and
/// (t/h) exp(-kappa t) over the sub-step (ca + cb = 1 - A). The colour is the
/// weighted mean of the ends' colours, times the sub-step's opacity 1 - A:
/// exact for a constant colour and for an opaque sub-step (its front
/// colour), the tau-weighted mean of the trapezoid rule for a thin one.
/// (The unnormalized closed form (tau_a c_a ca + tau_b c_b cb) / kappa tends
/// to c_a tau_a / kappa for an opaque sub-step: wrong by the extinction's
/// change across it, and black where tau_a = 0.)
inline void CompositeStep(const OpticalSample& a, const OpticalSample& b, double depth,
  double inverseDepth, double attenuation, double color[3], double& transmittance)
{
  double front, back;
  StepWeights(depth, inverseDepth, attenuation, front, back);
  StepColor(a, b, front, back, attenuation, transmittance, color);
  transmittance *= attenuation;
}

/// The optics at `count` evenly spaced scalars from a to b (both included; a
/// may exceed b), written to out[0], out[stride], ...: the same values as
/// Evaluate() at each (to rounding of the scalars), in one pass of each
/// function (VTK's GetTable walks its nodes once; GetValue and GetColor call
/// it once per scalar, which is most of a probe's cost, issue 45). A colour
/// function on a logarithmic scale (its GetTable spaces the scalars in
/// log10) or in indexed lookup (GetColor's own path) is evaluated one scalar
/// at a time.
void EvaluateEvenly(vtkVolumeProperty* property, int component, double a, double b, int count,
  OpticalSample* out, int stride)
{
  if (count <= 0)
  {
    return;
  }
  vtkColorTransferFunction* rgb = property->GetColorChannels(component) == 1
    ? nullptr
    : property->GetRGBTransferFunction(component);
  if (count == 1 || (rgb && (rgb->GetScale() != VTK_CTF_LINEAR || rgb->GetIndexedLookup())))
  {
    for (int i = 0; i < count; ++i)
    {
      out[i * stride] =
        Evaluate(property, component, count == 1 ? a : a + (b - a) * i / (count - 1));
    }
    return;
  }
  // GetTable needs increasing scalars: sample from the smaller end, and
  // write a descending run backwards.
  const bool ascending = a <= b;
  const double lo = ascending ? a : b, hi = ascending ? b : a;
  std::vector<double> opacity(count), color(3 * static_cast<size_t>(count));
  property->GetScalarOpacity(component)->GetTable(lo, hi, count, opacity.data());
  if (rgb)
  {
    rgb->GetTable(lo, hi, count, color.data());
  }
  else
  {
    property->GetGrayTransferFunction(component)->GetTable(lo, hi, count, color.data(), 3);
  }
  const double unit = property->GetScalarOpacityUnitDistance(component);
  for (int i = 0; i < count; ++i)
  {
    OpticalSample& sample = out[(ascending ? i : count - 1 - i) * stride];
    sample.Tau = std::max(0.0, opacity[i]) / unit;
    const double* c = color.data() + 3 * static_cast<size_t>(i);
    sample.Color[0] = c[0];
    sample.Color[1] = rgb ? c[1] : c[0];
    sample.Color[2] = rgb ? c[2] : c[0];
  }
}

/// The optics at the ends of n uniform sub-steps of (sf -> sb): at
/// sf + (sb - sf) j / n, j = 0 .. n. Given the samples of n / 2 (`coarser`),
/// those are the even ones here, and only the odd ones are evaluated.
void SampleSteps(vtkVolumeProperty* property, int component, double sf, double sb, int n,
  const std::vector<OpticalSample>* coarser, std::vector<OpticalSample>& out)
{
  out.resize(n + 1);
  if (!coarser)
  {
    EvaluateEvenly(property, component, sf, sb, n + 1, out.data(), 1);
    return;
  }
  for (int j = 0; j <= n; j += 2)
  {
    out[j] = (*coarser)[j / 2];
  }
  EvaluateEvenly(property, component, sf + (sb - sf) / n, sf + (sb - sf) * (n - 1) / n, n / 2,
    out.data() + 1, 2);
}

/// The segment of `length` composited over the sub-steps between `samples`.
void CompositeSamples(const std::vector<OpticalSample>& samples, double length, double rgba[4])
{
  double color[3] = { 0, 0, 0 };
  double transmittance = 1.0;
  const int n = static_cast<int>(samples.size()) - 1;
  const double h = length / n;
  for (int j = 1; j <= n; ++j)
  {
    const OpticalSample& a = samples[j - 1];
    const OpticalSample& b = samples[j];
    const double depth = 0.5 * h * (a.Tau + b.Tau);
    CompositeStep(
      a, b, depth, depth > 0.0 ? 1.0 / depth : 0.0, std::exp(-depth), color, transmittance);
  }
  rgba[0] = color[0];
  rgba[1] = color[1];
  rgba[2] = color[2];
  rgba[3] = 1.0 - transmittance;
}

/// The segment (sf -> sb, length) integrated with n sub-steps from the functions.
void IntegrateSteps(vtkVolumeProperty* property, int component, double sf, double sb, double length,
  int n, double rgba[4])
{
  std::vector<OpticalSample> samples;
  SampleSteps(property, component, sf, sb, n, nullptr, samples);
  CompositeSamples(samples, length, rgba);
}

/// CompositeStep's colours for a run of sub-steps, both directions, as
/// weights of their ends' colours: sub-step k (between fine samples k and
/// k + 1, optical depth depth[k] * scale, attenuation[k]) has forward (lower
/// end in front) colour lowerForward[k] c_k + upperForward[k] c_{k+1} and
/// backward colour lowerBackward[k] c_k + upperBackward[k] c_{k+1}. Written
/// without branches so that the compiler vectorizes it (the file is built
/// with -fno-trapping-math where the compiler has it: a comparison that may
/// raise an exception flag is not if-converted otherwise); most of a table's
/// build is here (issue 45).
// (The outputs alias nothing: said so, for the vectorizer's sake.)
#if defined(__GNUC__) || defined(__clang__) || defined(_MSC_VER)
#define HAVS_RESTRICT __restrict
#else
#define HAVS_RESTRICT
#endif
// With GCC on x86-64 ELF an AVX2 clone too, chosen at load time where the
// processor has it (4 doubles a vector instead of 2: a 64^3 table in 2.7 ms
// instead of 3.4 ms on 2 cores); not in sanitizer builds (their runtimes
// start after the clones' resolvers run).
#if defined(__x86_64__) && defined(__ELF__) && defined(__GNUC__) && !defined(__clang__) &&         \
  !defined(__SANITIZE_ADDRESS__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define HAVS_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#endif
#endif
#ifndef HAVS_VECTOR_CLONES
#define HAVS_VECTOR_CLONES
#endif
HAVS_VECTOR_CLONES void StepWeightsRun(int count, double scale, double inverseScale,
  const double* HAVS_RESTRICT depth, const double* HAVS_RESTRICT inverseDepth,
  const double* HAVS_RESTRICT attenuation, const double* HAVS_RESTRICT tau,
  double* HAVS_RESTRICT lowerForward, double* HAVS_RESTRICT upperForward,
  double* HAVS_RESTRICT lowerBackward, double* HAVS_RESTRICT upperBackward)
{
  for (int k = 0; k < count; ++k)
  {
    const double x = depth[k] * scale;
    const double a = attenuation[k];
    const double opacity = 1.0 - a;
    double front, back;
    StepWeights(x, inverseScale * inverseDepth[k], a, front, back);
    // StepColor: the ends weighed by their extinctions, normalized, times
    // the opacity (where a sum is 0 so are its terms: any finite divisor).
    const double wfl = front * tau[k], wfu = back * tau[k + 1];
    const double wbu = front * tau[k + 1], wbl = back * tau[k];
    const double kf = opacity / std::max(wfl + wfu, 1e-300);
    const double kb = opacity / std::max(wbu + wbl, 1e-300);
    lowerForward[k] = kf * wfl;
    upperForward[k] = kf * wfu;
    lowerBackward[k] = kb * wbl;
    upperBackward[k] = kb * wbu;
  }
}

/// Below this a sub-step's attenuation is taken as 0 (what it lets through
/// changes no entry; no denormals in the products of attenuations).
constexpr double TinyAttenuation = 1e-200;

/// A composited stretch of a segment: premultiplied colour and transmittance.
struct Composite
{
  double Color[3];
  double Transmittance;
};

/// Front composited over back (associative).
inline Composite Over(const Composite& front, const Composite& back)
{
  Composite out;
  for (int c = 0; c < 3; ++c)
  {
    out.Color[c] = front.Color[c] + front.Transmittance * back.Color[c];
  }
  out.Transmittance = front.Transmittance * back.Transmittance;
  return out;
}

/// The composites of every window of `width` consecutive items of `items`
/// (count of them), front to back, passed to emit(start, composite): the
/// items cut into blocks of `width`, a window is the suffix of one block
/// over the prefix of the next (van Herk / Gil-Werman), so each costs at most
/// 3 Over() whatever its width. prefix and suffix: scratch of count items.
template <typename Emit>
void WindowComposites(
  const Composite* items, int count, int width, Composite* prefix, Composite* suffix, Emit&& emit)
{
  for (int block = 0; block < count; block += width)
  {
    const int last = std::min(block + width, count) - 1;
    prefix[block] = items[block];
    for (int p = block + 1; p <= last; ++p)
    {
      prefix[p] = Over(prefix[p - 1], items[p]);
    }
    suffix[last] = items[last];
    for (int p = last - 1; p >= block; --p)
    {
      suffix[p] = Over(items[p], suffix[p + 1]);
    }
  }
  for (int s = 0; s + width <= count; ++s)
  {
    emit(s, s % width == 0 ? suffix[s] : Over(suffix[s], prefix[s + width - 1]));
  }
}
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::EvaluateColor(
  vtkVolumeProperty* property, int component, double s, double color[3])
{
  if (property->GetColorChannels(component) == 1)
  {
    color[0] = color[1] = color[2] = property->GetGrayTransferFunction(component)->GetValue(s);
  }
  else
  {
    property->GetRGBTransferFunction(component)->GetColor(s, color);
  }
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::EvaluateOptics(
  vtkVolumeProperty* property, int component, double s, double& tau, double color[3])
{
  const OpticalSample sample = Evaluate(property, component, s);
  tau = sample.Tau;
  std::copy_n(sample.Color, 3, color);
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::GetFunctionNodes(
  vtkVolumeProperty* property, int component, std::vector<double>& nodes)
{
  double node[6];
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(component);
  for (int i = 0; i < opacity->GetSize(); ++i)
  {
    opacity->GetNodeValue(i, node);
    nodes.push_back(node[0]);
  }
  if (property->GetColorChannels(component) == 1)
  {
    vtkPiecewiseFunction* gray = property->GetGrayTransferFunction(component);
    for (int i = 0; i < gray->GetSize(); ++i)
    {
      gray->GetNodeValue(i, node);
      nodes.push_back(node[0]);
    }
  }
  else
  {
    vtkColorTransferFunction* color = property->GetRGBTransferFunction(component);
    for (int i = 0; i < color->GetSize(); ++i)
    {
      color->GetNodeValue(i, node);
      nodes.push_back(node[0]);
    }
  }
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::IntegrateSubSteps(vtkVolumeProperty* property, int component,
  double sf, double sb, double length, int n, double rgba[4])
{
  IntegrateSteps(property, component, sf, sb, length, std::max(n, 1), rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::IntegrateSegment(vtkVolumeProperty* property, int component,
  double sf, double sb, double length, double rgba[4], int maximumSteps)
{
  // Second-order sub-steps, doubled and Richardson-extrapolated until two
  // successive estimates agree to 1e-7.
  // Each doubling evaluates the functions at the new (odd) samples only.
  double coarse[4], fine[4], previous[4] = { 0, 0, 0, 0 };
  std::vector<OpticalSample> samples, finer;
  SampleSteps(property, component, sf, sb, 16, nullptr, samples);
  CompositeSamples(samples, length, coarse);
  for (int n = 32; n <= std::max(maximumSteps, 32); n *= 2)
  {
    SampleSteps(property, component, sf, sb, n, &samples, finer);
    samples.swap(finer);
    CompositeSamples(samples, length, fine);
    double estimate[4], change = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      estimate[c] = (4.0 * fine[c] - coarse[c]) / 3.0;
      change = std::max(change, std::fabs(estimate[c] - previous[c]));
      previous[c] = estimate[c];
      coarse[c] = fine[c];
    }
    if (n > 32 && change < 1e-7)
    {
      break;
    }
  }
  std::copy(previous, previous + 4, rgba);
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::Zero(bool lengthZeroOnly)
{
  const size_t ns = static_cast<size_t>(this->ScalarResolution);
  const size_t floats = ns * ns * this->LengthResolution * 4;
  if (this->Table.capacity() > floats)
  {
    // A smaller table than the last (an edit that needs less resolution):
    // its memory follows, rather than staying at the largest table built.
    std::vector<float>().swap(this->Table);
  }
  if (lengthZeroOnly && this->Table.size() == floats)
  {
    // The same size again (an edit): every entry of length > 0 is written.
    std::fill_n(this->Table.begin(), ns * ns * 4, 0.0f);
  }
  else
  {
    this->Table.assign(floats, 0.0f);
  }
  this->TransferFunction1D.assign(ns * 4, 0.0f);
  this->Additive1D.assign(2 * AdditiveResolution, 0.0f);
  this->BuiltScalarResolution = this->ScalarResolution;
  this->BuiltLengthResolution = this->LengthResolution;
}

//------------------------------------------------------------------------------
bool vtkHAVSPreIntegrationTable::NeedsRebuild(
  vtkVolumeProperty* property, int component, const double scalarRange[2], double maxLength) const
{
  if (!property || property != this->BuiltProperty || component != this->Component ||
    scalarRange[0] != this->ScalarRange[0] || scalarRange[1] != this->ScalarRange[1] ||
    maxLength != this->MaxLength ||
    const_cast<vtkHAVSPreIntegrationTable*>(this)->GetMTime() > this->BuildTime ||
    this->BuiltScalarResolution != this->ScalarResolution ||
    this->BuiltLengthResolution != this->LengthResolution)
  {
    return true;
  }
  // vtkVolumeProperty::GetMTime includes its transfer functions.
  return property->GetMTime() > this->BuildTime;
}

//------------------------------------------------------------------------------
bool vtkHAVSPreIntegrationTable::Build(
  vtkVolumeProperty* property, int component, const double scalarRange[2], double maxLength)
{
  const double start = vtkTimerLog::GetUniversalTime();
  this->BuildTime.Modified();
  this->BuiltProperty = property;
  this->Component = component;
  this->ScalarRange[0] = scalarRange[0];
  this->ScalarRange[1] = scalarRange[1];
  this->MaxLength = maxLength;
  this->LengthLogScale = 0.0;
  if (!property)
  {
    this->Zero();
    vtkErrorMacro("No volume property.");
    return false;
  }
  if (!std::isfinite(scalarRange[0]) || !std::isfinite(scalarRange[1]) ||
    scalarRange[0] > scalarRange[1])
  {
    this->Zero();
    vtkErrorMacro("Invalid scalar range [" << scalarRange[0] << ", " << scalarRange[1] << "].");
    return false;
  }
  if (!(property->GetScalarOpacityUnitDistance(component) > 0.0))
  {
    this->Zero();
    vtkErrorMacro("ScalarOpacityUnitDistance must be positive, it is "
      << property->GetScalarOpacityUnitDistance(component) << ".");
    return false;
  }
  if (!(maxLength > 0.0) || !std::isfinite(maxLength))
  {
    this->Zero();
    vtkWarningMacro("Non-positive maximum segment length " << maxLength << ": the table is empty.");
    return true;
  }
  this->Zero(true); // every entry below is written, but those of length 0

  const int ns = this->ScalarResolution;
  const int nl = this->LengthResolution;
  const int sub = this->SubdivisionsPerInterval;
  const double lo = scalarRange[0];
  const double span = scalarRange[1] - scalarRange[0];

  // The functions, sampled serially (VTK function objects are not promised
  // to be thread-safe) on the fine grid; every node is a fine sample.
  // The functions' own nodes are fine samples too, so that a feature
  // narrower than a sub-step (a spike) is integrated, not stepped over:
  // positions (normalized) of the uniform sub-steps and of the nodes, merged;
  // tableSample[i] is where table scalar i lies among them.
  const int uniformCount = (ns - 1) * sub + 1;
  std::vector<double> positions(uniformCount);
  for (int i = 0; i < uniformCount; ++i)
  {
    positions[i] = static_cast<double>(i) / (uniformCount - 1);
  }
  if (span > 0.0)
  {
    std::vector<double> nodes;
    GetFunctionNodes(property, component, nodes);
    for (double x : nodes)
    {
      const double t = (x - lo) / span;
      if (t > 0.0 && t < 1.0)
      {
        positions.push_back(t);
      }
    }
    std::sort(positions.begin(), positions.end());
    positions.erase(std::unique(positions.begin(), positions.end()), positions.end());
  }
  const int fineCount = static_cast<int>(positions.size());
  std::vector<OpticalSample> fine(fineCount);
  for (int i = 0; i < fineCount; ++i)
  {
    fine[i] = Evaluate(property, component, lo + span * positions[i]);
  }
  std::vector<int> tableSample(ns);
  for (int i = 0; i < ns; ++i)
  {
    const double t = static_cast<double>(i * sub) / (uniformCount - 1);
    tableSample[i] =
      static_cast<int>(std::lower_bound(positions.begin(), positions.end(), t) - positions.begin());
  }
  for (int i = 0; i < ns; ++i)
  {
    const OpticalSample& s = fine[tableSample[i]];
    const double unit = property->GetScalarOpacityUnitDistance(component);
    for (int c = 0; c < 3; ++c)
    {
      this->TransferFunction1D[4 * i + c] = static_cast<float>(s.Color[c]);
    }
    this->TransferFunction1D[4 * i + 3] = static_cast<float>(s.Tau * unit);
  }

  // The additive blend's integrand g(s) = tau(s) * s (s normalized) and its
  // integral G, exact for g linear between the nodes (the trapezoid rule).
  double integral = 0.0, previous = 0.0;
  std::vector<OpticalSample> additive(AdditiveResolution);
  EvaluateEvenly(property, component, lo, lo + span, AdditiveResolution, additive.data(), 1);
  for (int i = 0; i < AdditiveResolution; ++i)
  {
    const double sn = static_cast<double>(i) / (AdditiveResolution - 1);
    const double g = additive[i].Tau * sn;
    if (i > 0)
    {
      integral += 0.5 * (previous + g) / (AdditiveResolution - 1);
    }
    this->Additive1D[2 * i] = static_cast<float>(g);
    this->Additive1D[2 * i + 1] = static_cast<float>(integral);
    previous = g;
  }

  // The length axis: logarithmic where the longest segment spans many
  // optical lengths (see the class description).
  double tauMax = 0.0;
  for (const OpticalSample& sample : fine)
  {
    tauMax = std::max(tauMax, std::isfinite(sample.Tau) ? sample.Tau : 0.0);
  }
  this->LengthLogScale = maxLength * tauMax > 16.0 ? 4.0 * tauMax : 0.0;
  const bool logarithmic = this->LengthLogScale > 0.0;
  std::vector<double> layerLength(nl);
  for (int l = 0; l < nl; ++l)
  {
    layerLength[l] = this->LengthAt(static_cast<double>(l) / (nl - 1));
  }

  float* table = this->Table.data();
  const double lengthStep = maxLength / (nl - 1);
  const size_t layer = static_cast<size_t>(ns) * ns * 4;
  auto entry = [&](int f, int b, int l) -> float*
  { return table + static_cast<size_t>(l) * layer + (static_cast<size_t>(b) * ns + f) * 4; };
  // A composite into entry (f, b, l): its colour and opacity 1 - transmittance.
  auto store = [&](int f, int b, int l, const Composite& c)
  {
    float* out = entry(f, b, l);
    out[0] = static_cast<float>(c.Color[0]);
    out[1] = static_cast<float>(c.Color[1]);
    out[2] = static_cast<float>(c.Color[2]);
    out[3] = static_cast<float>(1.0 - c.Transmittance);
  };

  // The sub-steps' extinction integrals over their scalar span (normalized).
  std::vector<double> stepDepth(fineCount - 1);
  for (int k = 0; k + 1 < fineCount; ++k)
  {
    stepDepth[k] = 0.5 * (fine[k].Tau + fine[k + 1].Tau) * (positions[k + 1] - positions[k]);
  }
  this->LastBuiltByEntryBuilder = false;
  if (this->Builder && !this->ExactIntegration)
  {
    // The entries built elsewhere (the GPU) from the same quadrature's inputs.
    Quadrature inputs;
    inputs.ScalarResolution = ns;
    inputs.LengthResolution = nl;
    inputs.Samples.resize(4 * static_cast<size_t>(fineCount));
    for (int k = 0; k < fineCount; ++k)
    {
      inputs.Samples[4 * k] = static_cast<float>(fine[k].Tau);
      for (int c = 0; c < 3; ++c)
      {
        inputs.Samples[4 * k + 1 + c] = static_cast<float>(fine[k].Color[c]);
      }
    }
    inputs.StepDepth.assign(stepDepth.begin(), stepDepth.end());
    inputs.TableSample = tableSample;
    inputs.LayerLength.assign(layerLength.begin(), layerLength.end());
    if (this->Builder(inputs, this->Table.data()))
    {
      this->LastBuiltByEntryBuilder = true;
      this->LastBuildSeconds = vtkTimerLog::GetUniversalTime() - start;
      return true;
    }
  }

  if (this->ExactIntegration)
  {
    vtkSMPTools::For(0, static_cast<vtkIdType>(ns) * ns,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType pair = begin; pair < end; ++pair)
        {
          const int f = static_cast<int>(pair % ns), b = static_cast<int>(pair / ns);
          for (int l = 1; l < nl; ++l)
          {
            double rgba[4];
            IntegrateSegment(property, component, lo + span * f / (ns - 1),
              lo + span * b / (ns - 1), layerLength[l], rgba);
            std::copy(rgba, rgba + 4, entry(f, b, l));
          }
        }
      });
  }
  else
  {
    // Windowed composites (see the class description). A segment from table
    // scalar f to b (f != b) of length L crosses whole fine sub-steps, each
    // of world length L * (its scalar span) / (the segment's scalar span):
    // for j = |b - f| and L both fixed, a sub-step's optical depth, and so its
    // composite, is the same in every segment that crosses it. Per (j,
    // direction, length): the sub-steps' composites, the table intervals'
    // composites (their sub-steps, front to back), and every entry of that j
    // as the composite of j consecutive intervals: a sliding window, 3
    // compositing operations an entry however long the segment.
    const int cells = ns - 1;
    const int steps = fineCount - 1;
    // The diagonal (f == b): one sub-step of the constant optics at f.
    vtkSMPTools::For(0, ns,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          const OpticalSample& a = fine[tableSample[f]];
          for (int l = 1; l < nl; ++l)
          {
            const double depth = a.Tau * layerLength[l];
            Composite c = { { 0, 0, 0 }, 1.0 };
            CompositeStep(a, a, depth, depth > 0.0 ? 1.0 / depth : 0.0, std::exp(-depth), c.Color,
              c.Transmittance);
            store(static_cast<int>(f), static_cast<int>(f), l, c);
          }
        }
      });
    // The sub-steps' reciprocal depths (a multiplication per sub-step below,
    // not a division).
    std::vector<double> inverseStepDepth(steps);
    for (int k = 0; k < steps; ++k)
    {
      inverseStepDepth[k] = stepDepth[k] > 0.0 ? 1.0 / stepDepth[k] : 0.0;
    }
    // The fine samples' extinctions and colours as arrays.
    std::vector<double> tau(fineCount);
    std::vector<double> color[3] = { std::vector<double>(fineCount), std::vector<double>(fineCount),
      std::vector<double>(fineCount) };
    for (int k = 0; k < fineCount; ++k)
    {
      tau[k] = fine[k].Tau;
      for (int c = 0; c < 3; ++c)
      {
        color[c][k] = fine[k].Color[c];
      }
    }
    // A sub-step's composite depends on j and L only through
    // scale = L (NS - 1) / j, its world length per unit normalized scalar. On
    // the linear length axis (L = l lengthStep) that is a function of l / j:
    // the pairs (q j0, q l0) share the interval composites of (j0, l0), which
    // are computed once (for the coprime pairs, about 61 % of them) and
    // windowed at every multiple. One task per j0, both directions: a
    // sub-step's depth, attenuation and weights are the same either way; only
    // its ends swap.
    vtkSMPTools::For(1, static_cast<vtkIdType>(cells) + 1, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        // cell[0]: the intervals forward, cell[1]: backward (see below).
        std::vector<Composite> cell[2] = { std::vector<Composite>(cells),
          std::vector<Composite>(cells) };
        std::vector<Composite> prefix(cells), suffix(cells);
        std::vector<double> unitAttenuation(steps), attenuation(steps);
        std::vector<double> weight[4] = { std::vector<double>(steps), std::vector<double>(steps),
          std::vector<double>(steps), std::vector<double>(steps) }; // StepWeightsRun's
        for (vtkIdType task = begin; task < end; ++task)
        {
          const int j0 = static_cast<int>(task);
          // World length per unit normalized scalar, per unit segment length.
          const double density = static_cast<double>(cells) / j0;
          for (int k = 0; k < steps; ++k)
          {
            unitAttenuation[k] = logarithmic ? 0.0 : std::exp(-stepDepth[k] * density * lengthStep);
            attenuation[k] = 1.0;
          }
          for (int l0 = 1; l0 < nl; ++l0)
          {
            const double scale = density * layerLength[l0];
            const double inverseScale = 1.0 / scale;
            // exp(-depth) at this length: by the recurrence on the linear
            // axis (no exp), then only the coprime pairs go on.
            for (int k = 0; k < steps; ++k)
            {
              const double a =
                logarithmic ? std::exp(-stepDepth[k] * scale) : attenuation[k] * unitAttenuation[k];
              attenuation[k] = a < TinyAttenuation ? 0.0 : a; // no denormals below
            }
            if (!logarithmic && std::gcd(j0, l0) != 1)
            {
              continue; // (j0, l0) is a multiple of a coprime pair
            }
            StepWeightsRun(steps, scale, inverseScale, stepDepth.data(), inverseStepDepth.data(),
              attenuation.data(), tau.data(), weight[0].data(), weight[1].data(), weight[2].data(),
              weight[3].data());
            // The intervals, front to back: forward (increasing scalar),
            // interval i's sub-steps in increasing order, cell[0][i];
            // backward (b < f), in decreasing order, cell[1][cells - 1 - i],
            // so that a window of cells is again front to back.
            for (int i = 0; i < cells; ++i)
            {
              Composite forward = { { 0, 0, 0 }, 1.0 }, backward = { { 0, 0, 0 }, 1.0 };
              for (int k = tableSample[i]; k < tableSample[i + 1]; ++k)
              {
                const double a = attenuation[k];
                for (int c = 0; c < 3; ++c)
                {
                  const double lower = color[c][k], upper = color[c][k + 1];
                  forward.Color[c] +=
                    forward.Transmittance * (weight[0][k] * lower + weight[1][k] * upper);
                  backward.Color[c] =
                    weight[2][k] * lower + weight[3][k] * upper + a * backward.Color[c];
                }
                forward.Transmittance *= a;
                backward.Transmittance *= a;
              }
              cell[0][i] = forward;
              cell[1][cells - 1 - i] = backward;
            }
            // Every entry of j = q j0 at layer q l0 (only q = 1 on the
            // logarithmic axis): a window of j intervals.
            const int multiples = logarithmic ? 1 : std::min(cells / j0, (nl - 1) / l0);
            for (int q = 1; q <= multiples; ++q)
            {
              const int j = q * j0, l = q * l0;
              for (int d = 0; d < 2; ++d)
              {
                const bool forward = d == 0;
                WindowComposites(cell[d].data(), cells, j, prefix.data(), suffix.data(),
                  [&](int s, const Composite& w)
                  {
                    // Forward: entry (s, s + j); backward: cells s .. s + j - 1
                    // are intervals cells - 1 - s down to cells - s - j: entry
                    // (cells - s, cells - s - j).
                    const int f = forward ? s : cells - s;
                    store(f, forward ? f + j : f - j, l, w);
                  });
              }
            }
          }
        }
      });
  }
  this->LastBuildSeconds = vtkTimerLog::GetUniversalTime() - start;
  return true;
}

//------------------------------------------------------------------------------
double vtkHAVSPreIntegrationTable::LengthCoordinate(double length) const
{
  if (!(this->MaxLength > 0.0) || !(length > 0.0))
  {
    return 0.0;
  }
  const double a = this->LengthLogScale;
  const double u =
    a > 0.0 ? std::log1p(a * length) / std::log1p(a * this->MaxLength) : length / this->MaxLength;
  return std::min(u, 1.0);
}

//------------------------------------------------------------------------------
double vtkHAVSPreIntegrationTable::LengthAt(double u) const
{
  const double a = this->LengthLogScale;
  return a > 0.0 ? std::expm1(u * std::log1p(a * this->MaxLength)) / a : u * this->MaxLength;
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::Lookup(double sf, double sb, double length, double rgba[4]) const
{
  const int ns = this->BuiltScalarResolution;
  const int nl = this->BuiltLengthResolution;
  const double span = this->ScalarRange[1] - this->ScalarRange[0];
  auto coordinate = [](double t, int n) { return std::min(std::max(t, 0.0), 1.0) * (n - 1); };
  const double x = coordinate(span > 0 ? (sf - this->ScalarRange[0]) / span : 0.0, ns);
  const double y = coordinate(span > 0 ? (sb - this->ScalarRange[0]) / span : 0.0, ns);
  const double z = coordinate(this->LengthCoordinate(length), nl);
  const int x0 = std::min(static_cast<int>(x), ns - 2);
  const int y0 = std::min(static_cast<int>(y), ns - 2);
  const int z0 = std::min(static_cast<int>(z), nl - 2);
  const double fx = x - x0, fy = y - y0, fz = z - z0;
  for (int c = 0; c < 4; ++c)
  {
    double v = 0.0;
    for (int corner = 0; corner < 8; ++corner)
    {
      const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
      const double w = (dx ? fx : 1 - fx) * (dy ? fy : 1 - fy) * (dz ? fz : 1 - fz);
      const size_t index =
        ((static_cast<size_t>(z0 + dz) * ns + (y0 + dy)) * ns + (x0 + dx)) * 4 + c;
      v += w * this->Table[index];
    }
    rgba[c] = v;
  }
}

//------------------------------------------------------------------------------
void vtkHAVSPreIntegrationTable::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ScalarResolution: " << this->ScalarResolution << "\n";
  os << indent << "LengthResolution: " << this->LengthResolution << "\n";
  os << indent << "SubdivisionsPerInterval: " << this->SubdivisionsPerInterval << "\n";
  os << indent << "ExactIntegration: " << this->ExactIntegration << "\n";
  os << indent << "ScalarRange: " << this->ScalarRange[0] << " " << this->ScalarRange[1] << "\n";
  os << indent << "MaxLength: " << this->MaxLength << "\n";
  os << indent << "LengthLogScale: " << this->LengthLogScale << "\n";
  os << indent << "LastBuildSeconds: " << this->LastBuildSeconds << "\n";
  os << indent << "EntryBuilder: " << (this->Builder ? "set" : "none")
     << ", last build by it: " << this->LastBuiltByEntryBuilder << "\n";
}

//------------------------------------------------------------------------------
size_t vtkHAVSPreIntegrationTable::GetMemoryBytes() const
{
  return (this->Table.capacity() + this->TransferFunction1D.capacity() +
           this->Additive1D.capacity()) *
    sizeof(float);
}

VTK_ABI_NAMESPACE_END

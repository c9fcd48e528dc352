/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSSoftwareKBuffer.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSSoftwareKBuffer.h"

#include "vtkFloatArray.h"
#include "vtkHAVSPreIntegrationTable.h"
#include "vtkHAVSReferenceRenderer.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSSoftwareKBuffer);

namespace
{
using Fragment = vtkHAVSReferenceRenderer::Fragment;

/// How close (relative) after an exit an internal fragment takes the exit's
/// role: HAVS_GRAZE in vtkHAVSKBufferLib.glsl.
constexpr double kGraze = 1.0e-3;

/// One k-buffer entry, as on the GPU.
struct Entry
{
  double Distance;
  double Scalar; ///< on the near side (a segment ending here)
  bool Exit;
  bool Entering; ///< a boundary face seen from outside
  double Behind; ///< on the far side (a segment starting here; cell scalars differ)

  /// The GPU's leave order: distance, near-ties internal < exit < entry.
  double Key() const
  {
    const double rank = this->Entering ? 2.0 : (this->Exit ? 1.0 : 0.0);
    return this->Distance + rank * 4.0e-6 * std::fabs(this->Distance);
  }
};

/// The GPU's k-buffer for one pixel (vtkHAVSKBufferLib.glsl, front to back).
class PixelKBuffer
{
public:
  PixelKBuffer(int k, const vtkHAVSPreIntegrationTable* table, double terminationOpacity)
    : K(k)
    , Table(table)
    , Termination(terminationOpacity)
  {
    this->Waiting.reserve(k);
  }

  void Insert(const Entry& f)
  {
    if (this->Ended())
    {
      return;
    }
    if (static_cast<int>(this->Waiting.size()) < this->K - 1)
    {
      this->Waiting.push_back(f);
      return;
    }
    Entry leaving = f;
    int nearest = -1;
    for (int i = 0; i < static_cast<int>(this->Waiting.size()); ++i)
    {
      if (this->Waiting[i].Key() < leaving.Key())
      {
        leaving = this->Waiting[i];
        nearest = i;
      }
    }
    if (nearest >= 0)
    {
      this->Waiting[nearest] = f;
    }
    this->Advance(leaving);
  }

  void Flush()
  {
    std::sort(this->Waiting.begin(), this->Waiting.end(),
      [](const Entry& a, const Entry& b) { return a.Key() < b.Key(); });
    for (const Entry& e : this->Waiting)
    {
      if (this->Ended())
      {
        break;
      }
      this->Advance(e);
    }
    this->Waiting.clear();
  }

  double Color[4] = { 0, 0, 0, 0 };

private:
  bool Ended() const { return this->Color[3] >= this->Termination; }

  void Advance(const Entry& p)
  {
    // As the GPU's k-buffer: a fragment behind the front (out of order)
    // leaves the front where it is (nothing is integrated twice) and gives it
    // only a boundary fragment's role.
    if (this->HaveFront && p.Distance < this->Front.Distance)
    {
      if (p.Exit || p.Entering)
      {
        this->Front.Exit = p.Exit;
        this->Front.Entering = p.Entering;
      }
      return;
    }
    if (this->HaveFront && !this->Front.Exit)
    {
      const double length = p.Distance - this->Front.Distance;
      if (length > 0.0)
      {
        double segment[4];
        this->Table->Lookup(this->Front.Behind, p.Scalar, length, segment);
        const double t = 1.0 - this->Color[3];
        for (int c = 0; c < 4; ++c)
        {
          this->Color[c] += t * segment[c];
        }
      }
    }
    // As the GPU's k-buffer (HAVS_GRAZE): an internal fragment a hair after
    // an exit takes the exit's role.
    const bool stray = this->HaveFront && this->Front.Exit && !p.Exit && !p.Entering &&
      p.Distance - this->Front.Distance < kGraze * std::fabs(this->Front.Distance);
    this->Front = p;
    this->Front.Exit = this->Front.Exit || stray;
    this->HaveFront = true;
  }

  int K;
  const vtkHAVSPreIntegrationTable* Table;
  double Termination;
  std::vector<Entry> Waiting;
  Entry Front{ 0, 0, false, false };
  bool HaveFront = false;
};

/// A pixel's fragments in draw order.
void DrawOrder(const Fragment* begin, const Fragment* end, const std::vector<uint32_t>& rank,
  std::vector<const Fragment*>& out)
{
  out.clear();
  for (const Fragment* f = begin; f != end; ++f)
  {
    out.push_back(f);
  }
  // The synthetic fragments where the near or a clipping plane cuts the mesh
  // are drawn first (entries) or last (exits), as the mapper draws them.
  const auto rankOf = [&](uint32_t face) -> int64_t
  {
    return face == vtkHAVSReferenceRenderer::StartFace
      ? -1
      : (face == vtkHAVSReferenceRenderer::EndFace ? std::numeric_limits<int64_t>::max()
                                                   : static_cast<int64_t>(rank[face]));
  };
  std::stable_sort(out.begin(), out.end(),
    [&](const Fragment* a, const Fragment* b) { return rankOf(a->Face) < rankOf(b->Face); });
}

/// True when the k-buffer with k entries outputs the distances sorted.
bool OutputsSorted(const double* d, int n, int k)
{
  std::vector<double> waiting;
  waiting.reserve(k);
  double last = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i)
  {
    if (static_cast<int>(waiting.size()) < k - 1)
    {
      waiting.push_back(d[i]);
      continue;
    }
    double leaving = d[i];
    int nearest = -1;
    for (int j = 0; j < static_cast<int>(waiting.size()); ++j)
    {
      if (waiting[j] < leaving)
      {
        leaving = waiting[j];
        nearest = j;
      }
    }
    if (nearest >= 0)
    {
      waiting[nearest] = d[i];
    }
    if (leaving < last)
    {
      return false;
    }
    last = leaving;
  }
  // The rest leaves in order; only its first can be out of order.
  for (double w : waiting)
  {
    if (w < last)
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
int vtkHAVSSoftwareKBuffer::RequiredK(const double* distances, int n)
{
  // Monotone in k: binary search between 1 and n (k = n holds everything).
  int lo = 1, hi = std::max(n, 1);
  while (lo < hi)
  {
    const int mid = (lo + hi) / 2;
    if (OutputsSorted(distances, n, mid))
    {
      hi = mid;
    }
    else
    {
      lo = mid + 1;
    }
  }
  return lo;
}

//------------------------------------------------------------------------------
void vtkHAVSSoftwareKBuffer::SetFaceOrder(const std::vector<uint32_t>& order)
{
  this->DrawRank.assign(order.size(), 0);
  for (size_t i = 0; i < order.size(); ++i)
  {
    this->DrawRank[order[i]] = static_cast<uint32_t>(i);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkHAVSSoftwareKBuffer::Render(vtkHAVSReferenceRenderer* fragments,
  vtkHAVSPreIntegrationTable* table, int k, double terminationOpacity, vtkFloatArray* image)
{
  if (!fragments || !table || !image || k < 1 || this->DrawRank.empty())
  {
    vtkErrorMacro("Render needs fragments, a table, an image, k >= 1 and a face order.");
    return false;
  }
  const int* size = fragments->GetSize();
  const vtkIdType pixels = static_cast<vtkIdType>(size[0]) * size[1];
  image->SetNumberOfComponents(4);
  image->SetNumberOfTuples(pixels);
  float* out = image->GetPointer(0);
  vtkSMPTools::For(0, pixels,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<const Fragment*> ordered;
      for (vtkIdType p = begin; p < end; ++p)
      {
        DrawOrder(fragments->GetPixelFragmentsBegin(p), fragments->GetPixelFragmentsEnd(p),
          this->DrawRank, ordered);
        PixelKBuffer buffer(k, table, terminationOpacity);
        for (const Fragment* f : ordered)
        {
          buffer.Insert(
            { f->Distance, f->Scalar, f->Exit, f->Boundary && !f->Exit, f->ScalarBehind() });
        }
        buffer.Flush();
        for (int c = 0; c < 4; ++c)
        {
          out[4 * p + c] = static_cast<float>(buffer.Color[c]);
        }
      }
    });
  image->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkHAVSSoftwareKBuffer::Analyze(
  vtkHAVSReferenceRenderer* fragments, vtkIntArray* requiredK, vtkUnsignedCharArray* colours)
{
  if (!fragments || !requiredK || this->DrawRank.empty())
  {
    vtkErrorMacro("Analyze needs fragments, an output array and a face order.");
    return false;
  }
  const int* size = fragments->GetSize();
  const vtkIdType pixels = static_cast<vtkIdType>(size[0]) * size[1];
  requiredK->SetNumberOfComponents(1);
  requiredK->SetNumberOfTuples(pixels);
  int* k = requiredK->GetPointer(0);
  vtkSMPTools::For(0, pixels,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<const Fragment*> ordered;
      std::vector<double> distances;
      for (vtkIdType p = begin; p < end; ++p)
      {
        DrawOrder(fragments->GetPixelFragmentsBegin(p), fragments->GetPixelFragmentsEnd(p),
          this->DrawRank, ordered);
        distances.clear();
        for (const Fragment* f : ordered)
        {
          distances.push_back(f->Distance);
        }
        k[p] =
          distances.empty() ? 0 : RequiredK(distances.data(), static_cast<int>(distances.size()));
      }
    });
  this->NumberOfFragments = fragments->GetNumberOfFragments();
  this->LongestList = 0;
  this->MaximumRequiredK = 0;
  this->PixelsOverK2 = this->PixelsOverK6 = this->PixelsOverK14 = 0;
  for (vtkIdType p = 0; p < pixels; ++p)
  {
    const int n =
      static_cast<int>(fragments->GetPixelFragmentsEnd(p) - fragments->GetPixelFragmentsBegin(p));
    this->LongestList = std::max(this->LongestList, n);
    this->MaximumRequiredK = std::max(this->MaximumRequiredK, k[p]);
    this->PixelsOverK2 += k[p] > 2 ? 1 : 0;
    this->PixelsOverK6 += k[p] > 6 ? 1 : 0;
    this->PixelsOverK14 += k[p] > 14 ? 1 : 0;
  }
  if (colours)
  {
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(pixels);
    for (vtkIdType p = 0; p < pixels; ++p)
    {
      unsigned char rgb[3] = { 0, 0, 0 }; // empty pixel: black
      if (k[p] > 6)
      {
        rgb[0] = 255;
      }
      else if (k[p] > 2)
      {
        rgb[0] = rgb[1] = 255;
      }
      else if (k[p] > 0)
      {
        rgb[1] = 200;
      }
      colours->SetTypedTuple(p, rgb);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkHAVSSoftwareKBuffer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfFragments: " << this->NumberOfFragments << "\n";
  os << indent << "LongestList: " << this->LongestList << "\n";
  os << indent << "MaximumRequiredK: " << this->MaximumRequiredK << "\n";
  os << indent << "PixelsOverK2: " << this->PixelsOverK2 << "\n";
  os << indent << "PixelsOverK6: " << this->PixelsOverK6 << "\n";
  os << indent << "PixelsOverK14: " << this->PixelsOverK14 << "\n";
}

VTK_ABI_NAMESPACE_END

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRadixSorter.cxx

=========================================================================*/
#include "vtkHAVSRadixSorter.h"

#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstring>

vtkStandardNewMacro(vtkHAVSRadixSorter);

namespace
{
constexpr size_t kSerialBelow = 65536;
constexpr int kRadix = 256;
}

//------------------------------------------------------------------------------
uint32_t vtkHAVSRadixSorter::FloatToSortableKey(float value)
{
  if (std::isnan(value))
  {
    return 0xFFFFFFFFu;
  }
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  // Negative: flip every bit (larger magnitude sorts first); positive: set the sign bit.
  return (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
}

//------------------------------------------------------------------------------
void vtkHAVSRadixSorter::Sort(const float* keys, size_t n, std::vector<uint32_t>& order)
{
  order.resize(n);
  if (n == 0)
  {
    return;
  }
  this->Keys.resize(n);
  this->KeysScratch.resize(n);
  this->OrderScratch.resize(n);
  const size_t chunks = n < kSerialBelow
    ? 1
    : std::min<size_t>(4 * std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()), n / 4096 + 1);
  const size_t chunkSize = (n + chunks - 1) / chunks;
  this->Histograms.assign(chunks * kRadix, 0);

  uint32_t* inKeys = this->Keys.data();
  uint32_t* outKeys = this->KeysScratch.data();
  uint32_t* inOrder = order.data();
  uint32_t* outOrder = this->OrderScratch.data();
  vtkSMPTools::For(0, static_cast<vtkIdType>(n), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      inKeys[i] = FloatToSortableKey(keys[i]);
      inOrder[i] = static_cast<uint32_t>(i);
    }
  });

  size_t* histograms = this->Histograms.data();
  for (int pass = 0; pass < 4; ++pass)
  {
    const int shift = 8 * pass;
    auto histogramChunk = [&](size_t c) {
      size_t* h = histograms + c * kRadix;
      std::fill(h, h + kRadix, size_t(0));
      const size_t begin = c * chunkSize, end = std::min(n, begin + chunkSize);
      for (size_t i = begin; i < end; ++i)
      {
        ++h[(inKeys[i] >> shift) & 0xFF];
      }
    };
    auto scatterChunk = [&](size_t c) {
      size_t* offsets = histograms + c * kRadix;
      const size_t begin = c * chunkSize, end = std::min(n, begin + chunkSize);
      for (size_t i = begin; i < end; ++i)
      {
        const size_t at = offsets[(inKeys[i] >> shift) & 0xFF]++;
        outKeys[at] = inKeys[i];
        outOrder[at] = inOrder[i];
      }
    };
    if (chunks == 1)
    {
      histogramChunk(0);
    }
    else
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), [&](vtkIdType b, vtkIdType e) {
        for (vtkIdType c = b; c < e; ++c)
        {
          histogramChunk(static_cast<size_t>(c));
        }
      });
    }
    // Skip a pass whose byte is the same everywhere.
    bool trivial = false;
    for (int bucket = 0; bucket < kRadix && !trivial; ++bucket)
    {
      size_t total = 0;
      for (size_t c = 0; c < chunks; ++c)
      {
        total += histograms[c * kRadix + bucket];
      }
      trivial = total == n;
    }
    if (trivial)
    {
      continue;
    }
    // Exclusive prefix over (bucket, chunk): chunk c's start for each bucket.
    size_t running = 0;
    for (int bucket = 0; bucket < kRadix; ++bucket)
    {
      for (size_t c = 0; c < chunks; ++c)
      {
        const size_t count = histograms[c * kRadix + bucket];
        histograms[c * kRadix + bucket] = running;
        running += count;
      }
    }
    if (chunks == 1)
    {
      scatterChunk(0);
    }
    else
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), [&](vtkIdType b, vtkIdType e) {
        for (vtkIdType c = b; c < e; ++c)
        {
          scatterChunk(static_cast<size_t>(c));
        }
      });
    }
    std::swap(inKeys, outKeys);
    std::swap(inOrder, outOrder);
  }
  if (inOrder != order.data())
  {
    std::copy(inOrder, inOrder + n, order.data());
  }
}

//------------------------------------------------------------------------------
void vtkHAVSRadixSorter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scratch capacity: " << this->Keys.capacity() << " keys\n";
}

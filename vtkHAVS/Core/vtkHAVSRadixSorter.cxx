/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRadixSorter.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
#include "vtkHAVSRadixSorter.h"

#include "vtkObjectFactory.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

VTK_ABI_NAMESPACE_BEGIN

vtkStandardNewMacro(vtkHAVSRadixSorter);

namespace
{
/// Fewer keys than this are sorted serially, in one chunk.
constexpr size_t SerialBelow = 65536;
/// No chunk is made smaller than this.
constexpr size_t MinimumChunkSize = 4096;
constexpr int NumberOfBuckets = 256;
constexpr int NumberOfPasses = 4;

/// Calls work(chunk) for every chunk; in parallel when there are several.
template <typename Work>
void ForEachChunk(size_t chunks, Work&& work)
{
  if (chunks == 1)
  {
    work(size_t(0));
    return;
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType chunk = begin; chunk < end; ++chunk)
      {
        work(static_cast<size_t>(chunk));
      }
    });
}
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
  // Negative: flip every bit (a larger magnitude sorts first); positive: set
  // the sign bit (above every negative). Only a NaN could reach 0xFFFFFFFF.
  return (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
}

//------------------------------------------------------------------------------
void vtkHAVSRadixSorter::Sort(const float* keys, size_t n, std::vector<uint32_t>& order)
{
  if (n > std::numeric_limits<uint32_t>::max())
  {
    vtkErrorMacro("Sort: " << n << " keys do not fit 32-bit indices.");
    order.clear();
    return;
  }
  order.resize(n);
  if (n == 0)
  {
    return;
  }
  this->Keys.resize(n);
  this->KeysScratch.resize(n);
  this->OrderScratch.resize(n);
  const size_t threads =
    static_cast<size_t>(std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()));
  const size_t chunks = n < SerialBelow ? 1 : std::min(4 * threads, n / MinimumChunkSize);
  const size_t chunkSize = (n + chunks - 1) / chunks;
  auto chunkBegin = [&](size_t chunk) { return std::min(n, chunk * chunkSize); };
  auto chunkEnd = [&](size_t chunk) { return std::min(n, (chunk + 1) * chunkSize); };
  this->BucketCounts.resize(chunks * NumberOfBuckets);
  size_t* counts = this->BucketCounts.data();

  uint32_t* inKeys = this->Keys.data();
  uint32_t* outKeys = this->KeysScratch.data();
  uint32_t* inOrder = order.data();
  uint32_t* outOrder = this->OrderScratch.data();
  ForEachChunk(chunks,
    [&](size_t chunk)
    {
      for (size_t i = chunkBegin(chunk); i < chunkEnd(chunk); ++i)
      {
        inKeys[i] = FloatToSortableKey(keys[i]);
        inOrder[i] = static_cast<uint32_t>(i);
      }
    });

  for (int pass = 0; pass < NumberOfPasses; ++pass)
  {
    const int shift = 8 * pass;
    auto bucketOf = [shift](uint32_t key) { return (key >> shift) & 0xFFu; };

    ForEachChunk(chunks,
      [&](size_t chunk)
      {
        size_t* chunkCounts = counts + chunk * NumberOfBuckets;
        std::fill(chunkCounts, chunkCounts + NumberOfBuckets, size_t(0));
        for (size_t i = chunkBegin(chunk); i < chunkEnd(chunk); ++i)
        {
          ++chunkCounts[bucketOf(inKeys[i])];
        }
      });

    // A byte shared by every key leaves the order as it is.
    const uint32_t firstBucket = bucketOf(inKeys[0]);
    size_t inFirstBucket = 0;
    for (size_t chunk = 0; chunk < chunks; ++chunk)
    {
      inFirstBucket += counts[chunk * NumberOfBuckets + firstBucket];
    }
    if (inFirstBucket == n)
    {
      continue;
    }

    // Counts to output offsets: bucket by bucket, and within a bucket chunk
    // by chunk, so that equal bytes keep their input order.
    size_t offset = 0;
    for (int bucket = 0; bucket < NumberOfBuckets; ++bucket)
    {
      for (size_t chunk = 0; chunk < chunks; ++chunk)
      {
        size_t& slot = counts[chunk * NumberOfBuckets + bucket];
        const size_t count = slot;
        slot = offset;
        offset += count;
      }
    }

    ForEachChunk(chunks,
      [&](size_t chunk)
      {
        size_t* chunkOffsets = counts + chunk * NumberOfBuckets;
        for (size_t i = chunkBegin(chunk); i < chunkEnd(chunk); ++i)
        {
          const size_t at = chunkOffsets[bucketOf(inKeys[i])]++;
          outKeys[at] = inKeys[i];
          outOrder[at] = inOrder[i];
        }
      });
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

//------------------------------------------------------------------------------
size_t vtkHAVSRadixSorter::GetMemoryBytes() const
{
  return vtkHAVSMemory::Bytes(
    this->Keys, this->KeysScratch, this->OrderScratch, this->BucketCounts);
}

VTK_ABI_NAMESPACE_END

/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRadixSorter.h

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
/**
 * @class   vtkHAVSRadixSorter
 * @brief   Stable parallel LSD radix sort of float keys (4 passes of 8 bits).
 *
 * The CPU sort of HAVS (Callahan, Ikits, Comba and Silva 2005, section
 * 4.3.1). Floats are mapped to uint32 keys that order like the floats
 * (FloatToSortableKey). Each pass counts its byte per chunk of the input in
 * parallel (vtkSMPTools), turns the counts into per-chunk, per-bucket output
 * offsets (bucket-major, so chunks keep their input order: stable) and
 * scatters the chunks in parallel. A pass whose byte is the same for every key
 * is skipped. Below 65536 keys everything runs serially in one chunk.
 *
 * Scratch buffers are members, reused across calls: one sorter must not sort
 * from two threads at once, two sorters may.
 */
#ifndef vtkHAVSRadixSorter_h
#define vtkHAVSRadixSorter_h

#include "vtkHAVSABINamespace.h" // For VTK_ABI_NAMESPACE_BEGIN

#include "vtkHAVSCoreModule.h" // For export macro
#include "vtkHAVSMemory.h"     // For vtkHAVSMemory::Bytes
#include "vtkObject.h"

#include <cstddef> // For size_t
#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

VTK_ABI_NAMESPACE_BEGIN

class VTKHAVSCORE_EXPORT vtkHAVSRadixSorter : public vtkObject
{
public:
  static vtkHAVSRadixSorter* New();
  vtkTypeMacro(vtkHAVSRadixSorter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Monotone map from floats to unsigned keys: a < b implies key(a) < key(b);
   * -0 maps just below +0; -inf and +inf map below and above every finite
   * value; every NaN maps to 0xFFFFFFFF (sorted last).
   */
  static uint32_t FloatToSortableKey(float value);

  /**
   * Fills `order` with the permutation that sorts `keys` ascending, stably:
   * keys[order[0]] <= keys[order[1]] <= ..., equal keys in input order.
   * At most 2^32 - 1 keys (an error, and an empty order, beyond).
   */
  void Sort(const float* keys, size_t n, std::vector<uint32_t>& order);

  /// The bytes its arrays hold (vtkHAVSMemory).
  size_t GetMemoryBytes() const;

protected:
  vtkHAVSRadixSorter() = default;
  ~vtkHAVSRadixSorter() override = default;

private:
  vtkHAVSRadixSorter(const vtkHAVSRadixSorter&) = delete;
  void operator=(const vtkHAVSRadixSorter&) = delete;

  std::vector<uint32_t> Keys;
  std::vector<uint32_t> KeysScratch;
  std::vector<uint32_t> OrderScratch;
  std::vector<size_t> BucketCounts; // 256 per chunk, then the chunk's output offsets
};

VTK_ABI_NAMESPACE_END
#endif

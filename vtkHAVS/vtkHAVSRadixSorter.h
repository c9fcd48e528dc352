/*=========================================================================

  Project:   vtkHAVS
  Module:    vtkHAVSRadixSorter.h

=========================================================================*/
/**
 * @class   vtkHAVSRadixSorter
 * @brief   Stable parallel LSD radix sort of float keys (4 passes of 8 bits).
 *
 * Floats are mapped to uint32 keys that order like the floats
 * (FloatToSortableKey); each pass histograms its byte per chunk in parallel
 * (vtkSMPTools), turns the histograms into per-chunk offsets and scatters the
 * chunks in parallel. A pass whose byte is the same for every key is skipped.
 * Scratch buffers are members, reused across calls (no static state).
 */
#ifndef vtkHAVSRadixSorter_h
#define vtkHAVSRadixSorter_h

#include "vtkHAVSModule.h" // For export macro
#include "vtkObject.h"

#include <cstddef> // For size_t
#include <cstdint> // For uint32_t
#include <vector>  // For std::vector

class VTKHAVS_EXPORT vtkHAVSRadixSorter : public vtkObject
{
public:
  static vtkHAVSRadixSorter* New();
  vtkTypeMacro(vtkHAVSRadixSorter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Monotone map: a < b implies key(a) < key(b); -0 and +0 map to adjacent
   * keys (-0 first); NaN maps to 0xFFFFFFFF (sorted last).
   */
  static uint32_t FloatToSortableKey(float value);

  /**
   * Fills `order` with the permutation that sorts `keys` ascending (stable).
   */
  void Sort(const float* keys, size_t n, std::vector<uint32_t>& order);

protected:
  vtkHAVSRadixSorter() = default;
  ~vtkHAVSRadixSorter() override = default;

private:
  vtkHAVSRadixSorter(const vtkHAVSRadixSorter&) = delete;
  void operator=(const vtkHAVSRadixSorter&) = delete;

  std::vector<uint32_t> Keys;
  std::vector<uint32_t> KeysScratch;
  std::vector<uint32_t> OrderScratch;
  std::vector<size_t> Histograms; // chunk x 256
};

#endif

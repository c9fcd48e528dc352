// vtkHAVSRadixSorter: the float -> key map is monotone (negatives, denormals,
// zeros, infinities, NaN last); Sort equals std::stable_sort on random arrays
// (serial and parallel sizes, duplicates, negatives), stably. Negative
// control: sorting raw bit patterns (the classic mistake) must disagree.
#include "vtkHAVSTestUtilities.h"

#include "vtkHAVSRadixSorter.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>

int main()
{
  const float values[] = { -std::numeric_limits<float>::infinity(), -3.4e38f, -1.0f, -1e-38f,
    -1e-45f, -0.0f, 0.0f, 1e-45f, 1e-38f, 1.0f, 3.4e38f, std::numeric_limits<float>::infinity() };
  bool monotone = true;
  for (size_t i = 0; i + 1 < sizeof(values) / sizeof(values[0]); ++i)
  {
    monotone = monotone &&
      vtkHAVSRadixSorter::FloatToSortableKey(values[i]) <
        vtkHAVSRadixSorter::FloatToSortableKey(values[i + 1]);
  }
  havstest::Check(monotone, "FloatToSortableKey is monotone");
  havstest::Check(vtkHAVSRadixSorter::FloatToSortableKey(std::nanf("")) == 0xFFFFFFFFu,
    "NaN sorts last");

  vtkNew<vtkHAVSRadixSorter> sorter;
  std::mt19937 random(7);
  for (size_t n : { size_t(0), size_t(1), size_t(1000), size_t(100000), size_t(1000003) })
  {
    std::vector<float> keys(n);
    std::uniform_real_distribution<float> value(-100.0f, 100.0f);
    for (auto& k : keys)
    {
      // many duplicates; + 0 turns -0 into +0, which std::sort treats as equal
      k = std::round(value(random) * 10.0f) / 10.0f + 0.0f;
    }
    std::vector<uint32_t> order;
    sorter->Sort(keys.data(), n, order);
    std::vector<uint32_t> expected(n);
    std::iota(expected.begin(), expected.end(), 0u);
    std::stable_sort(expected.begin(), expected.end(),
      [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
    havstest::Check(order == expected, "Sort equals std::stable_sort, n = " + std::to_string(n));

    if (n == 100000)
    {
      // Negative control: raw IEEE bit patterns do not order negative floats.
      std::vector<uint32_t> raw(n);
      std::iota(raw.begin(), raw.end(), 0u);
      std::stable_sort(raw.begin(), raw.end(), [&](uint32_t a, uint32_t b) {
        uint32_t ba, bb;
        std::memcpy(&ba, &keys[a], 4);
        std::memcpy(&bb, &keys[b], 4);
        return ba < bb;
      });
      havstest::Check(raw != expected, "negative control: a raw bit sort is detected as wrong");
    }
  }
  return havstest::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}

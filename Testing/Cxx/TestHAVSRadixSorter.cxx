/*=========================================================================

  Project:   vtkHAVS
  Module:    TestHAVSRadixSorter.cxx

  Copyright (c) 2026 the vtkHAVS developers
  SPDX-License-Identifier: BSD-3-Clause (see LICENSE)

=========================================================================*/
// vtkHAVSRadixSorter: the float -> key map is monotone (negatives, denormals,
// zeros, infinities; every NaN last); Sort equals std::stable_sort under an
// independent reference order on random arrays (serial and parallel sizes,
// duplicates, negatives, special values, constant and presorted inputs), and is
// stable. Negative control: sorting raw bit patterns (the classic mistake)
// must be detected as wrong by the same comparison.
#include "havsTestChecks.h"

#include "vtkHAVSRadixSorter.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <numeric>
#include <random>

namespace
{
float FromBits(uint32_t bits)
{
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

uint32_t ToBits(float value)
{
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

/// The order the sorter must produce, written from the floats themselves:
/// numeric order, -0 before +0, every NaN last (NaNs equal to each other).
bool ReferenceLess(float a, float b)
{
  if (std::isnan(a) || std::isnan(b))
  {
    return !std::isnan(a);
  }
  if (a != b)
  {
    return a < b;
  }
  return std::signbit(a) && !std::signbit(b);
}

/// The stable permutation that sorts `keys` under `less`.
std::vector<uint32_t> StableOrder(
  const std::vector<float>& keys, const std::function<bool(float, float)>& less)
{
  std::vector<uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(
    order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return less(keys[a], keys[b]); });
  return order;
}

/// True when `order` lists every index once, keys ascend under ReferenceLess,
/// and equal keys keep their input order.
bool SortedAndStable(const std::vector<float>& keys, const std::vector<uint32_t>& order)
{
  std::vector<bool> seen(keys.size(), false);
  for (size_t i = 0; i < order.size(); ++i)
  {
    if (order[i] >= keys.size() || seen[order[i]])
    {
      return false;
    }
    seen[order[i]] = true;
    if (i > 0)
    {
      const float previous = keys[order[i - 1]], current = keys[order[i]];
      if (ReferenceLess(current, previous))
      {
        return false;
      }
      if (!ReferenceLess(previous, current) && order[i - 1] > order[i])
      {
        return false;
      }
    }
  }
  return order.size() == keys.size();
}

void CheckKeyMap()
{
  using Limits = std::numeric_limits<float>;
  // Ascending, each strictly below the next (-0 below +0).
  const std::vector<float> ladder = { -Limits::infinity(), -Limits::max(), -3.0e38f, -1.0f,
    -Limits::min(), -1.0e-39f, -Limits::denorm_min(), -0.0f, 0.0f, Limits::denorm_min(), 1.0e-39f,
    Limits::min(), 1.0f, 1.0f + Limits::epsilon(), 3.0e38f, Limits::max(), Limits::infinity() };
  bool monotone = true;
  for (size_t i = 0; i + 1 < ladder.size(); ++i)
  {
    monotone = monotone &&
      vtkHAVSRadixSorter::FloatToSortableKey(ladder[i]) <
        vtkHAVSRadixSorter::FloatToSortableKey(ladder[i + 1]);
  }
  havstest::Check(monotone, "FloatToSortableKey is strictly monotone on the ladder");

  // Random bit patterns (every exponent, denormals included): keys order
  // exactly like ReferenceLess.
  std::mt19937 random(3);
  std::vector<float> values(200000);
  for (auto& v : values)
  {
    do
    {
      v = FromBits(static_cast<uint32_t>(random()));
    } while (std::isnan(v));
  }
  std::sort(values.begin(), values.end(), ReferenceLess);
  bool agrees = true;
  for (size_t i = 0; i + 1 < values.size(); ++i)
  {
    const uint32_t a = vtkHAVSRadixSorter::FloatToSortableKey(values[i]);
    const uint32_t b = vtkHAVSRadixSorter::FloatToSortableKey(values[i + 1]);
    agrees = agrees && (ReferenceLess(values[i], values[i + 1]) ? a < b : a == b);
  }
  havstest::Check(agrees, "FloatToSortableKey is monotone on random bit patterns");

  // Every NaN (quiet, signalling, negative) maps to the top; nothing else does.
  bool nanLast = true;
  for (uint32_t bits : { 0x7FC00000u, 0x7F800001u, 0x7FFFFFFFu, 0xFFC00000u, 0xFF800001u })
  {
    nanLast = nanLast && vtkHAVSRadixSorter::FloatToSortableKey(FromBits(bits)) == 0xFFFFFFFFu;
  }
  havstest::Check(nanLast, "every NaN maps to 0xFFFFFFFF");
  havstest::Check(
    vtkHAVSRadixSorter::FloatToSortableKey(Limits::infinity()) < 0xFFFFFFFFu, "+inf below NaN");
}

/// Test inputs of n keys.
std::vector<float> RoundedUniform(size_t n, std::mt19937& random)
{
  // Many duplicates, negatives, and both zeros (rounding -0.04 gives -0).
  std::uniform_real_distribution<float> value(-100.0f, 100.0f);
  std::vector<float> keys(n);
  for (auto& k : keys)
  {
    k = std::round(value(random) * 10.0f) / 10.0f;
  }
  return keys;
}

std::vector<float> AnyBits(size_t n, std::mt19937& random)
{
  // Every float: denormals, infinities, NaNs, huge and tiny magnitudes.
  std::vector<float> keys(n);
  for (auto& k : keys)
  {
    k = FromBits(static_cast<uint32_t>(random()));
  }
  return keys;
}

std::vector<float> Constant(size_t n, std::mt19937&)
{
  return std::vector<float>(n, -2.5f);
}

std::vector<float> Descending(size_t n, std::mt19937&)
{
  std::vector<float> keys(n);
  for (size_t i = 0; i < n; ++i)
  {
    keys[i] = static_cast<float>(n) - static_cast<float>(i) * 0.5f;
  }
  return keys;
}
}

int TestHAVSRadixSorter(int, char*[])
{
  CheckKeyMap();

  vtkNew<vtkHAVSRadixSorter> sorter;
  std::mt19937 random(7);
  using Generator = std::vector<float> (*)(size_t, std::mt19937&);
  const std::pair<const char*, Generator> inputs[] = { { "rounded uniform", RoundedUniform },
    { "any bits", AnyBits }, { "constant", Constant }, { "descending", Descending } };
  // The last size, after the largest, checks that reused scratch buffers do no harm.
  for (size_t n :
    { size_t(0), size_t(1), size_t(1000), size_t(100000), size_t(1000003), size_t(777) })
  {
    for (const auto& input : inputs)
    {
      const std::string name = std::string(input.first) + ", n = " + std::to_string(n);
      const std::vector<float> keys = input.second(n, random);
      std::vector<uint32_t> order(3, 42); // stale content must be replaced
      sorter->Sort(keys.data(), n, order);
      havstest::Check(
        order == StableOrder(keys, ReferenceLess), name + ": equals std::stable_sort");
      havstest::Check(SortedAndStable(keys, order), name + ": sorted and stable");
    }
  }

  // Negative control: ordering by raw IEEE bit patterns puts negative floats
  // after positive ones and larger negative magnitudes last; the checks above
  // must see it.
  const std::vector<float> keys = RoundedUniform(100000, random);
  const std::vector<uint32_t> rawBitOrder =
    StableOrder(keys, [](float a, float b) { return ToBits(a) < ToBits(b); });
  havstest::Check(rawBitOrder != StableOrder(keys, ReferenceLess),
    "negative control: a raw bit sort differs from the reference");
  havstest::Check(
    !SortedAndStable(keys, rawBitOrder), "negative control: a raw bit sort fails the order check");
  // ... and so must an unstable order of equal keys.
  std::vector<uint32_t> unstable = StableOrder(keys, ReferenceLess);
  const auto tie = std::adjacent_find(
    unstable.begin(), unstable.end(), [&](uint32_t a, uint32_t b) { return keys[a] == keys[b]; });
  std::iter_swap(tie, tie + 1);
  havstest::Check(!SortedAndStable(keys, unstable),
    "negative control: swapped equal keys fail the stability check");
  return havstest::Result();
}

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_RadixSortByKey_h
#define timecritical_RadixSortByKey_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
namespace collapse
{
/**
 * Stable sort of entries by their 32-bit unsigned member Key: least
 * significant digit first, three digits of 11 bits, through `buffer` (resized
 * to the entries' size, so that a caller reusing it does not allocate). A digit
 * that is the same in every entry is skipped. The collapse schedules sort
 * their candidates with it (float costs mapped to ordered bits).
 */
template <class Entry>
void RadixSortByKey(std::vector<Entry>& entries, std::vector<Entry>& buffer)
{
  constexpr unsigned bits = 11, buckets = 1u << bits, mask = buckets - 1;
  static_assert(3 * bits >= 32, "three digits cover the key");
  const size_t n = entries.size();
  if (n < 2)
  {
    return;
  }
  std::array<uint32_t, 3 * buckets> counts{}; // on the stack: no allocation
  for (const Entry& e : entries)
  {
    ++counts[e.Key & mask];
    ++counts[buckets + ((e.Key >> bits) & mask)];
    ++counts[2 * buckets + (e.Key >> (2 * bits))];
  }
  buffer.resize(n);
  for (unsigned digit = 0; digit < 3; ++digit)
  {
    uint32_t* count = counts.data() + digit * buckets;
    const unsigned shift = digit * bits;
    if (count[(entries[0].Key >> shift) & mask] == n)
    {
      continue;
    }
    uint32_t sum = 0;
    for (unsigned b = 0; b < buckets; ++b)
    {
      const uint32_t c = count[b];
      count[b] = sum;
      sum += c;
    }
    for (const Entry& e : entries)
    {
      buffer[count[(e.Key >> shift) & mask]++] = e;
    }
    entries.swap(buffer);
  }
}
} // namespace collapse
} // namespace timecritical

#endif

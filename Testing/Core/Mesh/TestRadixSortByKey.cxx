// SPDX-License-Identifier: BSD-3-Clause
#include "PassSchedule.h" // OrderedBits: float costs as sortable keys
#include "RadixSortByKey.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using timecritical::collapse::PassSchedule;
using timecritical::collapse::RadixSortByKey;

namespace
{
struct Entry
{
  uint32_t Key;
  uint32_t Vertex;
};
} // namespace

TEST(RadixSortByKey, IsAStableSortByKey)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<float> value(-10.f, 10.f);
  std::vector<Entry> entries, buffer;
  for (uint32_t v = 0; v < 20000; ++v)
  {
    // Few distinct keys (ties), across every digit of the bits.
    const float key = v % 3 == 0 ? std::ldexp(value(random), int(v % 40) - 20) : float(v % 7);
    entries.push_back({ PassSchedule::OrderedBits(key), v });
  }
  std::vector<Entry> expected = entries;
  std::stable_sort(expected.begin(), expected.end(),
    [](const Entry& a, const Entry& b) { return a.Key < b.Key; });
  RadixSortByKey(entries, buffer);
  ASSERT_EQ(entries.size(), expected.size());
  for (size_t i = 0; i < entries.size(); ++i)
  {
    ASSERT_EQ(entries[i].Vertex, expected[i].Vertex) << i;
    ASSERT_EQ(entries[i].Key, expected[i].Key) << i;
  }
  // Single and empty lists, and a list whose keys are all the same.
  std::vector<Entry> one = { { 7u, 3u } }, none, same(100, Entry{ 42u, 0u });
  for (uint32_t i = 0; i < same.size(); ++i)
  {
    same[i].Vertex = i;
  }
  RadixSortByKey(one, buffer);
  RadixSortByKey(none, buffer);
  RadixSortByKey(same, buffer);
  EXPECT_EQ(one[0].Vertex, 3u);
  EXPECT_TRUE(none.empty());
  for (uint32_t i = 0; i < same.size(); ++i)
  {
    EXPECT_EQ(same[i].Vertex, i);
  }
}


// SPDX-License-Identifier: BSD-3-Clause
// IndexedHeap, the engine's min-heap of vertices by key: the top is always a
// smallest key, SecondKey the next one, and keys can be changed and entries
// removed anywhere; checked against a plain array under random operations.

#include "IndexedHeap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace
{
using timecritical::collapse::IndexedHeap;

constexpr float Absent = std::numeric_limits<float>::infinity();

// The smallest and second smallest keys of the reference (+inf when none).
std::pair<float, float> TwoSmallest(const std::vector<float>& keys)
{
  std::vector<float> present;
  for (float k : keys)
  {
    if (k != Absent)
    {
      present.push_back(k);
    }
  }
  std::sort(present.begin(), present.end());
  return { present.empty() ? Absent : present[0], present.size() < 2 ? Absent : present[1] };
}

void ExpectSameAsReference(const IndexedHeap& heap, const std::vector<float>& keys)
{
  const std::pair<float, float> smallest = TwoSmallest(keys);
  ASSERT_EQ(heap.Empty(), smallest.first == Absent);
  if (!heap.Empty())
  {
    ASSERT_EQ(heap.Top().Key, smallest.first);
    ASSERT_EQ(keys[heap.Top().Vertex], heap.Top().Key);
  }
  ASSERT_EQ(heap.SecondKey(), smallest.second);
}

TEST(IndexedHeap, EmptyHeap)
{
  IndexedHeap heap;
  heap.Reset(4);
  EXPECT_TRUE(heap.Empty());
  EXPECT_EQ(heap.SecondKey(), Absent);
  heap.Remove(2); // not in the heap: nothing happens
  EXPECT_TRUE(heap.Empty());
}

TEST(IndexedHeap, HeapifiedEntriesComeOutInKeyOrder)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> key(0.f, 100.f);
  const uint32_t n = 1000;
  IndexedHeap heap;
  heap.Reset(n);
  std::vector<float> keys(n);
  for (uint32_t v = 0; v < n; ++v)
  {
    keys[v] = key(rng);
    heap.PushUnordered(v, keys[v]);
  }
  heap.Heapify();
  std::vector<float> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  for (float expected : sorted)
  {
    ASSERT_FALSE(heap.Empty());
    ASSERT_EQ(heap.Top().Key, expected);
    heap.Remove(heap.Top().Vertex);
  }
  EXPECT_TRUE(heap.Empty());
}

TEST(IndexedHeap, RandomSetsAndRemovalsKeepTheMinimumOnTop)
{
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> key(0.f, 10.f);
  const uint32_t n = 300;
  std::uniform_int_distribution<uint32_t> vertex(0, n - 1);
  IndexedHeap heap;
  heap.Reset(n);
  std::vector<float> keys(n, Absent);
  for (int i = 0; i < 20000; ++i)
  {
    const uint32_t v = vertex(rng);
    if (i % 3 == 2)
    {
      heap.Remove(v);
      keys[v] = Absent;
    }
    else
    {
      // Coarse keys: many ties, raised and lowered keys, new entries.
      keys[v] = static_cast<float>(static_cast<int>(key(rng)));
      heap.Set(v, keys[v]);
    }
    ExpectSameAsReference(heap, keys);
  }
}

TEST(IndexedHeap, ResetEmptiesTheHeap)
{
  IndexedHeap heap;
  heap.Reset(3);
  heap.Set(0, 1.f);
  heap.Set(1, 2.f);
  heap.Reset(3);
  EXPECT_TRUE(heap.Empty());
  heap.Set(1, 5.f);
  EXPECT_EQ(heap.Top().Vertex, 1u);
  EXPECT_EQ(heap.SecondKey(), Absent);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// ScratchBlocks hands the storage of finished arrays on: Take returns
// aligned room from the block with the least room that holds it, never
// overlapping earlier takes, and null when no block is large enough.

#include "ScratchBlocks.h"

#include "HugePageAllocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

namespace
{
using timecritical::collapse::BigVector;
using timecritical::collapse::ScratchBlocks;

TEST(ScratchBlocks, NothingAddedGivesNothing)
{
  ScratchBlocks blocks;
  EXPECT_EQ(blocks.Take<uint32_t>(1), nullptr);
}

TEST(ScratchBlocks, TakesFromTheTightestBlockWithoutOverlap)
{
  BigVector<uint64_t> small(100), large(1000);
  const uintptr_t smallBegin = reinterpret_cast<uintptr_t>(small.data());
  const uintptr_t largeBegin = reinterpret_cast<uintptr_t>(large.data());
  ScratchBlocks blocks;
  blocks.Add(std::move(large));
  blocks.Add(std::move(small));

  // 50 doubles fit both: the small block is the tighter fit.
  double* a = blocks.Take<double>(50);
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(a), smallBegin);
  // 60 more do not fit what is left of the small block: the large one.
  double* b = blocks.Take<double>(60);
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(b), largeBegin);
  // 10 ids fit the rest of both: the rest of the small block, right after a.
  uint32_t* c = blocks.Take<uint32_t>(10);
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(c), reinterpret_cast<uintptr_t>(a + 50));
  // 100 more ids fit only the large block: after b.
  uint32_t* d = blocks.Take<uint32_t>(100);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(d), reinterpret_cast<uintptr_t>(b + 60));
  // More than any block holds.
  EXPECT_EQ(blocks.Take<uint64_t>(2000), nullptr);
}

TEST(ScratchBlocks, AlignsEachTake)
{
  BigVector<unsigned char> bytes(256);
  ScratchBlocks blocks;
  blocks.Add(std::move(bytes));
  ASSERT_NE(blocks.Take<unsigned char>(3), nullptr);
  double* d = blocks.Take<double>(4);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(d) % alignof(double), 0u);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// HugePageAllocator: small and large arrays (above HugePageThreshold, on
// blocks of their own where the system allows) hold and keep their contents.

#include "HugePageAllocator.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace
{
using namespace timecritical::collapse;

void FillAndCheck(size_t n)
{
  BigVector<uint32_t> v(n);
  for (size_t i = 0; i < n; ++i)
  {
    v[i] = static_cast<uint32_t>(i * 2654435761u);
  }
  v.resize(n + n / 2 + 1); // a reallocation keeps the contents
  for (size_t i = 0; i < n; ++i)
  {
    ASSERT_EQ(v[i], static_cast<uint32_t>(i * 2654435761u)) << i;
  }
}

TEST(HugePageAllocator, SmallArray)
{
  FillAndCheck(1000);
}

TEST(HugePageAllocator, LargeArray)
{
  FillAndCheck(2 * HugePageThreshold / sizeof(uint32_t) + 12345);
}

TEST(HugePageAllocator, ReserveHugeOnAnOrdinaryVector)
{
  std::vector<double> v;
  ReserveHuge(v, HugePageThreshold);
  EXPECT_GE(v.capacity(), HugePageThreshold);
  v.assign(HugePageThreshold, 1.5);
  EXPECT_EQ(v.back(), 1.5);
}

TEST(HugePageAllocator, BlockIsAlignedWhereGiven)
{
  const size_t bytes = 3 * HugePageThreshold;
  void* p = AllocateHugePageBlock(bytes);
  if (!p)
  {
    GTEST_SKIP() << "no huge-page advice on this system";
  }
  EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % (size_t(2) << 20), 0u);
  static_cast<unsigned char*>(p)[bytes - 1] = 1;
  EXPECT_TRUE(FreeHugePageBlock(p, bytes));
}
}

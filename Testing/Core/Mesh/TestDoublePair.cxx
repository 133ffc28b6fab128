// SPDX-License-Identifier: BSD-3-Clause
// DoublePair: two doubles in one SSE2 register, each lane computed as the
// scalar arithmetic would, and KeepPositive per lane.

#include "CostLanes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
#if defined(__SSE2__)
using timecritical::collapse::DoublePair;
using timecritical::collapse::KeepPositive;

TEST(DoublePair, LanesKeepTheirValues)
{
  const DoublePair p = DoublePair::Of(1.5, -2.25);
  EXPECT_EQ(p.Lane0(), 1.5);
  EXPECT_EQ(p.Lane1(), -2.25);
  const DoublePair both(3.0);
  EXPECT_EQ(both.Lane0(), 3.0);
  EXPECT_EQ(both.Lane1(), 3.0);
}

TEST(DoublePair, ArithmeticIsPerLane)
{
  const DoublePair a = DoublePair::Of(0.1, 7.0);
  const DoublePair b = DoublePair::Of(0.2, -3.0);
  EXPECT_EQ((a + b).Lane0(), 0.1 + 0.2);
  EXPECT_EQ((a + b).Lane1(), 4.0);
  EXPECT_EQ((a - b).Lane0(), 0.1 - 0.2);
  EXPECT_EQ((a - b).Lane1(), 10.0);
  EXPECT_EQ((a * b).Lane0(), 0.1 * 0.2);
  EXPECT_EQ((a * b).Lane1(), -21.0);
}

TEST(DoublePair, KeepPositiveClampsEachLane)
{
  const DoublePair r = KeepPositive(DoublePair::Of(-1e-17, 2.5));
  EXPECT_EQ(r.Lane0(), 0.0);
  EXPECT_EQ(r.Lane1(), 2.5);
  const DoublePair n = KeepPositive(DoublePair::Of(std::numeric_limits<double>::quiet_NaN(), -0.0));
  EXPECT_EQ(n.Lane0(), 0.0);
  EXPECT_EQ(n.Lane1(), 0.0);
  EXPECT_FALSE(std::signbit(n.Lane1()));
  EXPECT_EQ(KeepPositive(-3.0), 0.0);
  EXPECT_EQ(KeepPositive(3.0), 3.0);
}
#else
TEST(DoublePair, NeedsSSE2)
{
  GTEST_SKIP() << "DoublePair exists only with SSE2";
}
#endif
}

// SPDX-License-Identifier: BSD-3-Clause
// The collapse cost costed in pairs (CostLanes<DoublePair>) must give the
// scalar result bit for bit, so that the TOM does not depend on the
// instruction set; the scalar lanes must compute the documented formula.

#include "CostLanes.h"

#include "CollapseCostReference.h"
#include "CollapseQuadric.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>

namespace
{
using namespace timecritical::collapse;
using namespace timecritical::collapse::reference;

TEST(CostLanes, ScalarLanesMatchTheDocumentedFormula)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int clamped = 0;
  for (int i = 0; i < 2000; ++i)
  {
    const LocalQuadric q(RandomRecord(rng), { coordinate(rng), coordinate(rng), coordinate(rng) });
    const Vec3 p{ coordinate(rng), coordinate(rng), coordinate(rng) };
    const double cost = CostLanes<double>(q).Cost(p.X, p.Y, p.Z);
    ASSERT_EQ(Bits(cost), Bits(ReferenceCost(q, p))) << i;
    clamped += q.Evaluate(p) == 0.0 ? 1 : 0;
  }
  EXPECT_GT(clamped, 100); // the clamp was taken
}

#if defined(__SSE2__)
TEST(CostLanes, PairedLanesGiveTheScalarBits)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i)
  {
    const LocalQuadric q(RandomRecord(rng), { coordinate(rng), coordinate(rng), coordinate(rng) });
    const Vec3 p0{ coordinate(rng), coordinate(rng), coordinate(rng) };
    const Vec3 p1{ coordinate(rng), coordinate(rng), coordinate(rng) };
    const DoublePair c = CostLanes<DoublePair>(q).Cost(
      DoublePair::Of(p0.X, p1.X), DoublePair::Of(p0.Y, p1.Y), DoublePair::Of(p0.Z, p1.Z));
    const CostLanes<double> scalar(q);
    ASSERT_EQ(Bits(c.Lane0()), Bits(scalar.Cost(p0.X, p0.Y, p0.Z))) << i;
    ASSERT_EQ(Bits(c.Lane1()), Bits(scalar.Cost(p1.X, p1.Y, p1.Z))) << i;
  }
}

TEST(CostLanes, PairedClampTreatsNaNAndNegativeZeroAsTheScalarOne)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const DoublePair kept = KeepPositive(DoublePair::Of(nan, -0.0));
  EXPECT_EQ(Bits(kept.Lane0()), Bits(KeepPositive(nan)));
  EXPECT_EQ(Bits(kept.Lane1()), Bits(KeepPositive(-0.0)));
  EXPECT_EQ(Bits(KeepPositive(nan)), Bits(0.0));
  const DoublePair passed = KeepPositive(DoublePair::Of(2.5, -1.0));
  EXPECT_EQ(passed.Lane0(), 2.5);
  EXPECT_EQ(passed.Lane1(), 0.0);
}
#endif
}

// SPDX-License-Identifier: BSD-3-Clause
// Quadric: the sum of weighted squared distances to planes, evaluated exactly
// against planes whose distances are known by hand.

#include "Quadric.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace timecritical::collapse;

TEST(Quadric, EmptyQuadricIsZeroEverywhere)
{
  const Quadric q;
  EXPECT_EQ(q.Evaluate({ 0.0, 0.0, 0.0 }), 0.0);
  EXPECT_EQ(q.Evaluate({ 3.0, -2.0, 5.0 }), 0.0);
}

TEST(Quadric, OnePlaneGivesTheWeightedSquaredDistance)
{
  Quadric q;
  q.AddPlane({ 0.0, 0.0, 1.0 }, -2.0, 3.0); // the plane z = 2, weight 3
  EXPECT_DOUBLE_EQ(q.Evaluate({ 7.0, -4.0, 2.0 }), 0.0);
  EXPECT_DOUBLE_EQ(q.Evaluate({ 0.0, 0.0, 5.0 }), 3.0 * 9.0);
  EXPECT_DOUBLE_EQ(q.Evaluate({ 1.0, 1.0, 0.0 }), 3.0 * 4.0);
  EXPECT_DOUBLE_EQ(q.A22, 3.0);
  EXPECT_DOUBLE_EQ(q.B2, -6.0);
  EXPECT_DOUBLE_EQ(q.C, 12.0);
  EXPECT_EQ(q.A00, 0.0);
  EXPECT_EQ(q.A01, 0.0);
}

TEST(Quadric, ThreePlanesSumTheirDistances)
{
  Quadric q;
  q.AddPlane({ 1.0, 0.0, 0.0 }, 0.0, 1.0);  // x = 0
  q.AddPlane({ 0.0, 1.0, 0.0 }, -1.0, 2.0); // y = 1, weight 2
  q.AddPlane({ 0.0, 0.0, 1.0 }, 1.0, 1.0);  // z = -1
  // (2)^2 + 2 (3 - 1)^2 + (1 + 1)^2 = 4 + 8 + 4
  EXPECT_DOUBLE_EQ(q.Evaluate({ 2.0, 3.0, 1.0 }), 16.0);
  EXPECT_DOUBLE_EQ(q.Evaluate({ 0.0, 1.0, -1.0 }), 0.0); // the corner of the three planes
}

TEST(Quadric, TiltedPlane)
{
  const double s = 1.0 / std::sqrt(2.0);
  Quadric q;
  q.AddPlane({ s, s, 0.0 }, 0.0, 1.0); // x + y = 0
  EXPECT_NEAR(q.Evaluate({ 1.0, 1.0, 9.0 }), 2.0, 1e-12); // distance sqrt(2)
  EXPECT_NEAR(q.Evaluate({ 1.0, -1.0, 0.0 }), 0.0, 1e-12);
  EXPECT_NEAR(q.A01, 0.5, 1e-15);
}

TEST(Quadric, AddAccumulatesEveryCoefficient)
{
  Quadric a;
  a.AddPlane({ 0.0, 0.0, 1.0 }, -1.0, 1.0);
  Quadric b;
  b.AddPlane({ 1.0, 0.0, 0.0 }, 2.0, 0.5);
  Quadric sum = a;
  sum.Add(b);
  for (const Vec3& p : { Vec3{ 0.0, 0.0, 0.0 }, Vec3{ 1.0, 2.0, 3.0 }, Vec3{ -2.0, 0.5, 1.0 } })
  {
    EXPECT_DOUBLE_EQ(sum.Evaluate(p), a.Evaluate(p) + b.Evaluate(p));
  }
  EXPECT_DOUBLE_EQ(sum.A00, 0.5);
  EXPECT_DOUBLE_EQ(sum.A22, 1.0);
  EXPECT_DOUBLE_EQ(sum.B0, 1.0);
  EXPECT_DOUBLE_EQ(sum.B2, -1.0);
  EXPECT_DOUBLE_EQ(sum.C, 1.0 + 0.5 * 4.0);
}

TEST(Quadric, EvaluateIsNeverNegative)
{
  Quadric q;
  q.C = -1e-18; // as cancellation can leave it
  EXPECT_EQ(q.Evaluate({ 0.0, 0.0, 0.0 }), 0.0);
}
}

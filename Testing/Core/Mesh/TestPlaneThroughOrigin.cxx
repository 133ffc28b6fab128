// SPDX-License-Identifier: BSD-3-Clause
// PlaneThroughOrigin: weight * n n^T, added to a record's matrix only.

#include "PlaneThroughOrigin.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace timecritical::collapse;

TEST(PlaneThroughOrigin, IsTheWeightedOuterProductOfTheNormal)
{
  const PlaneThroughOrigin plane({ 0.6, 0.0, 0.8 }, 2.0);
  EXPECT_DOUBLE_EQ(plane.A00, 2.0 * 0.36);
  EXPECT_DOUBLE_EQ(plane.A01, 0.0);
  EXPECT_DOUBLE_EQ(plane.A02, 2.0 * 0.48);
  EXPECT_DOUBLE_EQ(plane.A11, 0.0);
  EXPECT_DOUBLE_EQ(plane.A12, 0.0);
  EXPECT_DOUBLE_EQ(plane.A22, 2.0 * 0.64);
}

TEST(PlaneThroughOrigin, AddToGrowsTheMatrixOfTheRecordOnly)
{
  QuadricRecord r{};
  r.G1 = 3.0f;
  r.C = 1.0f;
  const PlaneThroughOrigin plane({ 0.0, 1.0, 0.0 }, 4.0); // the plane y = 0 through the vertex
  plane.AddTo(r);
  plane.AddTo(r);
  EXPECT_EQ(r.A11, 8.0f);
  EXPECT_EQ(r.A00, 0.0f);
  EXPECT_EQ(r.A22, 0.0f);
  EXPECT_EQ(r.A01, 0.0f);
  EXPECT_EQ(r.G1, 3.0f); // through the origin: no linear or constant term
  EXPECT_EQ(r.C, 1.0f);
}

TEST(PlaneThroughOrigin, GivesTheSquaredDistanceOfAnOffset)
{
  const double s = 1.0 / std::sqrt(3.0);
  const PlaneThroughOrigin plane({ s, s, s }, 1.0);
  // d^T A d for d = (1, 1, 1): (n.d)^2 = 3
  const double d[3] = { 1.0, 1.0, 1.0 };
  const double value = plane.A00 * d[0] * d[0] + plane.A11 * d[1] * d[1] + plane.A22 * d[2] * d[2] +
    2.0 * (plane.A01 * d[0] * d[1] + plane.A02 * d[0] * d[2] + plane.A12 * d[1] * d[2]);
  EXPECT_NEAR(value, 3.0, 1e-12);
}
}

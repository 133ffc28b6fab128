// SPDX-License-Identifier: BSD-3-Clause
// Vec3 and its operations: difference, cross and dot products, and the
// (unnormalised) normal of a triangle.

#include "CollapseGeometry.h"

#include <gtest/gtest.h>

namespace
{
using namespace timecritical::collapse;

void ExpectVec3(const Vec3& v, double x, double y, double z)
{
  EXPECT_DOUBLE_EQ(v.X, x);
  EXPECT_DOUBLE_EQ(v.Y, y);
  EXPECT_DOUBLE_EQ(v.Z, z);
}

TEST(Vec3, Sub)
{
  ExpectVec3(Sub({ 3.0, 5.0, -1.0 }, { 1.0, 7.0, 2.0 }), 2.0, -2.0, -3.0);
}

TEST(Vec3, CrossOfTheAxes)
{
  ExpectVec3(Cross({ 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }), 0.0, 0.0, 1.0);
  ExpectVec3(Cross({ 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 }), 1.0, 0.0, 0.0);
  ExpectVec3(Cross({ 0.0, 0.0, 1.0 }, { 1.0, 0.0, 0.0 }), 0.0, 1.0, 0.0);
  ExpectVec3(Cross({ 0.0, 1.0, 0.0 }, { 1.0, 0.0, 0.0 }), 0.0, 0.0, -1.0);
}

TEST(Vec3, CrossOfGeneralVectors)
{
  // (1,2,3) x (4,5,6) = (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4)
  ExpectVec3(Cross({ 1.0, 2.0, 3.0 }, { 4.0, 5.0, 6.0 }), -3.0, 6.0, -3.0);
  ExpectVec3(Cross({ 1.0, 2.0, 3.0 }, { 2.0, 4.0, 6.0 }), 0.0, 0.0, 0.0);
}

TEST(Vec3, Dot)
{
  EXPECT_DOUBLE_EQ(Dot({ 1.0, 2.0, 3.0 }, { 4.0, -5.0, 6.0 }), 4.0 - 10.0 + 18.0);
  EXPECT_DOUBLE_EQ(Dot({ 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }), 0.0);
}

TEST(Vec3, TriangleNormalFollowsTheWindingWithTwiceTheArea)
{
  const Vec3 a{ 1.0, 1.0, 2.0 }, b{ 3.0, 1.0, 2.0 }, c{ 1.0, 4.0, 2.0 };
  ExpectVec3(TriangleNormal(a, b, c), 0.0, 0.0, 6.0); // legs 2 and 3: area 3
  ExpectVec3(TriangleNormal(a, c, b), 0.0, 0.0, -6.0);
  ExpectVec3(TriangleNormal(a, b, { 5.0, 1.0, 2.0 }), 0.0, 0.0, 0.0); // degenerate
}

TEST(Vec3, Pi)
{
  EXPECT_DOUBLE_EQ(Pi, 3.14159265358979323846);
}
}

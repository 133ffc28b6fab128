// SPDX-License-Identifier: BSD-3-Clause
// LocalQuadric: the double-precision copy of a QuadricRecord around its
// origin, Q(origin + d) = C + 2 G.d + d^T A d, checked against values
// computed by hand; AddTo re-expresses it around another origin.

#include "LocalQuadric.h"

#include <gtest/gtest.h>

namespace
{
using namespace timecritical::collapse;

/// A = [[1, 0.5, 0], [0.5, 2, 0], [0, 0, 3]], G = (1, 0, -1), C = 4, face weight 4.
QuadricRecord HandRecord()
{
  QuadricRecord r{};
  r.A00 = 1.0f;
  r.A01 = 0.5f;
  r.A11 = 2.0f;
  r.A22 = 3.0f;
  r.G0 = 1.0f;
  r.G2 = -1.0f;
  r.C = 4.0f;
  SetFaceWeight(r, 4.0f);
  return r;
}

TEST(LocalQuadric, CopiesTheRecordAndItsOrigin)
{
  const LocalQuadric q(HandRecord(), { 1.0, 1.0, 1.0 });
  EXPECT_EQ(q.A01, 0.5);
  EXPECT_EQ(q.G2, -1.0);
  EXPECT_EQ(q.C, 4.0);
  EXPECT_EQ(q.Origin.Y, 1.0);
  EXPECT_EQ(q.Weight, 4.0);
  EXPECT_EQ(q.InverseRootWeight, 0.5);
}

TEST(LocalQuadric, ApplyMultipliesBySymmetricMatrix)
{
  const LocalQuadric q(HandRecord(), { 1.0, 1.0, 1.0 });
  const Vec3 ad = q.Apply({ 1.0, 2.0, 0.0 });
  EXPECT_EQ(ad.X, 2.0); // 1*1 + 0.5*2
  EXPECT_EQ(ad.Y, 4.5); // 0.5*1 + 2*2
  EXPECT_EQ(ad.Z, 0.0);
  const Vec3 az = q.Apply({ 0.0, 0.0, 2.0 });
  EXPECT_EQ(az.X, 0.0);
  EXPECT_EQ(az.Z, 6.0);
}

TEST(LocalQuadric, EvaluateAtTheOriginIsC)
{
  const LocalQuadric q(HandRecord(), { 1.0, 1.0, 1.0 });
  EXPECT_EQ(q.Evaluate({ 1.0, 1.0, 1.0 }), 4.0);
}

TEST(LocalQuadric, EvaluateAtAnOffset)
{
  const LocalQuadric q(HandRecord(), { 1.0, 1.0, 1.0 });
  // d = (1, 2, 0): C + 2 G.d + d.Ad = 4 + 2*1 + (1*2 + 2*4.5) = 17
  EXPECT_EQ(q.Evaluate({ 2.0, 3.0, 1.0 }), 17.0);
  // d = (0, 0, 1): 4 + 2*(-1) + 3 = 5
  EXPECT_EQ(q.Evaluate({ 1.0, 1.0, 2.0 }), 5.0);
}

TEST(LocalQuadric, EvaluateIsNeverNegative)
{
  QuadricRecord r{};
  r.G0 = 1.0f; // a linear term alone goes negative on one side
  SetFaceWeight(r, 1.0f);
  const LocalQuadric q(r, { 0.0, 0.0, 0.0 });
  EXPECT_EQ(q.Evaluate({ -1.0, 0.0, 0.0 }), 0.0);
  EXPECT_EQ(q.Evaluate({ 1.0, 0.0, 0.0 }), 2.0);
}

TEST(LocalQuadric, AddToReexpressesAroundTheNewOrigin)
{
  const LocalQuadric q(HandRecord(), { 1.0, 1.0, 1.0 });
  const Vec3 newOrigin{ 2.0, 3.0, 1.0 }; // d = (1, 2, 0)
  QuadricRecord r{};
  r.C = 1.0f;
  SetFaceWeight(r, 1.0f);
  q.AddTo(r, newOrigin);
  EXPECT_EQ(r.A00, 1.0f);
  EXPECT_EQ(r.A01, 0.5f);
  EXPECT_EQ(r.A11, 2.0f);
  EXPECT_EQ(r.A22, 3.0f);
  EXPECT_EQ(r.G0, 3.0f);  // G + A d = (1 + 2, 0 + 4.5, -1 + 0)
  EXPECT_EQ(r.G1, 4.5f);
  EXPECT_EQ(r.G2, -1.0f);
  EXPECT_EQ(r.C, 18.0f);  // 1 + Q(newOrigin) = 1 + 17
  EXPECT_EQ(r.FaceWeight, 1.0f); // the weight is the caller's to set

  // The moved quadric gives the same values as the original (plus r's own C).
  const LocalQuadric moved(r, newOrigin);
  for (const Vec3& p : { Vec3{ 1.0, 1.0, 1.0 }, Vec3{ 0.0, 2.0, 3.0 }, Vec3{ 2.5, 3.0, 0.5 } })
  {
    EXPECT_DOUBLE_EQ(moved.Evaluate(p), q.Evaluate(p) + 1.0);
  }
}
}

// SPDX-License-Identifier: BSD-3-Clause
// QuadricRecord: one cache line; AddMatrix grows its matrix in single
// precision and leaves the rest; SetFaceWeight keeps the inverse square root
// of the weight (clamped at the smallest normal float).

#include "QuadricRecord.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using namespace timecritical::collapse;

QuadricRecord ZeroRecord()
{
  QuadricRecord r{};
  r.Slot = 7;
  return r;
}

struct Matrix
{
  double A00, A01, A02, A11, A12, A22;
};

TEST(QuadricRecord, FitsOneCacheLine)
{
  EXPECT_EQ(sizeof(QuadricRecord), 64u);
  EXPECT_EQ(alignof(QuadricRecord), 64u);
}

TEST(QuadricRecord, AddMatrixAddsTheSixEntriesOnly)
{
  QuadricRecord r = ZeroRecord();
  r.G0 = 1.5f;
  r.C = 2.0f;
  AddMatrix(r, Matrix{ 1.0, 2.0, 3.0, 4.0, 5.0, 6.0 });
  AddMatrix(r, Matrix{ 0.5, 0.5, 0.5, 0.5, 0.5, 0.5 });
  EXPECT_EQ(r.A00, 1.5f);
  EXPECT_EQ(r.A01, 2.5f);
  EXPECT_EQ(r.A02, 3.5f);
  EXPECT_EQ(r.A11, 4.5f);
  EXPECT_EQ(r.A12, 5.5f);
  EXPECT_EQ(r.A22, 6.5f);
  EXPECT_EQ(r.G0, 1.5f);
  EXPECT_EQ(r.C, 2.0f);
  EXPECT_EQ(r.Slot, 7u);
}

TEST(QuadricRecord, AddMatrixRoundsToSinglePrecision)
{
  QuadricRecord r = ZeroRecord();
  AddMatrix(r, Matrix{ 0.1, 0.0, 0.0, 0.0, 0.0, 0.0 });
  EXPECT_EQ(r.A00, 0.1f);
  EXPECT_NE(static_cast<double>(r.A00), 0.1);
}

TEST(QuadricRecord, SetFaceWeightKeepsTheInverseRoot)
{
  QuadricRecord r = ZeroRecord();
  SetFaceWeight(r, 4.0f);
  EXPECT_EQ(r.FaceWeight, 4.0f);
  EXPECT_EQ(r.InverseRootWeight, 0.5);
  SetFaceWeight(r, 0.25f);
  EXPECT_EQ(r.InverseRootWeight, 2.0);
}

TEST(QuadricRecord, SetFaceWeightClampsZeroWeight)
{
  QuadricRecord r = ZeroRecord();
  SetFaceWeight(r, 0.0f);
  EXPECT_EQ(r.FaceWeight, 0.0f);
  EXPECT_EQ(r.InverseRootWeight,
    1.0 / std::sqrt(static_cast<double>(std::numeric_limits<float>::min())));
  EXPECT_TRUE(std::isfinite(r.InverseRootWeight));
}
}

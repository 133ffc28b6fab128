// SPDX-License-Identifier: BSD-3-Clause
// Tests of FrameTimeCorrector: it converges to a constant bias, follows a
// change of bias within a few frames, estimates the spread of noisy ratios,
// resists single outliers and ignores invalid samples.
#include "FrameTimeCorrector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
using timecritical::FrameTimeCorrector;

TEST(FrameTimeCorrector, StartsNeutral)
{
  FrameTimeCorrector corrector;
  EXPECT_DOUBLE_EQ(corrector.GetFactor(), 1.0);
  EXPECT_DOUBLE_EQ(corrector.Correct(0.08), 0.08);
  EXPECT_DOUBLE_EQ(corrector.GetRelativeSpread(), 0.15);
  EXPECT_EQ(corrector.GetSampleCount(), 0);
}

TEST(FrameTimeCorrector, ConvergesToAConstantBiasWithinAFewFrames)
{
  FrameTimeCorrector corrector;
  // The model predicts 60 ms for frames that take 90 ms.
  int frames = 0;
  while (std::abs(corrector.Correct(0.06) - 0.09) > 0.005 * 0.09 && frames < 100)
  {
    corrector.Update(0.06, 0.09);
    ++frames;
  }
  EXPECT_LE(frames, 25);
  EXPECT_NEAR(corrector.GetFactor(), 1.5, 0.01);
  // The shift shows as spread for a while; exact samples then shrink it.
  for (int i = 0; i < 60; ++i)
  {
    corrector.Update(0.06, 0.09);
  }
  EXPECT_LT(corrector.GetRelativeSpread(), 0.01);
}

TEST(FrameTimeCorrector, FollowsAChangeOfView)
{
  FrameTimeCorrector corrector;
  for (int i = 0; i < 50; ++i)
  {
    corrector.Update(0.1, 0.1);
  }
  EXPECT_NEAR(corrector.GetFactor(), 1.0, 1e-9);
  // The model now over-predicts by 30%: within 8 frames the error is under 5%.
  for (int i = 0; i < 8; ++i)
  {
    corrector.Update(0.1, 0.07);
  }
  EXPECT_NEAR(corrector.Correct(0.1), 0.07, 0.05 * 0.07);
}

TEST(FrameTimeCorrector, EstimatesTheSpreadOfNoisyFrames)
{
  FrameTimeCorrector corrector;
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.06);
  for (int i = 0; i < 2000; ++i)
  {
    corrector.Update(0.1, 0.1 * std::exp(noise(random)));
  }
  EXPECT_NEAR(corrector.GetRelativeSpread(), 0.06, 0.02);
  EXPECT_NEAR(corrector.GetFactor(), 1.0, 0.08);
}

TEST(FrameTimeCorrector, OneStalledFrameMovesTheFactorLittle)
{
  FrameTimeCorrector corrector;
  for (int i = 0; i < 50; ++i)
  {
    corrector.Update(0.1, 0.1);
  }
  corrector.Update(0.1, 1.5); // a 15x stall
  EXPECT_LT(corrector.GetFactor(), 1.1);
  EXPECT_GT(corrector.GetFactor(), 1.0);
}

TEST(FrameTimeCorrector, IgnoresInvalidSamples)
{
  FrameTimeCorrector corrector;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(corrector.Update(nan, 0.1));
  EXPECT_FALSE(corrector.Update(0.1, nan));
  EXPECT_FALSE(corrector.Update(0.0, 0.1));
  EXPECT_FALSE(corrector.Update(0.1, -1.0));
  EXPECT_FALSE(corrector.Update(inf, 0.1));
  EXPECT_EQ(corrector.GetSampleCount(), 0);
  EXPECT_DOUBLE_EQ(corrector.GetFactor(), 1.0);
  EXPECT_TRUE(corrector.Update(0.1, 0.2));
  EXPECT_EQ(corrector.GetSampleCount(), 1);
  corrector.Reset();
  EXPECT_EQ(corrector.GetSampleCount(), 0);
  EXPECT_DOUBLE_EQ(corrector.GetFactor(), 1.0);
}

TEST(FrameTimeCorrector, FactorIsBounded)
{
  FrameTimeCorrector corrector;
  for (int i = 0; i < 500; ++i)
  {
    corrector.Update(0.001, 10.0);
  }
  EXPECT_LE(corrector.GetFactor(), std::exp(1.0) * (1 + 1e-12));
}
}

namespace
{
TEST(FrameTimeCorrector, RareStallsDoNotInflateTheSpread)
{
  FrameTimeCorrector corrector;
  std::mt19937 random(11);
  std::normal_distribution<double> noise(0.0, 0.04);
  for (int i = 0; i < 600; ++i)
  {
    const double stall = (i % 25 == 0) ? 2.0 : 1.0; // 4% of the frames take twice as long
    corrector.Update(0.1, 0.1 * stall * std::exp(noise(random)));
  }
  EXPECT_LT(corrector.GetRelativeSpread(), 0.06);
  EXPECT_LT(corrector.GetFactor(), 1.08);
}
}

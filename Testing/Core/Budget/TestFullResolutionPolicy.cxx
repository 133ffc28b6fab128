// SPDX-License-Identifier: BSD-3-Clause
// Tests of FullResolutionPolicy and of what ResolutionPolicy::Select()
// reports for any policy (prediction, objective, over-budget flag).
#include "PolicyTestScene.h"

#include "FullResolutionPolicy.h"

#include <gtest/gtest.h>

namespace
{
using timecritical::FullResolutionPolicy;
using timecritical_test::PolicyScene;

TEST(FullResolutionPolicy, EverythingAtFullResolution)
{
  PolicyScene scene(100, 1.0, 1);
  FullResolutionPolicy policy;
  EXPECT_STREQ(policy.GetName(), "none");
  std::vector<double> r(100, 0.5);
  const auto result = policy.Select(scene.Input(), r.data());
  for (double x : r)
  {
    EXPECT_EQ(x, 1.0);
  }
  EXPECT_NEAR(result.PredictedFrameTime, scene.FixedTime + scene.Problem.CostAtFull(), 1e-12);
  EXPECT_NEAR(result.Objective, scene.Problem.View().Objective(r.data()), 1e-9);
  EXPECT_TRUE(result.OverBudget); // the budget is 30 % of the way from rmin to full
  EXPECT_GE(result.Seconds, 0.0);
}

TEST(FullResolutionPolicy, EmptyScene)
{
  FullResolutionPolicy policy;
  timecritical::PolicyInput in;
  in.FixedTime = 0.01;
  const auto result = policy.Select(in, nullptr);
  EXPECT_EQ(result.PredictedFrameTime, 0.01);
  EXPECT_FALSE(result.OverBudget);
}
}

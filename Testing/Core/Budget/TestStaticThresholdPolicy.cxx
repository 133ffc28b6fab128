// SPDX-License-Identifier: BSD-3-Clause
// Tests of StaticThresholdPolicy: the pixels-per-triangle rule and its clamps.
#include "PolicyTestScene.h"

#include "StaticThresholdPolicy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using timecritical::StaticThresholdPolicy;
using timecritical_test::PolicyScene;

TEST(StaticThresholdPolicy, PixelsPerTriangleRule)
{
  PolicyScene scene(200, 1.0, 2);
  StaticThresholdPolicy policy;
  policy.SetPixelsPerTriangle(4.0);
  EXPECT_STREQ(policy.GetName(), "static");
  std::vector<double> r(200);
  policy.Select(scene.Input(), r.data());
  const auto& p = scene.Problem;
  for (std::size_t i = 0; i < r.size(); ++i)
  {
    const double expected =
      std::min(1.0, std::max(p.MinResolution[i], p.Pixels[i] / (4.0 * p.Triangles[i])));
    EXPECT_DOUBLE_EQ(r[i], expected);
    // Where not clamped, an average triangle covers exactly k pixels.
    if (r[i] > p.MinResolution[i] && r[i] < 1.0)
    {
      EXPECT_NEAR(p.Pixels[i] / (r[i] * p.Triangles[i]), 4.0, 1e-12);
    }
  }
}

TEST(StaticThresholdPolicy, NotAdaptive)
{
  // Same threshold, twice the objects: twice the time over budget. This is
  // what the predictive policies fix.
  PolicyScene scene(100, 1.0, 3);
  StaticThresholdPolicy policy;
  std::vector<double> r(100);
  const double t1 = policy.Select(scene.Input(), r.data()).PredictedFrameTime - scene.FixedTime;
  PolicyScene doubled = scene;
  auto& q = doubled.Problem;
  for (auto* v : { &q.Weight, &q.MaxTime, &q.MinResolution, &q.Pixels, &q.Triangles })
  {
    v->insert(v->end(), v->begin(), v->end());
  }
  std::vector<double> r2(200);
  const double t2 = policy.Select(doubled.Input(), r2.data()).PredictedFrameTime - scene.FixedTime;
  EXPECT_NEAR(t2, 2.0 * t1, 1e-12);
}

TEST(StaticThresholdPolicy, MissingDataAndBadThreshold)
{
  PolicyScene scene(10, 1.0, 4);
  StaticThresholdPolicy policy;
  policy.SetPixelsPerTriangle(-3.0); // ignored
  policy.SetPixelsPerTriangle(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(policy.GetPixelsPerTriangle(), 8.0);
  auto in = scene.Input();
  in.Pixels = nullptr;
  std::vector<double> r(10);
  policy.Select(in, r.data());
  for (double x : r)
  {
    EXPECT_EQ(x, 1.0);
  }
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of FeedbackPolicy on a simulated renderer: convergence to the target,
// reaction to a sudden change of scene, anti-windup, PI gains, Reset().
#include "PolicyTestScene.h"

#include "FeedbackPolicy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using timecritical::FeedbackPolicy;
using timecritical_test::PolicyScene;

/// Run frames; returns the measured times.
std::vector<double> RunFrames(FeedbackPolicy& policy, const PolicyScene& scene, int frames,
  std::mt19937_64& rng, double last = -1.0)
{
  std::vector<double> times;
  std::vector<double> r(scene.Problem.Weight.size());
  for (int f = 0; f < frames; ++f)
  {
    policy.Select(scene.Input(false, last), r.data());
    last = scene.Render(r, rng);
    times.push_back(last);
  }
  return times;
}

double MeanRelativeError(const std::vector<double>& t, std::size_t from, double target)
{
  double s = 0.0;
  for (std::size_t i = from; i < t.size(); ++i)
  {
    s += std::abs(t[i] / target - 1.0);
  }
  return s / static_cast<double>(t.size() - from);
}

TEST(FeedbackPolicy, ConvergesOnASimulatedRenderer)
{
  for (double kp : { 0.0, 0.3 })
  {
    PolicyScene scene(300, 1.0, 5);
    FeedbackPolicy policy;
    FeedbackPolicy::Gains gains;
    gains.Proportional = kp;
    policy.SetGains(gains);
    policy.SetInitialPixelsPerTriangle(0.01); // everything at full resolution at first
    std::mt19937_64 rng(1);
    const auto t = RunFrames(policy, scene, 40, rng);
    EXPECT_GT(t.front(), 1.5 * scene.Target);               // starts way over
    EXPECT_LT(MeanRelativeError(t, 20, scene.Target), 0.03) << "kp " << kp; // then holds it
  }
}

TEST(FeedbackPolicy, OvershootsOnASuddenChangeThenRecovers)
{
  PolicyScene light(100, 1.0, 6), heavy(400, 1.0, 6);
  heavy.Target = light.Target;
  FeedbackPolicy policy;
  std::mt19937_64 rng(2);
  auto t = RunFrames(policy, light, 30, rng);
  // The turn to a view full of objects: the first frame uses the old threshold.
  const auto after = RunFrames(policy, heavy, 30, rng, t.back());
  EXPECT_GT(after.front(), 1.5 * light.Target);
  EXPECT_LT(MeanRelativeError(after, 15, light.Target), 0.03);
}

TEST(FeedbackPolicy, AntiWindupWhenTheTargetIsUnreachable)
{
  PolicyScene scene(50, 1.0, 7);
  for (std::size_t i = 0; i < 50; ++i)
  {
    scene.Problem.Pixels[i] = 2.0 * scene.Problem.Triangles[i]; // full resolution for k <= 2
  }
  scene.Target = 10.0; // everything fits: times far below target
  FeedbackPolicy policy;
  std::mt19937_64 rng(3);
  RunFrames(policy, scene, 50, rng);
  // The threshold stops once everything is at full resolution (k <= 2), one
  // step (at most a factor MaxStep = 4) past it, instead of running to its minimum.
  EXPECT_GE(policy.GetPixelsPerTriangle(), 2.0 / 4.0 - 1e-9);
  EXPECT_LE(policy.GetPixelsPerTriangle(), 2.0);
  policy.Reset();
  EXPECT_EQ(policy.GetPixelsPerTriangle(), 8.0);
}

TEST(FeedbackPolicy, IgnoresMissingMeasurements)
{
  PolicyScene scene(20, 1.0, 8);
  FeedbackPolicy policy;
  std::vector<double> r(20);
  policy.Select(scene.Input(), r.data()); // LastFrameTime NaN
  EXPECT_EQ(policy.GetPixelsPerTriangle(), 8.0);
  policy.Select(scene.Input(false, 2.0 * scene.Target), r.data());
  EXPECT_GT(policy.GetPixelsPerTriangle(), 8.0);
}
}

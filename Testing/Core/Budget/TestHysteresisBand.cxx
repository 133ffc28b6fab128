// SPDX-License-Identifier: BSD-3-Clause
// Tests of HysteresisBand: the band factor, which objects are held (in the
// band, with a last resolution, drawn, not below rmin), the budget (holds
// that free time first, then the cheapest that add time, within the slack),
// bad settings, no allocation once warm, and every policy through
// ResolutionPolicy::Select(): fewer changes under jitter, budget kept.
#include "AllocationCounter.h"
#include "PolicyTestScene.h"

#include "ActiveSetPolicy.h"
#include "FeedbackPolicy.h"
#include "GreedyLODPolicy.h"
#include "HysteresisBand.h"
#include "StaticThresholdPolicy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

namespace
{
using timecritical::HysteresisBand;

TEST(HysteresisBand, Factor)
{
  EXPECT_DOUBLE_EQ(HysteresisBand::Factor(0.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(HysteresisBand::Factor(0.5, 1.0), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(HysteresisBand::Factor(0.75, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(HysteresisBand::Factor(0.5, -0.5), 4.0);
  EXPECT_DOUBLE_EQ(HysteresisBand::Factor(0.5, 2.0), std::pow(2.0, 1.0 / 3.0));
}

TEST(HysteresisBand, RejectsBadSettings)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double h : { -0.1, 1.0, 2.0, nan, std::numeric_limits<double>::infinity() })
  {
    EXPECT_THROW(HysteresisBand::CheckHysteresis(h), std::invalid_argument) << h;
    EXPECT_THROW(HysteresisBand::Factor(h, 1.0), std::invalid_argument) << h;
  }
  for (double alpha : { -1.0, 0.0, -2.0, nan })
  {
    EXPECT_THROW(HysteresisBand::Factor(0.1, alpha), std::invalid_argument) << alpha;
  }
  HysteresisBand band;
  HysteresisBand::Input input;
  double r = 0.5;
  EXPECT_THROW(band.Apply(input, 1.5, &r), std::invalid_argument);
  EXPECT_NO_THROW(HysteresisBand::CheckHysteresis(0.0));
  EXPECT_NO_THROW(HysteresisBand::CheckHysteresis(0.99));
}

TEST(HysteresisBand, HoldsOnlyInsideTheBand)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // h = 0.75, alpha = 1: band factor 2.
  std::vector<double> t(8, 0.01), lo(8, 0.01);
  std::vector<double> previous = { 0.5, 0.5, 0.5, 0.45, nan, 0.0, 0.5, 0.005 };
  std::vector<double> r = { 0.3, 0.9, 0.2, 1.0, 0.5, 0.5, 0.0, 0.008 };
  lo[7] = 0.006; // last resolution below this frame's rmin
  HysteresisBand::Input input;
  input.Count = 8;
  input.MaxTime = t.data();
  input.MinResolution = lo.data();
  input.Previous = previous.data();
  input.Slack = 1.0;
  HysteresisBand band;
  EXPECT_EQ(band.Apply(input, 0.75, r.data()), 2u);
  EXPECT_EQ(r, (std::vector<double>{ 0.5, 0.5, 0.2, 1.0, 0.5, 0.5, 0.0, 0.008 }));
  // h = 0: nothing held.
  std::vector<double> r2 = { 0.3, 0.9, 0.2, 1.0, 0.5, 0.5, 0.0, 0.008 };
  EXPECT_EQ(band.Apply(input, 0.0, r2.data()), 0u);
  EXPECT_EQ(r2[0], 0.3);
}

TEST(HysteresisBand, KeepsTheBudget)
{
  // Three objects want to go down (holding them adds time), one up (holding
  // it frees time): the freed time plus the slack pays for the cheapest.
  std::vector<double> t = { 0.01, 0.02, 0.04, 0.01 };
  std::vector<double> previous = { 0.5, 0.5, 0.5, 0.5 };
  std::vector<double> r = { 0.4, 0.4, 0.4, 0.6 };
  HysteresisBand::Input input;
  input.Count = 4;
  input.MaxTime = t.data();
  input.Previous = previous.data();
  input.Slack = 0.002; // freed: 0.001; holds add 0.001, 0.002, 0.004
  const double before = 0.01 * 0.4 + 0.02 * 0.4 + 0.04 * 0.4 + 0.01 * 0.6;
  HysteresisBand band;
  EXPECT_EQ(band.Apply(input, 0.5, r.data()), 3u);
  EXPECT_EQ(r, (std::vector<double>{ 0.5, 0.5, 0.4, 0.5 }));
  const double after = 0.01 * 0.5 + 0.02 * 0.5 + 0.04 * 0.4 + 0.01 * 0.5;
  EXPECT_LE(after, before + input.Slack + 1e-15);
  // No slack: only the hold that frees time, and what it pays for.
  r = { 0.4, 0.4, 0.4, 0.6 };
  input.Slack = 0.0;
  EXPECT_EQ(band.Apply(input, 0.5, r.data()), 2u);
  EXPECT_EQ(r, (std::vector<double>{ 0.5, 0.4, 0.4, 0.5 }));
}

TEST(HysteresisBand, NoAllocationOnceWarm)
{
  timecritical_test::PolicyScene scene(500, 1.0, 3);
  std::vector<double> previous(500, 0.3), r(500, 0.31);
  HysteresisBand::Input input;
  input.Count = 500;
  input.MaxTime = scene.Problem.MaxTime.data();
  input.MinResolution = scene.Problem.MinResolution.data();
  input.Previous = previous.data();
  input.Slack = 1.0;
  HysteresisBand band;
  band.Apply(input, 0.2, r.data());
  std::fill(r.begin(), r.end(), 0.29);
  const std::size_t before = timecritical::testing::GetAllocationCount();
  band.Apply(input, 0.2, r.data());
  EXPECT_EQ(timecritical::testing::GetAllocationCount(), before);
}

/// Changes of r over 30 frames of jittering weights, for a policy and h.
int ChangesOver(timecritical::ResolutionPolicy& policy, double hysteresis, double& worstOver)
{
  timecritical_test::PolicyScene scene(200, 1.0, 11, 0.3);
  const std::vector<double> base = scene.Problem.Weight;
  std::vector<double> r(200);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(0.97, 1.03);
  int changes = 0;
  worstOver = 0.0;
  for (int frame = 0; frame < 30; ++frame)
  {
    for (std::size_t i = 0; i < base.size(); ++i)
    {
      scene.Problem.Weight[i] = base[i] * jitter(rng);
    }
    auto input = scene.Input(frame > 0, 0.1);
    input.Hysteresis = hysteresis;
    // The unheld choice's cost: the band may not exceed it or the target.
    const auto result = policy.Select(input, r.data());
    worstOver = std::max(worstOver, result.PredictedFrameTime - scene.Target);
    if (frame > 0)
    {
      for (std::size_t i = 0; i < r.size(); ++i)
      {
        changes += std::abs(r[i] - scene.Previous[i]) > 1e-9 * scene.Previous[i];
      }
    }
    scene.Previous = r;
  }
  return changes;
}

TEST(HysteresisBand, EveryPolicyChangesLess)
{
  std::vector<std::unique_ptr<timecritical::ResolutionPolicy>> policies;
  policies.emplace_back(new timecritical::ActiveSetPolicy);
  policies.emplace_back(new timecritical::GreedyLODPolicy);
  for (auto& policy : policies)
  {
    SCOPED_TRACE(policy->GetName());
    double overWithout = 0.0, overWith = 0.0;
    policy->Reset();
    const int without = ChangesOver(*policy, 0.0, overWithout);
    policy->Reset();
    const int with = ChangesOver(*policy, 0.3, overWith);
    EXPECT_GT(without, 0);
    EXPECT_LT(with * 2, without) << with << " vs " << without;
    // Within the budget whenever the policy alone was.
    EXPECT_LE(overWith, std::max(0.0, overWithout) + 1e-12);
  }
}

TEST(HysteresisBand, ThresholdPoliciesToo)
{
  // Policies without a budget of their own: the band holds what lies in it
  // and never raises the frame above its target or their own choice.
  timecritical_test::PolicyScene scene(100, 1.0, 4, 0.3);
  for (int kind = 0; kind < 2; ++kind)
  {
    auto make = [kind]() {
      return std::unique_ptr<timecritical::ResolutionPolicy>(kind == 0
          ? static_cast<timecritical::ResolutionPolicy*>(new timecritical::StaticThresholdPolicy)
          : new timecritical::FeedbackPolicy);
    };
    // Two policies in the same state; the second frame with and without hysteresis.
    auto plain = make(), held = make();
    SCOPED_TRACE(plain->GetName());
    std::vector<double> r(100), unheld(100), again(100);
    plain->Select(scene.Input(false, 0.1), r.data());
    held->Select(scene.Input(false, 0.1), r.data());
    scene.Previous = r;
    for (double& p : scene.Previous)
    {
      p = std::min(1.0, p * 1.05); // last frame a little finer
    }
    auto input = scene.Input(true, 0.1);
    const auto without = plain->Select(input, unheld.data());
    input.Hysteresis = 0.5; // band factor sqrt(2)
    const auto with = held->Select(input, again.data());
    std::size_t kept = 0;
    for (std::size_t i = 0; i < again.size(); ++i)
    {
      EXPECT_TRUE(again[i] == unheld[i] || again[i] == scene.Previous[i]) << i;
      kept += again[i] == scene.Previous[i] && scene.Previous[i] != unheld[i];
    }
    EXPECT_EQ(kept, with.Held);
    EXPECT_GT(kept, 0u);
    EXPECT_EQ(without.Held, 0u);
    EXPECT_LE(with.PredictedFrameTime,
      std::max(scene.Target, without.PredictedFrameTime) + 1e-12);
  }
}

TEST(HysteresisBand, SelectRejectsBadHysteresis)
{
  timecritical_test::PolicyScene scene(10, 1.0, 2);
  timecritical::ActiveSetPolicy policy;
  std::vector<double> r(10);
  auto input = scene.Input();
  input.Hysteresis = 1.0;
  EXPECT_THROW(policy.Select(input, r.data()), std::invalid_argument);
  input.Hysteresis = -0.5;
  EXPECT_THROW(policy.Select(input, r.data()), std::invalid_argument);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of GreedyLODPolicy (Funkhouser & Séquin): discrete levels, budget,
// special cases, quality against the continuous optimum, incremental
// (warm) operation and hysteresis against flip-flopping.
#include "PolicyTestScene.h"

#include "GreedyLODPolicy.h"
#include "ReferenceResolutionSolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
using timecritical::GreedyLODPolicy;
using timecritical::ReferenceResolutionSolver;
using timecritical_test::PolicyScene;

bool IsLevelOrMinimum(double r, double rmin, const std::vector<double>& levels)
{
  if (r == rmin)
  {
    return true;
  }
  return std::find(levels.begin(), levels.end(), r) != levels.end() && r > rmin;
}

TEST(GreedyLODPolicy, DiscreteLevelsWithinBudget)
{
  for (double alpha : { 1.0, 2.0, -0.5 })
  {
    for (double fraction : { 0.05, 0.3, 0.8 })
    {
      PolicyScene scene(300, alpha, 9, fraction);
      GreedyLODPolicy policy;
      std::vector<double> r(300);
      const auto result = policy.Select(scene.Input(), r.data());
      SCOPED_TRACE("alpha " + std::to_string(alpha) + " fraction " + std::to_string(fraction));
      EXPECT_FALSE(result.OverBudget);
      EXPECT_LE(result.PredictedFrameTime, scene.Target);
      EXPECT_TRUE(result.Converged);
      for (std::size_t i = 0; i < r.size(); ++i)
      {
        EXPECT_TRUE(IsLevelOrMinimum(r[i], scene.Problem.MinResolution[i], policy.GetLevels())) << r[i];
      }
      // Nothing left that would fit: every object below full resolution
      // costs more to raise one level than the budget has left (the greedy
      // stops at the first increment that does not fit and is undone, so
      // allow the cheapest step as slack).
      double cheapest = 1e300;
      for (std::size_t i = 0; i < r.size(); ++i)
      {
        if (r[i] < 1.0)
        {
          const auto& levels = policy.GetLevels();
          const auto next = std::upper_bound(levels.begin(), levels.end(), r[i]);
          cheapest = std::min(cheapest, scene.Problem.MaxTime[i] * (*next - r[i]));
        }
      }
      EXPECT_GT(result.PredictedFrameTime + cheapest, scene.Target * 0.98);
    }
  }
}

TEST(GreedyLODPolicy, CloseToTheContinuousOptimum)
{
  // Discrete levels cannot beat the continuous optimum; the greedy should
  // lose little to it on such scenes.
  PolicyScene scene(500, 1.0, 10);
  GreedyLODPolicy policy;
  std::vector<double> r(500), best(500);
  const auto result = policy.Select(scene.Input(), r.data());
  const auto reference = ReferenceResolutionSolver::Solve(scene.Problem.View(), best.data());
  EXPECT_GE(result.Objective, reference.Objective * (1.0 - 1e-12));
  EXPECT_LT((result.Objective - reference.Objective) / reference.Objective, 0.25);
}

TEST(GreedyLODPolicy, InfeasibleAndUnconstrained)
{
  PolicyScene scene(50, 1.0, 11);
  GreedyLODPolicy policy;
  std::vector<double> r(50);
  scene.Target = scene.FixedTime + 0.5 * scene.Problem.CostAtMin();
  auto result = policy.Select(scene.Input(), r.data());
  EXPECT_TRUE(result.OverBudget);
  for (std::size_t i = 0; i < r.size(); ++i)
  {
    EXPECT_EQ(r[i], std::max(scene.Problem.MinResolution[i], policy.GetLevels().front()));
  }
  scene.Target = scene.FixedTime + scene.Problem.CostAtFull();
  result = policy.Select(scene.Input(), r.data());
  EXPECT_FALSE(result.OverBudget);
  for (double x : r)
  {
    EXPECT_EQ(x, 1.0);
  }
}

TEST(GreedyLODPolicy, ZeroCostIsNeverDrawnInFull)
{
  // As in ActiveSetOptimizer: tmax = 0 is a failed cost model, not a free
  // object; the object stays at its lowest level, within budget or not.
  for (double fraction : { 0.3, 2.0 })
  {
    PolicyScene scene(30, 1.0, 4);
    for (std::size_t i = 0; i < 30; i += 3)
    {
      scene.Problem.MaxTime[i] = 0.0;
      scene.Problem.Weight[i] *= 1e3;
    }
    scene.Target = scene.FixedTime + fraction * scene.Problem.CostAtFull();
    GreedyLODPolicy policy;
    std::vector<double> r(30);
    policy.Select(scene.Input(), r.data());
    for (std::size_t i = 0; i < 30; ++i)
    {
      if (i % 3 == 0)
      {
        EXPECT_EQ(r[i], std::max(scene.Problem.MinResolution[i], policy.GetLevels().front()))
          << "object " << i << ", budget fraction " << fraction;
      }
      else if (fraction > 1.0)
      {
        EXPECT_EQ(r[i], 1.0);
      }
    }
  }
}

TEST(GreedyLODPolicy, IncrementalFromThePreviousFrame)
{
  PolicyScene scene(1000, 1.0, 12);
  GreedyLODPolicy policy;
  std::vector<double> r(1000);
  const auto cold = policy.Select(scene.Input(), r.data());
  scene.Previous = r;
  timecritical_test::Perturb(scene.Problem, 0.05, 1);
  const auto warm = policy.Select(scene.Input(true), r.data());
  EXPECT_LT(warm.Iterations * 10, cold.Iterations);
  EXPECT_LE(warm.PredictedFrameTime, scene.Target);
}

TEST(GreedyLODPolicy, HysteresisPreventsFlipFlopping)
{
  // 40 identical objects, room for about half of them one level up: with
  // weights jittering by 2 % each frame, which half goes up is a coin toss.
  auto changesOver = [](double hysteresis) {
    PolicyScene scene(40, 1.0, 13);
    auto& p = scene.Problem;
    std::fill(p.Weight.begin(), p.Weight.end(), 1.0);
    std::fill(p.MaxTime.begin(), p.MaxTime.end(), 0.01);
    std::fill(p.MinResolution.begin(), p.MinResolution.end(), 0.01);
    scene.Target = scene.FixedTime + 40 * 0.01 * 0.25 + 20 * 0.01 * 0.25; // 20 at 0.5, 20 at 0.25
    GreedyLODPolicy policy;
    std::vector<double> r(40);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(0.98, 1.02);
    int changes = 0;
    for (int frame = 0; frame < 30; ++frame)
    {
      for (double& c : p.Weight)
      {
        c = jitter(rng);
      }
      auto input = scene.Input(frame > 0);
      input.Hysteresis = hysteresis;
      const auto result = policy.Select(input, r.data());
      EXPECT_LE(result.PredictedFrameTime, scene.Target + 1e-12);
      if (frame > 0)
      {
        for (std::size_t i = 0; i < r.size(); ++i)
        {
          changes += r[i] != scene.Previous[i];
        }
      }
      scene.Previous = r;
    }
    return changes;
  };
  const int without = changesOver(0.0), with = changesOver(0.1);
  EXPECT_GT(without, 100);
  EXPECT_EQ(with, 0);
}

TEST(GreedyLODPolicy, CustomLevels)
{
  GreedyLODPolicy policy;
  const double levels[] = { 0.5, 0.1, -1.0, 2.0, 0.1 };
  policy.SetLevels(levels, 5);
  EXPECT_EQ(policy.GetLevels(), (std::vector<double>{ 0.1, 0.5, 1.0 }));
}
}

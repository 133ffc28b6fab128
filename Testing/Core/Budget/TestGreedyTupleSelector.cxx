// SPDX-License-Identifier: BSD-3-Clause
// Tests of GreedyTupleSelector (Funkhouser & Séquin's greedy over tuples):
// within its bound of half the optimum against an exhaustive search over
// the same candidates, dropping keeps the most valuable objects, still
// frames draw everything, bad input throws, GreedyLODPolicy forwards to it.
#include "TupleTestProblem.h"

#include "AllocationCounter.h"
#include "GreedyLODPolicy.h"
#include "GreedyTupleSelector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace
{
using timecritical::GreedyTupleSelector;
using timecritical::TupleProblem;
using timecritical_test::MakeRandomTupleProblem;

/// The best objective over every combination of the objects' candidates that fits.
double ExhaustiveOverCandidates(const GreedyTupleSelector& selector, const TupleProblem& p)
{
  const bool dropping = p.NeedsDropping();
  std::vector<std::vector<GreedyTupleSelector::Tuple>> candidates(p.Count);
  for (std::size_t i = 0; i < p.Count; ++i)
  {
    selector.GetCandidates(p, i, dropping, candidates[i]);
  }
  double best = std::numeric_limits<double>::infinity();
  const double budget = p.Budget + 1e-12 * std::abs(p.Budget);
  std::vector<std::size_t> digit(p.Count, 0);
  while (true)
  {
    double cost = 0.0, f = 0.0;
    for (std::size_t i = 0; i < p.Count; ++i)
    {
      cost += candidates[i][digit[i]].Cost;
      f += candidates[i][digit[i]].Degradation;
    }
    if (cost <= budget)
    {
      best = std::min(best, f);
    }
    std::size_t i = 0;
    while (i < p.Count && ++digit[i] == candidates[i].size())
    {
      digit[i++] = 0;
    }
    if (i == p.Count)
    {
      return best;
    }
  }
}

TEST(GreedyTupleSelector, WithinHalfOfTheOptimumOnSmallRandomProblems)
{
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 1.0, sum = 0.0;
  int trials = 0, dropping = 0;
  for (unsigned seed = 0; seed < 150; ++seed)
  {
    const std::size_t n = 2 + seed % 3;
    const std::size_t algorithms = 1 + (seed / 3) % 3;
    const double fraction = unit(rng) < 0.3 ? -0.6 * unit(rng) : unit(rng);
    auto owned = MakeRandomTupleProblem(n, algorithms, 2000 + seed, fraction, seed % 2 == 1);
    owned.WithBox = seed % 4 != 0;
    const TupleProblem p = owned.View();
    GreedyTupleSelector selector;
    std::vector<int> a(n);
    std::vector<double> r(n);
    const auto s = selector.Solve(p, a.data(), r.data());
    SCOPED_TRACE("seed " + std::to_string(seed));
    ASSERT_FALSE(s.Infeasible);
    EXPECT_LE(s.Cost, p.Budget * (1.0 + 1e-9) + 1e-15);
    const double optimum = ExhaustiveOverCandidates(selector, p);
    // Benefits over the base (not drawn when dropping, else the cheapest tuples).
    double base = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      base += s.Dropping ? p.DropDegradation[i] : p.Degradation(i, p.CheapestAlgorithm(i), 0.0);
    }
    const double tolerance = 1e-9 * std::abs(optimum) + 1e-12;
    EXPECT_GE(s.Objective, optimum - tolerance);
    EXPECT_LE(s.LowerBound, optimum + tolerance);
    const double best = base - optimum, got = base - s.Objective;
    if (best > 1e-12 * std::abs(base))
    {
      const double ratio = got / best;
      EXPECT_GE(ratio, 0.5 - 1e-9);
      worst = std::min(worst, ratio);
      sum += ratio;
      ++trials;
    }
    dropping += s.Dropping ? 1 : 0;
  }
  std::printf("GreedyTupleSelector vs exhaustive over its candidates: %d problems (%d dropping), "
              "benefit ratio worst %.4f, mean %.4f (bound 0.5)\n",
    trials, dropping, worst, sum / trials);
  EXPECT_GT(dropping, 20);
}

TEST(GreedyTupleSelector, DroppingKeepsTheMostValuableObjects)
{
  const std::size_t n = 1000;
  auto owned = MakeRandomTupleProblem(n, 3, 21, -0.7, true);
  owned.WithBox = false;
  const TupleProblem p = owned.View();
  GreedyTupleSelector selector;
  std::vector<int> a(n);
  std::vector<double> r(n);
  const auto s = selector.Solve(p, a.data(), r.data());
  EXPECT_TRUE(s.Dropping);
  EXPECT_GT(s.Dropped, 0u);
  EXPECT_LE(s.Cost, p.Budget * (1.0 + 1e-9));
  // An object is dropped only when no drawn object is clearly less valuable
  // and at least as expensive at its cheapest.
  for (std::size_t i = 0; i < n; ++i)
  {
    if (a[i] != TupleProblem::NotDrawn)
    {
      continue;
    }
    const double ci = p.Cost(i, p.CheapestAlgorithm(i), 0.0);
    for (std::size_t j = 0; j < n; ++j)
    {
      if (a[j] >= 0 && p.DropDegradation[i] > 1.05 * p.DropDegradation[j] &&
        ci < p.Cost(j, p.CheapestAlgorithm(j), 0.0))
      {
        ADD_FAILURE() << "object " << i << " dropped, " << j << " drawn";
      }
    }
  }
}

TEST(GreedyTupleSelector, SolvesAgainWithoutAllocatingAndAnswersTheSame)
{
  // The renderer's frame path with the greedy policy: once its buffers have
  // grown, a solve allocates nothing (the value order's scratch is a
  // member), and a reused selector answers as a fresh one.
  for (const std::size_t n : { std::size_t(12), std::size_t(5000) })
  {
    auto owned = MakeRandomTupleProblem(n, 1, 900 + static_cast<unsigned>(n), -0.66, true);
    owned.WithBox = false;
    const TupleProblem p = owned.View();
    std::vector<int> a(n), fresh(n);
    std::vector<double> r(n), freshR(n);
    GreedyTupleSelector reused;
    reused.Solve(p, a.data(), r.data());
    const std::size_t before = timecritical::testing::GetAllocationCount();
    const auto s = reused.Solve(p, a.data(), r.data());
    EXPECT_EQ(timecritical::testing::GetAllocationCount(), before) << n << " objects";
    GreedyTupleSelector other;
    other.Solve(p, fresh.data(), freshR.data());
    EXPECT_EQ(a, fresh);
    EXPECT_EQ(r, freshR);
    EXPECT_TRUE(s.Dropping);
    EXPECT_GT(s.Dropped, 0u);
    EXPECT_LE(s.Cost, p.Budget * (1.0 + 1e-9));
    TupleProblem::ValueOrderScratch scratch;
    std::size_t i = n, j = n;
    EXPECT_FALSE(p.FindValueOrderViolation(a.data(), i, j, scratch)) << i << " dropped, " << j << " drawn";
  }
}

TEST(GreedyTupleSelector, StillFramesDrawEverything)
{
  auto owned = MakeRandomTupleProblem(50, 2, 8, -0.4);
  owned.AllowDrop = false;
  const TupleProblem p = owned.View();
  GreedyTupleSelector selector;
  std::vector<int> a(50);
  std::vector<double> r(50);
  const auto s = selector.Solve(p, a.data(), r.data());
  EXPECT_TRUE(s.Infeasible);
  EXPECT_EQ(s.Dropped + s.Boxed, 0u);
  for (std::size_t i = 0; i < 50; ++i)
  {
    EXPECT_GE(a[i], 0);
  }
}

TEST(GreedyTupleSelector, BadInputThrows)
{
  auto owned = MakeRandomTupleProblem(10, 2, 1, 0.3);
  std::vector<int> a(10);
  std::vector<double> r(10);
  GreedyTupleSelector selector;
  TupleProblem p = owned.View();
  p.AlgorithmCount = 0;
  EXPECT_THROW(selector.Solve(p, a.data(), r.data()), std::invalid_argument);
  owned.FixedCost[2] = -1.0;
  EXPECT_THROW(selector.Solve(owned.View(), a.data(), r.data()), std::invalid_argument);
  owned.FixedCost[2] = 0.0;
  owned.Alpha[1] = std::nan("");
  EXPECT_THROW(selector.Solve(owned.View(), a.data(), r.data()), std::invalid_argument);
}

TEST(GreedyTupleSelector, LevelsAndGreedyLODPolicy)
{
  GreedyTupleSelector selector;
  const double levels[] = { 0.5, 0.1, 2.0, std::nan("") };
  selector.SetLevels(levels, 4);
  EXPECT_EQ(selector.GetLevels(), (std::vector<double>{ 0.1, 0.5, 1.0 }));
  // GreedyLODPolicy::SelectTuples uses the policy's levels.
  auto owned = MakeRandomTupleProblem(40, 3, 4, 0.3);
  const TupleProblem p = owned.View();
  timecritical::GreedyLODPolicy policy;
  policy.SetLevels(levels, 4);
  std::vector<int> a(40), b(40);
  std::vector<double> r(40), q(40);
  const auto viaPolicy = policy.SelectTuples(p, a.data(), r.data());
  const auto direct = selector.Solve(p, b.data(), q.data());
  EXPECT_EQ(a, b);
  EXPECT_EQ(r, q);
  EXPECT_EQ(viaPolicy.Objective, direct.Objective);
  for (std::size_t i = 0; i < 40; ++i)
  {
    const double lo = p.Lo(i, static_cast<std::size_t>(a[i]));
    const double hi = p.Hi(i, static_cast<std::size_t>(a[i]));
    const bool onLevel = r[i] == lo || r[i] == hi || r[i] == 0.1 || r[i] == 0.5 || r[i] == 1.0;
    EXPECT_TRUE(onLevel) << r[i];
  }
}
}

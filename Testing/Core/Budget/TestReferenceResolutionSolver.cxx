// SPDX-License-Identifier: BSD-3-Clause
// Tests of ReferenceResolutionSolver: it must itself satisfy the KKT
// conditions (checked independently), be exact on problems solvable by hand,
// and handle the infeasible and unconstrained cases.
#include "BudgetTestUtilities.h"

#include "ReferenceResolutionSolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using timecritical::ReferenceResolutionSolver;
using timecritical::ResolutionProblem;
using timecritical_test::CheckKKT;
using timecritical_test::MakeRandomProblem;

TEST(ReferenceResolutionSolver, SatisfiesKKT)
{
  for (double alpha : { 1.0, 2.0, -0.5, 0.3, -0.8 })
  {
    for (double fraction : { 0.01, 0.4, 0.95 })
    {
      auto p = MakeRandomProblem(500, alpha, 3, fraction);
      std::vector<double> r(p.Weight.size());
      const auto result = ReferenceResolutionSolver::Solve(p.View(), r.data());
      SCOPED_TRACE("alpha " + std::to_string(alpha) + " fraction " + std::to_string(fraction));
      EXPECT_FALSE(result.Infeasible);
      EXPECT_FALSE(result.Unconstrained);
      EXPECT_LE(result.Cost, p.Budget);
      EXPECT_NEAR(result.Cost, p.Budget, 1e-10 * p.Budget);
      const auto kkt = CheckKKT(p.View(), r.data());
      EXPECT_LE(kkt.Worst(), 1e-8);
      EXPECT_NEAR(result.Multiplier, kkt.Lambda, 1e-7 * kkt.Lambda);
      EXPECT_NEAR(result.Objective, p.View().Objective(r.data()), 1e-12 * std::abs(result.Objective));
    }
  }
}

TEST(ReferenceResolutionSolver, EqualObjectsShareTheBudget)
{
  // Identical objects: r = Budget / sum tmax for every alpha.
  const std::vector<double> c(8, 2.0), t(8, 0.01), lo(8, 0.01);
  for (double alpha : { 1.0, 2.0, -0.5 })
  {
    ResolutionProblem p;
    p.Count = 8;
    p.Weight = c.data();
    p.MaxTime = t.data();
    p.MinResolution = lo.data();
    p.Alpha = alpha;
    p.Budget = 0.02;
    std::vector<double> r(8);
    ReferenceResolutionSolver::Solve(p, r.data());
    for (double x : r)
    {
      EXPECT_NEAR(x, 0.25, 1e-12);
    }
  }
}

TEST(ReferenceResolutionSolver, TwoObjectsByHand)
{
  // alpha = 1: r_i proportional to sqrt(c_i / t_i); c = (4, 1), t = (1, 1):
  // r = (2k, k) with 3k = 0.6 -> r = (0.4, 0.2).
  const double c[] = { 4.0, 1.0 }, t[] = { 1.0, 1.0 }, lo[] = { 0.01, 0.01 };
  ResolutionProblem p;
  p.Count = 2;
  p.Weight = c;
  p.MaxTime = t;
  p.MinResolution = lo;
  p.Alpha = 1.0;
  p.Budget = 0.6;
  double r[2];
  const auto result = ReferenceResolutionSolver::Solve(p, r);
  EXPECT_NEAR(r[0], 0.4, 1e-12);
  EXPECT_NEAR(r[1], 0.2, 1e-12);
  EXPECT_NEAR(result.Multiplier, 4.0 / (0.4 * 0.4), 1e-9);
}

TEST(ReferenceResolutionSolver, InfeasibleAndUnconstrained)
{
  auto p = MakeRandomProblem(30, 1.0, 1);
  std::vector<double> r(p.Weight.size());
  p.Budget = 0.9 * p.CostAtMin();
  EXPECT_TRUE(ReferenceResolutionSolver::Solve(p.View(), r.data()).Infeasible);
  for (std::size_t i = 0; i < r.size(); ++i)
  {
    EXPECT_EQ(r[i], p.MinResolution[i]);
  }
  p.Budget = 1.01 * p.CostAtFull();
  EXPECT_TRUE(ReferenceResolutionSolver::Solve(p.View(), r.data()).Unconstrained);
  for (double x : r)
  {
    EXPECT_EQ(x, 1.0);
  }
}
}

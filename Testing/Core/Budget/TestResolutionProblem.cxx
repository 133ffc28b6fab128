// SPDX-License-Identifier: BSD-3-Clause
// Tests of ResolutionProblem: the eq. 11 terms (fast paths against pow()),
// their monotonicity and convexity for every admissible alpha, and the cost sums.
#include "ResolutionProblem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
using timecritical::ResolutionProblem;

TEST(ResolutionProblem, ValidAlpha)
{
  EXPECT_TRUE(ResolutionProblem::IsValidAlpha(1.0));
  EXPECT_TRUE(ResolutionProblem::IsValidAlpha(-0.5));
  EXPECT_TRUE(ResolutionProblem::IsValidAlpha(-0.999));
  EXPECT_FALSE(ResolutionProblem::IsValidAlpha(-1.0));
  EXPECT_FALSE(ResolutionProblem::IsValidAlpha(0.0));
  EXPECT_FALSE(ResolutionProblem::IsValidAlpha(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(ResolutionProblem::IsValidAlpha(std::numeric_limits<double>::infinity()));
}

TEST(ResolutionProblem, TermMatchesEquation9)
{
  for (double alpha : { 1.0, 2.0, -0.5, 0.7, -0.3 })
  {
    for (double r : { 1e-6, 0.01, 0.3, 1.0 })
    {
      const double expected = 2.5 / alpha * std::pow(r, -alpha);
      EXPECT_NEAR(ResolutionProblem::Term(2.5, alpha, r), expected, 1e-12 * std::abs(expected));
    }
  }
  EXPECT_EQ(ResolutionProblem::Term(0.0, 1.0, 0.5), 0.0);
}

TEST(ResolutionProblem, TermsDecreaseAndAreConvex)
{
  // The premise of section 5.3.1 (and of the sign conventions of eq. 14/16):
  // degradation decreases with r for alpha < 0 too.
  for (double alpha : { 3.0, 1.0, 0.2, -0.2, -0.5, -0.95 })
  {
    double previous = std::numeric_limits<double>::infinity();
    double previousSlope = -std::numeric_limits<double>::infinity();
    for (double r = 0.05; r <= 1.0; r += 0.05)
    {
      const double f = ResolutionProblem::Term(1.0, alpha, r);
      EXPECT_LT(f, previous) << alpha;
      const double slope = (ResolutionProblem::Term(1.0, alpha, r + 1e-4) - f) / 1e-4;
      EXPECT_LT(slope, 0.0);
      EXPECT_GT(slope, previousSlope) << "convex, alpha " << alpha;
      previous = f;
      previousSlope = slope;
    }
  }
}

TEST(ResolutionProblem, ObjectiveAndCosts)
{
  const std::vector<double> c = { 1.0, 2.0 }, t = { 0.01, 0.03 }, lo = { 0.2, 0.1 };
  ResolutionProblem p;
  p.Count = 2;
  p.Weight = c.data();
  p.MaxTime = t.data();
  p.MinResolution = lo.data();
  p.Alpha = 1.0;
  const double r[] = { 0.1, 0.5 };
  EXPECT_DOUBLE_EQ(p.Objective(r), 1.0 / 0.1 + 2.0 / 0.5);
  EXPECT_DOUBLE_EQ(p.Cost(r), 0.001 + 0.015);
  // Below rmin the object is fill-bound: it costs as at rmin.
  EXPECT_DOUBLE_EQ(p.EffectiveCost(r), 0.002 + 0.015);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of TupleProblem: degradation and cost of tuples and of the levels
// below the coarsest mesh, when dropping is in play, summaries, and the
// validation of bad input (each case a clear std::invalid_argument).
#include "TupleProblem.h"

#include "AllocationCounter.h"
#include "ResolutionProblem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace
{
using timecritical::TupleProblem;

/// Two objects, two algorithms (alpha 1 and 2).
struct Small
{
  std::vector<double> Alpha = { 1.0, 2.0 };
  std::vector<double> Weight = { 4.0, 2.0, 1.0, 0.0 };
  std::vector<double> Offset = { 0.0, 0.5, 0.0, 0.25 };
  std::vector<double> MaxTime = { 0.02, 0.01, 0.03, 0.0 };
  std::vector<double> FixedCost = { 0.0, 0.005, 0.001, 0.002 };
  std::vector<double> Lo = { 0.1, 0.2, 0.05, 0.5 };
  std::vector<double> Hi = { 1.0, 0.5, 1.0, 1.0 };
  std::vector<double> BoxCost = { 1e-4, 2e-4 };
  std::vector<double> BoxDegradation = { 9.0, 8.0 };
  std::vector<double> DropDegradation = { 10.0, 9.0 };

  TupleProblem View(double budget = 0.05, bool drop = true) const
  {
    TupleProblem p;
    p.Count = 2;
    p.AlgorithmCount = 2;
    p.Alpha = this->Alpha.data();
    p.Weight = this->Weight.data();
    p.Offset = this->Offset.data();
    p.MaxTime = this->MaxTime.data();
    p.FixedCost = this->FixedCost.data();
    p.MinResolution = this->Lo.data();
    p.MaxResolution = this->Hi.data();
    p.BoxCost = this->BoxCost.data();
    p.BoxDegradation = this->BoxDegradation.data();
    p.DropDegradation = this->DropDegradation.data();
    p.AllowDrop = drop;
    p.Budget = budget;
    return p;
  }
};

TEST(TupleProblem, DegradationAndCostOfTuples)
{
  const Small s;
  const TupleProblem p = s.View();
  EXPECT_NO_THROW(p.Validate());
  // Object 0, algorithm 0: 4 / r, cost 0.02 r.
  EXPECT_DOUBLE_EQ(p.Degradation(0, 0, 0.5), 8.0);
  EXPECT_DOUBLE_EQ(p.Cost(0, 0, 0.5), 0.01);
  // Below lo: clamped up (cost and degradation of lo).
  EXPECT_DOUBLE_EQ(p.Degradation(0, 0, 0.01), 40.0);
  EXPECT_DOUBLE_EQ(p.Cost(0, 0, 0.01), 0.002);
  // Object 0, algorithm 1: 2 / 2 r^-2 + 0.5, flat above hi = 0.5; cost 0.005 + 0.01 r.
  EXPECT_DOUBLE_EQ(p.Degradation(0, 1, 0.25), 16.5);
  EXPECT_DOUBLE_EQ(p.Degradation(0, 1, 1.0), 4.5);
  EXPECT_DOUBLE_EQ(p.Hi(0, 1), 0.5);
  EXPECT_DOUBLE_EQ(p.Cost(0, 1, 1.0), 0.015);
  // Box and not drawn.
  EXPECT_DOUBLE_EQ(p.Degradation(1, TupleProblem::BoundingBox, 0.0), 8.0);
  EXPECT_DOUBLE_EQ(p.Cost(1, TupleProblem::BoundingBox, 0.0), 2e-4);
  EXPECT_DOUBLE_EQ(p.Degradation(1, TupleProblem::NotDrawn, 0.0), 9.0);
  EXPECT_DOUBLE_EQ(p.Cost(1, TupleProblem::NotDrawn, 0.0), 0.0);
  // Object 1, algorithm 1: T = 0 pins it at lo: cost F, degradation the offset.
  EXPECT_DOUBLE_EQ(p.Cost(1, 1, 1.0), 0.002);
  EXPECT_DOUBLE_EQ(p.Degradation(1, 1, 1.0), 0.25);
}

TEST(TupleProblem, CheapestDroppingAndSummary)
{
  const Small s;
  // Cheapest: object 0 algorithm 0 (0.002 < 0.007), object 1 algorithm 1 (0.002 < 0.0025).
  TupleProblem p = s.View(0.0035);
  EXPECT_EQ(p.CheapestAlgorithm(0), 0);
  EXPECT_EQ(p.CheapestAlgorithm(1), 1);
  EXPECT_TRUE(p.NeedsDropping());
  p.Budget = 0.004;
  EXPECT_FALSE(p.NeedsDropping());
  p.Budget = 0.0;
  p.AllowDrop = false;
  EXPECT_FALSE(p.NeedsDropping()); // still frames never drop
  const int a[2] = { TupleProblem::NotDrawn, 0 };
  const double r[2] = { 0.0, 0.5 };
  TupleProblem::Solution sum;
  p.Summarize(a, r, sum);
  EXPECT_EQ(sum.Dropped, 1u);
  EXPECT_EQ(sum.Boxed, 0u);
  EXPECT_DOUBLE_EQ(sum.Objective, 10.0 + 2.0);
  EXPECT_DOUBLE_EQ(sum.Cost, 0.001 + 0.015);
}

namespace
{
/// Five objects, one algorithm, values 5 down to 1: cheapest cost MaxTime *
/// Lo (Lo = 0.1), value DropDegradation, dropping allowed.
struct FiveObjects
{
  explicit FiveObjects(std::vector<double> maxTime)
    : MaxTime(std::move(maxTime))
  {
  }
  TupleProblem View(double budget) const
  {
    TupleProblem p;
    p.Count = 5;
    p.AlgorithmCount = 1;
    p.Alpha = this->Alpha.data();
    p.Weight = this->Weight.data();
    p.MaxTime = this->MaxTime.data();
    p.MinResolution = this->Lo.data();
    p.DropDegradation = this->Value.data();
    p.AllowDrop = true;
    p.Budget = budget;
    return p;
  }
  std::vector<double> MaxTime;
  std::vector<double> Alpha = { 1.0 }, Weight = std::vector<double>(5, 1.0),
                      Lo = std::vector<double>(5, 0.1), Value = { 5.0, 4.0, 3.0, 2.0, 1.0 };
};
}

TEST(TupleProblem, ValueOrderViolationsWithReusedScratch)
{
  const FiveObjects five({ 0.01, 0.02, 0.03, 0.04, 0.05 });
  const std::vector<double>& maxTime = five.MaxTime;
  TupleProblem p = five.View(0.005);
  TupleProblem::ValueOrderScratch scratch;
  std::size_t dropped = 99, drawn = 99;
  // Object 1 (value 4, cost 0.002) dropped while object 4 (value 1, cost 0.005) is drawn.
  const int bad[5] = { 0, TupleProblem::NotDrawn, TupleProblem::NotDrawn, TupleProblem::NotDrawn, 0 };
  ASSERT_TRUE(p.FindValueOrderViolation(bad, dropped, drawn, scratch));
  EXPECT_EQ(dropped, 1u);
  EXPECT_EQ(drawn, 4u);
  // The most valuable drawn, the rest dropped: in order.
  const int good[5] = { 0, 0, TupleProblem::NotDrawn, TupleProblem::NotDrawn, TupleProblem::NotDrawn };
  EXPECT_FALSE(p.FindValueOrderViolation(good, dropped, drawn, scratch));
  // A less valuable drawn object that costs less is no violation.
  const int cheaper[5] = { TupleProblem::NotDrawn, 0, 0, 0, 0 };
  const std::vector<double> rising = { 0.05, 0.04, 0.03, 0.02, 0.01 };
  p.MaxTime = rising.data();
  EXPECT_FALSE(p.FindValueOrderViolation(cheaper, dropped, drawn, scratch));
  // The scratch has grown: the same questions again allocate nothing and answer the same.
  p.MaxTime = maxTime.data();
  const std::size_t before = timecritical::testing::GetAllocationCount();
  const bool again = p.FindValueOrderViolation(bad, dropped, drawn, scratch);
  const bool none = p.FindValueOrderViolation(good, dropped, drawn, scratch);
  EXPECT_EQ(timecritical::testing::GetAllocationCount(), before);
  EXPECT_TRUE(again);
  EXPECT_FALSE(none);
  // Without drop degradations there is no value order to violate.
  p.DropDegradation = nullptr;
  EXPECT_FALSE(p.FindValueOrderViolation(bad, dropped, drawn, scratch));
}

TEST(TupleProblem, BadInputThrowsClearly)
{
  auto expectThrow = [](const TupleProblem& p, const char* words) {
    try
    {
      p.Validate();
      ADD_FAILURE() << "no exception for " << words;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  Small s;
  TupleProblem p = s.View();
  p.AlgorithmCount = 0;
  expectThrow(p, "algorithms is empty");
  s.MaxTime[1] = -0.01;
  expectThrow(s.View(), "MaxTime[1]");
  s.MaxTime[1] = 0.01;
  s.Weight[2] = std::numeric_limits<double>::quiet_NaN();
  expectThrow(s.View(), "Weight[2]");
  s.Weight[2] = 1.0;
  s.Alpha[1] = -1.0;
  expectThrow(s.View(), "Alpha[1]");
  s.Alpha[1] = 2.0;
  s.Lo[0] = 0.0;
  expectThrow(s.View(), "MinResolution[0]");
  s.Lo[0] = 0.1;
  s.BoxCost[1] = std::numeric_limits<double>::infinity();
  expectThrow(s.View(), "BoxCost[1]");
  s.BoxCost[1] = 2e-4;
  expectThrow(s.View(std::numeric_limits<double>::quiet_NaN()), "budget is NaN");
  p = s.View();
  p.DropDegradation = nullptr;
  expectThrow(p, "DropDegradation");
  p = s.View();
  p.Weight = nullptr;
  expectThrow(p, "required");
  EXPECT_NO_THROW(s.View().Validate());
  p.Count = 0; // an empty frame is valid whatever the arrays
  EXPECT_NO_THROW(p.Validate());
}
}

TEST(TupleProblem, StrictValueOrderDropsTheLeastValuableFirst)
{
  // Value and cost grow together (fill-bound objects): the weak order lets
  // the most valuable go; the strict one draws it and drops the least
  // valuable until there is room, and never raises the cost.
  const FiveObjects five({ 0.05, 0.04, 0.03, 0.02, 0.01 }); // cheapest: 0.005 ... 0.001
  TupleProblem p = five.View(0.0075);
  TupleProblem::ValueOrderScratch scratch;
  const int N = TupleProblem::NotDrawn;
  std::size_t dropped = 99, drawn = 99;
  int choice[5] = { N, 0, 0, 0, 0 }; // 0.004 + 0.003 + 0.002 + 0.001 = 0.010
  EXPECT_FALSE(p.FindValueOrderViolation(choice, dropped, drawn, scratch)) << "weak order holds";
  EXPECT_EQ(p.ImposeStrictValueOrder(choice, scratch), 4u); // 0 in; 4, 3, 2 out (0.001+0.002+0.003 >= 0.005)
  const int expected[5] = { 0, 0, N, N, N };
  EXPECT_TRUE(std::equal(choice, choice + 5, expected));
  // In order already: nothing changes.
  EXPECT_EQ(p.ImposeStrictValueOrder(choice, scratch), 0u);
  // An object that the less valuable drawn ones cannot make room for stays dropped.
  int tight[5] = { N, N, N, N, 0 }; // only object 4 (0.001) drawn: no room for 3 (0.002)
  EXPECT_EQ(p.ImposeStrictValueOrder(tight, scratch), 0u);
  // The scratch has grown: again without allocating.
  int again[5] = { N, 0, 0, 0, 0 };
  const std::size_t before = timecritical::testing::GetAllocationCount();
  EXPECT_EQ(p.ImposeStrictValueOrder(again, scratch), 4u);
  EXPECT_EQ(timecritical::testing::GetAllocationCount(), before);
  p.DropDegradation = nullptr;
  EXPECT_EQ(p.ImposeStrictValueOrder(again, scratch), 0u);
}

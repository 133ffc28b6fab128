// SPDX-License-Identifier: BSD-3-Clause
// Tests of ResolutionPolicy::Select(), what every policy reports around its own
// choice: the predicted frame time (with objects below their minimum
// resolution counted at it), the objective of eq. 11, the over-budget flag,
// the time spent, and no choice at all for an empty scene; and of
// PolicyInput::GetProblem(), the problem a policy solves.
#include "ResolutionPolicy.h"
#include "ResolutionProblem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
using timecritical::PolicyInput;
using timecritical::PolicyResult;
using timecritical::ResolutionPolicy;

/// Sets every r_i to a fixed value and counts its calls.
class FixedPolicy : public ResolutionPolicy
{
public:
  explicit FixedPolicy(double value)
    : Value(value)
  {
  }
  const char* GetName() const override { return "fixed"; }
  int Calls = 0;

protected:
  void Choose(const PolicyInput& input, double* r, PolicyResult& result) override
  {
    ++this->Calls;
    for (std::size_t i = 0; i < input.Count; ++i)
    {
      r[i] = this->Value;
    }
    result.Iterations = 7;
    result.Converged = false;
  }

private:
  double Value;
};

/// Three objects: tmax 10, 20 and 30 ms, rmin 0.1, 0.5 and 0.2, weights 1, 2, 3.
struct ThreeObjects
{
  std::vector<double> Weight = { 1.0, 2.0, 3.0 };
  std::vector<double> MaxTime = { 0.010, 0.020, 0.030 };
  std::vector<double> MinResolution = { 0.1, 0.5, 0.2 };

  PolicyInput Input(double target, double fixed, double alpha = 1.0) const
  {
    PolicyInput in;
    in.Count = 3;
    in.Weight = this->Weight.data();
    in.MaxTime = this->MaxTime.data();
    in.MinResolution = this->MinResolution.data();
    in.Alpha = alpha;
    in.TargetFrameTime = target;
    in.FixedTime = fixed;
    return in;
  }
};
}

TEST(ResolutionPolicy, PredictionCountsObjectsBelowTheirMinimumAtIt)
{
  ThreeObjects scene;
  FixedPolicy policy(0.3);
  std::vector<double> r(3, -1.0);
  const PolicyResult result = policy.Select(scene.Input(0.1, 0.005), r.data());
  EXPECT_EQ(policy.Calls, 1);
  EXPECT_EQ(r, std::vector<double>(3, 0.3));
  // 5 ms + 10 * 0.3 + 20 * max(0.3, 0.5) + 30 * 0.3 ms = 27 ms.
  EXPECT_NEAR(result.PredictedFrameTime, 0.027, 1e-15);
  EXPECT_FALSE(result.OverBudget);
  // f(r) = sum c_i / alpha * r_i^-alpha at alpha 1: (1 + 2 + 3) / 0.3.
  EXPECT_NEAR(result.Objective, 6.0 / 0.3, 1e-12);
  // The policy's own figures pass through.
  EXPECT_EQ(result.Iterations, 7);
  EXPECT_FALSE(result.Converged);
  EXPECT_GE(result.Seconds, 0.0);
  EXPECT_LT(result.Seconds, 1.0);
}

TEST(ResolutionPolicy, OverBudgetBeyondTheTargetOnly)
{
  ThreeObjects scene;
  FixedPolicy policy(1.0);
  std::vector<double> r(3);
  // Full resolution: 60 ms of objects plus the fixed time.
  EXPECT_FALSE(policy.Select(scene.Input(0.070, 0.010), r.data()).OverBudget) << "exactly on target";
  EXPECT_TRUE(policy.Select(scene.Input(0.069, 0.010), r.data()).OverBudget);
  EXPECT_NEAR(policy.Select(scene.Input(0.069, 0.010), r.data()).PredictedFrameTime, 0.070, 1e-15);
}

TEST(ResolutionPolicy, ObjectiveFollowsAlphaAndNeedsWeights)
{
  ThreeObjects scene;
  FixedPolicy policy(0.25);
  std::vector<double> r(3);
  // alpha -1/2: f_i = -2 c_i sqrt(r) = -c_i at r = 1/4.
  EXPECT_NEAR(policy.Select(scene.Input(0.1, 0.0, -0.5), r.data()).Objective, -6.0, 1e-12);
  // No objective without weights or with an inadmissible alpha; the prediction stays.
  PolicyInput noWeights = scene.Input(0.1, 0.0);
  noWeights.Weight = nullptr;
  const PolicyResult unweighted = policy.Select(noWeights, r.data());
  EXPECT_EQ(unweighted.Objective, 0.0);
  EXPECT_NEAR(unweighted.PredictedFrameTime, 0.0025 + 0.010 + 0.0075, 1e-15);
  EXPECT_EQ(policy.Select(scene.Input(0.1, 0.0, 0.0), r.data()).Objective, 0.0);
  EXPECT_EQ(policy.Select(scene.Input(0.1, 0.0, -1.0), r.data()).Objective, 0.0);
}

TEST(ResolutionPolicy, EmptySceneIsNotChosen)
{
  FixedPolicy policy(0.5);
  PolicyInput in;
  in.FixedTime = 0.01;
  const PolicyResult result = policy.Select(in, nullptr);
  EXPECT_EQ(policy.Calls, 0);
  EXPECT_EQ(result.PredictedFrameTime, 0.01);
  EXPECT_FALSE(result.OverBudget);
  EXPECT_EQ(result.Objective, 0.0);
  // Objects but nowhere to write: no choice either.
  ThreeObjects scene;
  const PolicyResult noOutput = policy.Select(scene.Input(0.005, 0.01), nullptr);
  EXPECT_EQ(policy.Calls, 0);
  EXPECT_EQ(noOutput.PredictedFrameTime, 0.01);
  EXPECT_TRUE(noOutput.OverBudget) << "the fixed time alone exceeds the target";
  // Without times the prediction is the fixed time.
  PolicyInput noTimes = scene.Input(0.1, 0.01);
  noTimes.MaxTime = nullptr;
  std::vector<double> r(3);
  EXPECT_EQ(policy.Select(noTimes, r.data()).PredictedFrameTime, 0.01);
  EXPECT_EQ(policy.Calls, 1);
}

TEST(ResolutionPolicy, ResetIsANoOpByDefault)
{
  FixedPolicy policy(0.5);
  policy.Reset();
  EXPECT_STREQ(policy.GetName(), "fixed");
  EXPECT_EQ(policy.Calls, 0);
}

TEST(PolicyInput, GetProblemIsTheBudgetAfterTheFixedTime)
{
  ThreeObjects scene;
  const PolicyInput in = scene.Input(0.1, 0.025, 2.0);
  const timecritical::ResolutionProblem problem = in.GetProblem();
  EXPECT_EQ(problem.Count, 3u);
  EXPECT_EQ(problem.Weight, scene.Weight.data());
  EXPECT_EQ(problem.MaxTime, scene.MaxTime.data());
  EXPECT_EQ(problem.MinResolution, scene.MinResolution.data());
  EXPECT_EQ(problem.Alpha, 2.0);
  EXPECT_DOUBLE_EQ(problem.Budget, 0.075);
}

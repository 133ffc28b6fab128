// SPDX-License-Identifier: BSD-3-Clause
#include "ResolutionPolicy.h"

#include <algorithm>
#include <chrono>

namespace timecritical
{
ResolutionProblem PolicyInput::GetProblem() const
{
  ResolutionProblem problem;
  problem.Count = this->Count;
  problem.Weight = this->Weight;
  problem.MaxTime = this->MaxTime;
  problem.MinResolution = this->MinResolution;
  problem.Alpha = this->Alpha;
  problem.Budget = this->TargetFrameTime - this->FixedTime;
  return problem;
}

ResolutionPolicy::~ResolutionPolicy() = default;

PolicyResult ResolutionPolicy::Select(const PolicyInput& input, double* r)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  HysteresisBand::CheckHysteresis(input.Hysteresis);
  PolicyResult result;
  const ResolutionProblem problem = input.GetProblem();
  if (input.Count > 0 && r)
  {
    this->Choose(input, r, result);
    if (input.Hysteresis > 0.0 && input.Previous && input.MaxTime &&
      ResolutionProblem::IsValidAlpha(input.Alpha))
    {
      HysteresisBand::Input band;
      band.Count = input.Count;
      band.MaxTime = input.MaxTime;
      band.MinResolution = input.MinResolution;
      band.Previous = input.Previous;
      band.Alpha = input.Alpha;
      band.Slack = std::max(0.0, problem.Budget - problem.EffectiveCost(r));
      result.Held = this->Band.Apply(band, input.Hysteresis, r);
    }
  }
  result.Seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (input.Count > 0 && r && input.MaxTime)
  {
    result.PredictedFrameTime = input.FixedTime + problem.EffectiveCost(r);
    result.Objective = input.Weight && ResolutionProblem::IsValidAlpha(input.Alpha)
      ? problem.Objective(r)
      : 0.0;
  }
  else
  {
    result.PredictedFrameTime = input.FixedTime;
  }
  // Relative slack for the rounding of sums over many objects.
  result.OverBudget = result.PredictedFrameTime > input.TargetFrameTime * (1.0 + 1e-9);
  return result;
}
}

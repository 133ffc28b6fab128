// SPDX-License-Identifier: BSD-3-Clause
#include "ActiveSetOptimizerInternals.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace timecritical
{
ActiveSetOptimizer::ActiveSetOptimizer(const Options& options)
  : Opts(options)
{
}

const char* ActiveSetOptimizer::GetStatusName(Status status)
{
  switch (status)
  {
    case Status::Optimal:
      return "optimal";
    case Status::Unconstrained:
      return "unconstrained";
    case Status::Infeasible:
      return "infeasible";
    case Status::TimeLimit:
      return "time-limit";
    case Status::IterationLimit:
      return "iteration-limit";
    case Status::Empty:
      return "empty";
    case Status::InvalidInput:
      return "invalid-input";
  }
  return "unknown";
}

void ActiveSetOptimizer::Reserve(std::size_t n)
{
  if (n > this->T.size())
  {
    this->T.resize(n);
    this->Lo.resize(n);
    this->C.resize(n);
    this->G.resize(n);
    this->Scratch.resize(n);
    this->State.resize(n);
    this->Order.resize(n);
    this->Candidates.resize(3 * n);
  }
  if (this->BucketCost.empty())
  {
    this->BucketCost.resize(MaxLanes * KeyBuckets);
  }
}

bool ActiveSetOptimizer::TimeUp()
{
  if (!this->Expired && this->Work >= this->Opts.ClockCheckWork)
  {
    this->Work = 0;
    this->Expired = Now() > this->Deadline;
  }
  return this->Expired;
}

ActiveSetOptimizer::Result ActiveSetOptimizer::Solve(
  const ResolutionProblem& problem, double* r, bool warmStart)
{
  const double start = Now();
  Result result;
  const std::size_t n = problem.Count;
  this->N = n;
  this->StepCount = 0;
  this->Work = 0;
  const double timeLimit = this->Opts.TimeLimit;
  this->Expired = !(timeLimit > 0.0);
  this->Deadline = start + (this->Expired ? 0.0 : timeLimit);
  if (n == 0)
  {
    result.State = Status::Empty;
  }
  else if (!r || !problem.Weight || !problem.MaxTime ||
    !ResolutionProblem::IsValidAlpha(problem.Alpha))
  {
    if (r)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        const double lo = problem.MinResolution ? problem.MinResolution[i] : 0.0;
        r[i] = std::isfinite(lo) ? Clamp(lo, ResolutionProblem::TinyResolution, 1.0) : 1.0;
      }
    }
    result.State = Status::InvalidInput;
  }
  else
  {
    this->SolveValid(problem, r, warmStart, result);
  }
  result.Converged = result.State == Status::Optimal || result.State == Status::Unconstrained ||
    result.State == Status::Empty;
  result.Infeasible = result.State == Status::Infeasible;
  result.Steps = this->StepCount;
  result.Seconds = Now() - start;
  return result;
}

void ActiveSetOptimizer::SolveValid(
  const ResolutionProblem& problem, double* r, bool warmStart, Result& result)
{
  const std::size_t n = problem.Count;
  this->Reserve(n);
  this->Alpha = problem.Alpha;
  this->Gamma = 1.0 / (problem.Alpha + 1.0);

  // Sanitized copies, the start point and its sums in one pass.
  StartSums sums;
  this->PrepareStart(problem, r, warmStart, sums);
  result.InvalidCount = sums.Invalid;
  result.ZeroCostCount = sums.Zero;
  const double rawBudget = problem.Budget;
  if (this->SolveAtEnds(r, rawBudget, sums, result))
  {
    return;
  }
  // Solve against a budget shaved by the rounding of O(n)-term sums (at
  // least 1e-12), so that it cannot push a returned cost above the caller's.
  const double budget =
    rawBudget * (1.0 - std::max(1e-12, 4.0 * static_cast<double>(n) * DBL_EPSILON));
  if (sums.CostLow > budget) // within rounding of rmin: rmin is the answer
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = this->Lo[i];
      result.LowerCount += this->T[i] > 0.0;
    }
    result.State = Status::Optimal;
    result.Objective = result.InitialObjective = this->ObjectiveAt(r);
    result.Cost = this->CostAt(r);
    return;
  }

  // Start point: rmin, or the previous resolutions reduced until feasible
  // (applied in SolveMultiplier's passes when it runs).
  const bool noIteration = !(this->Opts.TimeLimit > 0.0);
  if (!noIteration && this->Opts.ProjectedSteps && this->Opts.BlockRelease)
  {
    this->SolveMultiplier(r, budget, rawBudget, sums, result);
    return;
  }
  this->SolveStepwise(r, budget, rawBudget, warmStart, sums, result);
}

void ActiveSetOptimizer::PrepareStart(
  const ResolutionProblem& problem, double* r, bool warmStart, StartSums& sums)
{
  const std::size_t n = this->N;
  switch (KindOf(this->Alpha))
  {
    case 1:
      this->Prepare<1>(problem, r, warmStart, sums);
      break;
    case 2:
      this->Prepare<2>(problem, r, warmStart, sums);
      break;
    case 3:
      this->Prepare<3>(problem, r, warmStart, sums);
      break;
    default:
      this->Prepare<0>(problem, r, warmStart, sums);
      break;
  }
  this->Work += n;
  // The lane sums differ from a sequential sum by rounding: where that
  // could decide a comparison with the budget, the sequential sum decides
  // (a caller that sets the budget to cost(rmin) or cost(1) gets that case).
  const double rawBudget = problem.Budget;
  const double rounding = 4.0 * static_cast<double>(n) * DBL_EPSILON;
  if (std::abs(sums.CostLow - rawBudget) <= rounding * sums.CostLow ||
    std::abs(sums.CostHigh - rawBudget) <= rounding * sums.CostHigh)
  {
    sums.CostLow = sums.CostHigh = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      sums.CostLow += this->T[i] * this->Lo[i];
      sums.CostHigh += this->T[i];
    }
  }
}

bool ActiveSetOptimizer::SolveAtEnds(
  double* r, double rawBudget, const StartSums& sums, Result& result)
{
  // Section 5.3.1: infeasible and all-full cases terminate at once.
  const double costLow = sums.CostLow, costHigh = sums.CostHigh;
  if (!(!std::isfinite(rawBudget) || costLow > rawBudget || costHigh <= rawBudget))
  {
    return false;
  }
  const bool full = std::isfinite(rawBudget) && costHigh <= rawBudget;
  for (std::size_t i = 0; i < this->N; ++i)
  {
    const bool inProblem = this->T[i] > 0.0;
    r[i] = inProblem && full ? 1.0 : this->Lo[i];
    result.UpperCount += inProblem && full;
    result.LowerCount += inProblem && !full;
  }
  result.State = full ? Status::Unconstrained : Status::Infeasible;
  result.Objective = result.InitialObjective = this->ObjectiveAt(r);
  result.Cost = this->CostAt(r);
  result.KKTResidual = full ? 0.0
                            : (std::isfinite(rawBudget) && rawBudget != 0.0
                                  ? (result.Cost - rawBudget) / std::abs(rawBudget)
                                  : Infinity);
  return true;
}

double ActiveSetOptimizer::ObjectiveAt(const double* r) const
{
  double f = 0.0;
  for (std::size_t i = 0; i < this->N; ++i)
  {
    f += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
  }
  return f;
}

double ActiveSetOptimizer::CostAt(const double* r) const
{
  double cost = 0.0;
  for (std::size_t i = 0; i < this->N; ++i)
  {
    cost += this->T[i] * r[i];
  }
  return cost;
}
}

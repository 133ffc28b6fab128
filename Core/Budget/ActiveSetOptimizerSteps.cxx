// SPDX-License-Identifier: BSD-3-Clause
// Algorithm 1 step by step (one of ProjectedSteps, BlockRelease off), and the
// closed form used without time to iterate.
#include "ActiveSetOptimizerInternals.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
void ActiveSetOptimizer::SolveStepwise(double* r, double budget, double rawBudget,
  bool warmStart, StartSums& sums, Result& result)
{
  const std::size_t n = this->N;
  if (sums.Cost > budget)
  {
    const Reduction plan = this->PlanReduction(r, budget, sums, false);
    if (plan.Active)
    {
      WithKind(this->Alpha, [&](auto kind) { this->ApplyReduction<decltype(kind)::value>(r, plan, sums); });
    }
  }

  // The paper's iteration (or one option off); without time to iterate, the
  // closed form (or the warm start if better).
  for (std::size_t i = 0; i < n; ++i)
  {
    this->State[i] = this->T[i] > 0.0 ? Free : PinnedLow;
  }
  if (!(this->Opts.TimeLimit > 0.0))
  {
    this->ClosedFormOrWarm(r, budget, warmStart);
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      // Algorithm 1: W(0) = the time constraint (section 5.3.1) + active bounds.
      this->State[i] = r[i] <= this->Lo[i] ? Lower : (r[i] >= 1.0 ? Upper : Free);
    }
  }
  double objective = this->ObjectiveAt(r);
  result.InitialObjective = objective;
  this->Work += 2 * n;

  const int stalls = this->Iterate(r, budget, objective, result);
  this->Report(r, budget, rawBudget, result);
  if (result.State == Status::IterationLimit && stalls >= 2 && result.KKTResidual <= 1e-8)
  {
    result.State = Status::Optimal;
  }
}

void ActiveSetOptimizer::ClosedFormOrWarm(double* r, double budget, bool warmStart)
{
  const std::size_t n = this->N;
  double* closed = warmStart ? this->Scratch.data() : r;
  if (warmStart)
  {
    std::copy(r, r + n, closed);
  }
  this->ClosedForm(closed, budget);
  if (warmStart)
  {
    double closedObjective = 0.0, warmObjective = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      closedObjective += ResolutionProblem::Term(this->C[i], this->Alpha, closed[i]);
      warmObjective += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    }
    if (closedObjective < warmObjective)
    {
      std::copy(closed, closed + n, r);
    }
  }
}

std::size_t ActiveSetOptimizer::Subspace(const double* r, double& fixedCost, double& weightSum)
{
  // Subspace data of the working set: sum of tmax_i g_i over F, fixed cost.
  // (Summed in locals: the references could alias the arrays.)
  const std::size_t n = this->N;
  std::size_t freeCount = 0;
  double fixedSum = 0.0, weights = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint8_t s = this->State[i];
    if (s == Free)
    {
      weights += this->T[i] * this->G[i];
      ++freeCount;
    }
    else if (s <= Upper)
    {
      fixedSum += this->T[i] * r[i];
    }
  }
  fixedCost = fixedSum;
  weightSum = weights;
  this->Work += n;
  return freeCount;
}

int ActiveSetOptimizer::Iterate(double* r, double budget, double& objective, Result& result)
{
  // Returns how many steps in a row changed nothing (2 stops the iteration).
  const std::size_t n = this->N;
  result.State = Status::IterationLimit;
  int stalls = 0;
  int fullReleases = 0;
  while (true)
  {
    if (result.Iterations >= this->Opts.MaxIterations || this->StepCount >= this->Opts.MaxSteps)
    {
      result.State = Status::IterationLimit;
      break;
    }
    if (this->TimeUp())
    {
      result.State = Status::TimeLimit;
      break;
    }
    ++result.Iterations;
    ++this->StepCount;

    double fixedCost = 0.0, weightSum = 0.0;
    const std::size_t freeCount = this->Subspace(r, fixedCost, weightSum);
    const double slack = budget - fixedCost;
    double kappa = Infinity;
    if (freeCount > 0)
    {
      kappa = slack / weightSum; // eq. 14
      if (this->Moving(r, kappa))
      {
        const double before = objective;
        const std::size_t changes = this->Step(r, budget, slack, kappa, objective);
        // A step that changes neither f nor the working set would repeat.
        stalls = objective < before || changes > 0 ? 0 : stalls + 1;
        if (stalls >= 2)
        {
          break;
        }
        continue;
      }
    }
    // d = 0: multipliers (eq. 16).
    bool slackTime = false;
    if (freeCount == 0)
    {
      slackTime = slack > 1e-12 * std::abs(budget);
      if (!slackTime)
      {
        kappa = this->BoundKappa();
        if (kappa < 0.0)
        {
          // Degenerate vertex (everything at a bound, time tight) whose
          // multipliers are not unique: free every bound and let the
          // projected step solve the whole problem.
          if (++fullReleases > 2)
          {
            break;
          }
          for (std::size_t i = 0; i < n; ++i)
          {
            if ((this->State[i] == Lower && this->G[i] > 0.0) || this->State[i] == Upper)
            {
              this->State[i] = Free;
            }
          }
          continue;
        }
      }
    }
    if (!this->Release(kappa, slackTime))
    {
      result.State = Status::Optimal;
      break;
    }
  }
  return stalls;
}

bool ActiveSetOptimizer::Moving(const double* r, double kappa)
{
  // Whether the subspace minimizer kappa g_i is away from r on the free set (d != 0).
  const std::size_t n = this->N;
  bool moving = false;
  for (std::size_t i = 0; i < n && !moving; ++i)
  {
    if (this->State[i] == Free)
    {
      moving = std::abs(kappa * this->G[i] - r[i]) > StepTolerance + StepRelativeTolerance * r[i];
    }
  }
  this->Work += n;
  return moving;
}

std::size_t ActiveSetOptimizer::Step(
  double* r, double budget, double slack, double kappa, double& objective)
{
  // One step towards the subspace minimizer; returns the working-set changes.
  std::size_t changes = 0;
  double stepSlack = slack, stepKappa = kappa;
  if (this->Opts.ProjectedSteps && this->Opts.BlockRelease && this->Release(kappa, false))
  {
    // Released now the bounds whose multiplier estimate at this kappa
    // is negative, so that one projected step covers them too (a warm
    // start would otherwise need a second one after the d = 0 test).
    // The free set changed: its slack and eq. 14 kappa with it.
    double releasedFixed = 0.0, releasedSum = 0.0;
    this->Subspace(r, releasedFixed, releasedSum);
    stepSlack = budget - releasedFixed;
    stepKappa = stepSlack / releasedSum;
    changes = 1;
  }
  if (!this->Opts.ProjectedSteps ||
    !this->ProjectedStep(r, stepSlack, stepKappa, objective, changes))
  {
    changes += this->LineStep(r, stepKappa, objective);
  }
  return changes;
}

double ActiveSetOptimizer::ClosedForm(double* r, double budget)
{
  // Every object free: r_i = clamp(kappa g_i, rmin_i, 1), the optimum's form,
  // with kappa from eq. 14, then a few safeguarded Newton corrections on
  // phi(kappa) = sum tmax_i clamp(kappa g_i) = budget (as in ProjectedStep),
  // keeping a bracket [kLo, kHi] with phi(kLo) <= budget < phi(kHi) (at
  // worst kappa = 0: rmin, and kappa = inf: every object in full, which is
  // over budget or Solve() would not get here). The answer is the point on
  // the segment between the bracket's two allocations that spends the
  // budget exactly: within the bounds, feasible, and the optimum whenever a
  // correction lands on it. A fixed number of O(n) passes; none repeats.
  constexpr int Passes = 6;
  const std::size_t n = this->N;
  auto clampAt = [this](double kappa, std::size_t i) {
    const double y = kappa * this->G[i];
    return std::isfinite(y) ? Clamp(y, this->Lo[i], 1.0) : (this->G[i] > 0.0 ? 1.0 : this->Lo[i]);
  };
  double weightSum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    weightSum += this->State[i] == Free ? this->T[i] * this->G[i] : 0.0;
  }
  double kLo = 0.0, kHi = Infinity;
  double kappa = weightSum > 0.0 ? budget / weightSum : Infinity;
  for (int pass = 0; pass < Passes && kappa > kLo && kappa < kHi; ++pass)
  {
    double clamped = 0.0, interior = 0.0, phi = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (this->State[i] != Free)
      {
        continue;
      }
      const double y = kappa * this->G[i];
      if (y <= this->Lo[i])
      {
        clamped += this->T[i] * this->Lo[i];
      }
      else if (y >= 1.0)
      {
        clamped += this->T[i];
      }
      else
      {
        interior += this->T[i] * this->G[i];
        phi += this->T[i] * y;
      }
    }
    phi += clamped;
    (phi <= budget ? kLo : kHi) = kappa;
    if (phi == budget)
    {
      kHi = kappa;
      break;
    }
    double next = interior > 0.0 ? (budget - clamped) / interior : -1.0;
    if (!(next > kLo && next < kHi))
    {
      next = !std::isfinite(kHi) ? 4.0 * std::max(kLo, kappa)
                                 : (kLo > 0.0 ? std::sqrt(kLo) * std::sqrt(kHi) : 0.25 * kHi);
    }
    kappa = next;
  }
  // The segment from the feasible allocation at kLo to the one at kHi.
  double costBelow = 0.0, costAbove = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      costBelow += this->T[i] * clampAt(kLo, i);
      costAbove += this->T[i] * clampAt(kHi, i);
    }
  }
  const double s = costAbove > costBelow
    ? Clamp((budget - costBelow) / (costAbove - costBelow), 0.0, 1.0)
    : 0.0;
  double cost = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double below = clampAt(kLo, i);
      r[i] = Clamp(below + s * (clampAt(kHi, i) - below), this->Lo[i], 1.0);
      cost += this->T[i] * r[i];
    }
  }
  if (cost > budget) // rounding: fall back to the feasible end
  {
    cost = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (this->State[i] == Free)
      {
        r[i] = clampAt(kLo, i);
        cost += this->T[i] * r[i];
      }
    }
  }
  this->Work += static_cast<std::size_t>(Passes + 3) * n;
  return cost;
}

bool ActiveSetOptimizer::ProjectedStep(
  double* r, double slack, double kappa0, double& objective, std::size_t& changes)
{
  // Minimize f over the free variables within their bounds, the working
  // set's bounds fixed, on sum_F tmax_i r_i = slack (ProjectedRoot()); the
  // step is taken only when it improves f.
  double solution = 0.0;
  if (!this->ProjectedRoot(slack, kappa0, solution))
  {
    return false;
  }
  const std::size_t n = this->N;
  // Accept only an improvement: f is monotone along the returned points.
  double delta = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double y = Clamp(solution * this->G[i], this->Lo[i], 1.0);
      delta += ResolutionProblem::Term(this->C[i], this->Alpha, y) -
        ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    }
  }
  this->Work += n;
  if (!(delta <= 0.0))
  {
    return false;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double y = solution * this->G[i];
      if (y <= this->Lo[i])
      {
        r[i] = this->Lo[i];
        this->State[i] = Lower;
        ++changes;
      }
      else if (y >= 1.0)
      {
        r[i] = 1.0;
        this->State[i] = Upper;
        ++changes;
      }
      else
      {
        r[i] = y;
      }
    }
  }
  objective += delta;
  return true;
}

bool ActiveSetOptimizer::ProjectedRoot(double slack, double kappa0, double& solution)
{
  // The projected step's solution is r_i = clamp(kappa g_i, rmin_i, 1)
  // where phi(kappa) = sum_F tmax_i clamp(kappa g_i) = slack; phi is non-decreasing and piecewise linear, so a
  // Newton iteration (each round = the eq. 14 solution for the bounds the last
  // round hit) safeguarded by a bracket finds the root exactly in a few
  // rounds. kappa below the root is feasible, so the bracket's lower end is a
  // feasible fall-back when the round or time limit stops the iteration.
  // False when there is none (then no step).
  const std::size_t n = this->N;
  double kLo = 0.0, kHi = Infinity;
  double kappa = kappa0;
  double previous = -1.0; // kappa of the last round, when this one is its Newton step
  bool exact = false;
  // Relative rounding of a sum of n terms.
  const double tolerance = std::max(1e-13, 2.0 * static_cast<double>(n) * DBL_EPSILON);
  for (int round = 0; round < MaxNewtonRounds; ++round)
  {
    if (round > 0)
    {
      ++this->StepCount;
      if (this->StepCount >= this->Opts.MaxSteps || this->TimeUp())
      {
        break;
      }
    }
    double phi = 0.0, slope = 0.0, clampedCost = 0.0;
    std::size_t freeCount = 0, upperCount = 0, moved = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (this->State[i] != Free)
      {
        continue;
      }
      ++freeCount;
      const double t = this->T[i];
      const double y = kappa * this->G[i];
      if (previous >= 0.0)
      {
        // Did a bound change between the last round and this Newton step?
        const double x = previous * this->G[i];
        moved += (x <= this->Lo[i]) != (y <= this->Lo[i]) || (x >= 1.0) != (y >= 1.0);
      }
      if (y <= this->Lo[i])
      {
        phi += t * this->Lo[i];
        clampedCost += t * this->Lo[i];
      }
      else if (y >= 1.0)
      {
        phi += t;
        clampedCost += t;
        ++upperCount;
      }
      else
      {
        phi += t * y;
        slope += t * this->G[i];
      }
    }
    this->Work += n;
    // Exact: phi meets the slack, or a Newton step kept every bound, so it
    // solved the linear piece it is on (up to the rounding of the sums).
    if (std::abs(phi - slack) <= tolerance * slack || (previous >= 0.0 && moved == 0))
    {
      exact = true;
      solution = kappa;
      break;
    }
    if (phi < slack)
    {
      if (upperCount == freeCount) // time is not binding on F: all to full
      {
        exact = true;
        solution = Infinity;
        break;
      }
      kLo = std::max(kLo, kappa);
    }
    else
    {
      kHi = std::min(kHi, kappa);
    }
    double next = slope > 0.0 ? (slack - clampedCost) / slope : -1.0;
    previous = kappa;
    if (!(next > kLo && next < kHi))
    {
      // Safeguard: bisection (geometric across orders of magnitude).
      previous = -1.0;
      next = !std::isfinite(kHi) ? 4.0 * std::max(kLo, kappa)
        : (kLo > 0.0 && kHi > 4.0 * kLo ? std::sqrt(kLo) * std::sqrt(kHi) : 0.5 * (kLo + kHi));
    }
    if (std::isfinite(kHi) && kHi - kLo <= 1e-15 * kHi)
    {
      break;
    }
    kappa = next;
  }
  if (!exact)
  {
    if (!(kLo > 0.0))
    {
      return false;
    }
    solution = kLo;
  }
  return true;
}

std::size_t ActiveSetOptimizer::LineStep(double* r, double kappa, double& objective)
{
  // Algorithm 1: the largest step mu <= 1 along d = kappa g - r (free
  // variables) that keeps every bound, then every bound reached joins the
  // working set. Along d the time constraint's left side moves linearly from
  // cost(r) <= Budget to Budget, so it holds for every mu in [0, 1].
  const std::size_t n = this->N;
  double mu = 1.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double d = kappa * this->G[i] - r[i];
      if (d > 0.0)
      {
        mu = std::min(mu, (1.0 - r[i]) / d);
      }
      else if (d < 0.0)
      {
        mu = std::min(mu, (this->Lo[i] - r[i]) / d);
      }
    }
  }
  mu = std::max(0.0, mu);
  double delta = 0.0;
  std::size_t changes = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Free)
    {
      const double d = kappa * this->G[i] - r[i];
      double y = r[i] + mu * d;
      if (d > 0.0 && y >= 1.0 - 1e-14)
      {
        y = 1.0;
        this->State[i] = Upper;
        ++changes;
      }
      else if (d < 0.0 && y <= this->Lo[i] * (1.0 + 1e-14))
      {
        y = this->Lo[i];
        this->State[i] = Lower;
        ++changes;
      }
      delta += ResolutionProblem::Term(this->C[i], this->Alpha, y) -
        ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
      r[i] = y;
    }
  }
  this->Work += 2 * n;
  objective += delta;
  return changes;
}

bool ActiveSetOptimizer::Release(double kappa, bool slackTime)
{
  // eq. 16: a lower bound's multiplier lambda tmax_i - c_i rmin_i^-(alpha+1)
  // is negative iff kappa g_i > rmin_i, an upper bound's c_i - lambda tmax_i
  // iff kappa g_i < 1. With the time constraint slack, lambda = 0.
  const std::size_t n = this->N;
  const double lambda = slackTime || !std::isfinite(kappa) ? 0.0 : std::pow(kappa, -(this->Alpha + 1.0));
  std::size_t best = n;
  double bestValue = 0.0;
  bool released = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint8_t s = this->State[i];
    bool negative = false;
    double multiplier = 0.0;
    if (s == Lower && this->G[i] > 0.0)
    {
      negative = slackTime || kappa * this->G[i] > this->Lo[i] * (1.0 + ReleaseTolerance);
      if (negative && !this->Opts.BlockRelease)
      {
        multiplier = this->T[i] * lambda -
          this->C[i] * std::pow(this->Lo[i], -(this->Alpha + 1.0));
      }
    }
    else if (s == Upper && !slackTime)
    {
      negative = kappa * this->G[i] < 1.0 - ReleaseTolerance;
      if (negative && !this->Opts.BlockRelease)
      {
        multiplier = this->C[i] - lambda * this->T[i];
      }
    }
    if (!negative)
    {
      continue;
    }
    if (this->Opts.BlockRelease)
    {
      this->State[i] = Free;
      released = true;
    }
    else if (best == n || multiplier < bestValue)
    {
      best = i;
      bestValue = multiplier;
    }
  }
  this->Work += n;
  if (!this->Opts.BlockRelease && best < n)
  {
    this->State[best] = Free;
    released = true;
  }
  return released;
}

double ActiveSetOptimizer::BoundKappa() const
{
  // Multiplier kappa when no variable is free: any kappa between the bounds'
  // limits satisfies eq. 16; -1 when none does.
  const std::size_t n = this->N;
  double lowest = 0.0, highest = Infinity;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->State[i] == Upper)
    {
      lowest = std::max(lowest, 1.0 / this->G[i]);
    }
    else if (this->State[i] == Lower && this->G[i] > 0.0)
    {
      highest = std::min(highest, this->Lo[i] / this->G[i]);
    }
  }
  if (lowest > highest * (1.0 + ReleaseTolerance))
  {
    return -1.0;
  }
  return std::isfinite(highest) ? (lowest > 0.0 ? std::sqrt(lowest * highest) : highest)
                                : std::max(lowest, 1.0);
}

void ActiveSetOptimizer::Report(const double* r, double budget, double rawBudget, Result& result)
{
  // Objective, cost, multiplier and KKT residual at r for the working set in
  // State: kappa from eq. 14 on its free variables.
  const std::size_t n = this->N;
  double objective = 0.0, cost = 0.0, fixedCost = 0.0, weightSum = 0.0;
  std::size_t freeCount = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    objective += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    cost += this->T[i] * r[i];
    const std::uint8_t s = this->State[i];
    if (s == Free)
    {
      weightSum += this->T[i] * this->G[i];
      ++freeCount;
    }
    else if (s <= Upper)
    {
      fixedCost += this->T[i] * r[i];
    }
  }
  result.Objective = objective;
  result.Cost = cost;
  double kappa = Infinity;
  if (freeCount > 0)
  {
    kappa = (budget - fixedCost) / weightSum;
  }
  else if (budget - fixedCost <= 1e-12 * std::abs(budget))
  {
    kappa = this->BoundKappa();
    kappa = kappa < 0.0 ? Infinity : kappa;
  }
  double residual = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint8_t s = this->State[i];
    if (s > Upper)
    {
      continue;
    }
    const double target = this->G[i] > 0.0 ? Clamp(kappa * this->G[i], this->Lo[i], 1.0) : this->Lo[i];
    residual = std::max(residual, std::abs(r[i] - target));
    result.FreeCount += s == Free;
    result.LowerCount += s == Lower;
    result.UpperCount += s == Upper;
  }
  const double violation = (result.Cost - rawBudget) / rawBudget;
  residual = std::max(residual, violation);
  if (std::isfinite(kappa))
  {
    residual = std::max(residual, std::abs(violation));
    result.Multiplier = std::pow(kappa, -(this->Alpha + 1.0));
  }
  result.KKTResidual = residual;
}
}

// SPDX-License-Identifier: BSD-3-Clause
#include "ActiveSetOptimizerInternals.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace timecritical
{
ActiveSetOptimizer::Reduction ActiveSetOptimizer::PlanReduction(
  double* r, double budget, StartSums& sums, bool bucketsSummed)
{
  // Section 5.3.1: reduce resolutions by Beta, least valuable objects first,
  // until the time constraint holds. "Value" is the marginal benefit per unit
  // of time, rho_i = -f_i'(r_i) / tmax_i = (g_i / r_i)^(alpha+1); ordering by
  // g_i / r_i is the same and needs no pow(). The objects are bucketed (half
  // octaves) with what each bucket gives (BucketPass, or the first
  // classification pass of the multiplier search, which reads the same
  // data); the buckets below the one that covers the excess are reduced by
  // Beta, that one by the fraction of it that spends the budget exactly (an
  // order within a half octave would be arbitrary). No sort, and the plan is
  // applied in the pass that needs the start point. When every reducible
  // object reduced once is not enough, the round is applied and repeated.
  Reduction plan;
  plan.Beta = this->Opts.Beta > 0.0 && this->Opts.Beta < 1.0 ? this->Opts.Beta : 0.8;
  double* bucketCost = this->BucketCost.data();
  const double rounding = 4.0 * static_cast<double>(this->N) * DBL_EPSILON * sums.Cost;
  for (int round = 0; sums.Cost > budget && round < 1000; ++round)
  {
    if (!bucketsSummed)
    {
      this->BucketPass(r, plan.Beta);
    }
    bucketsSummed = false;
    // Merge the lanes' sub-tables over the touched buckets, and clear them
    // (the table is all zero between uses).
    double total = 0.0;
    const int low = this->BucketLow, high = this->BucketHigh;
    for (int b = low; b <= high; ++b)
    {
      const std::size_t at = static_cast<std::size_t>(b);
      for (std::size_t k = 1; k < MaxLanes; ++k)
      {
        bucketCost[at] += bucketCost[k * KeyBuckets + at];
        bucketCost[k * KeyBuckets + at] = 0.0;
      }
      total += bucketCost[at];
    }
    this->BucketLow = KeyBuckets;
    this->BucketHigh = -1;
    auto clear = [&]() {
      std::fill(bucketCost + std::max(low, 0), bucketCost + std::max(low, high + 1), 0.0);
    };
    if (!(total > 0.0))
    {
      clear();
      break;
    }
    const double excess = sums.Cost - budget;
    double below = 0.0;
    plan.Cut = std::max(low, 0);
    for (; plan.Cut <= high && below + bucketCost[plan.Cut] < excess; ++plan.Cut)
    {
      below += bucketCost[plan.Cut];
    }
    plan.Active = true;
    if (plan.Cut <= high)
    {
      // Rounded up so that the start's cost cannot land above the budget.
      plan.Theta = std::min(1.0, (excess - below + rounding) / bucketCost[plan.Cut]);
      clear();
      return plan;
    }
    clear();
    plan.Cut = KeyBuckets;
    plan.Theta = 1.0;
    WithKind(this->Alpha, [&](auto kind) { this->ApplyReduction<decltype(kind)::value>(r, plan, sums); });
    plan.Active = false;
  }
  if (sums.Cost > budget) // rounding only: rmin is feasible
  {
    sums.Cost = sums.Objective = 0.0;
    for (std::size_t i = 0; i < this->N; ++i)
    {
      r[i] = this->Lo[i];
      sums.Cost += this->T[i] * r[i];
      sums.Objective += ResolutionProblem::Term(this->C[i], this->Alpha, r[i]);
    }
  }
  return plan;
}

bool ActiveSetOptimizer::SolveCandidates(double& low, double& high, double fixedCost,
  double slope, std::size_t count, double budget, double& kappa)
{
  // phi(kappa) = fixedCost + kappa slope + sum over the candidates of
  // tmax_i clamp(kappa g_i) on [low, high], phi(low) <= budget <= phi(high):
  // a safeguarded Newton iteration over the candidates only. Exact when phi
  // meets the budget, a Newton step crossed no breakpoint (it then solved
  // the linear piece it is on) or the bracket is down to rounding; otherwise
  // false with the bracket narrowed.
  const double tolerance = std::max(1e-13, 2.0 * static_cast<double>(this->N) * DBL_EPSILON);
  double k = low;
  double previous = -1.0;
  for (int round = 0; round < MaxNewtonRounds; ++round)
  {
    double phi = fixedCost + k * slope, d = slope, unused = 0.0;
    std::size_t moved = 0;
    if (previous >= 0.0)
    {
      this->CandidatePhi<false, true>(count, k, previous, phi, d, unused, unused, moved);
    }
    else
    {
      this->CandidatePhi<false, false>(count, k, 0.0, phi, d, unused, unused, moved);
    }
    if (std::abs(phi - budget) <= tolerance * budget || (previous >= 0.0 && moved == 0))
    {
      kappa = k;
      return true;
    }
    (phi < budget ? low : high) = k;
    if (high - low <= 1e-15 * high)
    {
      kappa = low; // within rounding of the root, on its feasible side
      return true;
    }
    double next = d > 0.0 ? k + (budget - phi) / d : -1.0;
    previous = k;
    if (!(next > low && next < high))
    {
      previous = -1.0;
      next = Bisect(low, high);
    }
    k = next;
  }
  return false;
}

/// Where the multiplier search stands: the warm-start reduction (planned in
/// its first pass when the start is over budget) and the bracket of the root.
struct ActiveSetOptimizer::MultiplierSearch
{
  Reduction Plan;
  bool Reduce = false; ///< the start is over budget and its reduction is not planned yet
  double Beta = 0.8;
  double Low = 0.0, High = Infinity; ///< phi(Low) <= budget < phi(High)
};

void ActiveSetOptimizer::SolveMultiplier(
  double* r, double budget, double rawBudget, StartSums& sums, Result& result)
{
  // Algorithm 1 with both options on: W = {time constraint}, every bound
  // resolved inside one projected step, so the answer is r_i = clamp(kappa
  // g_i, rmin_i, 1) with phi(kappa) = sum tmax_i r_i = budget, a root of a
  // non-decreasing piecewise-linear function. The start's eq. 14 kappa (the
  // previous frame's multiplier when warm) centres an interval; one pass sums
  // the objects whose form is fixed on it and lists the others (those with a
  // breakpoint inside: few for a frame-to-frame change), and the root is
  // found among those. When the interval misses the root, a
  // Newton step from its near end centres the next one, wider.
  // The start point (with its warm-start reduction) is not needed for that:
  // its reduction is planned in the first pass and applied only to report f
  // there, or when the search stops early and the start may be the answer.
  result.InitialObjective = sums.Objective;
  result.State = Status::IterationLimit;
  MultiplierSearch search;
  search.Reduce = sums.Cost > budget;
  search.Beta = this->Opts.Beta > 0.0 && this->Opts.Beta < 1.0 ? this->Opts.Beta : 0.8;
  double solution = -1.0;
  if (this->Opts.MaxIterations > 0 && this->Opts.MaxSteps > 0)
  {
    solution = this->FindMultiplier(r, budget, sums, search, result);
  }
  if (solution < 0.0)
  {
    this->StopAtStart(r, budget, rawBudget, sums, search, result);
    return;
  }
  if (search.Reduce) // no search pass (the solution was known): plan it for f at the start
  {
    search.Plan = this->PlanReduction(r, budget, sums, false);
    result.InitialObjective = sums.Objective;
  }
  WithKind(this->Alpha, [&](auto kind) {
    this->Finish<decltype(kind)::value>(r, solution, rawBudget, search.Plan, result);
  });
  result.State = solution < DBL_MAX || result.KKTResidual <= 1e-8 ? Status::Optimal
                                                                 : Status::IterationLimit;
}

double ActiveSetOptimizer::FindMultiplier(
  double* r, double budget, StartSums& sums, MultiplierSearch& search, Result& result)
{
  // The root kappa of phi(kappa) = budget; < 0 when stopped first (time,
  // MaxSteps), with the bracket in search.
  ++result.Iterations;
  double solution = -1.0;
  if (!(sums.Weight > 0.0))
  {
    solution = 0.0; // nothing can rise above rmin
  }
  else if (sums.CostTop <= budget)
  {
    solution = Infinity; // objects with c = 0 stay at rmin: the time is not binding
  }
  double& kLo = search.Low;
  double& kHi = search.High;
  // The start's free set: the previous frame's when warm (taken before the
  // reduction, which only scales it), else none.
  double kappa = sums.FreeWeight > 0.0 && budget > sums.FixedCost
    ? (budget - sums.FixedCost) / sums.FreeWeight
    : budget / sums.Weight;
  double spread = sums.FreeWeight > 0.0 ? 1.0 + 1.0 / 64.0 : 1.5; // interval: kappa / spread ... kappa spread
  while (solution < 0.0)
  {
    if (this->StepCount >= this->Opts.MaxSteps || this->TimeUp())
    {
      result.State = this->Expired ? Status::TimeLimit : Status::IterationLimit;
      break;
    }
    if (!(kLo < DBL_MAX))
    {
      // The root is beyond the largest kappa (g_i near the underflow: gamma
      // = 10 spans 600 decades): the best representable point, feasible.
      solution = DBL_MAX;
      break;
    }
    ++this->StepCount;
    if (!(kappa > kLo && kappa < kHi))
    {
      kappa = Bisect(kLo, kHi);
    }
    const double low = std::max(kLo, kappa / spread);
    const double high = std::min({ kHi, kappa * spread, DBL_MAX });
    double slope = 0.0;
    std::size_t count = 0;
    const double fixedCost =
      this->Classify(low, high, slope, count, search.Reduce ? r : nullptr, search.Beta);
    if (search.Reduce)
    {
      search.Plan = this->PlanReduction(r, budget, sums, true);
      result.InitialObjective = sums.Objective;
      search.Reduce = false;
    }
    // phi and its slope at both ends from the affine part and the candidates.
    double phiLow = fixedCost + low * slope, phiHigh = fixedCost + high * slope;
    double dLow = slope, dHigh = slope;
    std::size_t unused = 0;
    this->CandidatePhi<true, false>(count, low, high, phiLow, dLow, phiHigh, dHigh, unused);
    if (phiLow <= budget && budget <= phiHigh)
    {
      double root = low, rootLow = low, rootHigh = high;
      if (this->SolveCandidates(rootLow, rootHigh, fixedCost, slope, count, budget, root))
      {
        solution = root;
        break;
      }
      kLo = rootLow; // out of rounds: search on with the narrower bracket
      kHi = rootHigh;
      kappa = Bisect(kLo, kHi);
      spread = std::max(kappa / kLo, kHi / kappa);
      continue;
    }
    // Missed: a Newton step from the near end centres the next interval,
    // at least twice as wide in log scale.
    const bool above = phiLow > budget;
    const double from = above ? low : high;
    (above ? kHi : kLo) = from;
    const double d = above ? dLow : dHigh;
    const double next = d > 0.0 ? from + (budget - (above ? phiLow : phiHigh)) / d : -1.0;
    spread = std::min(1e300, std::max(spread * spread, 1.0 + 2.0 * std::abs(next - from) / from));
    kappa = next;
  }
  return solution;
}

void ActiveSetOptimizer::StopAtStart(double* r, double budget, double rawBudget,
  StartSums& sums, MultiplierSearch& search, Result& result)
{
  // Stopped: the start point, or the bracket's feasible end if it is
  // better (anytime).
  const std::size_t n = this->N;
  if (search.Reduce)
  {
    search.Plan = this->PlanReduction(r, budget, sums, false);
  }
  const Reduction& plan = search.Plan;
  if (plan.Active)
  {
    WithKind(this->Alpha, [&](auto kind) { this->ApplyReduction<decltype(kind)::value>(r, plan, sums); });
  }
  result.InitialObjective = sums.Objective;
  bool moved = false;
  const double kLo = search.Low;
  if (kLo > 0.0)
  {
    double objective = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      objective += ResolutionProblem::Term(
        this->C[i], this->Alpha, Clamp(kLo * this->G[i], this->Lo[i], 1.0));
    }
    if (objective < sums.Objective)
    {
      moved = true;
      for (std::size_t i = 0; i < n; ++i)
      {
        r[i] = Clamp(kLo * this->G[i], this->Lo[i], 1.0);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    this->State[i] = !(this->T[i] > 0.0)
      ? PinnedLow
      : (r[i] <= this->Lo[i] ? Lower : (r[i] >= 1.0 ? Upper : Free));
  }
  this->Report(r, budget, rawBudget, result);
  if (!moved) // the start, whose f was summed in another order
  {
    result.Objective = sums.Objective;
  }
}
}

// SPDX-License-Identifier: BSD-3-Clause
#include "ReferenceResolutionSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace timecritical
{
namespace
{
struct View
{
  const ResolutionProblem& P;

  double Lo(std::size_t i) const
  {
    const double lo = this->P.MinResolution ? this->P.MinResolution[i] : 0.0;
    return std::isfinite(lo) ? std::min(1.0, std::max(ResolutionProblem::TinyResolution, lo))
                             : ResolutionProblem::TinyResolution;
  }
  double C(std::size_t i) const
  {
    const double c = this->P.Weight[i];
    return std::isfinite(c) && c > 0.0 ? c : 0.0;
  }
  /// tmax, or -1 for an invalid or zero one (object left at rmin, outside the
  /// problem, as in ActiveSetOptimizer: a zero cost is a failed model).
  double T(std::size_t i) const
  {
    const double t = this->P.MaxTime[i];
    return std::isfinite(t) && t > 0.0 ? t : -1.0;
  }
  /// r_i(lambda); lambda = 0 means no time constraint.
  double At(std::size_t i, double lambda) const
  {
    const double t = this->T(i), c = this->C(i), lo = this->Lo(i);
    if (t < 0.0 || c == 0.0)
    {
      return lo;
    }
    if (lambda <= 0.0)
    {
      return 1.0;
    }
    const double r = std::pow(c / (lambda * t), 1.0 / (this->P.Alpha + 1.0));
    return std::min(1.0, std::max(lo, r));
  }
  double CostAt(double lambda) const
  {
    double cost = 0.0;
    for (std::size_t i = 0; i < this->P.Count; ++i)
    {
      const double t = this->T(i);
      cost += t > 0.0 ? t * this->At(i, lambda) : 0.0;
    }
    return cost;
  }
};
}

ReferenceResolutionSolver::Result ReferenceResolutionSolver::Solve(
  const ResolutionProblem& problem, double* r, int maxIterations)
{
  Result result;
  const std::size_t n = problem.Count;
  const View v{ problem };
  auto finish = [&](double lambda) {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = v.At(i, lambda);
    }
    result.Multiplier = lambda;
    return result;
  };
  auto report = [&]() {
    result.Objective = 0.0;
    result.Cost = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      result.Objective += ResolutionProblem::Term(v.C(i), problem.Alpha, r[i]);
      result.Cost += v.T(i) > 0.0 ? v.T(i) * r[i] : 0.0;
    }
  };
  if (n == 0)
  {
    return result;
  }
  if (!ResolutionProblem::IsValidAlpha(problem.Alpha) || !problem.Weight || !problem.MaxTime)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = v.Lo(i);
    }
    result.Infeasible = true;
    return result;
  }
  const double budget = problem.Budget;
  // Bracket: at lambda = hi every object is at rmin, at lambda = 0 at 1.
  double lowCost = 0.0, hi = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double t = v.T(i);
    if (t > 0.0)
    {
      lowCost += t * v.Lo(i);
      hi = std::max(hi, v.C(i) * std::pow(v.Lo(i), -(problem.Alpha + 1.0)) / t);
    }
  }
  if (!(lowCost <= budget))
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = v.Lo(i);
    }
    result.Infeasible = true;
    report();
    return result;
  }
  if (v.CostAt(0.0) <= budget)
  {
    result.Unconstrained = true;
    finish(0.0);
    report();
    return result;
  }
  double lo = hi;
  while (v.CostAt(lo) <= budget && lo > 1e-300)
  {
    lo *= 0.5;
    ++result.Iterations;
  }
  // cost(lo) > budget >= cost(hi)
  for (; result.Iterations < maxIterations && hi > lo * (1.0 + 1e-15); ++result.Iterations)
  {
    const double mid = std::sqrt(lo * hi);
    if (!(mid > lo && mid < hi))
    {
      break;
    }
    (v.CostAt(mid) <= budget ? hi : lo) = mid;
  }
  finish(hi);

  // Polish: on the linear piece of hi, the interior objects satisfy
  // sum tmax_i (c_i / (lambda tmax_i))^gamma = budget - clamped cost.
  const double gamma = 1.0 / (problem.Alpha + 1.0);
  double clamped = 0.0, interior = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double t = v.T(i);
    if (!(t > 0.0))
    {
      continue;
    }
    const double free = v.C(i) > 0.0 ? std::pow(v.C(i) / (hi * t), gamma) : 0.0;
    if (free > v.Lo(i) && free < 1.0)
    {
      interior += t * std::pow(v.C(i) / t, gamma);
    }
    else
    {
      clamped += t * r[i];
    }
  }
  if (interior > 0.0 && budget > clamped)
  {
    const double lambda = std::pow((budget - clamped) / interior, -1.0 / gamma);
    bool consistent = std::isfinite(lambda) && lambda > 0.0;
    double cost = 0.0;
    for (std::size_t i = 0; i < n && consistent; ++i)
    {
      const double t = v.T(i);
      if (t > 0.0)
      {
        const double before = v.C(i) > 0.0 ? std::pow(v.C(i) / (hi * t), gamma) : 0.0;
        const double after = v.C(i) > 0.0 ? std::pow(v.C(i) / (lambda * t), gamma) : 0.0;
        const bool inBefore = before > v.Lo(i) && before < 1.0;
        const bool inAfter = after > v.Lo(i) && after < 1.0;
        consistent = inBefore == inAfter;
        cost += t * v.At(i, lambda);
      }
    }
    if (consistent && cost <= budget)
    {
      finish(lambda);
    }
  }
  report();
  return result;
}
}

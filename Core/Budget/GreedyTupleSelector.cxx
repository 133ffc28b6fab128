// SPDX-License-Identifier: BSD-3-Clause
#include "GreedyTupleSelector.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace timecritical
{
namespace
{
/// Benefit gained per cost added from x to y (infinite for a free gain).
double Value(const GreedyTupleSelector::Tuple& x, const GreedyTupleSelector::Tuple& y)
{
  const double cost = y.Cost - x.Cost, benefit = x.Degradation - y.Degradation;
  return cost > 0.0 ? benefit / cost : std::numeric_limits<double>::infinity();
}
}

GreedyTupleSelector::GreedyTupleSelector()
{
  const double levels[] = { 1.0, 0.5, 0.25, 0.12, 0.06, 0.03 };
  this->SetLevels(levels, 6);
}

void GreedyTupleSelector::SetLevels(const double* levels, std::size_t count)
{
  this->Levels.clear();
  for (std::size_t i = 0; i < count; ++i)
  {
    if (std::isfinite(levels[i]) && levels[i] > 0.0 && levels[i] < 1.0)
    {
      this->Levels.push_back(levels[i]);
    }
  }
  this->Levels.push_back(1.0);
  std::sort(this->Levels.begin(), this->Levels.end());
  this->Levels.erase(std::unique(this->Levels.begin(), this->Levels.end()), this->Levels.end());
}

void GreedyTupleSelector::GetCandidates(
  const TupleProblem& p, std::size_t i, bool dropping, std::vector<Tuple>& out) const
{
  out.clear();
  for (std::size_t a = 0; a < p.AlgorithmCount; ++a)
  {
    // The coarsest mesh, then the levels above it (clamped to what pays).
    const double lo = p.Lo(i, a), hi = p.Hi(i, a);
    const int ai = static_cast<int>(a);
    out.push_back({ ai, lo, p.Cost(i, ai, lo), p.Degradation(i, ai, lo) });
    double last = lo;
    for (double level : this->Levels)
    {
      const double r = std::min(hi, std::max(lo, level));
      if (r != last)
      {
        out.push_back({ ai, r, p.Cost(i, ai, r), p.Degradation(i, ai, r) });
        last = r;
      }
    }
  }
  if (dropping)
  {
    if (p.BoxCost)
    {
      out.push_back({ TupleProblem::BoundingBox, 0.0, p.Cost(i, TupleProblem::BoundingBox, 0.0),
        p.Degradation(i, TupleProblem::BoundingBox, 0.0) });
    }
    out.push_back({ TupleProblem::NotDrawn, 0.0, 0.0, p.Degradation(i, TupleProblem::NotDrawn, 0.0) });
  }
}

void GreedyTupleSelector::BuildHull(const TupleProblem& p, std::size_t i, bool dropping,
  const Tuple& base, double remaining)
{
  this->GetCandidates(p, i, dropping, this->Candidates);
  std::sort(this->Candidates.begin(), this->Candidates.end(), [](const Tuple& x, const Tuple& y) {
    return x.Cost != y.Cost ? x.Cost < y.Cost : x.Degradation < y.Degradation;
  });
  const std::size_t first = this->Points.size();
  this->Start[i] = first;
  this->Points.push_back(base);
  for (const Tuple& t : this->Candidates)
  {
    // Worse than the hull's last point, or unable to fit even alone: never taken.
    if (t.Cost < base.Cost || t.Cost - base.Cost > remaining ||
      !(t.Degradation < this->Points.back().Degradation))
    {
      continue;
    }
    // Keep the steps' values decreasing (upper convex hull of (cost, benefit)).
    while (this->Points.size() >= first + 2 &&
      Value(this->Points[this->Points.size() - 2], this->Points.back()) <=
        Value(this->Points.back(), t))
    {
      this->Points.pop_back();
    }
    this->Points.push_back(t);
  }
  for (std::size_t k = first + 1; k < this->Points.size(); ++k)
  {
    const Tuple& x = this->Points[k - 1];
    const Tuple& y = this->Points[k];
    this->Steps.push_back({ static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(k),
      y.Cost - x.Cost, x.Degradation - y.Degradation });
  }
}

TupleProblem::Solution GreedyTupleSelector::Solve(const TupleProblem& p, int* a, double* r)
{
  p.Validate();
  TupleProblem::Solution s;
  const std::size_t n = p.Count;
  if (n == 0)
  {
    return s;
  }
  const bool dropping = p.NeedsDropping();
  s.Dropping = dropping;
  const double budget = p.Budget + 1e-12 * std::abs(p.Budget);
  this->Points.clear();
  this->Steps.clear();
  this->Start.assign(n, 0);
  this->Current.assign(n, 0);
  this->Blocked.assign(n, 0);
  double baseCost = 0.0, baseObjective = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    a[i] = dropping ? TupleProblem::NotDrawn : p.CheapestAlgorithm(i);
    r[i] = a[i] >= 0 ? p.Lo(i, static_cast<std::size_t>(a[i])) : 0.0;
    baseCost += p.Cost(i, a[i], r[i]);
    baseObjective += p.Degradation(i, a[i], r[i]);
  }
  const double remaining0 = budget - baseCost;
  if (remaining0 < 0.0)
  {
    s.Infeasible = true;
    p.Summarize(a, r, s);
    s.LowerBound = s.Objective;
    return s;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const Tuple base{ a[i], r[i], p.Cost(i, a[i], r[i]), p.Degradation(i, a[i], r[i]) };
    this->BuildHull(p, i, dropping, base, remaining0);
    this->Current[i] = this->Start[i];
  }
  std::sort(this->Steps.begin(), this->Steps.end(), [](const Step& x, const Step& y) {
    const double vx = x.Cost > 0.0 ? x.Benefit / x.Cost : std::numeric_limits<double>::infinity();
    const double vy = y.Cost > 0.0 ? y.Benefit / y.Cost : std::numeric_limits<double>::infinity();
    if (vx != vy)
    {
      return vx > vy;
    }
    return x.Object != y.Object ? x.Object < y.Object : x.To < y.To;
  });
  double remaining = remaining0, gain = 0.0, bound = 0.0;
  const Step* split = nullptr;
  for (const Step& step : this->Steps)
  {
    std::size_t& at = this->Current[step.Object];
    if (this->Blocked[step.Object] || at + 1 != step.To)
    {
      continue; // an earlier step of this object did not fit
    }
    if (step.Cost <= remaining)
    {
      at = step.To;
      remaining -= step.Cost;
      gain += step.Benefit;
      continue;
    }
    if (!split)
    {
      split = &step;
      bound = gain + step.Benefit * (remaining / step.Cost); // the linear relaxation
    }
    this->Blocked[step.Object] = 1;
  }
  ++s.Iterations;
  s.LowerBound = baseObjective - (split ? bound : gain);
  // The first step that did not fit, taken alone (every other object at its base).
  const bool alone = split &&
    this->Points[this->Start[split->Object]].Degradation - this->Points[split->To].Degradation >
      gain;
  for (std::size_t i = 0; i < n; ++i)
  {
    std::size_t k = this->Current[i];
    if (alone)
    {
      k = i == split->Object ? split->To : this->Start[i];
    }
    a[i] = this->Points[k].Algorithm;
    r[i] = this->Points[k].Resolution;
  }
  // Value order: no object dropped while a less valuable, costlier one is
  // drawn (the swap fits: the dropped one's cheapest tuple costs less).
  for (std::size_t swaps = 0; dropping && swaps < n; ++swaps)
  {
    std::size_t i = n, j = n;
    if (!p.FindValueOrderViolation(a, i, j, this->ValueOrder))
    {
      break;
    }
    a[i] = p.CheapestAlgorithm(i);
    r[i] = p.Lo(i, static_cast<std::size_t>(a[i]));
    a[j] = TupleProblem::NotDrawn;
    r[j] = 0.0;
    ++s.Iterations;
  }
  if (dropping && p.StrictValueOrder && p.ImposeStrictValueOrder(a, this->ValueOrder) > 0)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      // Those drawn now start at their coarsest; those dropped draw nothing.
      r[i] = a[i] == TupleProblem::NotDrawn ? 0.0
        : (a[i] >= 0 && r[i] == 0.0 ? p.Lo(i, static_cast<std::size_t>(a[i])) : r[i]);
    }
  }
  p.Summarize(a, r, s);
  return s;
}
}

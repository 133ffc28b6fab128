// SPDX-License-Identifier: BSD-3-Clause
#include "TupleOptimizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace timecritical
{
namespace
{
/// x^(1 / (alpha + 1)), with the exponents of eq. 10 and Funkhouser's m = 3 without pow().
double Root(double x, double alpha)
{
  if (alpha == 1.0)
  {
    return std::sqrt(x);
  }
  if (alpha == 2.0)
  {
    return std::cbrt(x);
  }
  if (alpha == -0.5)
  {
    return x * x;
  }
  if (alpha == 3.0)
  {
    return std::sqrt(std::sqrt(x));
  }
  return std::pow(x, 1.0 / (alpha + 1.0));
}

/// Geometric midpoint of a bracket of positive multipliers (arithmetic when close).
double Middle(double lo, double hi)
{
  return hi > 4.0 * lo ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * (lo + hi);
}
}

TupleOptimizer::TupleOptimizer(const Options& options)
  : Opts(options)
{
}

double TupleOptimizer::TupleResolution(std::size_t i, std::size_t a, double lambda) const
{
  const TupleProblem& p = *this->P;
  const std::size_t k = i * p.AlgorithmCount + a;
  const double c = p.Weight[k], t = p.MaxTime[k];
  const double lo = p.Lo(i, a), hi = p.Hi(i, a);
  if (!(t > 0.0 && c > 0.0))
  {
    return lo;
  }
  const double r = lambda > 0.0 ? std::min(hi, std::max(lo, Root(c / (lambda * t), p.Alpha[a]))) : hi;
  return std::isfinite(r) ? r : (lambda > 0.0 ? lo : hi);
}

double TupleOptimizer::Best(std::size_t i, double lambda, int& bestA, double& bestR) const
{
  const TupleProblem& p = *this->P;
  double best = std::numeric_limits<double>::infinity(), bestCost = best;
  auto offer = [&](int a, double r) {
    const double cost = p.Cost(i, a, r);
    const double value = p.Degradation(i, a, r) + lambda * cost;
    if (value < best || (value == best && cost < bestCost))
    {
      best = value;
      bestCost = cost;
      bestA = a;
      bestR = r;
    }
  };
  for (std::size_t a = 0; a < p.AlgorithmCount; ++a)
  {
    offer(static_cast<int>(a), this->TupleResolution(i, a, lambda));
  }
  if (this->Drop)
  {
    if (p.BoxCost)
    {
      offer(TupleProblem::BoundingBox, 0.0);
    }
    offer(TupleProblem::NotDrawn, 0.0);
  }
  return best;
}

double TupleOptimizer::Sweep(double lambda, int* a, double* r, double& lagrangian) const
{
  double cost = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < this->P->Count; ++i)
  {
    sum += this->Best(i, lambda, a[i], r[i]);
    cost += this->P->Cost(i, a[i], r[i]);
  }
  lagrangian = sum - lambda * this->P->Budget;
  return cost;
}

void TupleOptimizer::Cheapest(int* a, double* r) const
{
  for (std::size_t i = 0; i < this->P->Count; ++i)
  {
    a[i] = this->P->CheapestAlgorithm(i);
    r[i] = this->P->Lo(i, static_cast<std::size_t>(a[i]));
  }
}

bool TupleOptimizer::SolveResolutions(const int* a, double* r, int& iterations)
{
  // The convex eq. 11 over the drawn objects whose resolution matters, with
  // per-object exponents: r_i(mu) = clamp((c_i / (mu T_i))^(1 / (alpha_i + 1)), lo_i, hi_i),
  // cost non-increasing in mu; bisection on log(mu), answer on the feasible side.
  const TupleProblem& p = *this->P;
  const std::size_t n = p.Count;
  double fixed = 0.0, low = 0.0, high = 0.0;
  double muLow = std::numeric_limits<double>::infinity(), muHigh = 0.0;
  auto variable = [&](std::size_t i) {
    if (a[i] < 0)
    {
      return false;
    }
    const std::size_t k = i * p.AlgorithmCount + static_cast<std::size_t>(a[i]);
    return p.MaxTime[k] > 0.0 && p.Weight[k] > 0.0 && p.Hi(i, static_cast<std::size_t>(a[i])) >
      p.Lo(i, static_cast<std::size_t>(a[i]));
  };
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!variable(i))
    {
      r[i] = a[i] < 0 ? 0.0 : p.Lo(i, static_cast<std::size_t>(a[i]));
      fixed += p.Cost(i, a[i], r[i]);
      continue;
    }
    const std::size_t ai = static_cast<std::size_t>(a[i]);
    const std::size_t k = i * p.AlgorithmCount + ai;
    const double t = p.MaxTime[k], c = p.Weight[k], lo = p.Lo(i, ai), hi = p.Hi(i, ai);
    fixed += p.FixedCost ? p.FixedCost[k] : 0.0;
    low += t * lo;
    high += t * hi;
    const double e = p.Alpha[ai] + 1.0;
    muHigh = std::max(muHigh, c / (t * std::pow(lo, e))); // every object at lo
    muLow = std::min(muLow, c / (t * std::pow(hi, e)));   // every object at hi
  }
  auto at = [&](double mu, double* out) {
    double cost = fixed;
    for (std::size_t i = 0; i < n; ++i)
    {
      if (variable(i))
      {
        const std::size_t ai = static_cast<std::size_t>(a[i]);
        const std::size_t k = i * p.AlgorithmCount + ai;
        const double t = p.MaxTime[k];
        const double x = Root(p.Weight[k] / (mu * t), p.Alpha[ai]);
        const double ri = std::min(p.Hi(i, ai), std::max(p.Lo(i, ai), x));
        cost += t * ri;
        if (out)
        {
          out[i] = ri;
        }
      }
    }
    return cost;
  };
  if (fixed + low > this->Budget)
  {
    return false;
  }
  if (fixed + high <= this->Budget)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = variable(i) ? p.Hi(i, static_cast<std::size_t>(a[i])) : r[i];
    }
    return true;
  }
  // cost(muLow) = high > budget >= cost(muHigh) = low.
  muLow = std::max(muLow, std::numeric_limits<double>::min());
  for (int k = 0; k < 400 && muHigh > muLow * (1.0 + 1e-13); ++k, ++iterations)
  {
    const double mid = Middle(muLow, muHigh);
    if (!(mid > muLow && mid < muHigh))
    {
      break;
    }
    (at(mid, nullptr) <= this->Budget ? muHigh : muLow) = mid;
  }
  at(muHigh, r);
  return true;
}

TupleProblem::Solution TupleOptimizer::Solve(const TupleProblem& problem, int* a, double* r)
{
  problem.Validate();
  TupleProblem::Solution s;
  const std::size_t n = problem.Count;
  if (n == 0)
  {
    return s;
  }
  this->P = &problem;
  if (this->LowA.size() < n)
  {
    this->LowA.resize(n);
    this->TryA.resize(n);
    this->LowR.resize(n);
    this->TryR.resize(n);
  }
  this->Drop = problem.NeedsDropping();
  this->Budget = problem.Budget + 1e-12 * std::abs(problem.Budget);
  s.Dropping = this->Drop;
  auto finish = [&]() {
    problem.Summarize(a, r, s);
    this->P = nullptr;
    return s;
  };
  double bound = -std::numeric_limits<double>::infinity(), lagrangian = 0.0;
  // Over budget even at the cheapest choice allowed: the cheapest tuples
  // (dropping off), or nothing drawn (dropping on and a negative budget).
  if (!this->Drop)
  {
    this->Cheapest(a, r);
    if (problem.TotalCost(a, r) > this->Budget)
    {
      s.Infeasible = true;
      return finish();
    }
  }
  if (this->Drop && this->Budget < 0.0)
  {
    std::fill(a, a + n, TupleProblem::NotDrawn);
    std::fill(r, r + n, 0.0);
    s.Infeasible = true;
    return finish();
  }
  ++s.Iterations;
  if (this->Sweep(0.0, a, r, lagrangian) <= this->Budget)
  {
    s.LowerBound = lagrangian; // the unconstrained optimum
    return finish();
  }
  // Bracket [low, high]: the choice at low exceeds the budget, at high fits.
  double low = 0.0, high = 1.0;
  std::copy(a, a + n, this->LowA.begin());
  std::copy(r, r + n, this->LowR.begin());
  bool fits = false;
  for (int k = 0; k < 600 && std::isfinite(high); ++k, high *= 16.0)
  {
    ++s.Iterations;
    fits = this->Sweep(high, this->TryA.data(), this->TryR.data(), lagrangian) <= this->Budget;
    bound = std::max(bound, lagrangian);
    if (fits)
    {
      break;
    }
    low = high;
    std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n), this->LowA.begin());
    std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n), this->LowR.begin());
  }
  if (!fits)
  {
    this->Cheapest(a, r); // fits (checked above); only an overflow of the multiplier gets here
    s.LowerBound = bound;
    return finish();
  }
  std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n), a);
  std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n), r);
  while (low == 0.0 && high > 1e-300)
  {
    ++s.Iterations;
    const double lower = high / 16.0;
    if (this->Sweep(lower, this->TryA.data(), this->TryR.data(), lagrangian) > this->Budget)
    {
      low = lower;
      std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n), this->LowA.begin());
      std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n), this->LowR.begin());
    }
    else
    {
      high = lower;
      std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n), a);
      std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n), r);
    }
    bound = std::max(bound, lagrangian);
  }
  for (int k = 0; k < this->Opts.MaxIterations && high > low * (1.0 + this->Opts.Tolerance); ++k)
  {
    const double mid = Middle(low, high);
    if (!(mid > low && mid < high))
    {
      break;
    }
    ++s.Iterations;
    const bool ok = this->Sweep(mid, this->TryA.data(), this->TryR.data(), lagrangian) <= this->Budget;
    bound = std::max(bound, lagrangian);
    (ok ? high : low) = mid;
    std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n),
      ok ? a : this->LowA.data());
    std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n),
      ok ? r : this->LowR.data());
  }
  s.Multiplier = high;
  s.LowerBound = bound;
  this->Repair(a, r, high, s);
  return finish();
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Shared helpers of the BudgetCore tests and benchmark: random problems
// shaped like the W1 walkthrough, an independent KKT check, and an allocation
// counter (the test that uses it defines TIMECRITICAL_COUNT_ALLOCATIONS in
// exactly one translation unit).
#ifndef timecritical_BudgetTestUtilities_h
#define timecritical_BudgetTestUtilities_h

#include "ResolutionProblem.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

namespace timecritical_test
{
/// An owning problem: n objects with W1-like sizes (cow-sized meshes,
/// coverages from a few pixels to a quarter of a 512^2 view).
struct RandomProblem
{
  std::vector<double> Weight, MaxTime, MinResolution, Pixels, Triangles;
  double Alpha = 1.0;
  double Budget = 0.0;

  timecritical::ResolutionProblem View() const
  {
    timecritical::ResolutionProblem p;
    p.Count = this->Weight.size();
    p.Weight = this->Weight.data();
    p.MaxTime = this->MaxTime.data();
    p.MinResolution = this->MinResolution.data();
    p.Alpha = this->Alpha;
    p.Budget = this->Budget;
    return p;
  }

  double CostAtMin() const
  {
    double s = 0.0;
    for (std::size_t i = 0; i < this->MaxTime.size(); ++i)
    {
      s += this->MaxTime[i] * this->MinResolution[i];
    }
    return s;
  }
  double CostAtFull() const
  {
    double s = 0.0;
    for (double t : this->MaxTime)
    {
      s += t;
    }
    return s;
  }
  /// Budget = cost(rmin) + fraction * (cost(1) - cost(rmin)).
  void SetBudgetFraction(double fraction)
  {
    this->Budget = this->CostAtMin() + fraction * (this->CostAtFull() - this->CostAtMin());
  }
};

/// Weights follow eq. 10's family for alpha in {1, 2, -1/2}, Hitchner's otherwise,
/// times an interest factor in [0.05, 1].
inline RandomProblem MakeRandomProblem(
  std::size_t n, double alpha, unsigned seed, double budgetFraction = 0.3)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomProblem p;
  p.Alpha = alpha;
  const double tTri = 2e-6, tPix = 5e-9;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double triangles = std::exp(std::log(500.0) + unit(rng) * std::log(40.0));
    const double pixels = std::exp(std::log(4.0) + unit(rng) * std::log(16000.0));
    const double interest = 0.05 + 0.95 * unit(rng);
    double w = pixels / triangles;
    if (alpha == 2.0)
    {
      w = pixels / (triangles * triangles);
    }
    else if (alpha == -0.5)
    {
      w = pixels * std::sqrt(triangles);
    }
    p.Triangles.push_back(triangles);
    p.Pixels.push_back(pixels);
    p.Weight.push_back(w * interest);
    p.MaxTime.push_back(tTri * triangles);
    const double coarsest = 4.0 / triangles;
    p.MinResolution.push_back(
      std::min(1.0, std::max(coarsest, tPix * pixels / (tTri * triangles))));
  }
  p.SetBudgetFraction(budgetFraction);
  return p;
}

/// Multiply every weight by a factor in [1 - amount, 1 + amount] (a camera move).
inline void Perturb(RandomProblem& p, double amount, unsigned seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-amount, amount);
  for (double& c : p.Weight)
  {
    c *= 1.0 + unit(rng);
  }
}

/// The optimizer benchmark's frame-to-frame change (a camera move): weights
/// by up to 10 %, the budget's free part by up to 5 % either way.
inline RandomProblem NextFrame(const RandomProblem& base, unsigned seed)
{
  RandomProblem p = base;
  Perturb(p, 0.10, seed);
  const double s = 1.0 + 0.05 * std::sin(1.7 * seed);
  p.Budget = p.CostAtMin() + s * (base.Budget - base.CostAtMin());
  return p;
}

/// KKT conditions of eq. 11 checked from scratch (pow() on the raw inputs).
struct KKTCheck
{
  double Lambda = 0.0;        ///< from the free variables (or a bound interval)
  double FreeDeviation = 0.0; ///< max |rho_i / lambda - 1| over free variables
  double BoundViolation = 0.0; ///< max relative violation of the bound multipliers' sign
  double Complementarity = 0.0; ///< |cost - budget| / budget when lambda > 0
  double PrimalViolation = 0.0; ///< max(0, cost - budget) / budget and bound violations
  std::size_t Free = 0, Lower = 0, Upper = 0;

  double Worst() const
  {
    return std::max({ this->FreeDeviation, this->BoundViolation, this->Complementarity,
      this->PrimalViolation });
  }
};

inline KKTCheck CheckKKT(const timecritical::ResolutionProblem& p, const double* r,
  double boundTolerance = 1e-9)
{
  KKTCheck k;
  const double a1 = p.Alpha + 1.0;
  // rho_i(r) = -f_i'(r) / tmax_i = c_i r^-(alpha+1) / tmax_i
  auto rho = [&](std::size_t i, double x) { return p.Weight[i] * std::pow(x, -a1) / p.MaxTime[i]; };
  double cost = 0.0;
  double logSum = 0.0;
  double lowerMax = 0.0, upperMin = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.Count; ++i)
  {
    const double lo = p.MinResolution[i];
    cost += p.MaxTime[i] * r[i];
    k.PrimalViolation = std::max(k.PrimalViolation, std::max(lo - r[i], r[i] - 1.0));
    if (r[i] <= lo * (1.0 + boundTolerance))
    {
      ++k.Lower;
      if (p.Weight[i] > 0.0)
      {
        lowerMax = std::max(lowerMax, rho(i, lo));
      }
    }
    else if (r[i] >= 1.0 - boundTolerance)
    {
      ++k.Upper;
      upperMin = std::min(upperMin, rho(i, 1.0));
    }
    else
    {
      ++k.Free;
      logSum += std::log(rho(i, r[i]));
    }
  }
  if (k.Free > 0)
  {
    k.Lambda = std::exp(logSum / static_cast<double>(k.Free));
    for (std::size_t i = 0; i < p.Count; ++i)
    {
      const double lo = p.MinResolution[i];
      if (r[i] > lo * (1.0 + boundTolerance) && r[i] < 1.0 - boundTolerance)
      {
        k.FreeDeviation = std::max(k.FreeDeviation, std::abs(rho(i, r[i]) / k.Lambda - 1.0));
      }
    }
  }
  else
  {
    k.Lambda = std::isfinite(upperMin) ? std::min(upperMin, std::max(lowerMax, 0.0)) : lowerMax;
  }
  // Lower-bound multiplier >= 0  <=>  rho_i(rmin) <= lambda; upper  <=>  rho_i(1) >= lambda.
  if (k.Lambda > 0.0)
  {
    k.BoundViolation = std::max(k.BoundViolation, lowerMax / k.Lambda - 1.0);
    if (std::isfinite(upperMin))
    {
      k.BoundViolation = std::max(k.BoundViolation, 1.0 - upperMin / k.Lambda);
    }
  }
  else if (k.Lower > 0 && lowerMax > 0.0)
  {
    k.BoundViolation = 1.0; // slack time yet an object held at its minimum
  }
  const double violation = (cost - p.Budget) / p.Budget;
  k.PrimalViolation = std::max(k.PrimalViolation, violation);
  if (k.Lambda > 0.0 && k.Free + k.Upper + k.Lower > k.Upper)
  {
    k.Complementarity = std::abs(violation);
  }
  return k;
}
}

#endif

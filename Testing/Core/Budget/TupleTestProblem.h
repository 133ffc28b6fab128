// SPDX-License-Identifier: BSD-3-Clause
// Shared by the tuple tests: an owning TupleProblem built from random
// objects through AlgorithmCostModel and AlgorithmDegradation (llvmpipe-like
// coefficients per algorithm), and an exhaustive reference solver that
// tries every assignment of algorithms (and box / not drawn) and solves the
// resolutions of each exactly, written apart from TupleOptimizer.
#ifndef timecritical_TupleTestProblem_h
#define timecritical_TupleTestProblem_h

#include "AlgorithmCostModel.h"
#include "AlgorithmDegradation.h"
#include "TupleProblem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace timecritical_test
{
struct OwnedTupleProblem
{
  std::size_t N = 0, A = 0;
  std::vector<double> Alpha, Weight, Offset, MaxTime, FixedCost, Lo, Hi;
  std::vector<double> BoxCost, BoxDegradation, DropDegradation;
  std::vector<double> Pixels; ///< per object, for the dropping tests
  bool AllowDrop = false, WithBox = true;
  double Budget = 0.0;

  timecritical::TupleProblem View() const
  {
    timecritical::TupleProblem p;
    p.Count = this->N;
    p.AlgorithmCount = this->A;
    p.Alpha = this->Alpha.data();
    p.Weight = this->Weight.data();
    p.Offset = this->Offset.data();
    p.MaxTime = this->MaxTime.data();
    p.FixedCost = this->FixedCost.data();
    p.MinResolution = this->Lo.data();
    p.MaxResolution = this->Hi.data();
    p.BoxCost = this->WithBox ? this->BoxCost.data() : nullptr;
    p.BoxDegradation = this->BoxDegradation.data();
    p.DropDegradation = this->DropDegradation.data();
    p.AllowDrop = this->AllowDrop;
    p.Budget = this->Budget;
    return p;
  }
  /// Cost of every object at its cheapest tuple, and at its most expensive (r = hi).
  double CheapestCost() const
  {
    const timecritical::TupleProblem p = this->View();
    double s = 0.0;
    for (std::size_t i = 0; i < this->N; ++i)
    {
      s += p.Cost(i, p.CheapestAlgorithm(i), 0.0);
    }
    return s;
  }
  double FullCost() const
  {
    const timecritical::TupleProblem p = this->View();
    double s = 0.0;
    for (std::size_t i = 0; i < this->N; ++i)
    {
      double most = 0.0;
      for (std::size_t a = 0; a < this->A; ++a)
      {
        most = std::max(most, p.Cost(i, static_cast<int>(a), p.Hi(i, a)));
      }
      s += most;
    }
    return s;
  }
};

inline timecritical::AlgorithmCostModel MakeTestCostModel(std::size_t algorithms, bool additive)
{
  using timecritical::RenderingAlgorithm;
  timecritical::AlgorithmCostModel model;
  model.SetPixelMode(additive ? timecritical::FrameCostModel::PixelMode::Additive
                              : timecritical::FrameCostModel::PixelMode::Overlapped);
  // Per-fragment lighting costs most per pixel, unlit least (llvmpipe-like).
  const timecritical::AlgorithmCostModel::Coefficients c[4] = {
    { 3e-4, 2e-7, 0.0, 4e-8 },   // per-fragment lit
    { 3e-4, 2e-7, 1e-7, 1.5e-8 }, // per-vertex lit
    { 3e-4, 2.4e-7, 0.0, 1e-8 },  // flat (unshared vertices)
    { 2e-4, 1.5e-7, 0.0, 5e-9 }   // unlit
  };
  for (std::size_t a = 0; a < algorithms && a < 4; ++a)
  {
    model.SetAlgorithm(static_cast<RenderingAlgorithm>(a), c[a]);
  }
  return model;
}

/**
 * n random objects (W1-like sizes), the first `algorithms` algorithms,
 * Funkhouser's family; budget = cheapest + fraction (full - cheapest), so a
 * negative fraction is below the cheapest tuples.
 */
inline OwnedTupleProblem MakeRandomTupleProblem(std::size_t n, std::size_t algorithms,
  unsigned seed, double fraction, bool additive = false, bool measured = false)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto model = MakeTestCostModel(algorithms, additive);
  timecritical::AlgorithmDegradation degradation(measured
      ? timecritical::AlgorithmDegradation::Family::Measured
      : timecritical::AlgorithmDegradation::Family::Funkhouser);
  const double errors[4] = { 0.0, 0.02, 0.08, 0.3 };
  for (std::size_t a = 0; a < 4; ++a)
  {
    degradation.SetMeasuredError(static_cast<timecritical::RenderingAlgorithm>(a), errors[a]);
  }
  OwnedTupleProblem p;
  p.N = n;
  p.A = model.GetAlgorithmCount();
  std::vector<double> triangles(n), vertices(n), coarsest(n);
  std::vector<timecritical::AlgorithmDegradation::ObjectInput> objects(n);
  p.Pixels.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    triangles[i] = std::exp(std::log(500.0) + unit(rng) * std::log(40.0));
    vertices[i] = triangles[i] * (0.45 + 0.1 * unit(rng));
    coarsest[i] = 50.0 / triangles[i];
    p.Pixels[i] = std::exp(std::log(4.0) + unit(rng) * std::log(16000.0));
    objects[i].Interest = 0.05 + 0.95 * unit(rng);
    objects[i].Pixels = p.Pixels[i];
    objects[i].MaxTriangles = triangles[i];
    objects[i].MaxVertices = vertices[i];
    objects[i].GeometricWeight = objects[i].Interest * p.Pixels[i] / triangles[i]; // Hitchner
  }
  const std::size_t k = n * p.A;
  p.Alpha.resize(p.A);
  p.Weight.resize(k);
  p.Offset.resize(k);
  p.MaxTime.resize(k);
  p.FixedCost.resize(k);
  p.Lo.resize(k);
  p.Hi.resize(k);
  p.BoxCost.assign(n, 2e-6);
  p.BoxDegradation.resize(n);
  p.DropDegradation.resize(n);
  std::vector<timecritical::RenderingAlgorithm> set;
  for (std::size_t a = 0; a < p.A; ++a)
  {
    set.push_back(model.GetAlgorithm(a));
  }
  model.Evaluate(n, triangles.data(), vertices.data(), p.Pixels.data(), coarsest.data(),
    p.MaxTime.data(), p.FixedCost.data(), p.Lo.data());
  degradation.Evaluate(n, objects.data(), set.data(), p.A, p.Alpha.data(), p.Weight.data(),
    p.Offset.data(), p.Hi.data(), p.BoxDegradation.data(), p.DropDegradation.data());
  p.AllowDrop = true;
  const double cheapest = p.CheapestCost(), full = p.FullCost();
  p.Budget = fraction >= 0.0 ? cheapest + fraction * (full - cheapest) : cheapest * (1.0 + fraction);
  return p;
}

/// The optimal resolutions of fixed algorithms (bisection on the multiplier); false if they do not fit.
inline bool ExactResolutions(
  const timecritical::TupleProblem& p, const std::vector<int>& a, std::vector<double>& r)
{
  const std::size_t n = p.Count;
  auto resolution = [&](std::size_t i, double mu) {
    if (a[i] < 0)
    {
      return 0.0;
    }
    const std::size_t k = i * p.AlgorithmCount + static_cast<std::size_t>(a[i]);
    const double lo = p.Lo(i, static_cast<std::size_t>(a[i]));
    const double hi = p.Hi(i, static_cast<std::size_t>(a[i]));
    if (!(p.MaxTime[k] > 0.0 && p.Weight[k] > 0.0))
    {
      return lo;
    }
    if (mu <= 0.0)
    {
      return hi;
    }
    const double x =
      std::pow(p.Weight[k] / (mu * p.MaxTime[k]), 1.0 / (p.Alpha[a[i]] + 1.0));
    return std::min(hi, std::max(lo, x));
  };
  auto cost = [&](double mu) {
    double c = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = resolution(i, mu);
      c += p.Cost(i, a[i], r[i]);
    }
    return c;
  };
  const double budget = p.Budget + 1e-12 * std::abs(p.Budget);
  if (cost(0.0) <= budget)
  {
    return true;
  }
  if (cost(1e300) > budget)
  {
    return false;
  }
  double lo = -700.0, hi = 690.0; // log(mu)
  for (int k = 0; k < 200; ++k)
  {
    const double mid = 0.5 * (lo + hi);
    (cost(std::exp(mid)) <= budget ? hi : lo) = mid;
  }
  cost(std::exp(hi));
  return true;
}

/// Smallest objective over every assignment (options: the algorithms, and box / not drawn when dropping).
inline double ExhaustiveOptimum(const timecritical::TupleProblem& p, std::vector<int>* bestA = nullptr)
{
  const std::size_t n = p.Count;
  std::vector<int> options;
  for (std::size_t a = 0; a < p.AlgorithmCount; ++a)
  {
    options.push_back(static_cast<int>(a));
  }
  if (p.NeedsDropping())
  {
    if (p.BoxCost)
    {
      options.push_back(timecritical::TupleProblem::BoundingBox);
    }
    options.push_back(timecritical::TupleProblem::NotDrawn);
  }
  std::vector<int> a(n, 0);
  std::vector<double> r(n);
  std::vector<std::size_t> digit(n, 0);
  double best = std::numeric_limits<double>::infinity();
  while (true)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      a[i] = options[digit[i]];
    }
    if (ExactResolutions(p, a, r))
    {
      const double f = p.Objective(a.data(), r.data());
      if (f < best)
      {
        best = f;
        if (bestA)
        {
          *bestA = a;
        }
      }
    }
    std::size_t i = 0;
    while (i < n && ++digit[i] == options.size())
    {
      digit[i++] = 0;
    }
    if (i == n)
    {
      break;
    }
  }
  return best;
}
}

#endif

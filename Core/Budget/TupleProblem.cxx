// SPDX-License-Identifier: BSD-3-Clause
#include "TupleProblem.h"

#include "ResolutionProblem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace timecritical
{
namespace
{
[[noreturn]] void Fail(const std::string& what)
{
  throw std::invalid_argument("TupleProblem: " + what);
}

void CheckNonNegative(const double* values, std::size_t count, const char* name)
{
  for (std::size_t k = 0; values && k < count; ++k)
  {
    if (!std::isfinite(values[k]) || values[k] < 0.0)
    {
      Fail(std::string(name) + "[" + std::to_string(k) + "] = " + std::to_string(values[k]) +
        " is negative or not finite");
    }
  }
}

void CheckFinite(const double* values, std::size_t count, const char* name)
{
  for (std::size_t k = 0; values && k < count; ++k)
  {
    if (!std::isfinite(values[k]))
    {
      Fail(std::string(name) + "[" + std::to_string(k) + "] is not finite");
    }
  }
}

void CheckResolution(const double* values, std::size_t count, const char* name)
{
  for (std::size_t k = 0; values && k < count; ++k)
  {
    if (!(values[k] > 0.0 && values[k] <= 1.0)) // also NaN
    {
      Fail(std::string(name) + "[" + std::to_string(k) + "] = " + std::to_string(values[k]) +
        " is outside (0, 1]");
    }
  }
}
}

void TupleProblem::Validate() const
{
  if (this->Count == 0)
  {
    return;
  }
  if (this->AlgorithmCount == 0)
  {
    Fail("the set of rendering algorithms is empty");
  }
  if (!this->Alpha || !this->Weight || !this->MaxTime)
  {
    Fail("Alpha, Weight and MaxTime are required");
  }
  if (this->BoxCost && !this->BoxDegradation)
  {
    Fail("BoxCost is given without BoxDegradation");
  }
  if (this->AllowDrop && !this->DropDegradation)
  {
    Fail("AllowDrop is set without DropDegradation");
  }
  if (std::isnan(this->Budget))
  {
    Fail("the budget is NaN");
  }
  for (std::size_t a = 0; a < this->AlgorithmCount; ++a)
  {
    if (!ResolutionProblem::IsValidAlpha(this->Alpha[a]))
    {
      Fail("Alpha[" + std::to_string(a) + "] = " + std::to_string(this->Alpha[a]) +
        " is not > -1, != 0 and finite");
    }
  }
  const std::size_t tuples = this->Count * this->AlgorithmCount;
  CheckNonNegative(this->Weight, tuples, "Weight");
  CheckNonNegative(this->MaxTime, tuples, "MaxTime");
  CheckNonNegative(this->FixedCost, tuples, "FixedCost");
  CheckFinite(this->Offset, tuples, "Offset");
  CheckResolution(this->MinResolution, tuples, "MinResolution");
  CheckResolution(this->MaxResolution, tuples, "MaxResolution");
  CheckNonNegative(this->BoxCost, this->Count, "BoxCost");
  CheckFinite(this->BoxDegradation, this->Count, "BoxDegradation");
  CheckFinite(this->DropDegradation, this->Count, "DropDegradation");
}

double TupleProblem::Lo(std::size_t i, std::size_t a) const
{
  return this->MinResolution
    ? std::max(TinyResolution, this->MinResolution[i * this->AlgorithmCount + a])
    : TinyResolution;
}

double TupleProblem::Hi(std::size_t i, std::size_t a) const
{
  const double hi = this->MaxResolution ? this->MaxResolution[i * this->AlgorithmCount + a] : 1.0;
  return std::max(this->Lo(i, a), hi);
}

double TupleProblem::Degradation(std::size_t i, int a, double r) const
{
  if (a == NotDrawn)
  {
    return this->DropDegradation ? this->DropDegradation[i] : 0.0;
  }
  if (a == BoundingBox)
  {
    return this->BoxDegradation ? this->BoxDegradation[i] : 0.0;
  }
  const std::size_t k = i * this->AlgorithmCount + static_cast<std::size_t>(a);
  const double hi = this->MaxResolution ? this->MaxResolution[k] : 1.0;
  const double effective = std::min(std::max(r, this->Lo(i, static_cast<std::size_t>(a))), hi);
  const double offset = this->Offset ? this->Offset[k] : 0.0;
  return ResolutionProblem::Term(this->Weight[k], this->Alpha[a], effective) + offset;
}

double TupleProblem::Cost(std::size_t i, int a, double r) const
{
  if (a == NotDrawn)
  {
    return 0.0;
  }
  if (a == BoundingBox)
  {
    return this->BoxCost ? this->BoxCost[i] : 0.0;
  }
  const std::size_t k = i * this->AlgorithmCount + static_cast<std::size_t>(a);
  const double fixed = this->FixedCost ? this->FixedCost[k] : 0.0;
  return fixed + this->MaxTime[k] * std::max(r, this->Lo(i, static_cast<std::size_t>(a)));
}

int TupleProblem::CheapestAlgorithm(std::size_t i) const
{
  int best = 0;
  double bestCost = this->Cost(i, 0, 0.0), bestDegradation = this->Degradation(i, 0, 0.0);
  for (int a = 1; a < static_cast<int>(this->AlgorithmCount); ++a)
  {
    const double cost = this->Cost(i, a, 0.0), degradation = this->Degradation(i, a, 0.0);
    if (cost < bestCost || (cost == bestCost && degradation < bestDegradation))
    {
      best = a;
      bestCost = cost;
      bestDegradation = degradation;
    }
  }
  return best;
}

double TupleProblem::Objective(const int* algorithms, const double* r) const
{
  double f = 0.0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    f += this->Degradation(i, algorithms[i], r[i]);
  }
  return f;
}

double TupleProblem::TotalCost(const int* algorithms, const double* r) const
{
  double cost = 0.0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    cost += this->Cost(i, algorithms[i], r[i]);
  }
  return cost;
}

bool TupleProblem::NeedsDropping() const
{
  if (!this->AllowDrop || this->Count == 0)
  {
    return false;
  }
  double cheapest = 0.0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    cheapest += this->Cost(i, this->CheapestAlgorithm(i), 0.0);
  }
  return cheapest > this->Budget + 1e-12 * std::abs(this->Budget);
}

void TupleProblem::Summarize(const int* algorithms, const double* r, Solution& s) const
{
  s.Objective = this->Objective(algorithms, r);
  s.Cost = this->TotalCost(algorithms, r);
  s.Boxed = 0;
  s.Dropped = 0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    s.Boxed += algorithms[i] == BoundingBox ? 1 : 0;
    s.Dropped += algorithms[i] == NotDrawn ? 1 : 0;
  }
}

bool TupleProblem::FindValueOrderViolation(const int* algorithms, std::size_t& dropped,
  std::size_t& drawn, ValueOrderScratch& scratch) const
{
  if (!this->DropDegradation)
  {
    return false;
  }
  // Drawn objects by value, with the costliest (at its cheapest tuple) of
  // each prefix: a dropped object is out of order when a less valuable drawn
  // one costs more. The arrays keep their capacity from call to call.
  const std::size_t n = this->Count;
  std::vector<double>& cheapest = scratch.Cheapest;
  std::vector<std::size_t>& order = scratch.Order;
  std::vector<std::size_t>& costliest = scratch.Costliest;
  cheapest.resize(n);
  order.clear();
  for (std::size_t j = 0; j < n; ++j)
  {
    cheapest[j] = this->Cost(j, this->CheapestAlgorithm(j), 0.0);
    if (algorithms[j] >= 0)
    {
      order.push_back(j);
    }
  }
  const double* value = this->DropDegradation;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return value[x] != value[y] ? value[x] < value[y] : x < y;
  });
  costliest.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    const std::size_t j = order[k];
    costliest[k] = k > 0 && cheapest[costliest[k - 1]] >= cheapest[j] ? costliest[k - 1] : j;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (algorithms[i] != NotDrawn)
    {
      continue;
    }
    const auto end = std::lower_bound(order.begin(), order.end(), i,
      [&](std::size_t x, std::size_t y) { return value[x] < value[y]; });
    const std::size_t k = static_cast<std::size_t>(end - order.begin());
    if (k > 0 && cheapest[costliest[k - 1]] > cheapest[i])
    {
      dropped = i;
      drawn = costliest[k - 1];
      return true;
    }
  }
  return false;
}

std::size_t TupleProblem::ImposeStrictValueOrder(int* algorithms, ValueOrderScratch& scratch) const
{
  if (!this->DropDegradation)
  {
    return 0;
  }
  // Objects drawn with a mesh or not drawn, by value, most valuable first;
  // `below` is what the drawn ones after the current position take at their
  // cheapest tuples, `tail` the least valuable drawn one not yet dropped.
  const std::size_t n = this->Count;
  std::vector<double>& cheapest = scratch.Cheapest;
  std::vector<std::size_t>& order = scratch.Order;
  cheapest.resize(n);
  order.clear();
  double below = 0.0;
  for (std::size_t j = 0; j < n; ++j)
  {
    if (algorithms[j] >= 0 || algorithms[j] == NotDrawn)
    {
      cheapest[j] = this->Cost(j, this->CheapestAlgorithm(j), 0.0);
      order.push_back(j);
      below += algorithms[j] >= 0 ? cheapest[j] : 0.0;
    }
  }
  const double* value = this->DropDegradation;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return value[x] != value[y] ? value[x] > value[y] : x < y;
  });
  std::size_t changed = 0;
  std::size_t tail = order.size();
  for (std::size_t k = 0; k < order.size() && k < tail; ++k)
  {
    const std::size_t i = order[k];
    if (algorithms[i] >= 0)
    {
      below -= cheapest[i];
      continue;
    }
    if (below < cheapest[i])
    {
      continue; // the less valuable drawn ones could not make room for it
    }
    double freed = 0.0;
    while (freed < cheapest[i] && tail > k + 1)
    {
      const std::size_t j = order[--tail];
      if (algorithms[j] >= 0)
      {
        algorithms[j] = NotDrawn;
        freed += cheapest[j];
        below -= cheapest[j];
        ++changed;
      }
    }
    algorithms[i] = this->CheapestAlgorithm(i);
    ++changed;
  }
  return changed;
}
}

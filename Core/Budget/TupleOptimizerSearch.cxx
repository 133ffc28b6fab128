// SPDX-License-Identifier: BSD-3-Clause
// TupleOptimizer's repair of the relaxation's discrete gap: re-solved
// resolutions, the fill of the time left and the local search.
#include "TupleOptimizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace timecritical
{
void TupleOptimizer::Repair(int* a, double* r, double lambda, TupleProblem::Solution& s)
{
  const TupleProblem& p = *this->P;
  const std::size_t n = p.Count;
  // Step 1: spend the time the jump left on the resolutions of the chosen algorithms.
  double objective = p.Objective(a, r);
  std::copy(a, a + n, this->TryA.begin());
  this->Accept(a, r, this->Evaluate(s.Iterations), objective);
  // Step 2: fill the time left, then re-solve.
  this->Fill(a, r, lambda);
  std::copy(a, a + n, this->TryA.begin());
  const double filled = this->Evaluate(s.Iterations);
  objective = p.Objective(a, r);
  this->Accept(a, r, filled, objective);
  // Steps 3 and 4: the greedy start, the local search on the candidates.
  this->Jumpers.clear();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->LowA[i] != a[i])
    {
      this->Jumpers.push_back(i);
    }
  }
  // Second start: the greedy's assignment (discrete levels, packed by
  // value), its resolutions re-solved; the better one goes on.
  auto proven = [&]() {
    return objective - s.LowerBound <= this->Opts.GapTolerance * std::abs(objective);
  };
  if (this->Opts.GreedyStart && !proven())
  {
    this->Greedy.Solve(p, this->TryA.data(), this->TryR.data());
    this->Accept(a, r, this->Evaluate(s.Iterations), objective);
  }
  if (n <= this->Opts.SearchLimit && !proven())
  {
    this->ChooseCandidates(a, r, lambda);
    this->LocalSearch(a, r, objective, s.Iterations);
    this->Fill(a, r, lambda); // the time a search move may have left
    std::copy(a, a + n, this->TryA.begin());
    const double refilled = this->Evaluate(s.Iterations);
    objective = p.Objective(a, r);
    this->Accept(a, r, refilled, objective);
  }
  if (this->Drop)
  {
    this->KeepValueOrder(a, r, objective, s.Iterations);
  }
}

void TupleOptimizer::OptionsOf(std::vector<int>& out) const
{
  out.clear();
  for (std::size_t a = 0; a < this->P->AlgorithmCount; ++a)
  {
    out.push_back(static_cast<int>(a));
  }
  if (this->Drop)
  {
    if (this->P->BoxCost)
    {
      out.push_back(TupleProblem::BoundingBox);
    }
    out.push_back(TupleProblem::NotDrawn);
  }
}

double TupleOptimizer::Evaluate(int& iterations)
{
  const TupleProblem& p = *this->P;
  if (!this->SolveResolutions(this->TryA.data(), this->TryR.data(), iterations) ||
    // The solve spends Budget to its own rounding; the sum here may differ in the last bits.
    p.TotalCost(this->TryA.data(), this->TryR.data()) > this->Budget + 1e-12 * std::abs(this->Budget))
  {
    return std::numeric_limits<double>::infinity();
  }
  return p.Objective(this->TryA.data(), this->TryR.data());
}

bool TupleOptimizer::Accept(int* a, double* r, double f, double& objective) const
{
  // A relative margin, so that rounding does not make moves cycle.
  if (!(f < objective - 1e-13 * std::abs(objective)))
  {
    return false;
  }
  const std::size_t n = this->P->Count;
  objective = f;
  std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n), a);
  std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n), r);
  return true;
}

void TupleOptimizer::Fill(int* a, double* r, double lambda)
{
  const TupleProblem& p = *this->P;
  const std::size_t n = p.Count;
  double slack = this->Budget - p.TotalCost(a, r);
  const std::size_t rounds = 4 * this->Opts.Candidates + 8;
  for (std::size_t round = 0; round < rounds && slack > 0.0; ++round)
  {
    std::size_t bestObject = n;
    int bestA = 0;
    double bestValue = 0.0, bestR = 0.0, bestCost = 0.0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const double cost = p.Cost(i, a[i], r[i]), degradation = p.Degradation(i, a[i], r[i]);
      this->OptionsOf(this->Choices);
      for (int o : this->Choices)
      {
        const double ro = o >= 0 ? this->TupleResolution(i, static_cast<std::size_t>(o), lambda) : 0.0;
        const double dc = p.Cost(i, o, ro) - cost, dd = degradation - p.Degradation(i, o, ro);
        if (o == a[i] || !(dd > 0.0) || dc > slack)
        {
          continue;
        }
        const double value = dc > 0.0 ? dd / dc : std::numeric_limits<double>::infinity();
        if (bestObject == n || value > bestValue)
        {
          bestObject = i;
          bestA = o;
          bestR = ro;
          bestValue = value;
          bestCost = dc;
        }
      }
    }
    if (bestObject == n)
    {
      return;
    }
    a[bestObject] = bestA;
    r[bestObject] = bestR;
    slack -= bestCost;
  }
}

void TupleOptimizer::ChooseCandidates(const int* a, const double* r, double lambda)
{
  const TupleProblem& p = *this->P;
  const std::size_t n = p.Count;
  const std::size_t k = std::min(n, this->Opts.Candidates);
  this->Chosen.clear();
  if (n <= k)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      this->Chosen.push_back(i);
    }
    return;
  }
  // The objects whose tuple changes across the jump first (largest gain first).
  std::sort(this->Jumpers.begin(), this->Jumpers.end(), [&](std::size_t x, std::size_t y) {
    const double gx = p.Degradation(x, a[x], r[x]) - p.Degradation(x, this->LowA[x], this->LowR[x]);
    const double gy = p.Degradation(y, a[y], r[y]) - p.Degradation(y, this->LowA[y], this->LowR[y]);
    return gx != gy ? gx > gy : x < y;
  });
  for (std::size_t j = 0; j < this->Jumpers.size() && this->Chosen.size() < k; ++j)
  {
    this->Chosen.push_back(this->Jumpers[j]);
  }
  // Then the objects nearest to changing: smallest regret D + lambda C of
  // their best other option over their current one.
  this->Regret.resize(n);
  this->Others.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double current = p.Degradation(i, a[i], r[i]) + lambda * p.Cost(i, a[i], r[i]);
    double regret = std::numeric_limits<double>::infinity();
    this->OptionsOf(this->Choices);
    for (int o : this->Choices)
    {
      if (o != a[i])
      {
        const double ro = o >= 0 ? this->TupleResolution(i, static_cast<std::size_t>(o), lambda) : 0.0;
        regret = std::min(regret, p.Degradation(i, o, ro) + lambda * p.Cost(i, o, ro) - current);
      }
    }
    this->Regret[i] = regret;
    this->Others[i] = static_cast<int>(i);
  }
  const std::size_t more = std::min(n, k + this->Chosen.size());
  std::partial_sort(this->Others.begin(), this->Others.begin() + static_cast<std::ptrdiff_t>(more),
    this->Others.end(), [&](int x, int y) {
      return this->Regret[static_cast<std::size_t>(x)] != this->Regret[static_cast<std::size_t>(y)]
        ? this->Regret[static_cast<std::size_t>(x)] < this->Regret[static_cast<std::size_t>(y)]
        : x < y;
    });
  for (std::size_t j = 0; j < more && this->Chosen.size() < k; ++j)
  {
    const std::size_t i = static_cast<std::size_t>(this->Others[j]);
    if (std::find(this->Chosen.begin(), this->Chosen.end(), i) == this->Chosen.end())
    {
      this->Chosen.push_back(i);
    }
  }
}

bool TupleOptimizer::MakeRoom(const int* a, const double* r, std::size_t i, int o, bool byLoss)
{
  const TupleProblem& p = *this->P;
  const std::size_t n = p.Count;
  std::copy(a, a + n, this->TryA.begin());
  this->TryA[i] = o;
  double needed = -this->Budget; // the least time the assignment can take, over the budget
  for (std::size_t j = 0; j < n; ++j)
  {
    needed += p.Cost(j, this->TryA[j], 0.0);
  }
  // One pool of moves of the other objects: to their cheapest algorithm,
  // and when dropping to the box and to nothing; taken by loss per second
  // freed (or by loss), an object moving on down when a later move frees
  // more than where it is.
  this->Moves.clear();
  for (std::size_t j = 0; j < n; ++j)
  {
    if (j == i)
    {
      continue;
    }
    const int targets[3] = { p.CheapestAlgorithm(j), TupleProblem::BoundingBox, TupleProblem::NotDrawn };
    for (int t = 0; t < (this->Drop ? 3 : 1); ++t)
    {
      const int to = targets[t];
      const double freed = p.Cost(j, a[j], 0.0) - p.Cost(j, to, 0.0);
      if (freed > 0.0 && (to != TupleProblem::BoundingBox || p.BoxCost))
      {
        const double loss = p.Degradation(j, to, 0.0) - p.Degradation(j, a[j], r[j]);
        this->Moves.push_back({ j, to, byLoss ? loss : loss / freed });
      }
    }
  }
  std::sort(this->Moves.begin(), this->Moves.end(), [](const Move& x, const Move& y) {
    return x.Key != y.Key ? x.Key < y.Key : (x.Object != y.Object ? x.Object < y.Object : x.To > y.To);
  });
  for (std::size_t k = 0; k < this->Moves.size() && needed > 0.0; ++k)
  {
    const Move& m = this->Moves[k];
    const double freed = p.Cost(m.Object, this->TryA[m.Object], 0.0) - p.Cost(m.Object, m.To, 0.0);
    if (freed > 0.0)
    {
      needed -= freed;
      this->TryA[m.Object] = m.To;
    }
  }
  return needed <= 0.0;
}

void TupleOptimizer::LocalSearch(int* a, double* r, double& objective, int& iterations)
{
  const std::size_t n = this->P->Count;
  const bool pairs = n <= this->Opts.PairLimit;
  std::vector<int>& first = this->Choices;
  std::vector<int>& second = this->PairChoices; // a member: no allocation per call
  for (int round = 0; round < 4; ++round)
  {
    bool improved = false;
    for (std::size_t i : this->Chosen)
    {
      this->OptionsOf(first);
      for (int o : first)
      {
        if (o == a[i])
        {
          continue;
        }
        std::copy(a, a + n, this->TryA.begin());
        this->TryA[i] = o;
        const double f = this->Evaluate(iterations);
        if (this->Accept(a, r, f, objective))
        {
          improved = true;
          continue;
        }
        if (std::isfinite(f))
        {
          continue;
        }
        // Does not fit: make room by dropping (or, on still frames, making
        // cheapest) the objects that lose least per second freed.
        for (bool byLoss : { false, true })
        {
          if (a[i] != o && this->MakeRoom(a, r, i, o, byLoss))
          {
            improved = this->Accept(a, r, this->Evaluate(iterations), objective) || improved;
          }
        }
        if (!pairs)
        {
          continue;
        }
        // Does not fit alone: with another candidate giving time back.
        for (std::size_t j : this->Chosen)
        {
          this->OptionsOf(second);
          for (int q : second)
          {
            if (j == i || q == a[j] || a[i] == o)
            {
              continue;
            }
            std::copy(a, a + n, this->TryA.begin());
            this->TryA[i] = o;
            this->TryA[j] = q;
            improved = this->Accept(a, r, this->Evaluate(iterations), objective) || improved;
          }
        }
      }
    }
    if (!improved)
    {
      return;
    }
  }
}
}

namespace timecritical
{
void TupleOptimizer::KeepValueOrder(int* a, double* r, double& objective, int& iterations)
{
  const TupleProblem& p = *this->P;
  const std::size_t n = p.Count;
  // The swaps depend on the algorithms only, and every swap frees time (i's
  // cheapest tuple costs less than what j takes), so the resolutions are
  // re-solved once, after the last swap: the same answer as re-solving after
  // each, without its O(n) bisection per swap.
  std::copy(a, a + n, this->TryA.begin());
  std::size_t swaps = 0;
  for (; swaps < n; ++swaps)
  {
    std::size_t i = n, j = n;
    if (!p.FindValueOrderViolation(this->TryA.data(), i, j, this->ValueOrder))
    {
      break;
    }
    // Draw i instead of j: i's cheapest tuple costs less than j's, so it fits.
    this->TryA[i] = p.CheapestAlgorithm(i);
    this->TryA[j] = TupleProblem::NotDrawn;
  }
  if (p.StrictValueOrder)
  {
    swaps += p.ImposeStrictValueOrder(this->TryA.data(), this->ValueOrder);
  }
  if (swaps == 0)
  {
    return;
  }
  const double f = this->Evaluate(iterations);
  if (!std::isfinite(f))
  {
    return; // cannot happen but for rounding
  }
  objective = f;
  std::copy(this->TryA.begin(), this->TryA.begin() + static_cast<std::ptrdiff_t>(n), a);
  std::copy(this->TryR.begin(), this->TryR.begin() + static_cast<std::ptrdiff_t>(n), r);
}
}

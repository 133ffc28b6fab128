// SPDX-License-Identifier: BSD-3-Clause
#include "GreedyLODPolicy.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
void GreedyLODPolicy::Heap::Reset(std::size_t n, bool maxFirst)
{
  if (this->Items.size() < n)
  {
    this->Items.resize(n);
    this->Position.resize(n);
    this->Key.resize(n);
  }
  std::fill(this->Position.begin(), this->Position.begin() + static_cast<std::ptrdiff_t>(n), -1);
  this->Size = 0;
  this->MaxFirst = maxFirst;
}

bool GreedyLODPolicy::Heap::Before(std::uint32_t a, std::uint32_t b) const
{
  const double ka = this->Key[a], kb = this->Key[b];
  if (ka != kb)
  {
    return this->MaxFirst ? ka > kb : ka < kb;
  }
  return a < b; // deterministic ties
}

void GreedyLODPolicy::Heap::Place(std::size_t at, std::uint32_t id)
{
  this->Items[at] = id;
  this->Position[id] = static_cast<std::int64_t>(at);
}

void GreedyLODPolicy::Heap::Up(std::size_t at)
{
  const std::uint32_t id = this->Items[at];
  while (at > 0)
  {
    const std::size_t parent = (at - 1) / 2;
    if (!this->Before(id, this->Items[parent]))
    {
      break;
    }
    this->Place(at, this->Items[parent]);
    at = parent;
  }
  this->Place(at, id);
}

void GreedyLODPolicy::Heap::Down(std::size_t at)
{
  const std::uint32_t id = this->Items[at];
  while (true)
  {
    std::size_t child = 2 * at + 1;
    if (child >= this->Size)
    {
      break;
    }
    if (child + 1 < this->Size && this->Before(this->Items[child + 1], this->Items[child]))
    {
      ++child;
    }
    if (!this->Before(this->Items[child], id))
    {
      break;
    }
    this->Place(at, this->Items[child]);
    at = child;
  }
  this->Place(at, id);
}

void GreedyLODPolicy::Heap::Set(std::uint32_t id, double key)
{
  this->Key[id] = key;
  if (this->Position[id] < 0)
  {
    this->Place(this->Size++, id);
    this->Up(this->Size - 1);
    return;
  }
  const std::size_t at = static_cast<std::size_t>(this->Position[id]);
  this->Up(at);
  this->Down(static_cast<std::size_t>(this->Position[id]));
}

void GreedyLODPolicy::Heap::Remove(std::uint32_t id)
{
  if (this->Position[id] < 0)
  {
    return;
  }
  const std::size_t at = static_cast<std::size_t>(this->Position[id]);
  this->Position[id] = -1;
  --this->Size;
  if (at == this->Size)
  {
    return;
  }
  const std::uint32_t moved = this->Items[this->Size];
  this->Place(at, moved);
  this->Up(at);
  this->Down(static_cast<std::size_t>(this->Position[moved]));
}

GreedyLODPolicy::GreedyLODPolicy()
{
  const double levels[] = { 1.0, 0.5, 0.25, 0.12, 0.06, 0.03 };
  this->SetLevels(levels, 6);
}

void GreedyLODPolicy::SetLevels(const double* levels, std::size_t count)
{
  // The tuple selector keeps the same normalised levels: one rule for both.
  this->Tuples.SetLevels(levels, count);
  this->Levels = this->Tuples.GetLevels();
}

double GreedyLODPolicy::Resolution(std::size_t i, int level) const
{
  return std::max(this->Levels[static_cast<std::size_t>(level)], this->Lo[i]);
}

double GreedyLODPolicy::UpValue(std::size_t i) const
{
  const int l = this->Level[i];
  const double a = this->Resolution(i, l), b = this->Resolution(i, l + 1);
  const double alpha = this->Input->Alpha;
  double value = (ResolutionProblem::Term(this->C[i], alpha, a) -
                   ResolutionProblem::Term(this->C[i], alpha, b)) /
    (this->T[i] * (b - a));
  if (this->PreviousLevel[i] >= 0 && l >= this->PreviousLevel[i])
  {
    value *= 1.0 - this->Input->Hysteresis; // moving away from last frame's level
  }
  return value;
}

double GreedyLODPolicy::DownValue(std::size_t i) const
{
  const int l = this->Level[i];
  const double a = this->Resolution(i, l - 1), b = this->Resolution(i, l);
  const double alpha = this->Input->Alpha;
  double value = (ResolutionProblem::Term(this->C[i], alpha, a) -
                   ResolutionProblem::Term(this->C[i], alpha, b)) /
    (this->T[i] * (b - a));
  if (this->PreviousLevel[i] >= 0 && l <= this->PreviousLevel[i])
  {
    value /= 1.0 - this->Input->Hysteresis;
  }
  return value;
}

void GreedyLODPolicy::Refresh(std::size_t i)
{
  const std::uint32_t id = static_cast<std::uint32_t>(i);
  const int top = static_cast<int>(this->Levels.size()) - 1;
  if (this->Level[i] < top)
  {
    this->Ups.Set(id, this->UpValue(i));
  }
  else
  {
    this->Ups.Remove(id);
  }
  if (this->Level[i] > this->MinLevel[i])
  {
    this->Downs.Set(id, this->DownValue(i));
  }
  else
  {
    this->Downs.Remove(id);
  }
}

void GreedyLODPolicy::Choose(const PolicyInput& input, double* r, PolicyResult& result)
{
  const std::size_t n = input.Count;
  this->Input = &input;
  if (this->Level.size() < n)
  {
    this->Level.resize(n);
    this->MinLevel.resize(n);
    this->PreviousLevel.resize(n);
    this->Lo.resize(n);
    this->C.resize(n);
    this->T.resize(n);
  }
  const int top = static_cast<int>(this->Levels.size()) - 1;
  // Costs are summed incrementally: allow their rounding.
  const double rawBudget = input.TargetFrameTime - input.FixedTime;
  const double budget = rawBudget + 1e-12 * std::abs(rawBudget);
  this->Ups.Reset(n, true);
  this->Downs.Reset(n, false);
  double cost = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double lo = input.MinResolution ? input.MinResolution[i] : 0.0;
    this->Lo[i] = std::isfinite(lo) ? std::min(1.0, std::max(ResolutionProblem::TinyResolution, lo))
                                    : ResolutionProblem::TinyResolution;
    const double c = input.Weight ? input.Weight[i] : 0.0;
    this->C[i] = std::isfinite(c) && c > 0.0 ? c : 0.0;
    const double t = input.MaxTime ? input.MaxTime[i] : 0.0;
    this->T[i] = std::isfinite(t) && t > 0.0 ? t : 0.0;
    int lowest = 0;
    for (int l = 0; l <= top; ++l)
    {
      if (this->Levels[static_cast<std::size_t>(l)] <= this->Lo[i])
      {
        lowest = l;
      }
    }
    this->MinLevel[i] = lowest;
    this->PreviousLevel[i] = -1;
    const double previous = input.Previous ? input.Previous[i] : 0.0;
    if (std::isfinite(previous) && previous > 0.0)
    {
      // Nearest usable level in log scale.
      int best = lowest;
      for (int l = lowest; l <= top; ++l)
      {
        if (std::abs(std::log(this->Resolution(i, l) / previous)) <
          std::abs(std::log(this->Resolution(i, best) / previous)))
        {
          best = l;
        }
      }
      this->PreviousLevel[i] = best;
    }
    if (this->T[i] == 0.0)
    {
      // No valid cost: lowest level, as the optimizer does (a zero cost is a
      // failed model, not a free object).
      this->Level[i] = lowest;
      continue;
    }
    this->Level[i] = this->PreviousLevel[i] >= 0 ? this->PreviousLevel[i] : lowest;
    cost += this->T[i] * this->Resolution(i, this->Level[i]);
  }
  double fullCost = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    fullCost += this->T[i];
  }
  if (fullCost <= budget) // everything fits: no trade to make
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      r[i] = this->T[i] > 0.0 ? 1.0 : this->Resolution(i, this->Level[i]);
    }
    this->Input = nullptr;
    return;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->T[i] > 0.0)
    {
      this->Refresh(i);
    }
  }

  // Funkhouser & Séquin's incremental loop.
  const long cap = 4L * static_cast<long>(n) * static_cast<long>(this->Levels.size()) + 16;
  long moves = 0;
  bool done = false;
  while (!done && moves < cap)
  {
    if (this->Ups.Empty() && cost <= budget)
    {
      break;
    }
    std::int64_t incremented = -1;
    if (!this->Ups.Empty())
    {
      const std::uint32_t i = this->Ups.Top();
      cost -= this->T[i] * this->Resolution(i, this->Level[i]);
      ++this->Level[i];
      cost += this->T[i] * this->Resolution(i, this->Level[i]);
      this->Refresh(i);
      incremented = i;
      ++moves;
    }
    while (cost > budget)
    {
      if (this->Downs.Empty())
      {
        done = true; // infeasible: everything at its lowest level
        break;
      }
      const std::uint32_t j = this->Downs.Top();
      cost -= this->T[j] * this->Resolution(j, this->Level[j]);
      --this->Level[j];
      cost += this->T[j] * this->Resolution(j, this->Level[j]);
      this->Refresh(j);
      ++moves;
      if (static_cast<std::int64_t>(j) == incremented)
      {
        done = true; // the same object went up and down: no better trade left
      }
    }
    if (incremented < 0)
    {
      break;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    r[i] = this->Resolution(i, this->Level[i]);
  }
  result.Iterations = static_cast<int>(std::min<long>(moves, 2147483647L));
  result.Converged = moves < cap;
  this->Input = nullptr;
}
}

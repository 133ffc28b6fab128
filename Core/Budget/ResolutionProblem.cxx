// SPDX-License-Identifier: BSD-3-Clause
#include "ResolutionProblem.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
bool ResolutionProblem::IsValidAlpha(double alpha)
{
  return std::isfinite(alpha) && alpha > -1.0 && alpha != 0.0;
}

double ResolutionProblem::Term(double c, double alpha, double r)
{
  if (c == 0.0)
  {
    return 0.0;
  }
  // The three exponents of eq. 10 avoid pow(): the objective is evaluated
  // inside the optimizer's loop.
  if (alpha == 1.0)
  {
    return c / r;
  }
  if (alpha == 2.0)
  {
    return 0.5 * c / (r * r);
  }
  if (alpha == -0.5)
  {
    return -2.0 * c * std::sqrt(r);
  }
  return c / alpha * std::pow(r, -alpha);
}

double ResolutionProblem::Objective(const double* r) const
{
  double f = 0.0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    f += Term(this->Weight[i], this->Alpha, r[i]);
  }
  return f;
}

double ResolutionProblem::Cost(const double* r) const
{
  double cost = 0.0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    cost += this->MaxTime[i] * r[i];
  }
  return cost;
}

double ResolutionProblem::EffectiveCost(const double* r) const
{
  double cost = 0.0;
  for (std::size_t i = 0; i < this->Count; ++i)
  {
    const double lo = this->MinResolution ? this->MinResolution[i] : 0.0;
    cost += this->MaxTime[i] * std::max(r[i], lo);
  }
  return cost;
}
}

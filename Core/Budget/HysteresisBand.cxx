// SPDX-License-Identifier: BSD-3-Clause
#include "HysteresisBand.h"

#include "ResolutionProblem.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace timecritical
{
void HysteresisBand::CheckHysteresis(double hysteresis)
{
  if (!std::isfinite(hysteresis) || hysteresis < 0.0 || hysteresis >= 1.0)
  {
    throw std::invalid_argument(
      "hysteresis must be finite and in [0, 1), got " + std::to_string(hysteresis));
  }
}

double HysteresisBand::Factor(double hysteresis, double alpha)
{
  CheckHysteresis(hysteresis);
  if (!ResolutionProblem::IsValidAlpha(alpha))
  {
    throw std::invalid_argument(
      "hysteresis band: alpha must be finite, > -1 and != 0, got " + std::to_string(alpha));
  }
  return std::pow(1.0 - hysteresis, -1.0 / (alpha + 1.0));
}

std::size_t HysteresisBand::Apply(const Input& input, double hysteresis, double* r)
{
  const double factor = Factor(hysteresis, input.Alpha);
  if (hysteresis == 0.0 || !input.Previous || !input.MaxTime || !r || input.Count == 0)
  {
    return 0;
  }
  const std::size_t n = input.Count;
  if (this->Extra.size() < n)
  {
    this->Extra.resize(n);
    this->Raise.reserve(n);
  }
  this->Raise.clear();
  // Time an object takes at r: tmax max(r, rmin) (eq. 3).
  auto cost = [&input](std::size_t i, double value) {
    const double lo = input.MinResolution ? input.MinResolution[i] : 0.0;
    return input.MaxTime[i] * std::max(value, std::isfinite(lo) ? lo : 0.0);
  };
  std::size_t held = 0;
  double room = std::max(0.0, std::isfinite(input.Slack) ? input.Slack : 0.0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double previous = input.Previous[i];
    const double lo = input.MinResolution ? input.MinResolution[i] : 0.0;
    const double t = input.MaxTime[i];
    if (!(previous > 0.0) || previous > 1.0 || !(r[i] > 0.0) || previous == r[i] ||
      !(std::isfinite(t) && t >= 0.0) || (std::isfinite(lo) && previous < lo))
    {
      continue;
    }
    if (r[i] < previous / factor || r[i] > previous * factor)
    {
      continue; // a change worth its price
    }
    const double extra = cost(i, previous) - cost(i, r[i]);
    if (extra <= 0.0)
    {
      room -= extra; // this hold frees time
      r[i] = previous;
      ++held;
    }
    else
    {
      this->Extra[i] = extra;
      this->Raise.push_back(i);
    }
  }
  std::sort(this->Raise.begin(), this->Raise.end(), [this](std::size_t a, std::size_t b) {
    return this->Extra[a] != this->Extra[b] ? this->Extra[a] < this->Extra[b] : a < b;
  });
  for (const std::size_t i : this->Raise)
  {
    if (this->Extra[i] > room)
    {
      break; // cheapest first: nothing after fits either
    }
    room -= this->Extra[i];
    r[i] = input.Previous[i];
    ++held;
  }
  return held;
}
}

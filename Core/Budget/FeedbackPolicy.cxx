// SPDX-License-Identifier: BSD-3-Clause
#include "FeedbackPolicy.h"

#include "StaticThresholdPolicy.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
FeedbackPolicy::FeedbackPolicy() = default;

void FeedbackPolicy::Reset()
{
  this->PixelsPerTriangle = this->InitialPixelsPerTriangle;
  this->LastError = 0.0;
  this->HasLastError = false;
  this->SaturatedHigh = this->SaturatedLow = false;
}

void FeedbackPolicy::SetInitialPixelsPerTriangle(double k)
{
  if (std::isfinite(k) && k > 0.0)
  {
    this->InitialPixelsPerTriangle = k;
    this->PixelsPerTriangle = k;
  }
}

void FeedbackPolicy::Choose(const PolicyInput& input, double* r, PolicyResult&)
{
  const double measured = input.LastFrameTime;
  const double target = input.TargetFrameTime;
  if (std::isfinite(measured) && measured > 0.0 && std::isfinite(target) && target > 0.0)
  {
    const double error = std::log(measured / target);
    double change = this->Control.Integral * error;
    if (this->HasLastError)
    {
      change += this->Control.Proportional * (error - this->LastError);
    }
    const double limit = std::log(std::max(1.0, this->Control.MaxStep));
    change = std::min(limit, std::max(-limit, change));
    if ((change < 0.0 && this->SaturatedHigh) || (change > 0.0 && this->SaturatedLow))
    {
      change = 0.0; // anti-windup: the threshold has no effect that way
    }
    const double k = this->PixelsPerTriangle * std::exp(change);
    this->PixelsPerTriangle = std::min(this->Control.MaxPixelsPerTriangle,
      std::max(this->Control.MinPixelsPerTriangle, k));
    this->LastError = error;
    this->HasLastError = true;
  }
  StaticThresholdPolicy::Apply(input, this->PixelsPerTriangle, r);
  this->SaturatedHigh = this->SaturatedLow = input.Count > 0;
  for (std::size_t i = 0; i < input.Count; ++i)
  {
    const double lo = input.MinResolution ? input.MinResolution[i] : 0.0;
    this->SaturatedHigh = this->SaturatedHigh && r[i] >= 1.0;
    this->SaturatedLow = this->SaturatedLow && r[i] <= lo;
  }
}
}

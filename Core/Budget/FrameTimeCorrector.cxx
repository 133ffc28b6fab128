// SPDX-License-Identifier: BSD-3-Clause
#include "FrameTimeCorrector.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace timecritical
{
namespace
{
// Median absolute deviation to standard deviation, for normal samples.
constexpr double MedianAbsoluteToSigma = 1.4826;
}

FrameTimeCorrector::FrameTimeCorrector(const Options& options)
  : Opts(options)
{
  this->Reset();
}

void FrameTimeCorrector::Reset()
{
  this->LogFactor = 0.0;
  this->Spread = std::max(0.0, this->Opts.InitialSpread);
  this->Samples = 0;
}

bool FrameTimeCorrector::Update(double predicted, double measured)
{
  if (!(predicted > 0.0) || !(measured > 0.0) || !std::isfinite(predicted) ||
    !std::isfinite(measured))
  {
    return false;
  }
  const double clamp = std::max(3.0 * this->Spread, this->Opts.MinimumClamp);
  const double residual = std::log(measured / predicted) - this->LogFactor;
  const double deviation = std::clamp(residual, -clamp, clamp);
  const double gain = std::clamp(this->Opts.Gain, 0.0, 1.0);
  this->Residuals[static_cast<std::size_t>(this->Samples % Window)] = std::abs(residual);
  const long count = std::min<long>(this->Samples + 1, Window);
  if (count >= MinimumSamples)
  {
    std::array<double, Window> sorted = this->Residuals;
    const auto middle = sorted.begin() + count / 2;
    std::nth_element(sorted.begin(), middle, sorted.begin() + count);
    this->Spread = MedianAbsoluteToSigma * *middle;
  }
  this->LogFactor = std::clamp(this->LogFactor + gain * deviation, -this->Opts.MaxLogFactor,
    this->Opts.MaxLogFactor);
  ++this->Samples;
  return true;
}

double FrameTimeCorrector::GetFactor() const
{
  return std::exp(this->LogFactor);
}
}

// SPDX-License-Identifier: BSD-3-Clause
#include "StaticThresholdPolicy.h"

#include <algorithm>
#include <cmath>

namespace timecritical
{
void StaticThresholdPolicy::SetPixelsPerTriangle(double k)
{
  if (std::isfinite(k) && k > 0.0)
  {
    this->PixelsPerTriangle = k;
  }
}

void StaticThresholdPolicy::Apply(const PolicyInput& input, double pixelsPerTriangle, double* r)
{
  for (std::size_t i = 0; i < input.Count; ++i)
  {
    const double lo = input.MinResolution
      ? std::min(1.0, std::max(ResolutionProblem::TinyResolution, input.MinResolution[i]))
      : ResolutionProblem::TinyResolution;
    double x = 1.0;
    if (input.Pixels && input.MaxTriangles && input.MaxTriangles[i] > 0.0)
    {
      x = input.Pixels[i] / (pixelsPerTriangle * input.MaxTriangles[i]);
    }
    r[i] = std::isfinite(x) ? std::min(1.0, std::max(lo, x)) : 1.0;
  }
}

void StaticThresholdPolicy::Choose(const PolicyInput& input, double* r, PolicyResult&)
{
  Apply(input, this->PixelsPerTriangle, r);
}
}

// SPDX-License-Identifier: BSD-3-Clause
#include "FullResolutionPolicy.h"

#include <algorithm>

namespace timecritical
{
void FullResolutionPolicy::Choose(const PolicyInput& input, double* r, PolicyResult&)
{
  std::fill(r, r + input.Count, 1.0);
}
}

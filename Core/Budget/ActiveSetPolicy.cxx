// SPDX-License-Identifier: BSD-3-Clause
#include "ActiveSetPolicy.h"

#include <algorithm>

namespace timecritical
{
void ActiveSetPolicy::Choose(const PolicyInput& input, double* r, PolicyResult& result)
{
  const bool warm = input.Previous != nullptr;
  if (warm && input.Previous != r)
  {
    std::copy(input.Previous, input.Previous + input.Count, r);
  }
  this->Last = this->Optimizer.Solve(input.GetProblem(), r, warm);
  result.Iterations = this->Last.Iterations;
  result.Converged = this->Last.Converged;
}
}

// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkRandom.h"

namespace timecritical
{
namespace benchmark
{
BenchmarkRandom::BenchmarkRandom(unsigned seed)
  : Engine(seed)
{
}

double BenchmarkRandom::Uniform(double low, double high)
{
  const double u = static_cast<double>(this->Engine() >> 8) * (1.0 / 16777216.0);
  return low + (high - low) * u;
}
}
}

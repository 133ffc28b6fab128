// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkRandom_h
#define timecritical_BenchmarkRandom_h

#include <random>

namespace timecritical
{
namespace benchmark
{
/**
 * Portable uniform numbers: std::mt19937's output is fixed by the standard,
 * std::uniform_real_distribution's is not. Each number takes the top 24 bits
 * of one raw draw, which scripts/make_w1_scene.py reproduces with numpy.
 */
class BenchmarkRandom
{
public:
  explicit BenchmarkRandom(unsigned seed);
  double Uniform(double low, double high);

private:
  std::mt19937 Engine;
};
}
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
// Private to the ActiveSetOptimizer*.cxx files: tolerances and the small
// scalar helpers that the start, the multiplier search and the step-by-step
// iteration share.
#ifndef timecritical_ActiveSetOptimizerInternals_h
#define timecritical_ActiveSetOptimizerInternals_h

#include "ActiveSetOptimizer.h"

#include <algorithm>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace timecritical
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
/// |d_i| below this (absolute + relative to r_i) counts as d = 0 (section 5.3.3).
constexpr double StepTolerance = 1e-12;
constexpr double StepRelativeTolerance = 1e-10;
/// A bound is released only when kappa g_i is beyond it by this relative margin.
constexpr double ReleaseTolerance = 1e-10;
/// Newton rounds of one projected step (the bracket halves at worst: ~60 suffice).
constexpr int MaxNewtonRounds = 200;
/// Half-octave buckets of the warm-start reduction (see Bucket()).
constexpr int KeyBuckets = 4096;
/// Widest lane type: the reduction's bucket table has one sub-table per lane.
constexpr std::size_t MaxLanes = 4;

inline double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
    .count();
}

inline double Clamp(double x, double lo, double hi)
{
  return x < lo ? lo : (x > hi ? hi : x);
}

/// Safeguard of a search for a root of phi in (lo, hi), phi(lo) <= budget
/// < phi(hi): bisection, geometric across orders of magnitude (rooted
/// separately: kappa spans 600 decades when gamma = 10), outward without hi.
inline double Bisect(double lo, double hi)
{
  if (!(hi < Infinity))
  {
    return lo > 0.0 ? std::min(4.0 * lo, DBL_MAX) : 1.0;
  }
  if (!(lo > 0.0))
  {
    return 0.25 * hi;
  }
  return hi > 4.0 * lo ? std::sqrt(lo) * std::sqrt(hi) : 0.5 * (lo + hi);
}

inline int KindOf(double alpha)
{
  return alpha == 1.0 ? 1 : (alpha == 2.0 ? 2 : (alpha == -0.5 ? 3 : 0));
}

/// f(std::integral_constant<int, KindOf(alpha)>()).
template <class F>
void WithKind(double alpha, F&& f)
{
  switch (KindOf(alpha))
  {
    case 1:
      f(std::integral_constant<int, 1>());
      break;
    case 2:
      f(std::integral_constant<int, 2>());
      break;
    case 3:
      f(std::integral_constant<int, 3>());
      break;
    default:
      f(std::integral_constant<int, 0>());
      break;
  }
}
}
}

#endif

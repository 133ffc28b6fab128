// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ResolutionProblem_h
#define timecritical_ResolutionProblem_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>

namespace timecritical
{
/**
 * The per-frame resolution optimization problem of Gobbetti & Bouvier (eq. 11):
 *
 *   minimize   f(r) = sum_i c_i / alpha * r_i^-alpha
 *   subject to sum_i tmax_i r_i <= Budget,   rmin_i <= r_i <= 1
 *
 * with Budget = t_desired - t_fixed (eq. 4). A non-owning view over
 * structure-of-arrays data so that callers keep their own buffers and no copy
 * is made per frame.
 *
 * For every admissible alpha (alpha > -1, alpha != 0) each term is strictly
 * decreasing and convex in r: f_i'(r) = -c_i r^-(alpha+1), f_i'' > 0. For
 * -1 < alpha < 0 (e.g. the alpha = -1/2 family, f_i = -2 c_i sqrt(r)) the terms
 * are negative: f is then minus a benefit, which is why only differences and
 * orderings of objective values are meaningful.
 */
struct TIMECRITICALBUDGETCORE_EXPORT ResolutionProblem
{
  std::size_t Count = 0;
  const double* Weight = nullptr;        ///< c_i >= 0 (degradation weight, eq. 11)
  const double* MaxTime = nullptr;       ///< tmax_i >= 0 (s): time at full resolution
  const double* MinResolution = nullptr; ///< rmin_i in (0, 1] (eq. 3)
  double Alpha = 1.0;                    ///< shape of the error curve (eq. 9)
  double Budget = 0.0;                   ///< t_desired - t_fixed (s)

  /// Smallest resolution the solvers hand out (a TOM never goes below its base mesh anyway).
  static constexpr double TinyResolution = 1e-6;

  /// alpha > -1, alpha != 0 and finite.
  static bool IsValidAlpha(double alpha);

  /// One term of eq. 11, c / alpha * r^-alpha, with fast paths for the eq. 10 exponents.
  static double Term(double c, double alpha, double r);

  /// f(r) over all objects.
  double Objective(const double* r) const;

  /// sum_i tmax_i r_i: the resolution-dependent part of the predicted frame time.
  double Cost(const double* r) const;

  /// sum_i tmax_i max(r_i, rmin_i): the time actually predicted, since below rmin an
  /// object is fill-bound (eq. 3) and lowering r saves nothing.
  double EffectiveCost(const double* r) const;
};
}

#endif

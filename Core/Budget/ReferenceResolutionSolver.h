// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ReferenceResolutionSolver_h
#define timecritical_ReferenceResolutionSolver_h

#include "ResolutionProblem.h"
#include "TimeCriticalBudgetCoreExport.h"

namespace timecritical
{
/**
 * Exact reference solution of the resolution problem (eq. 11) for tests and
 * benchmarks, written independently of ActiveSetOptimizer.
 *
 * The problem is convex and separable with one coupling constraint, so its
 * KKT point is r_i(lambda) = clamp((c_i / (lambda tmax_i))^(1/(alpha+1)),
 * rmin_i, 1) for the single multiplier lambda of the time constraint;
 * cost(r(lambda)) is non-increasing in lambda, and lambda is found by
 * bisection on log(lambda). The returned point is on the feasible side of the
 * final bracket, then polished by solving the linear piece it lies on exactly.
 * Slow (one pow() per object per bisection step) but simple.
 */
class TIMECRITICALBUDGETCORE_EXPORT ReferenceResolutionSolver
{
public:
  struct Result
  {
    bool Infeasible = false;    ///< cost(rmin) > Budget: rmin returned
    bool Unconstrained = false; ///< time constraint slack at the optimum
    double Multiplier = 0.0;    ///< lambda
    double Objective = 0.0;
    double Cost = 0.0; ///< sum tmax_i r_i
    int Iterations = 0;
  };

  /// r: output, problem.Count values. Invalid alpha: rmin returned, Infeasible set.
  static Result Solve(const ResolutionProblem& problem, double* r, int maxIterations = 300);
};
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TupleOptimizer_h
#define timecritical_TupleOptimizer_h

#include "TimeCriticalBudgetCoreExport.h"
#include "TupleProblem.h"

#include <cstddef>
#include <vector>

namespace timecritical
{
/**
 * Chooses (algorithm, resolution) tuples for the continuous optimizer's side
 * (ActiveSetPolicy): Gobbetti & Bouvier's problem with Funkhouser & Séquin's
 * algorithm axis and "no polygons" levels (TupleProblem).
 *
 * Method chosen: Lagrangian relaxation of the one coupling constraint, the
 * frame time. For a multiplier lambda every object is independent: for each
 * of its tuples the best resolution is the closed form of eq. 14,
 * r = clamp((c / (lambda T))^(1 / (alpha + 1)), lo, hi), and the object takes
 * the tuple (or the box, or nothing) with the smallest D + lambda C. The
 * chosen cost falls as lambda grows; a search on log(lambda) (bracketing,
 * then bisection) finds the smallest lambda whose choice fits. Then
 * 1. the algorithms of that choice are fixed and the resolutions re-solved
 *    exactly for them (the convex eq. 11 with per-object exponents and
 *    costs, by bisection on its own multiplier), which spends the time
 *    freed by the discrete jump of the algorithm choice;
 * 2. a few objects whose tuple differs on the two sides of the jump
 *    (Options::Candidates) are switched to their other tuple, resolutions
 *    re-solved, and the switch kept when it lowers the objective.
 * Why: the algorithm choice is discrete and each algorithm has its own error
 * exponent (Funkhouser's m = 1 flat, 2 Gouraud), so one ActiveSetOptimizer
 * call cannot hold it; the relaxation keeps the per-object closed form and
 * an O(n A) pass per multiplier, decides every object by one number (so an
 * object is dropped only when every drawn object has a better benefit/cost
 * trade at that multiplier: never while a cheaper tuple of a less valuable
 * object could be dropped instead), and gives a certificate: every lambda
 * tried yields the lower bound sum_i min (D_i + lambda C_i) - lambda Budget
 * on the optimum (weak duality), reported as Solution::LowerBound. The gap
 * to it is at most lambda times the time the discrete jump leaves unused
 * before step 1, one object's worth.
 *
 * Levels below the coarsest mesh are used only when TupleProblem::NeedsDropping();
 * with dropping off and the cheapest tuples over budget, every object gets
 * its cheapest tuple and Solution::Infeasible is set. The resolution of a
 * box or dropped object is returned as 0. Buffers are reused across calls.
 */
class TIMECRITICALBUDGETCORE_EXPORT TupleOptimizer
{
public:
  struct Options
  {
    int MaxIterations = 200;    ///< multiplier search steps (each one O(n A) pass)
    std::size_t Candidates = 4; ///< objects at the jump tried with their other tuple
    double Tolerance = 1e-10;   ///< relative width of the final multiplier bracket
  };

  TupleOptimizer() = default;
  explicit TupleOptimizer(const Options& options);
  void SetOptions(const Options& options) { this->Opts = options; }
  const Options& GetOptions() const { return this->Opts; }

  /**
   * algorithms, r: problem.Count values each, written. Throws
   * std::invalid_argument on bad input (TupleProblem::Validate()).
   */
  TupleProblem::Solution Solve(const TupleProblem& problem, int* algorithms, double* r);

private:
  /// Every object's best tuple at lambda; returns the chosen cost and adds
  /// sum_i min(D_i + lambda C_i) to lagrangian.
  double Sweep(double lambda, int* a, double* r, double& lagrangian) const;
  /// Object i's best tuple at lambda; returns D + lambda C.
  double Best(std::size_t i, double lambda, int& a, double& r) const;
  /// The resolutions of fixed algorithms a, optimal for them; false when they do not fit.
  bool SolveResolutions(const int* a, double* r, int& iterations);
  /// Step 2: tries the objects whose tuple changes across the jump.
  void TryJumpers(int* a, double* r, double& objective, int& iterations);
  void Cheapest(int* a, double* r) const;

  Options Opts;
  const TupleProblem* P = nullptr;
  bool Drop = false;
  double Budget = 0.0; ///< with a rounding allowance
  std::vector<int> LowA, TryA;
  std::vector<double> LowR, TryR;
  std::vector<std::size_t> Jumpers;
};
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ActiveSetPolicy_h
#define timecritical_ActiveSetPolicy_h

#include "ActiveSetOptimizer.h"
#include "ResolutionPolicy.h"
#include "TupleOptimizer.h"

namespace timecritical
{
/**
 * The time-critical policy of Gobbetti & Bouvier: the degradation heuristic's
 * c_i and alpha (computed by the caller with DegradationModel, as for every
 * policy) and the cost model's tmax and rmin, optimized by ActiveSetOptimizer
 * within its time limit, warm-started from the previous frame's resolutions
 * when the input provides them.
 *
 * SelectTuples() chooses (rendering algorithm, resolution) tuples and the
 * levels below the coarsest mesh instead, with TupleOptimizer (a Lagrangian
 * choice of the algorithm per object, see there); with one algorithm and no
 * dropping it solves the same problem as Select().
 */
class TIMECRITICALBUDGETCORE_EXPORT ActiveSetPolicy : public ResolutionPolicy
{
public:
  const char* GetName() const override { return "active-set"; }

  void SetOptions(const ActiveSetOptimizer::Options& options) { this->Optimizer.SetOptions(options); }
  const ActiveSetOptimizer::Options& GetOptions() const { return this->Optimizer.GetOptions(); }
  /// Full report of the last optimization.
  const ActiveSetOptimizer::Result& GetLastResult() const { return this->Last; }
  ActiveSetOptimizer& GetOptimizer() { return this->Optimizer; }

  /// Tuples for the frame (TupleOptimizer::Solve()); throws std::invalid_argument on bad input.
  TupleProblem::Solution SelectTuples(const TupleProblem& problem, int* algorithms, double* r)
  {
    return this->Tuples.Solve(problem, algorithms, r);
  }
  TupleOptimizer& GetTupleOptimizer() { return this->Tuples; }

protected:
  void Choose(const PolicyInput& input, double* r, PolicyResult& result) override;

private:
  ActiveSetOptimizer Optimizer;
  ActiveSetOptimizer::Result Last;
  TupleOptimizer Tuples;
};
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_GreedyTupleSelector_h
#define timecritical_GreedyTupleSelector_h

#include "TimeCriticalBudgetCoreExport.h"
#include "TupleProblem.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
/**
 * Funkhouser & Séquin's greedy choice of object tuples (section 6), for the
 * discrete side (GreedyLODPolicy): each object's candidates are its levels
 * of detail (its coarsest mesh lo and GetLevels() clamped to [lo, hi]) times the
 * algorithms of the TupleProblem, plus, when TupleProblem::NeedsDropping(),
 * a bounding box and "not drawn"; Benefit = minus the tuple's degradation,
 * Cost = its predicted time.
 *
 * What is implemented: the multiple-choice knapsack greedy in its form with
 * a proven bound. Every object starts at its base (not drawn when dropping,
 * else its cheapest tuple); candidates that cannot fit alone are discarded;
 * each object's candidates are reduced to the upper convex hull of
 * (cost, benefit) above the base, whose steps have decreasing Value =
 * benefit gained / cost added; all steps of all objects are taken in
 * descending Value while they fit (an object whose step does not fit takes
 * no further step). The paper adds whole tuples by Benefit / Cost and keeps
 * the better of two tuples of one object, which is the same thing when
 * Values decrease with accuracy (its "diminishing returns" assumption); the
 * hull makes it so. Finally the answer is compared with the first step that
 * did not fit taken alone (every other object at its base), and the better
 * one returned, which gives the bound the paper cites [Garey & Johnson]:
 *   benefit over the base >= 1/2 of the optimum's, among these candidates.
 * Then, when dropping, an object is never left out while a less valuable
 * one (less to lose) whose cheapest tuple costs more is drawn: the two are
 * swapped (TupleProblem::FindValueOrderViolation()); the greedy rarely
 * needs it, and the swap may cost a little of the bound.
 * Solution::LowerBound is the linear relaxation's bound on the optimal
 * objective among these candidates. O(N log N) for N candidates.
 */
class TIMECRITICALBUDGETCORE_EXPORT GreedyTupleSelector
{
public:
  /// One candidate tuple of an object.
  struct Tuple
  {
    int Algorithm = TupleProblem::NotDrawn; ///< index, BoundingBox or NotDrawn
    double Resolution = 0.0;
    double Cost = 0.0;
    double Degradation = 0.0;
  };

  GreedyTupleSelector();

  /// Level resolutions in (0, 1], any order; 1 is always included (as GreedyLODPolicy).
  void SetLevels(const double* levels, std::size_t count);
  const std::vector<double>& GetLevels() const { return this->Levels; }

  /// algorithms, r: problem.Count values each. Throws std::invalid_argument on bad input.
  TupleProblem::Solution Solve(const TupleProblem& problem, int* algorithms, double* r);

  /// Object i's candidates (dropping: with the box and "not drawn"), unsorted.
  void GetCandidates(
    const TupleProblem& problem, std::size_t i, bool dropping, std::vector<Tuple>& out) const;

private:
  struct Step
  {
    std::uint32_t Object = 0, To = 0; ///< hull point reached (index into Points)
    double Cost = 0.0, Benefit = 0.0;
  };
  void BuildHull(const TupleProblem& problem, std::size_t i, bool dropping, const Tuple& base,
    double remaining);

  std::vector<double> Levels; // ascending, last = 1
  std::vector<Tuple> Candidates, Points;
  std::vector<Step> Steps;
  std::vector<std::size_t> Start, Current; // per object: first hull point (its base), point taken
  std::vector<char> Blocked;               // per object: a step did not fit
  TupleProblem::ValueOrderScratch ValueOrder;
};
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TupleOptimizer_h
#define timecritical_TupleOptimizer_h

#include "GreedyTupleSelector.h"
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
 * frame time, then a repair of its discrete gap. For a multiplier lambda
 * every object is independent: for each of its tuples the best resolution
 * is the closed form of eq. 14, r = clamp((c / (lambda T))^(1 / (alpha + 1)),
 * lo, hi), and the object takes the tuple (or the box, or nothing) with the
 * smallest D + lambda C. The chosen cost falls as lambda grows; a search on
 * log(lambda) (bracketing, then bisection) finds the smallest lambda whose
 * choice fits. Then
 * 1. the resolutions of the chosen algorithms are re-solved exactly (the
 *    convex eq. 11 with per-object exponents and costs, by bisection on its
 *    own multiplier), which spends the time left by the discrete jump;
 * 2. fill: while some object can move to a less degraded tuple within the
 *    time left, the move with the best degradation saved per second is made
 *    (then 1 again);
 * 3. second start: GreedyTupleSelector's assignment (Funkhouser's greedy
 *    over discrete levels, which packs the time by value), its resolutions
 *    re-solved, replaces the answer when better (Options::GreedyStart), so
 *    the answer is never worse than the greedy's;
 * 4. local search over a few candidates (Options::Candidates: the objects
 *    whose tuple changes across the jump, then those nearest to changing at
 *    the multiplier; all objects when fewer): any change of one object's
 *    tuple; when it does not fit, the same change with room made by the
 *    objects that lose least per second freed, or least (two tries; their
 *    cheapest algorithm, the box or nothing), and for small
 *    frames (Count <= Options::PairLimit, where one object is a large share
 *    of the frame) with a change of one other candidate; resolutions
 *    re-solved each time, a move kept when it lowers the objective. Each
 *    move costs a re-solve, O(n); above Options::SearchLimit objects the
 *    relaxation's gap is a tiny share of the frame and the search is
 *    skipped, as it is when the certificate below already proves the
 *    answer within Options::GapTolerance;
 * 5. value order: while an object is dropped and a less valuable one (less
 *    to lose when not drawn) whose cheapest tuple costs more is drawn, the
 *    two are swapped (it fits: the dropped one is cheaper). The relaxation
 *    never does that; the search, packing the time, can. The resolutions
 *    are re-solved once, after the last swap.
 * Why: the algorithm choice is discrete and each algorithm has its own error
 * exponent (Funkhouser's m = 1 flat, 2 Gouraud), so one ActiveSetOptimizer
 * call cannot hold it; the relaxation keeps the per-object closed form and
 * an O(n A) pass per multiplier, decides every object by one number (an
 * object is dropped only when, at that multiplier, its best benefit per
 * second is below every drawn object's), and gives a certificate: every
 * lambda tried yields the lower bound sum_i min (D_i + lambda C_i) - lambda
 * Budget on the optimum (weak duality), reported as Solution::LowerBound.
 * The relaxation alone loses up to one object's worth (the discrete jump),
 * which is large only when objects are few; steps 1-4 recover it.
 *
 * Levels below the coarsest mesh are used only when TupleProblem::NeedsDropping();
 * with dropping off and the cheapest tuples over budget, every object gets
 * its cheapest tuple and Solution::Infeasible is set. The resolution of a
 * box or dropped object is returned as 0. Buffers are reused across calls: once they have grown to
 * the problem's size, Solve() does not allocate.
 */
class TIMECRITICALBUDGETCORE_EXPORT TupleOptimizer
{
public:
  struct Options
  {
    int MaxIterations = 200;    ///< multiplier search steps (each one O(n A) pass)
    std::size_t Candidates = 8; ///< objects of the local search (step 4)
    std::size_t PairLimit = 16; ///< pair moves when Count <= this
    std::size_t SearchLimit = 2000; ///< local search (step 4) when Count <= this
    bool GreedyStart = true;    ///< step 3: also start from GreedyTupleSelector's assignment
    double GapTolerance = 1e-7; ///< no step 4 when LowerBound proves the answer this close (relative)
    double Tolerance = 1e-6;    ///< relative width of the final multiplier bracket (step 1 makes r exact)
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
  /// Steps 1-5 from the relaxation's choice at lambda.
  void Repair(int* a, double* r, double lambda, TupleProblem::Solution& s);
  /// The best resolution of tuple (i, a) at lambda (closed form).
  double TupleResolution(std::size_t i, std::size_t a, double lambda) const;
  /// An object's options: the algorithms, and the box and "not drawn" when dropping.
  void OptionsOf(std::vector<int>& out) const;
  /// Resolutions re-solved for TryA (into TryR); the objective when it fits, else +infinity.
  double Evaluate(int& iterations);
  /// Step 2: moves within the time left, best value first.
  void Fill(int* a, double* r, double lambda);
  /// Step 4 on the candidates; objective updated.
  void LocalSearch(int* a, double* r, double& objective, int& iterations);
  /// TryA = a with object i at option o and, until it can fit, the objects
  /// that lose least per second freed (byLoss: least) moved to their cheapest
  /// algorithm or (when dropping) to the box or to nothing; false when it
  /// cannot.
  bool MakeRoom(const int* a, const double* r, std::size_t i, int o, bool byLoss);
  /// The candidates of step 4 (Jumpers first, then the smallest regret at lambda).
  void ChooseCandidates(const int* a, const double* r, double lambda);
  /// Step 5: swaps until no object is dropped while a less valuable one
  /// whose cheapest tuple costs more is drawn.
  void KeepValueOrder(int* a, double* r, double& objective, int& iterations);
  /// Keeps TryA / TryR as the answer when better.
  bool Accept(int* a, double* r, double f, double& objective) const;
  void Cheapest(int* a, double* r) const;

  Options Opts;
  GreedyTupleSelector Greedy;
  const TupleProblem* P = nullptr;
  bool Drop = false;
  double Budget = 0.0; ///< with a rounding allowance
  std::vector<int> LowA, TryA;
  std::vector<double> LowR, TryR;
  std::vector<std::size_t> Jumpers, Chosen;
  std::vector<double> Regret;
  struct Move
  {
    std::size_t Object;
    int To;
    double Key;
  };
  std::vector<Move> Moves;
  std::vector<int> Choices, Others, PairChoices;
  TupleProblem::ValueOrderScratch ValueOrder;
};
}

#endif

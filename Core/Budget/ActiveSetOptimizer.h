// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ActiveSetOptimizer_h
#define timecritical_ActiveSetOptimizer_h

#include "ResolutionProblem.h"
#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
/**
 * Active-set solver of the resolution problem (Gobbetti & Bouvier section 5,
 * Algorithm 1), anytime: every return is feasible and no worse than the start.
 *
 * Derivation used (rather than the typography of eq. 14 and 16). With
 * gamma = 1 / (alpha + 1) and g_i = (c_i / tmax_i)^gamma, stationarity of the
 * Lagrangian on the free set F gives r_i = kappa g_i with a single scalar
 * kappa = lambda^-gamma fixed by the time constraint:
 *   kappa = (Budget - sum_{i not in F} tmax_i r_i) / sum_{i in F} tmax_i g_i   (eq. 14)
 *   lambda = kappa^-(alpha+1) >= 0 (time constraint)
 *   lower bound of i: lambda tmax_i - c_i rmin_i^-(alpha+1), upper: c_i - lambda tmax_i   (eq. 16)
 * f_i' = -c_i r^-(alpha+1) < 0 for every alpha > -1, alpha != 0, so the same
 * formulas hold for the alpha < 0 families (eq. 16's r^(alpha-1) is a typo).
 * A bound's multiplier is negative exactly when kappa g_i lies on the far
 * side of the bound, which is the test used (dimensionless, no pow()).
 *
 * Per call, O(n) work per step and no allocation once sized:
 * 1. the infeasible (cost(rmin) > Budget: rmin returned) and all-full
 *    (cost(1) <= Budget: 1 returned) cases of section 5.3.1;
 * 2. start: rmin (cold), or the caller's previous resolutions (warm, objects
 *    given as NaN or <= 0 start at rmin), reduced by Beta until feasible,
 *    least valuable first (smallest -f_i'/tmax_i; half-octave buckets, not
 *    sorted; the last bucket reduced by the fraction that meets the budget);
 * 3. Algorithm 1: working set = time constraint + bounds active at the start;
 *    direction to the subspace minimizer (eq. 14); when it is reached,
 *    multipliers (eq. 16) and release of negative ones; else a step.
 *
 * Two options, both on by default, turn what is O(n) iterations of O(n) in
 * the textbook method into one (set both off for the paper's method):
 * - ProjectedSteps: the bounds that a step runs into are resolved inside the
 *   step instead of stopping at the first one (ratio test);
 * - BlockRelease: every bound with a negative multiplier is released at once
 *   instead of only the most negative one.
 * With both, the first step releases every bound and resolves them all, so
 * the answer is r_i = clamp(kappa g_i, rmin_i, 1) with kappa the root of the
 * non-decreasing piecewise-linear phi(kappa) = sum_i tmax_i r_i = Budget,
 * optimal by construction (every eq. 16 multiplier is then non-negative).
 * The start's eq. 14 kappa (the previous frame's when warm) centres an
 * interval; one O(n) pass sums the objects whose clamp has a fixed form on it
 * and lists the others, whose breakpoints lie inside (few after a
 * frame-to-frame change), and a safeguarded Newton iteration
 * over that list finds the root; an interval that misses it is followed by a
 * wider one around a Newton step. A warm solve is three O(n) passes: the
 * start (g_i), the classification (which also buckets the Beta reduction of
 * an over-budget start), and the answer (which also reports f at the
 * reduced start; the start itself is built only when the search stops
 * early). The passes are branch-free, four objects per instruction with AVX2
 * (two with SSE2, chosen at run time).
 * With one option off, Algorithm 1 runs step by step as described above
 * (ProjectedSteps: a safeguarded Newton iteration on kappa over the free
 * variables, each round O(n), accepted only when feasible and not worse than
 * the current point; BlockRelease: the projected step puts back the bounds
 * that should stay).
 *
 * TimeLimit (t_opt) is checked every ClockCheckWork object visits; at any stop
 * (time, MaxIterations, MaxSteps) the current point is returned, feasible and
 * with an objective that never increases with more iterations.
 *
 * TimeLimit <= 0 asks for no iteration at all: the answer is then the
 * closed-form allocation (r_i = clamp(kappa g_i, rmin_i, 1) for every object,
 * kappa from eq. 14 and six safeguarded Newton corrections for the clamps,
 * then the point between the last feasible and infeasible allocations that
 * spends the budget exactly: a fixed number of O(n) passes), or the warm
 * start when that is better. It is the optimum when the corrections reach
 * it, spends the whole budget, and is never worse than rmin, where the
 * paper's start point would leave every object.
 *
 * An object whose tmax is 0 (or not finite, or negative) is left at rmin and
 * kept out of the problem: a zero cost comes from a cost model that failed,
 * and drawing such an object in full is how a collapsed model stalls a frame.
 * A caller that wants an object drawn in full outside the budget gives it
 * rmin = 1.
 */
class TIMECRITICALBUDGETCORE_EXPORT ActiveSetOptimizer
{
public:
  enum class Status
  {
    Optimal,        ///< KKT conditions hold
    Unconstrained,  ///< cost(1) <= Budget: every object at full resolution
    Infeasible,     ///< cost(rmin) > Budget: every object at rmin (over budget)
    TimeLimit,      ///< stopped by TimeLimit, feasible
    IterationLimit, ///< stopped by MaxIterations or MaxSteps, feasible
    Empty,          ///< no object
    InvalidInput    ///< alpha out of range or missing arrays
  };

  struct Options
  {
    double TimeLimit = 1e-3;             ///< t_opt (s) for the whole call; <= 0: closed form, no iteration
    int MaxIterations = 100000;          ///< Algorithm 1 iterations
    long MaxSteps = 10000000;            ///< O(n) passes (subspace solves and Newton rounds)
    double Beta = 0.8;                   ///< warm start reduction factor (section 5.3.1), in (0, 1)
    bool ProjectedSteps = true;          ///< resolve bounds within a step (see class comment)
    bool BlockRelease = true;            ///< release all negative multipliers at once
    std::size_t ClockCheckWork = 1 << 14; ///< object visits between two clock reads
  };

  struct Result
  {
    Status State = Status::Empty;
    bool Converged = false;  ///< Optimal, Unconstrained or Empty
    bool Infeasible = false; ///< Status::Infeasible
    int Iterations = 0;      ///< Algorithm 1 iterations
    long Steps = 0;          ///< O(n) passes, including Newton rounds of projected steps
    double Objective = 0.0;  ///< f(r) returned
    double InitialObjective = 0.0; ///< f at the start point (after the warm-start reduction)
    double Cost = 0.0;       ///< sum tmax_i r_i returned (<= Budget unless infeasible)
    double Multiplier = 0.0; ///< lambda of the time constraint (0 when slack)
    double KKTResidual = 0.0; ///< max |r_i - clamp(kappa g_i)|, relative budget violation/slack
    double Seconds = 0.0;    ///< wall time of the call
    std::size_t FreeCount = 0, LowerCount = 0, UpperCount = 0; ///< final working set
    std::size_t InvalidCount = 0; ///< objects with a NaN/negative tmax, left at rmin
    std::size_t ZeroCostCount = 0; ///< objects with tmax = 0, left at rmin
  };

  ActiveSetOptimizer() = default;
  explicit ActiveSetOptimizer(const Options& options);

  void SetOptions(const Options& options) { this->Opts = options; }
  const Options& GetOptions() const { return this->Opts; }

  /// Size the buffers for n objects (Solve() grows them if needed, never shrinks).
  void Reserve(std::size_t n);
  std::size_t GetCapacity() const { return this->T.size(); }

  /**
   * Solve for problem.Count objects. resolutions (size Count): on input, when
   * warmStart, the previous frame's resolutions (NaN or <= 0 for a new object);
   * on output, the result. Objects with tmax <= 0 or c = 0 get rmin.
   */
  Result Solve(const ResolutionProblem& problem, double* resolutions, bool warmStart);

  static const char* GetStatusName(Status status);

private:
  enum : std::uint8_t
  {
    Free = 0,
    Lower = 1,
    Upper = 2,
    PinnedLow = 3 ///< tmax invalid or 0: left at rmin, not in the problem
  };

  /// Sums over the objects gathered with the start point (one pass).
  struct StartSums
  {
    double CostLow = 0.0, CostHigh = 0.0; ///< cost(rmin), cost(1)
    double CostTop = 0.0; ///< cost with every object whose c > 0 at 1, the others at rmin
    double Cost = 0.0, Objective = 0.0;   ///< cost and f of the start point
    double FixedCost = 0.0;  ///< sum tmax_i r_i over the start's bounds
    double FreeWeight = 0.0; ///< sum tmax_i g_i over the start's free objects
    double Weight = 0.0;     ///< sum tmax_i g_i over every object
    std::size_t Invalid = 0, Zero = 0;
  };

  // ActiveSetOptimizer.cxx: the start and the cases decided at once.
  /// Solve() once the input is known to be valid (Count > 0).
  void SolveValid(const ResolutionProblem& problem, double* r, bool warmStart, Result& result);
  /// The sanitized copies, the start point and its sums (Prepare()).
  void PrepareStart(const ResolutionProblem& problem, double* r, bool warmStart, StartSums& sums);
  /// Infeasible (rmin) or all full (1): true when so, with the answer in r.
  bool SolveAtEnds(double* r, double rawBudget, const StartSums& sums, Result& result);
  double ObjectiveAt(const double* r) const;
  double CostAt(const double* r) const;

  // ActiveSetOptimizerPasses.cxx: the O(n) lane passes.
  template <int Kind>
  void Prepare(const ResolutionProblem& problem, double* r, bool warmStart, StartSums& sums);
  /// The warm-start reduction: buckets below Cut by Beta, bucket Cut by Theta of that.
  struct Reduction
  {
    bool Active = false;
    int Cut = 0;
    double Theta = 1.0, Beta = 0.8;
  };
  void BucketPass(const double* r, double beta);
  template <int Kind>
  void ApplyReduction(double* r, const Reduction& plan, StartSums& sums);
  template <int Kind>
  void Finish(double* r, double kappa, double rawBudget, const Reduction& plan, Result& result);
  double Classify(double low, double high, double& slope, std::size_t& count,
    const double* bucketsOf, double beta);
  template <bool Two, bool Track>
  void CandidatePhi(std::size_t count, double kappa, double other, double& phi, double& slope,
    double& phiOther, double& slopeOther, std::size_t& moved);

  // ActiveSetOptimizerMultiplier.cxx: both options on, the root of phi; and
  // the warm-start reduction's plan.
  struct MultiplierSearch;
  Reduction PlanReduction(double* r, double budget, StartSums& sums, bool bucketsSummed);
  void SolveMultiplier(double* r, double budget, double rawBudget, StartSums& sums, Result& result);
  /// The root kappa of phi(kappa) = budget; < 0 when stopped first.
  double FindMultiplier(
    double* r, double budget, StartSums& sums, MultiplierSearch& search, Result& result);
  /// Stopped early: the reduced start, or the bracket's feasible end if better.
  void StopAtStart(double* r, double budget, double rawBudget, StartSums& sums,
    MultiplierSearch& search, Result& result);
  bool SolveCandidates(double& low, double& high, double fixedCost, double slope,
    std::size_t count, double budget, double& kappa);

  // ActiveSetOptimizerSteps.cxx: Algorithm 1 step by step, and the closed form.
  void SolveStepwise(double* r, double budget, double rawBudget, bool warmStart,
    StartSums& sums, Result& result);
  /// The closed form, or the warm start r when that is better.
  void ClosedFormOrWarm(double* r, double budget, bool warmStart);
  /// Algorithm 1's iterations; returns the steps in a row that changed nothing.
  int Iterate(double* r, double budget, double& objective, Result& result);
  /// Fixed cost and sum tmax_i g_i of the working set; returns its free count.
  std::size_t Subspace(const double* r, double& fixedCost, double& weightSum);
  /// Whether the subspace minimizer at kappa is away from r (d != 0).
  bool Moving(const double* r, double kappa);
  /// One step towards it; returns the working-set changes.
  std::size_t Step(double* r, double budget, double slack, double kappa, double& objective);
  void Report(const double* r, double budget, double rawBudget, Result& result);
  double BoundKappa() const;
  double ClosedForm(double* r, double budget);
  bool ProjectedStep(double* r, double slack, double kappa0, double& objective, std::size_t& changes);
  /// The kappa of ProjectedStep()'s solution (a safeguarded Newton iteration from kappa0).
  bool ProjectedRoot(double slack, double kappa0, double& solution);
  std::size_t LineStep(double* r, double kappa, double& objective);
  bool Release(double kappa, bool slackTime);
  bool TimeUp();

  Options Opts;
  // Per-object data of the current call (sized to the largest n seen).
  std::vector<double> T, Lo, C, G, Scratch;
  std::vector<std::uint8_t> State;
  std::vector<std::uint32_t> Order; // the multiplier search's candidates
  std::vector<double> Candidates;   // their tmax, g and rmin
  std::vector<double> BucketCost;    // reducible cost per bucket and lane
  int BucketLow = 1 << 30, BucketHigh = -1; // buckets touched since cleared
  // Current call.
  std::size_t N = 0;
  double Alpha = 1.0, Gamma = 0.5;
  long StepCount = 0;
  std::size_t Work = 0;
  bool Expired = false;
  double Deadline = 0.0; // steady clock seconds
};
}

#endif

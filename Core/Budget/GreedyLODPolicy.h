// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_GreedyLODPolicy_h
#define timecritical_GreedyLODPolicy_h

#include "GreedyTupleSelector.h"
#include "ResolutionPolicy.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace timecritical
{
/**
 * Funkhouser & Séquin's incremental cost/benefit optimization over discrete
 * levels of detail (section 6 of their paper), the predictive LOD baseline.
 *
 * Starting from last frame's levels (the lowest for newly visible objects),
 * each iteration increments the object with the highest Value, then
 * decrements the objects with the lowest Value until the predicted time fits
 * the budget; it stops when the same object's level is both incremented and
 * decremented in one iteration, or nothing can be incremented.
 *
 * Value of a level step = decrease of the eq. 11 degradation per unit of
 * predicted time (the marginal benefit/cost ratio; for the convex error
 * curves of eq. 9 it is the greedy of the multiple-choice knapsack's
 * relaxation), so that this policy optimizes the same objective as the
 * active-set one and the two can be compared. Hysteresis (their benefit
 * factor for temporal coherence) is PolicyInput::Hysteresis h, the one
 * setting of every policy (HysteresisBand): the value of a step away from
 * last frame's level is multiplied by (1 - h) upward and divided by it
 * downward, so small changes in the scene do not make levels flip-flop. This
 * is the band's rule (a change must pay for itself by 1 / (1 - h) in
 * marginal value) applied to discrete moves, whose levels lie a factor of
 * about 2 apart, outside the band's resolution form for small h.
 *
 * Levels default to the paper's six LODs 100, 50, 25, 12, 6, 3 %; below rmin
 * a level costs as much as rmin (eq. 3) and is not used. Indexed heaps make
 * each move O(log n); buffers are reused across frames.
 *
 * SelectTuples() chooses (rendering algorithm, level) tuples and the levels
 * below the coarsest mesh instead, over the same levels, with
 * GreedyTupleSelector (Funkhouser & Séquin's greedy by benefit / cost, with
 * its bound of half the optimum); the renderer applies the hysteresis band
 * to the tuples' resolutions.
 */
class TIMECRITICALBUDGETCORE_EXPORT GreedyLODPolicy : public ResolutionPolicy
{
public:
  GreedyLODPolicy();

  const char* GetName() const override { return "greedy"; }

  /// Level resolutions in (0, 1], any order; 1 is always included.
  void SetLevels(const double* levels, std::size_t count);
  const std::vector<double>& GetLevels() const { return this->Levels; }

  /// Tuples for the frame (GreedyTupleSelector::Solve()); throws std::invalid_argument on bad input.
  TupleProblem::Solution SelectTuples(const TupleProblem& problem, int* algorithms, double* r)
  {
    return this->Tuples.Solve(problem, algorithms, r);
  }

protected:
  void Choose(const PolicyInput& input, double* r, PolicyResult& result) override;

private:
  /// Binary heap over object ids with a key per id and positions, so keys update in O(log n).
  class Heap
  {
  public:
    void Reset(std::size_t n, bool maxFirst);
    bool Empty() const { return this->Size == 0; }
    std::uint32_t Top() const { return this->Items[0]; }
    double TopKey() const { return this->Key[this->Items[0]]; }
    void Set(std::uint32_t id, double key);
    void Remove(std::uint32_t id);

  private:
    bool Before(std::uint32_t a, std::uint32_t b) const;
    void Up(std::size_t at);
    void Down(std::size_t at);
    void Place(std::size_t at, std::uint32_t id);

    std::vector<std::uint32_t> Items;
    std::vector<std::int64_t> Position;
    std::vector<double> Key;
    std::size_t Size = 0;
    bool MaxFirst = true;
  };

  double Resolution(std::size_t i, int level) const;
  double UpValue(std::size_t i) const;
  double DownValue(std::size_t i) const;
  void Refresh(std::size_t i);

  std::vector<double> Levels; // ascending, last = 1
  // Current frame.
  const PolicyInput* Input = nullptr;
  std::vector<int> Level, MinLevel, PreviousLevel;
  std::vector<double> Lo, C, T;
  Heap Ups, Downs;
  GreedyTupleSelector Tuples; // over the same Levels
};
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TupleProblem_h
#define timecritical_TupleProblem_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>
#include <vector>

namespace timecritical
{
/**
 * The per-frame choice of Funkhouser & Séquin's object tuples (O, L, R): for
 * every object, a rendering algorithm a (of AlgorithmCount) and a resolution
 * r, or one of the two levels below the coarsest mesh (a bounding-box outline
 * or nothing), with Gobbetti & Bouvier's continuous resolutions:
 *
 *   minimize   sum_i D_i(a_i, r_i)
 *   subject to sum_i C_i(a_i, r_i) <= Budget
 *
 *   D_i(a, r) = c_ia / alpha_a * min(r, hi_ia)^-alpha_a + E_ia   (eq. 9, per algorithm)
 *   C_i(a, r) = F_ia + T_ia * r,   lo_ia <= r <= 1                (eq. 2-4, per algorithm)
 *   D_i(box) = BoxDegradation_i, C_i(box) = BoxCost_i
 *   D_i(not drawn) = DropDegradation_i, C_i(not drawn) = 0
 *
 * Per-tuple arrays are row-major, [i * AlgorithmCount + a]; a null optional
 * array means its default. hi_ia is where more resolution stops paying
 * (Funkhouser's samples capped at the covered pixels): the degradation is
 * flat above it, so no solver goes above max(lo_ia, hi_ia). T_ia = 0 (a cost
 * model that failed) pins the tuple at lo_ia, as in ActiveSetOptimizer.
 *
 * The levels below the coarsest mesh are used only when AllowDrop is set and
 * even the cheapest drawn tuple of every object does not fit: a still frame
 * (AllowDrop off) draws everything. A non-owning view, like ResolutionProblem.
 */
struct TIMECRITICALBUDGETCORE_EXPORT TupleProblem
{
  /// Values of an object's algorithm index for the levels below the coarsest mesh.
  static constexpr int BoundingBox = -1;
  static constexpr int NotDrawn = -2;

  std::size_t Count = 0;          ///< objects
  std::size_t AlgorithmCount = 0; ///< algorithms each object may use (>= 1)
  const double* Alpha = nullptr;  ///< AlgorithmCount exponents, each > -1 and != 0
  const double* Weight = nullptr; ///< c_ia >= 0
  const double* Offset = nullptr; ///< E_ia, resolution-independent degradation (null: 0)
  const double* MaxTime = nullptr;       ///< T_ia >= 0 (s): time of the resolution-dependent part at r = 1
  const double* FixedCost = nullptr;     ///< F_ia >= 0 (s): time that r does not change (null: 0)
  const double* MinResolution = nullptr; ///< lo_ia in (0, 1] (null: TinyResolution)
  const double* MaxResolution = nullptr; ///< hi_ia in (0, 1] (null: 1)
  const double* BoxCost = nullptr;        ///< per object (null: no bounding-box level)
  const double* BoxDegradation = nullptr; ///< per object, required with BoxCost
  const double* DropDegradation = nullptr; ///< per object, required with AllowDrop
  bool AllowDrop = false; ///< levels below the coarsest mesh allowed (interactive frames)
  /// Dropping strictly by value: see ImposeStrictValueOrder(). Off: only
  /// FindValueOrderViolation()'s weaker order holds.
  bool StrictValueOrder = false;
  double Budget = 0.0;    ///< t_desired - t_fixed (s)

  /// What a tuple solver reports.
  struct Solution
  {
    double Objective = 0.0;  ///< sum of D_i at the answer
    double Cost = 0.0;       ///< sum of C_i at the answer
    double LowerBound = 0.0; ///< no answer has a smaller objective (solver-specific; see each)
    double Multiplier = 0.0; ///< lambda of the time constraint (TupleOptimizer)
    bool Infeasible = false; ///< over budget even at the cheapest choice allowed
    bool Dropping = false;   ///< the levels below the coarsest mesh were in play
    std::size_t Boxed = 0, Dropped = 0; ///< objects drawn as a box, not drawn
    int Iterations = 0;      ///< solver-specific passes over the objects
  };

  static constexpr double TinyResolution = 1e-6;

  /**
   * Throws std::invalid_argument, naming the first problem: objects without
   * an algorithm, a missing array, an alpha out of range, a negative or
   * non-finite weight, time or cost, a non-finite offset or degradation, a
   * resolution outside (0, 1] or NaN, a NaN budget.
   */
  void Validate() const;

  double Lo(std::size_t i, std::size_t a) const;
  /// max(lo, hi): the largest resolution worth drawing.
  double Hi(std::size_t i, std::size_t a) const;
  /// D_i for algorithm index a (or BoundingBox, NotDrawn) at resolution r.
  double Degradation(std::size_t i, int a, double r) const;
  /// C_i for algorithm index a (or BoundingBox, NotDrawn) at resolution r (clamped up to lo).
  double Cost(std::size_t i, int a, double r) const;
  /// The cheapest drawn tuple of object i (lowest cost; ties: lowest degradation).
  int CheapestAlgorithm(std::size_t i) const;

  /// Sums over all objects of a choice (algorithms: Count indices; r: Count resolutions).
  double Objective(const int* algorithms, const double* r) const;
  double TotalCost(const int* algorithms, const double* r) const;
  /// Whether the levels below the coarsest mesh are in play: AllowDrop and the
  /// cheapest drawn tuples exceed the budget.
  bool NeedsDropping() const;
  /// Working arrays of FindValueOrderViolation(), held by the solver and
  /// reused: no allocation once they have grown to the object count.
  struct ValueOrderScratch
  {
    std::vector<double> Cheapest;
    std::vector<std::size_t> Order, Costliest;
  };
  /**
   * The value order of dropping: finds an object not drawn (dropped) while a
   * less valuable one (smaller DropDegradation: less to lose) whose
   * cheapest tuple costs more is drawn with a mesh (drawn); false when there
   * is none. O(n log n); allocates only when scratch grows.
   */
  bool FindValueOrderViolation(const int* algorithms, std::size_t& dropped, std::size_t& drawn,
    ValueOrderScratch& scratch) const;
  /**
   * The strict value order of dropping: in descending value, an object not
   * drawn whose cheapest tuple costs no more than the cheapest tuples of all
   * the less valuable drawn objects together is drawn at its cheapest tuple,
   * and the least valuable drawn objects are dropped, fewest first, until
   * they free that much. So an object is dropped only while every less
   * valuable one is dropped too, or could not make room for it; the cost of
   * the choice does not grow. Changes `algorithms` in place (the caller
   * solves the resolutions again) and returns the objects changed. O(n log
   * n); allocates only when scratch grows.
   */
  std::size_t ImposeStrictValueOrder(int* algorithms, ValueOrderScratch& scratch) const;
  /// Fill in Objective, Cost, Boxed, Dropped of s from a choice.
  void Summarize(const int* algorithms, const double* r, Solution& s) const;
};
}

#endif

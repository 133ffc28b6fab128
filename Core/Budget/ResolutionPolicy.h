// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_ResolutionPolicy_h
#define timecritical_ResolutionPolicy_h

#include "HysteresisBand.h"
#include "ResolutionProblem.h"
#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>
#include <limits>

namespace timecritical
{
/// Everything a policy may use for one frame (non-owning, structure of arrays).
struct TIMECRITICALBUDGETCORE_EXPORT PolicyInput
{
  std::size_t Count = 0;
  const double* Weight = nullptr;        ///< c_i (DegradationModel), all policies judged on it
  const double* MaxTime = nullptr;       ///< tmax_i (FrameCostModel)
  const double* MinResolution = nullptr; ///< rmin_i (FrameCostModel)
  const double* Pixels = nullptr;        ///< Npix_i (threshold policies)
  const double* MaxTriangles = nullptr;  ///< Nmaxtri_i (threshold policies)
  const double* Previous = nullptr;      ///< last frame's r_i (NaN: newly visible); null: none
  double Alpha = 1.0;                    ///< degradation exponent (eq. 9)
  double TargetFrameTime = 0.1;          ///< t_desired (s)
  double FixedTime = 0.0;                ///< t_fixed (s) (eq. 4)
  double LastFrameTime = std::numeric_limits<double>::quiet_NaN(); ///< measured, previous frame
  /// h in [0, 1): a change from Previous must pay for itself by 1 / (1 - h) in
  /// marginal value (HysteresisBand); 0: none. Needs Previous.
  double Hysteresis = 0.0;

  /// The eq. 11 problem of this frame (Budget = TargetFrameTime - FixedTime).
  ResolutionProblem GetProblem() const;
};

/// What a policy reports for its choice.
struct TIMECRITICALBUDGETCORE_EXPORT PolicyResult
{
  double PredictedFrameTime = 0.0; ///< FixedTime + sum tmax_i max(r_i, rmin_i)
  double Objective = 0.0;          ///< f(r) of eq. 11: comparable across policies
  int Iterations = 0;              ///< policy-specific (optimizer iterations, greedy moves)
  bool Converged = true;           ///< the policy finished its own procedure
  bool OverBudget = false;         ///< PredictedFrameTime > TargetFrameTime
  double Seconds = 0.0;            ///< time spent choosing
  std::size_t Held = 0;            ///< objects kept at last frame's r by the hysteresis band
};

/**
 * A way of choosing per-object resolutions for a frame: the time-critical
 * optimizer and the baselines it is compared with (none, static threshold,
 * feedback threshold, Funkhouser & Séquin's greedy) share this interface, so
 * the renderer and the benchmarks swap them freely. Select() times the choice
 * and evaluates every policy with the same cost and degradation models.
 */
class TIMECRITICALBUDGETCORE_EXPORT ResolutionPolicy
{
public:
  virtual ~ResolutionPolicy();
  virtual const char* GetName() const = 0;

  /**
   * Choose r (input.Count values, each in [rmin_i, 1]). Then, for every
   * policy alike, the hysteresis band (HysteresisBand) keeps last frame's
   * resolution of the objects whose new one lies within it, within the
   * budget left. Throws std::invalid_argument for a hysteresis outside [0, 1).
   */
  PolicyResult Select(const PolicyInput& input, double* r);

  /// Forget any state carried between frames.
  virtual void Reset() {}

protected:
  virtual void Choose(const PolicyInput& input, double* r, PolicyResult& result) = 0;

private:
  HysteresisBand Band;
};
}

#endif

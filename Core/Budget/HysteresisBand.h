// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_HysteresisBand_h
#define timecritical_HysteresisBand_h

#include "TimeCriticalBudgetCoreExport.h"

#include <cstddef>
#include <vector>

namespace timecritical
{
/**
 * Hysteresis on the per-object choice, the one mechanism every policy uses
 * (Funkhouser & Séquin's benefit factor for temporal coherence): a change of
 * an object's resolution from last frame must pay for itself by a factor
 * 1 / (1 - h) in marginal value (degradation saved per second of predicted
 * time), so small changes in the scene do not make resolutions flip-flop.
 *
 * For eq. 11 the marginal value of object i at r is c_i r^-(alpha+1) / tmax_i,
 * so the dead zone of that rule around last frame's r_prev is, in resolution,
 * the band
 *
 *   r_prev / B <= r <= r_prev * B,   B = (1 - h)^(-1 / (alpha + 1)),
 *
 * and Apply() keeps r_prev for every object whose new choice lies in it. The
 * greedy policy, whose levels are a factor of about 2 apart (outside any such
 * band for small h), applies the same factor to its move values instead
 * (GreedyLODPolicy); both read the one setting, PolicyInput::Hysteresis.
 *
 * The band never costs the frame its budget: holds that lower the predicted
 * time are applied first, then those that raise it, cheapest first, while the
 * total stays within the choice's cost plus the slack the caller allows (the
 * budget left; 0 when the choice was already over it). Objects without a last
 * resolution (NaN or <= 0: new, back from culling, dropped) or not drawn now
 * (r <= 0) are never held, nor a last resolution below this frame's rmin
 * (holding it would save nothing) or above 1.
 *
 * Working arrays are kept and reused: no allocation once they have grown to
 * the object count.
 */
class TIMECRITICALBUDGETCORE_EXPORT HysteresisBand
{
public:
  /// One frame's objects (non-owning, Count entries each; MinResolution may be null: none).
  struct Input
  {
    std::size_t Count = 0;
    const double* MaxTime = nullptr;       ///< tmax_i >= 0 (s): time of the resolution-dependent part at r = 1
    const double* MinResolution = nullptr; ///< rmin_i: below it lowering r saves nothing (eq. 3)
    const double* Previous = nullptr;      ///< last frame's r_i (NaN or <= 0: none)
    double Alpha = 1.0;                    ///< degradation exponent (eq. 9), > -1 and != 0
    double Slack = 0.0;                    ///< seconds the holds may add in all (>= 0)
  };

  /// The band factor B of hysteresis h in [0, 1) and exponent alpha; throws std::invalid_argument.
  static double Factor(double hysteresis, double alpha);

  /// Throws std::invalid_argument unless h is finite and in [0, 1).
  static void CheckHysteresis(double hysteresis);

  /**
   * Holds the objects of r whose choice lies in the band around last frame's
   * (see the class comment); returns how many were held. h = 0, no Previous
   * or no MaxTime: nothing. Throws std::invalid_argument for a bad h or alpha.
   */
  std::size_t Apply(const Input& input, double hysteresis, double* r);

private:
  std::vector<std::size_t> Raise; // holds that add time, sorted by what they add
  std::vector<double> Extra;
};
}

#endif

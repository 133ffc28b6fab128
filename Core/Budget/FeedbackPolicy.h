// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_FeedbackPolicy_h
#define timecritical_FeedbackPolicy_h

#include "ResolutionPolicy.h"

namespace timecritical
{
/**
 * Feedback detail elision (Funkhouser & Séquin's "Feedback", IRIS Performer
 * style): the static pixels-per-triangle rule with its threshold k adapted
 * from the previous frame's measured time. The controller acts on log k,
 * where the plant is roughly linear (triangles ~ 1/k):
 *   log k += Kp (e_j - e_{j-1}) + Ki e_j,   e_j = log(t_measured / t_target)
 * i.e. a PI controller in velocity form; Kp = 0 is the usual multiplicative
 * update k *= (t / t_target)^Ki. The change per frame is limited to MaxStep.
 * Anti-windup: k is not pushed further while the last frame's choice was
 * saturated in that direction (everything at full resolution, or at rmin).
 * Reactive by nature: it overshoots when the scene changes abruptly, which is
 * what the predictive policies are compared against.
 */
class TIMECRITICALBUDGETCORE_EXPORT FeedbackPolicy : public ResolutionPolicy
{
public:
  struct Gains
  {
    double Proportional = 0.0;
    double Integral = 0.7;
    double MaxStep = 4.0; ///< k changes by at most this factor per frame
    double MinPixelsPerTriangle = 1e-3;
    double MaxPixelsPerTriangle = 1e6;
  };

  FeedbackPolicy();

  const char* GetName() const override { return "feedback"; }
  void Reset() override;

  void SetGains(const Gains& gains) { this->Control = gains; }
  const Gains& GetGains() const { return this->Control; }
  /// Starting threshold (and the one Reset() returns to).
  void SetInitialPixelsPerTriangle(double k);
  double GetPixelsPerTriangle() const { return this->PixelsPerTriangle; }

protected:
  void Choose(const PolicyInput& input, double* r, PolicyResult& result) override;

private:
  Gains Control;
  double InitialPixelsPerTriangle = 8.0;
  double PixelsPerTriangle = 8.0;
  double LastError = 0.0;
  bool HasLastError = false;
  bool SaturatedHigh = false; ///< last choice: every object at 1
  bool SaturatedLow = false;  ///< last choice: every object at rmin
};
}

#endif

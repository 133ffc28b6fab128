// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_FrameTimeCorrector_h
#define timecritical_FrameTimeCorrector_h

#include "TimeCriticalBudgetCoreExport.h"

#include <array>

namespace timecritical
{
/**
 * Short-term correction and spread of frame-time predictions.
 *
 * The cost model is linear in a few features (triangles, covered pixels, draw
 * calls) fitted over the last tens of frames, but a software rasterizer's
 * true cost also follows what those features miss (triangle sizes, overlap,
 * clipping), which changes with the view. This tracks the ratio measured /
 * predicted as an exponential average of its logarithm, so that a view whose
 * cost the model misjudges is corrected within a few frames, and the spread
 * of that ratio (1.4826 x the median absolute log residual of the last
 * Window frames: a robust standard deviation), which sizes the safety margin
 * of the time budget. Rare stalls of the machine (frames twice as long for
 * no reason in the scene) neither inflate the spread nor move the factor
 * much: each sample's log ratio is clamped to the current estimate plus or
 * minus max(3 spread, MinimumClamp). Non-finite or non-positive times are
 * ignored. No allocation.
 */
class TIMECRITICALBUDGETCORE_EXPORT FrameTimeCorrector
{
public:
  struct Options
  {
    double Gain = 0.3;           ///< weight of a new sample in the factor (0: never corrects)
    double InitialSpread = 0.15; ///< relative spread assumed before MinimumSamples (cautious)
    double MinimumClamp = 0.25;  ///< smallest clamp of a sample's log ratio
    double MaxLogFactor = 1.0;   ///< |log factor| never exceeds this (e^1 = 2.7x)
  };

  FrameTimeCorrector() = default;
  explicit FrameTimeCorrector(const Options& options);

  void SetOptions(const Options& options) { this->Opts = options; }
  const Options& GetOptions() const { return this->Opts; }

  /// Forget every sample.
  void Reset();

  /// Fold in one frame: the uncorrected prediction and the measured time.
  /// Returns false when the sample was ignored.
  bool Update(double predicted, double measured);

  /// Multiplier of the predictions (1 before any sample).
  double GetFactor() const;
  /// prediction * factor.
  double Correct(double predicted) const { return predicted * this->GetFactor(); }
  /// Robust standard deviation of log(measured / corrected prediction), ~ relative spread.
  double GetRelativeSpread() const { return this->Spread; }

  static constexpr int Window = 32;         ///< residuals kept for the spread
  static constexpr int MinimumSamples = 8;  ///< before that, InitialSpread
  long GetSampleCount() const { return this->Samples; }

private:
  Options Opts;
  double LogFactor = 0.0;
  double Spread = Options().InitialSpread;
  long Samples = 0;
  std::array<double, Window> Residuals{}; ///< |log residual| of the last frames (ring)
};
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CostModelCalibrator_h
#define timecritical_CostModelCalibrator_h

#include "TimeCriticalBudgetCoreExport.h"

#include <array>
#include <cstddef>

namespace timecritical
{
/// Settings of CostModelCalibrator (outside the class so that it can be a default argument).
struct CostModelCalibratorOptions
{
  double Forgetting = 0.98;      ///< lambda of RLS, memory ~ 1 / (1 - lambda) frames
  double OutlierThreshold = 2.5; ///< Huber threshold, in robust scales
  double RejectThreshold = 6.0;  ///< ignore beyond, in robust scales
  int ChangeWindow = 16;         ///< recent frames watched for a change of regime (<= 16)
  int ChangeCount = 10;          ///< rejections in a recent block that mean a new regime
  double PriorWeight = 1e-3;     ///< ridge towards the prior coefficients (scaled features)
  double MinimumScale = 1e-5;    ///< floor of the robust scale (s)
  double RelativeMinimumScale = 0.002; ///< floor of the robust scale relative to the mean time
};

/**
 * Online estimation of the cost model's coefficients from measured frame
 * times: time = theta . x with theta >= 0, x the frame's features (e.g.
 * FrameCostModel::GetFeatures(): 1, draw calls, objects, triangles, pixels).
 *
 * Why each part:
 * - recursive least squares with a forgetting factor, in information form
 *   (R = lambda R + w z z', b = lambda b + w z t): old frames fade so the fit
 *   follows the hardware's state and the view mix; a constant ridge towards
 *   the prior keeps R invertible when a feature does not vary (no wind-up);
 * - theta >= 0 exactly: each update solves min theta'R theta - 2 b'theta,
 *   theta >= 0 (Lawson-Hanson, d <= 20, microseconds). Clamping a
 *   covariance-form RLS estimate instead makes the recursion inconsistent;
 * - robustness: frame times have outliers (page faults, scheduling). The
 *   a-priori residual is compared with a robust scale (1.4826 x median of
 *   recent |residuals|): beyond OutlierThreshold the frame is down-weighted
 *   (Huber), beyond RejectThreshold ignored;
 * - change detection: rejecting outliers also rejects a genuine change of
 *   the hardware. When the most recent frames (at most ChangeWindow, all but
 *   one) include ChangeCount rejected ones (random spikes do not do that;
 *   either side counts, as a poor model of a new regime errs both ways),
 *   the estimator is refitted on that block alone (least absolute
 *   deviations, then Huber IRLS, non-negative: a spike among the frames
 *   does not spoil it), with its residual scale; forgetting then refines it.
 *   A refit that a quarter of the block disagrees with is retried on the
 *   next frame (the block then holds one more frame of the new regime);
 * - features scaled internally (triangles ~ 1e6, draw calls ~ 10);
 *   non-finite samples are ignored. No allocation after construction.
 * FitBatch() is the start-up calibration: a robust (Huber IRLS)
 * non-negative least-squares fit of a set of (features, time) samples.
 */
class TIMECRITICALBUDGETCORE_EXPORT CostModelCalibrator
{
public:
  static constexpr std::size_t MaxFeatures = 20; ///< 17 for four algorithms (AlgorithmCostModel)
  static constexpr std::size_t MaxWindow = 31;

  using Options = CostModelCalibratorOptions;

  struct Statistics
  {
    long Accepted = 0;     ///< full weight (main estimator)
    long DownWeighted = 0; ///< Huber-weighted
    long Rejected = 0;     ///< ignored as outliers
    long Invalid = 0;      ///< non-finite or non-positive input
    long Changes = 0;      ///< changes of regime detected (refits)
  };

  /// featureCount in [1, MaxFeatures]; scales: typical magnitude of each feature (may be null).
  explicit CostModelCalibrator(std::size_t featureCount, const Options& options = Options(),
    const double* scales = nullptr);

  std::size_t GetFeatureCount() const { return this->D; }
  void SetOptions(const Options& options) { this->Opts = options; }
  const Options& GetOptions() const { return this->Opts; }

  /**
   * Prior coefficients (e.g. defaults), also the current estimate; negative
   * or non-finite ones become 0. Forgets the accumulated information.
   * frames: how much the prior counts, in frames whose features are at the
   * scales given to the constructor (0: only PriorWeight, which the first
   * frames override; coefficients
   * measured elsewhere deserve more, or two or three frames whose features
   * move together can drive any coefficient anywhere). It fades with the
   * forgetting factor like data.
   */
  void SetCoefficients(const double* theta, double frames = 0.0);
  /**
   * Lower bounds of the coefficients (unscaled, FeatureCount values; null or
   * non-positive: 0). Every estimate honours them: the online fit, a refit
   * after a change of regime and Calibrate(). Non-negativity alone lets a
   * fit drive a coefficient to 0 when its feature moves with another one or
   * when the measured time stops depending on it (a time-critical renderer
   * holds the frame time constant whatever the triangles), and a triangle
   * that costs nothing makes the optimizer draw everything. The current
   * estimate is raised to the bounds at once.
   */
  void SetLowerBounds(const double* lower);
  double GetLowerBound(std::size_t j) const;

  /// theta (unscaled), FeatureCount values, all >= their lower bounds and finite.
  void GetCoefficients(double* theta) const;
  double GetCoefficient(std::size_t j) const;

  /// Fold in one frame. Returns false when it was ignored (invalid or outlier).
  bool Update(const double* x, double time);

  /// Predicted time for features x.
  double Predict(const double* x) const;

  /// Robust scale of the residuals (s), 0 before any sample.
  double GetResidualScale() const { return this->Main.Scale; }
  const Statistics& GetStatistics() const { return this->Stats; }
  long GetSampleCount() const { return this->Samples; }

  /**
   * Robust non-negative least squares over samples rows of x (row-major,
   * samples x featureCount) and times, with theta >= lower when lower is
   * given; theta receives featureCount values. Returns false (theta = 0)
   * when there are no valid samples.
   */
  static bool FitBatch(const double* x, const double* times, std::size_t samples,
    std::size_t featureCount, double* theta, const Options& options = Options(),
    double* residualScale = nullptr, const double* lower = nullptr);

  /// FitBatch() and initialize the online state from it.
  bool Calibrate(const double* x, const double* times, std::size_t samples);

private:
  /// Robust information-form RLS state (coefficients of the scaled features).
  struct Estimator
  {
    std::array<double, MaxFeatures> Theta{};
    std::array<double, MaxFeatures> Prior{};
    std::array<double, MaxFeatures * MaxFeatures> R{};
    std::array<double, MaxFeatures> B{};
    std::array<double, MaxWindow> Residuals{}; ///< recent |a-priori residuals| of used frames
    std::size_t Count = 0, Next = 0;
    double Scale = 0.0;
  };
  static constexpr std::size_t MaxFrames = 16;

  void Reset(double priorWeight);
  double Weight(double residual) const;
  void Push(double residual);
  void Accumulate(const double* z, double time, double weight);
  void Solve();
  void Rescale(const double* x);
  bool Refit();

  std::size_t D;
  Options Opts;
  Statistics Stats;
  long Samples = 0;
  double MeanTime = 0.0;
  std::array<double, MaxFeatures> FeatureScale{};
  std::array<double, MaxFeatures> Lower{}; ///< lower bounds, unscaled
  Estimator Main;
  // The last frames: raw features, time, and -1/0/+1 = rejected below / used / rejected above.
  std::array<std::array<double, MaxFeatures>, MaxFrames> FrameFeatures{};
  std::array<double, MaxFrames> FrameTimes{};
  std::array<int, MaxFrames> FrameSide{};
  std::size_t FrameCount = 0, FrameNext = 0;
};
}

#endif

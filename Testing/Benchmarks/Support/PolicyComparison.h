// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PolicyComparison_h
#define timecritical_PolicyComparison_h

/**
 * What the policy-comparison benchmarks (W1, W2) share: the per-frame record
 * fields every policy run measures, the statistics computed once from those
 * records, their JSON fields and the table cells. A benchmark derives its own
 * frame record from PolicyFrame and its statistics from PolicyStatistics to
 * add what only it measures.
 */
#include "BenchmarkJson.h"
#include "BenchmarkTiming.h"

#include <string>
#include <vector>

namespace timecritical
{
namespace benchmark
{
/// The fields every policy run records per frame.
struct PolicyFrame
{
  double Measured = NaN;  ///< wall clock around Render() (+ glFinish), seconds
  double Predicted = NaN; ///< vtkTimeCriticalRenderer's prediction, seconds
  double Triangles = 0.0; ///< triangles drawn
  double PSNR = NaN;      ///< against the full-resolution frame of the same camera
  bool Identical = false; ///< the image equals that frame
};

/// Statistics of PolicyFrame fields over one policy run (NaN where undefined).
struct PolicyStatistics
{
  int Frames = 0;
  double Mean = NaN, Median = NaN, Min = NaN, Max = NaN, CV = NaN;
  double ShareWithin = NaN; ///< frames <= 1.1 target
  double PredictionError = NaN, PredictionErrorMax = NaN; ///< |predicted - measured| / measured
  double TrianglesMean = NaN, TrianglesMedian = NaN;
  double PSNRMean = NaN, PSNRMedian = NaN, PSNRMin = NaN;
  int PSNRFrames = 0, IdenticalFrames = 0;
};

/// Collects PolicyFrames one at a time and computes PolicyStatistics.
class PolicyStatisticsAccumulator
{
public:
  explicit PolicyStatisticsAccumulator(double target);
  void Add(const PolicyFrame& frame);
  PolicyStatistics Compute() const;

private:
  double Target;
  int Within = 0, Identical = 0;
  std::vector<double> Measured, Error, Triangles, PSNR;
};

/// The common statistics of a run's frames (any record derived from PolicyFrame).
template <typename Record>
PolicyStatistics ComputePolicyStatistics(const std::vector<Record>& frames, double target)
{
  PolicyStatisticsAccumulator accumulator(target);
  for (const PolicyFrame& frame : frames)
  {
    accumulator.Add(frame);
  }
  return accumulator.Compute();
}

/// The JSON fields (no braces) of the statistics every run has: frames, mean,
/// median, max, share_within_110_percent, prediction_error, triangles_mean,
/// psnr_mean, psnr_median, psnr_min, identical_frames.
std::string PolicyStatisticsJsonFields(const PolicyStatistics& s);

/// The JSON fields (no braces) of the per-frame arrays every run has:
/// measured, predicted, triangles, psnr, joined by separator.
template <typename Record>
std::string PolicyFramesJsonFields(const std::vector<Record>& f, const std::string& separator)
{
  return "\"measured\": " + Array(f, [](const Record& r) { return r.Measured; }) + separator +
    "\"predicted\": " + Array(f, [](const Record& r) { return r.Predicted; }) + separator +
    "\"triangles\": " + Array(f, [](const Record& r) { return r.Triangles; }, 10) + separator +
    "\"psnr\": " + Array(f, [](const Record& r) { return r.PSNR; }, 5);
}

/// Table cells: "-" for NaN, else milliseconds with the given decimals, a
/// percentage with one decimal, decibels with two decimals.
std::string MillisecondsCell(double seconds, int decimals = 1);
std::string PercentCell(double share);
std::string DecibelCell(double decibels);
}
}

#endif

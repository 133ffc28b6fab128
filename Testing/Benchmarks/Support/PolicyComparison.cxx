// SPDX-License-Identifier: BSD-3-Clause
#include "PolicyComparison.h"

#include "BenchmarkStatistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace timecritical
{
namespace benchmark
{
PolicyStatisticsAccumulator::PolicyStatisticsAccumulator(double target)
  : Target(target)
{
}

void PolicyStatisticsAccumulator::Add(const PolicyFrame& frame)
{
  this->Measured.push_back(frame.Measured);
  this->Within += frame.Measured <= 1.1 * this->Target ? 1 : 0;
  this->Triangles.push_back(frame.Triangles);
  if (std::isfinite(frame.Predicted) && frame.Measured > 0.0)
  {
    this->Error.push_back(std::abs(frame.Predicted - frame.Measured) / frame.Measured);
  }
  if (std::isfinite(frame.PSNR))
  {
    this->PSNR.push_back(frame.PSNR);
    this->Identical += frame.Identical ? 1 : 0;
  }
}

PolicyStatistics PolicyStatisticsAccumulator::Compute() const
{
  PolicyStatistics s;
  s.Frames = static_cast<int>(this->Measured.size());
  s.IdenticalFrames = this->Identical;
  if (this->Measured.empty())
  {
    return s;
  }
  const std::vector<double>& measured = this->Measured;
  s.Mean = Mean(measured);
  s.Median = Median(measured);
  s.Min = *std::min_element(measured.begin(), measured.end());
  s.Max = *std::max_element(measured.begin(), measured.end());
  double variance = 0.0;
  for (double x : measured)
  {
    variance += (x - s.Mean) * (x - s.Mean);
  }
  variance /= static_cast<double>(measured.size());
  s.CV = s.Mean > 0.0 ? std::sqrt(variance) / s.Mean : NaN;
  s.ShareWithin = static_cast<double>(this->Within) / static_cast<double>(measured.size());
  s.PredictionError = Mean(this->Error);
  s.PredictionErrorMax =
    this->Error.empty() ? NaN : *std::max_element(this->Error.begin(), this->Error.end());
  s.TrianglesMean = Mean(this->Triangles);
  s.TrianglesMedian = Median(this->Triangles);
  s.PSNRFrames = static_cast<int>(this->PSNR.size());
  s.PSNRMean = Mean(this->PSNR);
  s.PSNRMedian = Median(this->PSNR);
  s.PSNRMin = this->PSNR.empty() ? NaN : *std::min_element(this->PSNR.begin(), this->PSNR.end());
  return s;
}

std::string PolicyStatisticsJsonFields(const PolicyStatistics& s)
{
  std::ostringstream out;
  out << "\"frames\": " << s.Frames << ", \"mean\": " << Number(s.Mean)
      << ", \"median\": " << Number(s.Median) << ", \"max\": " << Number(s.Max)
      << ", \"share_within_110_percent\": " << Number(s.ShareWithin)
      << ", \"prediction_error\": " << Number(s.PredictionError)
      << ", \"triangles_mean\": " << Number(s.TrianglesMean, 9)
      << ", \"psnr_mean\": " << Number(s.PSNRMean) << ", \"psnr_median\": " << Number(s.PSNRMedian)
      << ", \"psnr_min\": " << Number(s.PSNRMin) << ", \"identical_frames\": " << s.IdenticalFrames;
  return out.str();
}

namespace
{
std::string Formatted(const char* format, double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}
}

std::string MillisecondsCell(double seconds, int decimals)
{
  if (!std::isfinite(seconds))
  {
    return "-";
  }
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals, 1000.0 * seconds);
  return buffer;
}

std::string PercentCell(double share)
{
  return std::isfinite(share) ? Formatted("%.1f%%", 100.0 * share) : "-";
}

std::string DecibelCell(double decibels)
{
  return std::isfinite(decibels) ? Formatted("%.2f", decibels) : "-";
}
}
}

// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkStatistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
namespace
{
constexpr double NotANumber = std::numeric_limits<double>::quiet_NaN();
}

double Mean(const std::vector<double>& values)
{
  if (values.empty())
  {
    return NotANumber;
  }
  double sum = 0.0;
  for (double x : values)
  {
    sum += x;
  }
  return sum / static_cast<double>(values.size());
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return NotANumber;
  }
  std::sort(values.begin(), values.end());
  const size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

double Percentile(std::vector<double> values, double p)
{
  if (!(p >= 0.0 && p <= 100.0))
  {
    throw std::invalid_argument("Percentile: p must be in [0, 100]");
  }
  if (values.empty())
  {
    return NotANumber;
  }
  std::sort(values.begin(), values.end());
  const double rank = p / 100.0 * static_cast<double>(values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(rank));
  const size_t above = std::min(below + 1, values.size() - 1);
  const double t = rank - static_cast<double>(below);
  return values[below] + t * (values[above] - values[below]);
}

double Maximum(const std::vector<double>& values)
{
  return values.empty() ? NotANumber : *std::max_element(values.begin(), values.end());
}
}
}

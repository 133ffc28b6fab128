// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkStatistics_h
#define timecritical_BenchmarkStatistics_h

/**
 * Summary statistics of timings and errors. Each returns NaN for an empty
 * sample, which the JSON writers turn into null.
 */
#include <vector>

namespace timecritical
{
namespace benchmark
{
double Mean(const std::vector<double>& values);

/// The middle value, or the mean of the two middle values of an even count.
double Median(std::vector<double> values);

/// The p-th percentile (0 <= p <= 100), linear between the closest ranks.
double Percentile(std::vector<double> values, double p);

/// The largest value.
double Maximum(const std::vector<double>& values);
}
}

#endif

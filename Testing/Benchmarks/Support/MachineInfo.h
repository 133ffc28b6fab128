// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_MachineInfo_h
#define timecritical_MachineInfo_h

/**
 * What the benchmarks record about the machine next to their figures:
 * timings are only as good as a quiet machine, so the load is written at the
 * start and end of every run.
 */
#include <array>
#include <string>

namespace timecritical
{
namespace benchmark
{
/// The 1, 5 and 15 minute load averages (NaN where the system gives none).
std::array<double, 3> LoadAverages();

/// The three load averages with two decimals, separated by spaces.
std::string LoadAverageText();

/// The CPU's model name from /proc/cpuinfo, or "unknown".
std::string CpuModel();

/// The current time, ISO 8601 in UTC (2000-01-31T12:00:00Z).
std::string UtcNow();
}
}

#endif

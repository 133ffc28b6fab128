// SPDX-License-Identifier: BSD-3-Clause
#include "MachineInfo.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <limits>

namespace timecritical
{
namespace benchmark
{
std::array<double, 3> LoadAverages()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::array<double, 3> load = { nan, nan, nan };
  double sample[3];
  const int count = getloadavg(sample, 3);
  for (int i = 0; i < count && i < 3; ++i)
  {
    load[static_cast<size_t>(i)] = sample[i];
  }
  return load;
}

std::string LoadAverageText()
{
  const std::array<double, 3> load = LoadAverages();
  char text[96];
  std::snprintf(text, sizeof(text), "%.2f %.2f %.2f", load[0], load[1], load[2]);
  return text;
}

std::string CpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const size_t value = line.find_first_not_of(" \t", line.find(':') + 1);
      return value == std::string::npos ? line : line.substr(value);
    }
  }
  return "unknown";
}

std::string UtcNow()
{
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}
}
}

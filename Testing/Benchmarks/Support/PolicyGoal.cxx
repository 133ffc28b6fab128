// SPDX-License-Identifier: BSD-3-Clause
#include "PolicyGoal.h"

#include "BenchmarkJson.h"

#include <cstdio>

namespace timecritical
{
namespace benchmark
{
void PrintGoals(const std::string& title, const std::vector<PolicyGoal>& goals, int nameWidth,
  int measuredWidth)
{
  std::printf("\n%s\n%-*s %-22s %-*s %s\n", title.c_str(), nameWidth, "goal", "required",
    measuredWidth, "measured", "status");
  for (const PolicyGoal& g : goals)
  {
    std::printf("%-*s %-22s %-*s %s\n", nameWidth, g.Name.c_str(), g.Required.c_str(),
      measuredWidth, g.Measured.c_str(), !g.Evaluated ? "n/a" : g.Met ? "met" : "MISSED");
  }
}

std::string GoalsJson(const std::vector<PolicyGoal>& goals)
{
  std::string out = "[";
  for (size_t g = 0; g < goals.size(); ++g)
  {
    out += std::string(g ? ", " : "") + "{\"goal\": " + Quoted(goals[g].Name) +
      ", \"required\": " + Quoted(goals[g].Required) + ", \"measured\": " +
      Quoted(goals[g].Measured) + ", \"met\": " +
      (!goals[g].Evaluated ? "null" : goals[g].Met ? "true" : "false") + "}";
  }
  return out + "]";
}
}
}

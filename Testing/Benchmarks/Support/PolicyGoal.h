// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PolicyGoal_h
#define timecritical_PolicyGoal_h

/**
 * The goals of the policy-comparison benchmarks (W1, W2): what each requires,
 * what the run measured and whether it was met, printed as a table and
 * written to the JSON report.
 */
#include <string>
#include <vector>

namespace timecritical
{
namespace benchmark
{
struct PolicyGoal
{
  std::string Name, Required, Measured;
  bool Met = false;
  bool Evaluated = true; ///< false when the run lacks what the goal compares with
};

/// "\n<title>" and one row per goal (status met, MISSED or n/a), with the
/// name and measured columns `nameWidth` and `measuredWidth` wide.
void PrintGoals(const std::string& title, const std::vector<PolicyGoal>& goals, int nameWidth,
  int measuredWidth);

/// The goals as a JSON array of {goal, required, measured, met} (met null
/// when not evaluated).
std::string GoalsJson(const std::vector<PolicyGoal>& goals);
}
}

#endif

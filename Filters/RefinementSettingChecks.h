// SPDX-License-Identifier: BSD-3-Clause
// VTK-level checks of the numeric settings of vtkExtractViewDependentMesh,
// vtkMultiresolutionPolyDataMapper and vtkTimeCriticalRenderer (view-dependent
// refinement, display, cost model): the rules and messages are those of the
// core checker (RefinementSettings.h), reported as an error on the object. A
// bad value (NaN, infinite or out of range) gives an error and false; the
// caller then keeps its setting. In Filters so that both Filters and
// Rendering (which sits above it) use the same checks.
#ifndef timecritical_RefinementSettingChecks_h
#define timecritical_RefinementSettingChecks_h

#include "RefinementSettings.h"
#include "vtkObject.h"
#include "vtkSetGet.h"

#include <cstdint>

namespace timecritical
{
/// Reports an invalid check as an error on `object`; returns whether it is valid.
inline bool ReportSettingCheck(vtkObject* object, const SettingCheck& check)
{
  if (!check.Valid)
  {
    vtkErrorWithObjectMacro(object, << check.Message << "; ignored.");
  }
  return check.Valid;
}

/// A finite number >= 0 (pixel thresholds, time limits).
inline bool CheckNonNegativeSetting(vtkObject* object, const char* name, double value)
{
  return ReportSettingCheck(object, CheckNonNegative(name, value));
}

/// A finite number > 0 (sizes, distances, resolutions).
inline bool CheckPositiveSetting(vtkObject* object, const char* name, double value)
{
  return ReportSettingCheck(object, CheckPositive(name, value));
}

/// A number in [minimum, maximum] (not clamped: an out-of-range value is a mistake).
inline bool CheckRangeSetting(
  vtkObject* object, const char* name, double value, double minimum, double maximum)
{
  return ReportSettingCheck(object, CheckRange(name, value, minimum, maximum));
}

/// A factor on the pixel threshold, in (0, 1].
inline bool CheckFactorSetting(vtkObject* object, const char* name, double value)
{
  return ReportSettingCheck(object, CheckFactor(name, value));
}

/// A triangle budget, in [0, MaximumTriangleBudget].
inline bool CheckTriangleBudgetSetting(vtkObject* object, const char* name, int64_t value)
{
  return ReportSettingCheck(object, CheckTriangleBudget(name, value));
}

/**
 * Setter body for a checked setting: keeps `member` and reports an error on
 * `object` when `check` fails, else assigns `value`. Returns true when
 * `member` changed (the caller then calls Modified()).
 */
template <typename T>
bool SetCheckedSetting(vtkObject* object, const SettingCheck& check, T value, T& member)
{
  if (!ReportSettingCheck(object, check) || member == value)
  {
    return false;
  }
  member = value;
  return true;
}
}

#endif

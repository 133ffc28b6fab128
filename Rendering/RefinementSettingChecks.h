// SPDX-License-Identifier: BSD-3-Clause
// Checks of the numeric settings of vtkMultiresolutionPolyDataMapper and
// vtkTimeCriticalRenderer (view-dependent refinement, display, cost model):
// one rule and one message per kind of setting. A bad value (NaN, infinite or
// out of range) gives an error and false; the caller then keeps its setting.
#ifndef timecritical_RefinementSettingChecks_h
#define timecritical_RefinementSettingChecks_h

#include "vtkObject.h"
#include "vtkSetGet.h"

#include <cmath>

namespace timecritical
{
/// A finite number >= 0 (pixel thresholds, time limits).
inline bool CheckNonNegativeSetting(vtkObject* object, const char* name, double value)
{
  if (!(value >= 0.0) || std::isinf(value))
  {
    vtkErrorWithObjectMacro(
      object, << name << " must be a finite number >= 0, not " << value << "; ignored.");
    return false;
  }
  return true;
}

/// A finite number > 0 (sizes, distances, resolutions).
inline bool CheckPositiveSetting(vtkObject* object, const char* name, double value)
{
  if (!(value > 0.0) || std::isinf(value))
  {
    vtkErrorWithObjectMacro(
      object, << name << " must be a finite number > 0, not " << value << "; ignored.");
    return false;
  }
  return true;
}

/// A number in [minimum, maximum] (not clamped: an out-of-range value is a mistake).
inline bool CheckRangeSetting(
  vtkObject* object, const char* name, double value, double minimum, double maximum)
{
  if (!(value >= minimum && value <= maximum))
  {
    vtkErrorWithObjectMacro(object, << name << " must be in [" << minimum << ", " << maximum
                                    << "], not " << value << "; ignored.");
    return false;
  }
  return true;
}

/// A factor on the pixel threshold, in (0, 1].
inline bool CheckFactorSetting(vtkObject* object, const char* name, double value)
{
  if (!(value > 0.0 && value <= 1.0))
  {
    vtkErrorWithObjectMacro(object, << name << " must be in (0, 1], not " << value << "; ignored.");
    return false;
  }
  return true;
}
}

#endif

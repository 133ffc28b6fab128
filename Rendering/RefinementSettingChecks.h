// SPDX-License-Identifier: BSD-3-Clause
// Checks of the view-dependent refinement settings that
// vtkMultiresolutionPolyDataMapper and vtkTimeCriticalRenderer both take:
// one rule and one message per kind of setting. A bad value gives an error
// and false; the caller then keeps its setting.
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

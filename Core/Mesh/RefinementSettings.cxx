// SPDX-License-Identifier: BSD-3-Clause
#include "RefinementSettings.h"

#include "ViewDependentRefinement.h"

#include <cmath>
#include <sstream>

namespace timecritical
{
namespace
{
SettingCheck Invalid(const char* name, const char* rule, double value)
{
  std::ostringstream message;
  message << name << " must be " << rule << ", not " << value;
  return { false, message.str() };
}
}

SettingCheck CheckNonNegative(const char* name, double value)
{
  if (!(value >= 0.0) || std::isinf(value))
  {
    return Invalid(name, "a finite number >= 0", value);
  }
  return {};
}

SettingCheck CheckPositive(const char* name, double value)
{
  if (!(value > 0.0) || std::isinf(value))
  {
    return Invalid(name, "a finite number > 0", value);
  }
  return {};
}

SettingCheck CheckRange(const char* name, double value, double minimum, double maximum)
{
  if (!(value >= minimum && value <= maximum))
  {
    std::ostringstream rule;
    rule << "in [" << minimum << ", " << maximum << "]";
    return Invalid(name, rule.str().c_str(), value);
  }
  return {};
}

SettingCheck CheckFactor(const char* name, double value)
{
  if (!(value > 0.0 && value <= 1.0))
  {
    return Invalid(name, "in (0, 1]", value);
  }
  return {};
}

SettingCheck CheckTriangleBudget(const char* name, int64_t value)
{
  if (value < 0 || value > MaximumTriangleBudget)
  {
    std::ostringstream message;
    message << name << " must be an integer in [0, " << MaximumTriangleBudget << "], not "
            << value;
    return { false, message.str() };
  }
  return {};
}

SettingCheck CheckRefinementMode(const char* name, int value)
{
  if (value != RefinementModeBudget && value != RefinementModeFixedAccuracy)
  {
    std::ostringstream message;
    message << name << " must be " << RefinementModeBudget << " (budget) or "
            << RefinementModeFixedAccuracy << " (fixed accuracy), not " << value;
    return { false, message.str() };
  }
  return {};
}

RefinementMode ClampRefinementMode(int mode)
{
  return mode <= RefinementModeBudget ? RefinementMode::Budget : RefinementMode::FixedAccuracy;
}

const char* RefinementModeName(RefinementMode mode)
{
  return mode == RefinementMode::FixedAccuracy ? "FIXED_ACCURACY" : "BUDGET";
}

void ApplyRefinementSettings(const RefinementSettings& settings, ViewDependentRefinement& refinement)
{
  refinement.SetPixelThreshold(settings.PixelThreshold);
  refinement.SetBackFaceSimplification(settings.BackFaceSimplification);
  refinement.SetSilhouetteRefinement(settings.SilhouetteRefinement);
  refinement.SetSilhouetteFactor(settings.SilhouetteFactor);
  refinement.SetHighlightRefinement(settings.HighlightRefinement);
  refinement.SetHighlightFactor(settings.HighlightFactor);
}

SettingCheck CheckRefinementSettings(const RefinementSettings& settings)
{
  for (SettingCheck check : { CheckNonNegative("PixelThreshold", settings.PixelThreshold),
         CheckFactor("SilhouetteFactor", settings.SilhouetteFactor),
         CheckFactor("HighlightFactor", settings.HighlightFactor),
         CheckNonNegative("TimeLimit", settings.TimeLimit),
         CheckTriangleBudget("TriangleBudget", settings.TriangleBudget) })
  {
    if (!check)
    {
      return check;
    }
  }
  return {};
}
}

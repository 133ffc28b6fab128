// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_RefinementSettings_h
#define timecritical_RefinementSettings_h

#include "TimeCriticalMeshCoreExport.h"

#include <cstdint>
#include <string>

namespace timecritical
{
/**
 * How a view-dependent front is chosen. One numbering for every class and
 * proxy that exposes it (vtkExtractViewDependentMesh,
 * vtkMultiresolutionPolyDataMapper, vtkTimeCriticalRenderer, the ParaView
 * filter and view): 0 is the budget mode, 1 the fixed-accuracy mode.
 */
enum class RefinementMode : int
{
  /// Refine where the projected error is largest until a triangle budget
  /// (the filter's TriangleBudget, or the renderer's resolution) is spent;
  /// PixelThreshold is a floor.
  Budget = 0,
  /// Split while a node's projected error exceeds PixelThreshold, whatever
  /// the front costs.
  FixedAccuracy = 1
};

/// The integers of RefinementMode, for the VTK enumerations and the XML files.
constexpr int RefinementModeBudget = static_cast<int>(RefinementMode::Budget);
constexpr int RefinementModeFixedAccuracy = static_cast<int>(RefinementMode::FixedAccuracy);

/**
 * The settings of view-dependent refinement that the filter, the mapper and
 * the renderer share, with their defaults. VTK-free, so that every layer can
 * hold and check them the same way.
 *
 * One rule per setting, the same in every class:
 * - numbers (PixelThreshold, the factors, TimeLimit, TriangleBudget) outside
 *   their range, NaN included, are rejected: the class reports an error
 *   (vtkErrorMacro) and keeps its previous value. A value out of range is a
 *   mistake, and silently moving it would hide it;
 * - Mode is clamped into [Budget, FixedAccuracy], as VTK does for its other
 *   enumerations (vtkSetClampMacro).
 * The Check*() functions below state each range and give the message.
 */
struct RefinementSettings
{
  RefinementMode Mode = RefinementMode::Budget;
  /// Screen-space error threshold in pixels, finite and >= 0 (0: full detail in view).
  double PixelThreshold = 1.0;
  /// Keep regions facing away from the camera coarse.
  bool BackFaceSimplification = true;
  /// Near silhouettes, multiply the threshold by SilhouetteFactor, in (0, 1].
  bool SilhouetteRefinement = true;
  double SilhouetteFactor = 0.25;
  /// Near specular highlights, multiply the threshold by HighlightFactor, in (0, 1].
  bool HighlightRefinement = true;
  double HighlightFactor = 0.5;
  /// Budget mode: seconds one update may spend, finite and >= 0 (0: no limit).
  double TimeLimit = 0.0;
  /// Budget mode of the filter: triangles of the front, in [0, MaximumTriangleBudget].
  int64_t TriangleBudget = 10000;
};

/// The largest triangle budget (the refinement counts triangles in 32-bit signed range).
constexpr int64_t MaximumTriangleBudget = 2147483647;

/// The outcome of a check: whether the value is valid, and if not, why.
struct SettingCheck
{
  bool Valid = true;
  std::string Message; ///< empty when valid, e.g. "PixelThreshold must be ... not -1"

  explicit operator bool() const { return this->Valid; }
};

///@{
/**
 * Checks of single values; `name` starts the message. The rules are those of
 * RefinementSettings, and of the renderer's other numeric settings (sizes,
 * distances, ranges), so that every class words a rejection the same way.
 */
/// A finite number >= 0 (pixel thresholds, time limits).
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckNonNegative(const char* name, double value);
/// A finite number > 0 (sizes, distances, resolutions).
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckPositive(const char* name, double value);
/// A number in [minimum, maximum].
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckRange(
  const char* name, double value, double minimum, double maximum);
/// A factor on the pixel threshold, in (0, 1].
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckFactor(const char* name, double value);
/// A triangle budget, an integer in [0, MaximumTriangleBudget].
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckTriangleBudget(const char* name, int64_t value);
/// A mode, 0 (budget) or 1 (fixed accuracy).
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckRefinementMode(const char* name, int value);
///@}

/// `mode` clamped into [Budget, FixedAccuracy] (the rule for the mode).
TIMECRITICALMESHCORE_EXPORT RefinementMode ClampRefinementMode(int mode);

/// "BUDGET" or "FIXED_ACCURACY" (the enumerators' names, for PrintSelf).
TIMECRITICALMESHCORE_EXPORT const char* RefinementModeName(RefinementMode mode);

class ViewDependentRefinement;

/**
 * Passes the threshold and the back-face, silhouette and highlight switches
 * and factors of `settings` to `refinement` (the mode, time limit and budget
 * are arguments of its updates).
 */
TIMECRITICALMESHCORE_EXPORT void ApplyRefinementSettings(
  const RefinementSettings& settings, ViewDependentRefinement& refinement);

/**
 * All numbers of `settings` at once (the mode is a valid enumerator by
 * construction): the first invalid one, or a valid check.
 */
TIMECRITICALMESHCORE_EXPORT SettingCheck CheckRefinementSettings(
  const RefinementSettings& settings);
}

#endif

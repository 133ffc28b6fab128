// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_W1SceneSpecification_h
#define timecritical_W1SceneSpecification_h

/**
 * The numbers that define W1's scene and camera path, read from W1Scene.json
 * (compiled in), which scripts/make_w1_scene.py reads too: the layout is
 * written once, for both generators. The field comments give the JSON names.
 */
#include <array>
#include <string>

namespace timecritical
{
namespace benchmark
{
struct W1SceneSpecification
{
  // defaults
  unsigned DefaultSeed = 0;
  int DefaultObjects = 0;
  int DefaultFrames = 0;
  // view
  int WindowSize = 0;
  double ViewAngle = 0.0;
  std::array<double, 3> Background{};
  // substitute_object
  int SubstituteLatitudes = 0;
  int SubstituteLongitudes = 0;
  double BumpAmplitude = 0.0;
  std::array<double, 3> BumpFrequencies{};
  std::array<double, 3> SubstituteScale{};
  // placement
  double Gap = 0.0;
  double JitterFractionOfGap = 0.0;
  std::array<double, 2> FocusNear{};
  // colors
  std::array<double, 2> Hue{}, Saturation{}, Value{};
  // camera_path (fractions of the extent L or of the footprint radius r)
  std::array<double, 3> AOffset{};
  double TargetHeight = 0.0;
  double BDistance = 0.0, BHeight = 0.0;
  std::array<double, 3> TurnDirection{};
  double TurnFocusDistance = 0.0;
  std::array<double, 3> CDirection{};
  double CDistance = 0.0, CHeight = 0.0;
  double KeyB = 0.0;
  double FocusEaseScale = 0.0;

  /// The specification parsed from `json`; throws std::runtime_error on
  /// malformed text or a missing or mistyped field.
  static W1SceneSpecification Parse(const std::string& json);

  /// The compiled-in W1Scene.json (parsed once).
  static const W1SceneSpecification& Get();
};
}
}

#endif

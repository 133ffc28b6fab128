// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_W1CameraPath_h
#define timecritical_W1CameraPath_h

#include "CameraPose.h"

namespace timecritical
{
namespace benchmark
{
struct Scene;

/**
 * W1's camera path (section 7.2.2), a pure function of the frame index: from
 * A (the whole herd in view) easing out to a stop at B (close to the focus
 * object), a one-frame turn along the herd's diagonal, then backing away
 * (easing in) to C. Its numbers are W1Scene.json's camera_path.
 */
class W1CameraPath
{
public:
  /// frames >= 2.
  W1CameraPath(const Scene& scene, int frames);

  Pose At(int frame) const;

  int GetKeyA() const { return 0; }
  int GetKeyB() const { return this->KeyB; }
  int GetKeyTurn() const;
  int GetKeyC() const { return this->Frames - 1; }
  Vec3 GetA() const { return this->A; }
  Vec3 GetCenter() const { return this->Center; }

private:
  int Frames;
  int KeyB = 0;
  Vec3 Center, Target, A, B, C, TurnDirection, TurnFocus;
};
}
}

#endif

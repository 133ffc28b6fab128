// SPDX-License-Identifier: BSD-3-Clause
#include "W1CameraPath.h"

#include "W1Scene.h"
#include "W1SceneSpecification.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
namespace
{
Vec3 ToVec3(const std::array<double, 3>& v)
{
  return { v[0], v[1], v[2] };
}
}

W1CameraPath::W1CameraPath(const Scene& scene, int frames)
  : Frames(frames)
{
  if (frames < 2 || scene.Objects.empty())
  {
    throw std::invalid_argument("W1CameraPath: needs at least 2 frames and one object");
  }
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  const double L = scene.Extent;
  const double r = scene.Radius;
  this->Center = { 0.5 * L, 0.0, 0.5 * L };
  const Placement& focus = scene.Objects[static_cast<size_t>(scene.Focus)];
  this->Target = { focus.X, spec.TargetHeight * scene.Height, focus.Z };
  // A: outside the herd beyond one corner and high up: the whole herd in view.
  this->A = this->Center + Vec3{ spec.AOffset[0] * L, spec.AOffset[1] * L, spec.AOffset[2] * L };
  // B: a few footprint radii from the focus object on A's side, above it: the
  // object fills a third of the view, a few dozen others the background.
  const Vec3 towardA =
    Normalized(Vec3{ this->A.X - this->Target.X, 0.0, this->A.Z - this->Target.Z });
  this->B = this->Target + towardA * (spec.BDistance * r) + Vec3{ 0.0, spec.BHeight * r, 0.0 };
  // The sudden turn: from looking down at the object to looking along the
  // herd's diagonal, slightly downward: near objects large, hundreds behind.
  this->TurnDirection = Normalized(ToVec3(spec.TurnDirection));
  this->TurnFocus = this->B + this->TurnDirection * (spec.TurnFocusDistance * L);
  // C: backed away along the diagonal, outside the herd and up again.
  const Vec3 back = Normalized(ToVec3(spec.CDirection));
  this->C = Vec3{ this->B.X, 0.0, this->B.Z } - back * (spec.CDistance * L) +
    Vec3{ 0.0, spec.CHeight * L, 0.0 };
  this->KeyB = static_cast<int>(std::lround(spec.KeyB * (frames - 1)));
}

Pose W1CameraPath::At(int frame) const
{
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  Pose pose;
  if (frame <= this->KeyB)
  {
    // Approach: fast at A, slowing down to a stop at B (ease-out), the view
    // turning from the herd's centre to the focus object.
    const double s = this->KeyB > 0 ? static_cast<double>(frame) / this->KeyB : 1.0;
    pose.Position = Lerp(this->A, this->B, 1.0 - (1.0 - s) * (1.0 - s));
    pose.FocalPoint = Lerp(this->Center, this->Target, SmoothStep(spec.FocusEaseScale * s));
  }
  else
  {
    // After the turn (one frame): backing away, slowly at first (ease-in),
    // the view drifting back to the herd's centre.
    const int last = this->Frames - 1;
    const double s = last > this->KeyB + 1
      ? static_cast<double>(frame - this->KeyB - 1) / (last - this->KeyB - 1)
      : 1.0;
    pose.Position = Lerp(this->B, this->C, s * s);
    pose.FocalPoint = Lerp(this->TurnFocus, this->Center, SmoothStep(s));
  }
  return pose;
}

int W1CameraPath::GetKeyTurn() const
{
  return std::min(this->KeyB + 1, this->Frames - 1);
}
}
}

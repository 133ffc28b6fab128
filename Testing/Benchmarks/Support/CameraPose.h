// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CameraPose_h
#define timecritical_CameraPose_h

/**
 * The small vector algebra of the benchmarks' camera paths and the pose a
 * path gives per frame (view up +y, the benchmarks' view angle).
 */
class vtkCamera;

namespace timecritical
{
namespace benchmark
{
struct Vec3
{
  double X = 0.0, Y = 0.0, Z = 0.0;
};

Vec3 operator+(const Vec3& a, const Vec3& b);
Vec3 operator-(const Vec3& a, const Vec3& b);
Vec3 operator*(const Vec3& a, double s);
Vec3 Lerp(const Vec3& a, const Vec3& b, double t);
/// `a` scaled to unit length; a zero vector stays zero.
Vec3 Normalized(const Vec3& a);
/// 3t^2 - 2t^3 of t clamped to [0, 1].
double SmoothStep(double t);

struct Pose
{
  Vec3 Position, FocalPoint;
};

void ApplyPose(vtkCamera* camera, const Pose& pose);
}
}

#endif

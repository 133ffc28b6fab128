// SPDX-License-Identifier: BSD-3-Clause
#include "CameraPose.h"

#include "BenchmarkTiming.h"

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>

namespace timecritical
{
namespace benchmark
{
Vec3 operator+(const Vec3& a, const Vec3& b)
{
  return { a.X + b.X, a.Y + b.Y, a.Z + b.Z };
}

Vec3 operator-(const Vec3& a, const Vec3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}

Vec3 operator*(const Vec3& a, double s)
{
  return { a.X * s, a.Y * s, a.Z * s };
}

Vec3 Lerp(const Vec3& a, const Vec3& b, double t)
{
  return a + (b - a) * t;
}

Vec3 Normalized(const Vec3& a)
{
  const double length = std::sqrt(a.X * a.X + a.Y * a.Y + a.Z * a.Z);
  return length > 0.0 ? a * (1.0 / length) : a;
}

double SmoothStep(double t)
{
  t = std::min(std::max(t, 0.0), 1.0);
  return t * t * (3.0 - 2.0 * t);
}

void ApplyPose(vtkCamera* camera, const Pose& pose)
{
  camera->SetPosition(pose.Position.X, pose.Position.Y, pose.Position.Z);
  camera->SetFocalPoint(pose.FocalPoint.X, pose.FocalPoint.Y, pose.FocalPoint.Z);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(ViewAngle);
}
}
}

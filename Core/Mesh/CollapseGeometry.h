// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseGeometry_h
#define timecritical_CollapseGeometry_h

/*
 * Internal to TimeCritical::MeshCore: the vector arithmetic of the collapse
 * engine (double precision, in the unit box the engine works in).
 */

namespace timecritical
{
namespace collapse
{
constexpr double Pi = 3.14159265358979323846;

struct Vec3
{
  double X, Y, Z;
};
inline Vec3 Sub(const Vec3& a, const Vec3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}
inline double Dot(const Vec3& a, const Vec3& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}
inline Vec3 TriangleNormal(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return Cross(Sub(b, a), Sub(c, a));
}
}
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_Quadric_h
#define timecritical_Quadric_h

/*
 * Internal to TimeCritical::MeshCore: the double-precision quadric of the collapse
 * engine's constraint planes.
 */

#include "CollapseGeometry.h"

namespace timecritical
{
namespace collapse
{
/// Symmetric quadric Q(p) = p^T A p + 2 b.p + c.
struct Quadric
{
  double A00 = 0, A01 = 0, A02 = 0, A11 = 0, A12 = 0, A22 = 0;
  double B0 = 0, B1 = 0, B2 = 0, C = 0;

  /// Adds weight * (distance to the plane n.p + d = 0)^2, n of unit length.
  void AddPlane(const Vec3& n, double d, double weight)
  {
    this->A00 += weight * n.X * n.X;
    this->A01 += weight * n.X * n.Y;
    this->A02 += weight * n.X * n.Z;
    this->A11 += weight * n.Y * n.Y;
    this->A12 += weight * n.Y * n.Z;
    this->A22 += weight * n.Z * n.Z;
    this->B0 += weight * d * n.X;
    this->B1 += weight * d * n.Y;
    this->B2 += weight * d * n.Z;
    this->C += weight * d * d;
  }
  void Add(const Quadric& q)
  {
    this->A00 += q.A00;
    this->A01 += q.A01;
    this->A02 += q.A02;
    this->A11 += q.A11;
    this->A12 += q.A12;
    this->A22 += q.A22;
    this->B0 += q.B0;
    this->B1 += q.B1;
    this->B2 += q.B2;
    this->C += q.C;
  }
  double Evaluate(const Vec3& p) const
  {
    const double x = p.X, y = p.Y, z = p.Z;
    const double r = x * (this->A00 * x + 2.0 * (this->A01 * y + this->A02 * z + this->B0)) +
      y * (this->A11 * y + 2.0 * (this->A12 * z + this->B1)) + z * (this->A22 * z + 2.0 * this->B2) +
      this->C;
    return r > 0.0 ? r : 0.0; // cancellation can dip slightly below 0
  }
};
}
}

#endif

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_PlaneThroughOrigin_h
#define timecritical_PlaneThroughOrigin_h

/*
 * Internal to TimeCritical::MeshCore: the matrix of a plane through a
 * record's own vertex, computed once for all the records it is added to.
 */

#include "CollapseGeometry.h"
#include "QuadricRecord.h"

namespace timecritical
{
namespace collapse
{
/// weight * n n^T, a plane through a record's own vertex (n of unit length),
/// computed once for all the vertices it is added to.
struct PlaneThroughOrigin
{
  double A00, A01, A02, A11, A12, A22;

  PlaneThroughOrigin(const Vec3& n, double weight)
    : A00(weight * n.X * n.X)
    , A01(weight * n.X * n.Y)
    , A02(weight * n.X * n.Z)
    , A11(weight * n.Y * n.Y)
    , A12(weight * n.Y * n.Z)
    , A22(weight * n.Z * n.Z)
  {
  }
  void AddTo(QuadricRecord& r) const
  {
    AddMatrix(r, *this);
  }
};
}
}

#endif

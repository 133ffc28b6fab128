// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_LocalQuadric_h
#define timecritical_LocalQuadric_h

/*
 * Internal to TimeCritical::MeshCore: the double-precision working copy of a
 * QuadricRecord, for evaluation and merging.
 */

#include "CollapseGeometry.h"
#include "CostLanes.h"
#include "QuadricRecord.h"

namespace timecritical
{
namespace collapse
{
/// A QuadricRecord in double precision, for evaluation and merging.
struct LocalQuadric
{
  double A00, A01, A02, A11, A12, A22, G0, G1, G2, C;
  Vec3 Origin;
  double Weight;            // area behind the face planes
  double InverseRootWeight; // 1 / sqrt(Weight), see CollapseEngine::Cost

  LocalQuadric(const QuadricRecord& r, const Vec3& origin)
    : A00(r.A00)
    , A01(r.A01)
    , A02(r.A02)
    , A11(r.A11)
    , A12(r.A12)
    , A22(r.A22)
    , G0(r.G0)
    , G1(r.G1)
    , G2(r.G2)
    , C(r.C)
    , Origin(origin)
    , Weight(r.FaceWeight)
    , InverseRootWeight(r.InverseRootWeight)
  {
  }
  /// A d, for an offset d from the origin.
  Vec3 Apply(const Vec3& d) const;
  /// Q(p), at least 0.
  double Evaluate(const Vec3& p) const;
  /// Adds this quadric, re-expressed around newOrigin, to the record r (stored around newOrigin).
  void AddTo(QuadricRecord& r, const Vec3& newOrigin) const
  {
    const Vec3 d = Sub(newOrigin, this->Origin);
    const Vec3 ad = this->Apply(d);
    AddMatrix(r, *this);
    r.G0 = static_cast<float>(r.G0 + this->G0 + ad.X);
    r.G1 = static_cast<float>(r.G1 + this->G1 + ad.Y);
    r.G2 = static_cast<float>(r.G2 + this->G2 + ad.Z);
    r.C = static_cast<float>(r.C + this->Evaluate(newOrigin));
  }
};

inline Vec3 LocalQuadric::Apply(const Vec3& d) const
{
  Vec3 ad;
  CostLanes<double>(*this).Apply(d.X, d.Y, d.Z, ad.X, ad.Y, ad.Z);
  return ad;
}

inline double LocalQuadric::Evaluate(const Vec3& p) const
{
  const Vec3 d = Sub(p, this->Origin);
  return CostLanes<double>(*this).Value(d.X, d.Y, d.Z);
}
}
}

#endif

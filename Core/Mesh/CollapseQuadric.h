// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseQuadric_h
#define timecritical_CollapseQuadric_h

/*
 * Internal to TimeCritical::MeshCore: the quadrics of the collapse engine:
 * the double-precision quadric of the constraint planes, the per-vertex
 * record in single precision around its vertex, its double-precision working
 * copy, and the planes added to records.
 */

#include "CollapseGeometry.h"
#include "CostLanes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

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

/**
 * The per-vertex quadric (face planes + weighted constraint planes, which
 * order the collapses), read only to compute the vertex's own candidates.
 *
 * It is stored relative to the vertex's own position p0, as
 * Q(p0 + d) = C + 2 G.d + d^T A d, which is well conditioned even in single
 * precision: d is an edge length or so, and C is the error accumulated at the
 * vertex itself. Single precision fits the record in one cache line.
 */
struct alignas(64) QuadricRecord
{
  float A00, A01, A02, A11, A12, A22;
  float G0, G1, G2;
  float C;
  float FaceWeight; // total area behind the face planes
  uint32_t Slot;    // index into the constraint records, Invalid when none
  double InverseRootWeight; // 1 / sqrt(FaceWeight), see SetFaceWeight
};
static_assert(sizeof(QuadricRecord) == 64, "one cache line per quadric");

/// Adds the symmetric matrix of m (any record with A00 ... A22) to r's, in
/// single precision: the one place where a record's matrix grows.
template <typename M>
inline void AddMatrix(QuadricRecord& r, const M& m)
{
  r.A00 = static_cast<float>(r.A00 + m.A00);
  r.A01 = static_cast<float>(r.A01 + m.A01);
  r.A02 = static_cast<float>(r.A02 + m.A02);
  r.A11 = static_cast<float>(r.A11 + m.A11);
  r.A12 = static_cast<float>(r.A12 + m.A12);
  r.A22 = static_cast<float>(r.A22 + m.A22);
}

/// Sets the face weight of r and its inverse square root, which every cost
/// evaluation reads (CollapseEngine::Cost): computed once per change, not per
/// evaluation.
inline void SetFaceWeight(QuadricRecord& r, float weight)
{
  r.FaceWeight = weight;
  r.InverseRootWeight = 1.0 / std::sqrt(double(std::max(weight, std::numeric_limits<float>::min())));
}

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

/// The constraint planes alone, kept apart (few vertices have any) to report
/// a geometric error that their weights do not distort.
struct ConstraintRecord
{
  Quadric Q;
  double Weight;
};
}
}

#endif

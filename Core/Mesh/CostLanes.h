// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CostLanes_h
#define timecritical_CostLanes_h

/*
 * Internal to TimeCritical::MeshCore: the formulas of the collapse cost,
 * once for one target (double) and once for two (DoublePair, SSE2).
 */

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h> // CostLanes<DoublePair>: two costs per instruction
#endif

namespace timecritical
{
namespace collapse
{
// Weight of the tie-breaking "moment" term of the collapse cost (unit box units).
constexpr double EdgeLengthWeight = 1e-7;

/// KeepPositive(r): r where r > 0, else +0 (NaN included): rounding can dip
/// a quadric slightly below 0.
inline double KeepPositive(double r)
{
  return r > 0.0 ? r : 0.0;
}

#if defined(__SSE2__)
/// Two doubles in one SSE2 register, with the arithmetic CostLanes needs.
struct DoublePair
{
  __m128d V;

  DoublePair() = default;
  explicit DoublePair(double x)
    : V(_mm_set1_pd(x))
  {
  }
  DoublePair(__m128d v)
    : V(v)
  {
  }
  static DoublePair Of(double lane0, double lane1) { return _mm_set_pd(lane1, lane0); }
  double Lane0() const { return _mm_cvtsd_f64(this->V); }
  double Lane1() const { return _mm_cvtsd_f64(_mm_unpackhi_pd(this->V, this->V)); }
};
inline DoublePair operator+(DoublePair a, DoublePair b)
{
  return _mm_add_pd(a.V, b.V);
}
inline DoublePair operator-(DoublePair a, DoublePair b)
{
  return _mm_sub_pd(a.V, b.V);
}
inline DoublePair operator*(DoublePair a, DoublePair b)
{
  return _mm_mul_pd(a.V, b.V);
}
inline DoublePair KeepPositive(DoublePair r)
{
  return _mm_and_pd(r.V, _mm_cmpgt_pd(r.V, _mm_setzero_pd()));
}
#endif

/**
 * A LocalQuadric with every coefficient in a T: double, or DoublePair to
 * cost two targets at once. The formulas exist once, as templates, so both
 * take the same operations in the same order and every lane gives the scalar
 * result bit for bit: the TOM does not depend on the instruction set.
 * Costing candidates is a large part of a build's work.
 */
template <typename T>
struct CostLanes
{
  T A00, A01, A02, A11, A12, A22, G0, G1, G2, C, OriginX, OriginY, OriginZ;
  T InverseRootWeight, MomentWeight;

  /// From a quadric with the fields of LocalQuadric (LocalQuadric.h).
  template <typename Q>
  explicit CostLanes(const Q& q)
    : A00(q.A00)
    , A01(q.A01)
    , A02(q.A02)
    , A11(q.A11)
    , A12(q.A12)
    , A22(q.A22)
    , G0(q.G0)
    , G1(q.G1)
    , G2(q.G2)
    , C(q.C)
    , OriginX(q.Origin.X)
    , OriginY(q.Origin.Y)
    , OriginZ(q.Origin.Z)
    , InverseRootWeight(q.InverseRootWeight)
    , MomentWeight(EdgeLengthWeight * q.Weight)
  {
  }
  /// A d, for the offset d from the origin.
  void Apply(T dx, T dy, T dz, T& adx, T& ady, T& adz) const
  {
    adx = this->A00 * dx + this->A01 * dy + this->A02 * dz;
    ady = this->A01 * dx + this->A11 * dy + this->A12 * dz;
    adz = this->A02 * dx + this->A12 * dy + this->A22 * dz;
  }
  /// The quadric at the offset d from its origin, at least 0.
  T Value(T dx, T dy, T dz) const
  {
    T adx, ady, adz;
    this->Apply(dx, dy, dz, adx, ady, adz);
    const T linear = this->G0 * dx + this->G1 * dy + this->G2 * dz;
    return KeepPositive(this->C + T(2.0) * linear + (dx * adx + dy * ady + dz * adz));
  }
  /// CollapseEngine::Cost of moving the origin to p (see there).
  T Cost(T x, T y, T z) const
  {
    const T dx = x - this->OriginX, dy = y - this->OriginY, dz = z - this->OriginZ;
    const T length2 = dx * dx + dy * dy + dz * dz;
    return this->Value(dx, dy, dz) * this->InverseRootWeight + this->MomentWeight * length2;
  }
};
}
}

#endif

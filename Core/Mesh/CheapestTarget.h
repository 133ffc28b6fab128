// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CheapestTarget_h
#define timecritical_CheapestTarget_h

#include "CollapseQuadric.h"
#include "CollapseRecords.h"
#include "CostLanes.h"

#include <cstdint>
#include <limits>

namespace timecritical
{
namespace collapse
{
/**
 * The cheapest of the targets offered one by one (the first of equal ones,
 * as a scalar loop would keep), costed in pairs where SSE2 allows.
 */
class CheapestTarget
{
public:
  CheapestTarget(const LocalQuadric& q, const Vertex* vertices)
    : Scalar(q)
#if defined(__SSE2__)
    , Paired(q)
#endif
    , Vertices(vertices)
  {
  }
  void Offer(uint32_t x)
  {
#if defined(__SSE2__)
    if (this->Pending == Invalid)
    {
      this->Pending = x;
      return;
    }
    const Vec3& p0 = this->PositionOf(this->Pending);
    const Vec3& p1 = this->PositionOf(x);
    const DoublePair c = this->Paired.Cost(DoublePair::Of(p0.X, p1.X),
      DoublePair::Of(p0.Y, p1.Y), DoublePair::Of(p0.Z, p1.Z));
    this->Take(this->Pending, c.Lane0());
    this->Take(x, c.Lane1());
    this->Pending = Invalid;
#else
    const Vec3& p = this->PositionOf(x);
    this->Take(x, this->Scalar.Cost(p.X, p.Y, p.Z));
#endif
  }
  /// The cheapest of all offered ({+inf, Invalid} when none was).
  const Candidate& Best()
  {
    if (this->Pending != Invalid)
    {
      const Vec3& p = this->PositionOf(this->Pending);
      this->Take(this->Pending, this->Scalar.Cost(p.X, p.Y, p.Z));
      this->Pending = Invalid;
    }
    return this->Cheapest;
  }

private:
  const Vec3& PositionOf(uint32_t x) const { return this->Vertices[x].P; }
  void Take(uint32_t x, double cost)
  {
    if (cost < this->Cheapest.Cost)
    {
      this->Cheapest = { cost, x };
    }
  }

  CostLanes<double> Scalar;
#if defined(__SSE2__)
  CostLanes<DoublePair> Paired;
#endif
  const Vertex* Vertices;
  uint32_t Pending = Invalid;
  Candidate Cheapest{ std::numeric_limits<double>::infinity(), Invalid };
};
}
}

#endif

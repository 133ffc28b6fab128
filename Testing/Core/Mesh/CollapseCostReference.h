// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_CollapseCostReference_h
#define timecritical_CollapseCostReference_h

// What the tests of the cost lanes and of CheapestTarget compare against:
// the collapse cost written out in scalar code, and random quadrics.

#include "CollapseQuadric.h"
#include "CollapseRecords.h"
#include "CostLanes.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

namespace timecritical
{
namespace collapse
{
namespace reference
{
inline uint64_t Bits(double x)
{
  uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

inline QuadricRecord RandomRecord(std::mt19937& rng)
{
  std::uniform_real_distribution<float> coefficient(-2.f, 2.f);
  QuadricRecord r{};
  r.A00 = std::abs(coefficient(rng));
  r.A01 = coefficient(rng);
  r.A02 = coefficient(rng);
  r.A11 = std::abs(coefficient(rng));
  r.A12 = coefficient(rng);
  r.A22 = std::abs(coefficient(rng));
  r.G0 = coefficient(rng);
  r.G1 = coefficient(rng);
  r.G2 = coefficient(rng);
  r.C = coefficient(rng); // negative too: the clamp to 0 is exercised
  SetFaceWeight(r, std::abs(coefficient(rng)) + 1e-3f);
  r.Slot = Invalid;
  return r;
}

// The scalar cost written out from CollapseEngine::Cost's documentation, the
// reference for both CostLanes instantiations.
inline double ReferenceCost(const LocalQuadric& q, const Vec3& p)
{
  const Vec3 d = Sub(p, q.Origin);
  const Vec3 ad{ q.A00 * d.X + q.A01 * d.Y + q.A02 * d.Z, q.A01 * d.X + q.A11 * d.Y + q.A12 * d.Z,
    q.A02 * d.X + q.A12 * d.Y + q.A22 * d.Z };
  const double r = q.C + 2.0 * (q.G0 * d.X + q.G1 * d.Y + q.G2 * d.Z) + Dot(d, ad);
  return (r > 0.0 ? r : 0.0) * q.InverseRootWeight + EdgeLengthWeight * q.Weight * Dot(d, d);
}
}
}
}

#endif

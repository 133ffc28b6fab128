// SPDX-License-Identifier: BSD-3-Clause
// The collapse cost costed in pairs (CostLanes<DoublePair>, CheapestTarget)
// must give the scalar result bit for bit, so that the TOM does not depend on
// the instruction set, and keep the scalar loop's choice among equal costs.

#include "CollapseEngine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace
{
using namespace timecritical::collapse;

uint64_t Bits(double x)
{
  uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

QuadricRecord RandomRecord(std::mt19937& rng)
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
double ReferenceCost(const LocalQuadric& q, const Vec3& p)
{
  const Vec3 d = Sub(p, q.Origin);
  const Vec3 ad{ q.A00 * d.X + q.A01 * d.Y + q.A02 * d.Z, q.A01 * d.X + q.A11 * d.Y + q.A12 * d.Z,
    q.A02 * d.X + q.A12 * d.Y + q.A22 * d.Z };
  const double r = q.C + 2.0 * (q.G0 * d.X + q.G1 * d.Y + q.G2 * d.Z) + Dot(d, ad);
  return (r > 0.0 ? r : 0.0) * q.InverseRootWeight + EdgeLengthWeight * q.Weight * Dot(d, d);
}

TEST(CollapseCost, ScalarLanesMatchTheDocumentedFormula)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int clamped = 0;
  for (int i = 0; i < 2000; ++i)
  {
    const LocalQuadric q(RandomRecord(rng), { coordinate(rng), coordinate(rng), coordinate(rng) });
    const Vec3 p{ coordinate(rng), coordinate(rng), coordinate(rng) };
    const double cost = CostLanes<double>(q).Cost(p.X, p.Y, p.Z);
    ASSERT_EQ(Bits(cost), Bits(ReferenceCost(q, p))) << i;
    clamped += q.Evaluate(p) == 0.0 ? 1 : 0;
  }
  EXPECT_GT(clamped, 100); // the clamp was taken
}

#if defined(__SSE2__)
TEST(CollapseCost, PairedLanesGiveTheScalarBits)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i)
  {
    const LocalQuadric q(RandomRecord(rng), { coordinate(rng), coordinate(rng), coordinate(rng) });
    const Vec3 p0{ coordinate(rng), coordinate(rng), coordinate(rng) };
    const Vec3 p1{ coordinate(rng), coordinate(rng), coordinate(rng) };
    const DoublePair c = CostLanes<DoublePair>(q).Cost(
      DoublePair::Of(p0.X, p1.X), DoublePair::Of(p0.Y, p1.Y), DoublePair::Of(p0.Z, p1.Z));
    const CostLanes<double> scalar(q);
    ASSERT_EQ(Bits(c.Lane0()), Bits(scalar.Cost(p0.X, p0.Y, p0.Z))) << i;
    ASSERT_EQ(Bits(c.Lane1()), Bits(scalar.Cost(p1.X, p1.Y, p1.Z))) << i;
  }
}

TEST(CollapseCost, PairedClampTreatsNaNAndNegativeZeroAsTheScalarOne)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const DoublePair kept = KeepPositive(DoublePair::Of(nan, -0.0));
  EXPECT_EQ(Bits(kept.Lane0()), Bits(KeepPositive(nan)));
  EXPECT_EQ(Bits(kept.Lane1()), Bits(KeepPositive(-0.0)));
  EXPECT_EQ(Bits(KeepPositive(nan)), Bits(0.0));
  const DoublePair passed = KeepPositive(DoublePair::Of(2.5, -1.0));
  EXPECT_EQ(passed.Lane0(), 2.5);
  EXPECT_EQ(passed.Lane1(), 0.0);
}
#endif

std::vector<Vertex> VerticesAt(const std::vector<Vec3>& positions)
{
  std::vector<Vertex> vertices(positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
  {
    vertices[i].P = positions[i];
  }
  return vertices;
}

TEST(CollapseCost, CheapestTargetIsTheScalarLoopsChoice)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<Vec3> positions(64);
  for (Vec3& p : positions)
  {
    p = { coordinate(rng), coordinate(rng), coordinate(rng) };
  }
  const std::vector<Vertex> vertices = VerticesAt(positions);
  std::uniform_int_distribution<uint32_t> pick(0, 63);
  for (int i = 0; i < 500; ++i)
  {
    const LocalQuadric q(RandomRecord(rng), positions[pick(rng)]);
    const uint32_t count = static_cast<uint32_t>(i % 9); // odd and even counts, none
    CheapestTarget cheapest(q, vertices.data());
    Candidate expected{ std::numeric_limits<double>::infinity(), Invalid };
    for (uint32_t k = 0; k < count; ++k)
    {
      const uint32_t x = pick(rng);
      cheapest.Offer(x);
      const double c = ReferenceCost(q, positions[x]);
      if (c < expected.Cost)
      {
        expected = { c, x };
      }
    }
    const Candidate best = cheapest.Best();
    ASSERT_EQ(best.Target, expected.Target) << i;
    ASSERT_EQ(Bits(best.Cost), Bits(expected.Cost)) << i;
  }
}

TEST(CollapseCost, CheapestTargetKeepsTheFirstOfEqualCosts)
{
  // Targets 1, 2 and 3 are the same point: whatever lanes they are costed
  // in, the first offered wins, as in the scalar loop.
  const std::vector<Vertex> vertices = VerticesAt(
    { { 0, 0, 0 }, { 0.5, 0.5, 0 }, { 0.5, 0.5, 0 }, { 0.5, 0.5, 0 }, { 3, 3, 3 } });
  QuadricRecord r{};
  SetFaceWeight(r, 1.f);
  r.A22 = 1.f;
  const LocalQuadric q(r, vertices[0].P);
  const std::vector<std::pair<std::vector<uint32_t>, uint32_t>> cases = {
    { { 4, 2, 1, 3 }, 2 }, { { 3, 1, 2 }, 3 }, { { 4, 4, 1, 2, 3 }, 1 }, { { 1 }, 1 }
  };
  for (const auto& c : cases)
  {
    CheapestTarget cheapest(q, vertices.data());
    for (uint32_t x : c.first)
    {
      cheapest.Offer(x);
    }
    EXPECT_EQ(cheapest.Best().Target, c.second);
  }
}
}

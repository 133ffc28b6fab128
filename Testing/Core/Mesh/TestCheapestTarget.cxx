// SPDX-License-Identifier: BSD-3-Clause
// CheapestTarget, which costs candidates in pairs where SSE2 allows, must
// choose what the scalar loop over the targets chooses, the first of equal
// costs included.

#include "CheapestTarget.h"

#include "CollapseCostReference.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace
{
using namespace timecritical::collapse;
using namespace timecritical::collapse::reference;

std::vector<Vertex> VerticesAt(const std::vector<Vec3>& positions)
{
  std::vector<Vertex> vertices(positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
  {
    vertices[i].P = positions[i];
  }
  return vertices;
}

TEST(CheapestTarget, IsTheScalarLoopsChoice)
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

TEST(CheapestTarget, KeepsTheFirstOfEqualCosts)
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

// SPDX-License-Identifier: BSD-3-Clause
// Tests of PointGrid: fixed-radius queries against a brute-force search,
// at ordinary and extreme coordinates, and the early stop.
#include "PointGrid.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

using timecritical::collapse::PointGrid;
using timecritical::collapse::Vec3;

namespace
{
std::vector<Vec3> RandomPoints(size_t n, double scale, uint32_t seed)
{
  std::vector<Vec3> points(n);
  auto next = [&seed]() {
    seed = seed * 1664525u + 1013904223u;
    return double(seed >> 8) / double(1u << 24) - 0.5;
  };
  for (Vec3& p : points)
  {
    p = { scale * next(), scale * next(), scale * next() };
  }
  return points;
}

/// The ids within `radius` of q, by the grid and by brute force.
std::pair<std::set<uint32_t>, std::set<uint32_t>> Both(
  const std::vector<Vec3>& points, const PointGrid& grid, const Vec3& q, double radius)
{
  std::set<uint32_t> found, expected;
  grid.ForEachWithin(q, radius, [&found](uint32_t id, double) {
    EXPECT_TRUE(found.insert(id).second) << "point " << id << " reported twice";
    return true;
  });
  for (uint32_t i = 0; i < points.size(); ++i)
  {
    const Vec3 d = { points[i].X - q.X, points[i].Y - q.Y, points[i].Z - q.Z };
    if (d.X * d.X + d.Y * d.Y + d.Z * d.Z < radius * radius)
    {
      expected.insert(i);
    }
  }
  return { found, expected };
}
}

TEST(PointGrid, FindsExactlyThePointsWithinTheRadius)
{
  const std::vector<Vec3> points = RandomPoints(3000, 1.0, 7);
  for (double radius : { 0.02, 0.1, 0.5, 2.0 })
  {
    PointGrid grid(radius);
    for (uint32_t i = 0; i < points.size(); ++i)
    {
      grid.Add(i, points[i]);
    }
    grid.Build();
    ASSERT_EQ(grid.Size(), points.size());
    size_t total = 0;
    for (const Vec3& q : RandomPoints(50, 1.2, 11))
    {
      const auto [found, expected] = Both(points, grid, q, radius);
      ASSERT_EQ(found, expected) << "radius " << radius;
      total += found.size();
    }
    EXPECT_GT(total, 0u) << radius;
  }
}

TEST(PointGrid, ExtremeCoordinatesStayExact)
{
  // Cells beyond 2^20 per axis are clamped (merged), never lost.
  const std::vector<Vec3> points = RandomPoints(500, 1e9, 3);
  PointGrid grid(1e-3);
  for (uint32_t i = 0; i < points.size(); ++i)
  {
    grid.Add(i, points[i]);
  }
  grid.Build();
  for (uint32_t i = 0; i < 50; ++i)
  {
    const auto [found, expected] = Both(points, grid, points[i], 1e-3);
    ASSERT_EQ(found, expected);
    EXPECT_EQ(found.count(i), 1u);
  }
}

TEST(PointGrid, QueryStopsWhenAsked)
{
  PointGrid grid(1.0);
  for (uint32_t i = 0; i < 100; ++i)
  {
    grid.Add(i, { 0.001 * i, 0.0, 0.0 });
  }
  grid.Build();
  size_t calls = 0;
  const size_t visited = grid.ForEachWithin({ 0.0, 0.0, 0.0 }, 1.0, [&calls](uint32_t, double) {
    return ++calls < 10;
  });
  EXPECT_EQ(calls, 10u);
  EXPECT_EQ(visited, 10u);
  // An empty grid finds nothing.
  const PointGrid empty(0.5);
  EXPECT_EQ(empty.ForEachWithin({ 0.0, 0.0, 0.0 }, 0.5, [](uint32_t, double) { return true; }), 0u);
}

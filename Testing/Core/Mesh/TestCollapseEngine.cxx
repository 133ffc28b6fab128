// SPDX-License-Identifier: BSD-3-Clause
// CollapseEngine driven directly by small schedules on hand-built meshes: the
// input clean-up it reports, the heap of cheapest collapses, the candidates
// of a vertex, and a checked collapse recorded as a removed vertex.

#include "CollapseEngine.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace
{
using namespace timecritical;
using collapse::CollapseEngine;

/// A flat n x n grid of points in the plane z = 0, two triangles per cell.
struct Grid
{
  std::vector<double> Points;
  std::vector<uint32_t> Triangles;

  explicit Grid(uint32_t n)
  {
    for (uint32_t j = 0; j < n; ++j)
    {
      for (uint32_t i = 0; i < n; ++i)
      {
        this->Points.insert(this->Points.end(), { double(i), double(j), 0.0 });
      }
    }
    for (uint32_t j = 0; j + 1 < n; ++j)
    {
      for (uint32_t i = 0; i + 1 < n; ++i)
      {
        const uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
        this->Triangles.insert(this->Triangles.end(), { a, b, d, a, d, c });
      }
    }
  }
  size_t NumberOfPoints() const { return this->Points.size() / 3; }
  size_t NumberOfTriangles() const { return this->Triangles.size() / 3; }
};

TOMBuildResult RunWith(CollapseEngine& engine, const Grid& grid, const std::function<bool()>& schedule)
{
  return engine.Run(grid.Points.data(), grid.NumberOfPoints(), grid.Triangles.data(),
    grid.NumberOfTriangles(), schedule);
}

TEST(CollapseEngine, EmptyScheduleKeepsEveryVertex)
{
  const Grid grid(4);
  const TOMBuildOptions options; // outlives the engine, which keeps its progress callback
  CollapseEngine engine(options, true);
  bool scheduled = false;
  const TOMBuildResult result = RunWith(engine, grid, [&] {
    scheduled = true;
    EXPECT_EQ(engine.GetNumberOfVertices(), 16u);
    EXPECT_EQ(engine.GetRemovedCount(), 0u);
    EXPECT_FALSE(engine.HeapEmpty());
    return true;
  });
  EXPECT_TRUE(scheduled);
  EXPECT_EQ(result.VertexOrder.size(), 16u);
  EXPECT_EQ(result.TriangleOrder.size(), 18u);
  EXPECT_EQ(result.DroppedDegenerateTriangles, 0u);
  EXPECT_EQ(result.DroppedDuplicateTriangles, 0u);
  EXPECT_EQ(result.UnusedPoints, 0u);
}

TEST(CollapseEngine, ReportsTheInputItDrops)
{
  Grid grid(3);
  grid.Points.insert(grid.Points.end(), { 5.0, 5.0, 5.0 });            // point 9: unused
  grid.Triangles.insert(grid.Triangles.end(), { 0, 1, 4 });             // a copy of the first triangle
  grid.Triangles.insert(grid.Triangles.end(), { 4, 1, 0 });             // the same points the other way round
  grid.Triangles.insert(grid.Triangles.end(), { 2, 2, 5 });             // two corners the same
  const TOMBuildOptions options; // outlives the engine, which keeps its progress callback
  CollapseEngine engine(options, true);
  const TOMBuildResult result = RunWith(engine, grid, [&] {
    EXPECT_EQ(engine.GetNumberOfVertices(), 9u); // compact ids: the used points only
    return true;
  });
  EXPECT_EQ(result.UnusedPoints, 1u);
  EXPECT_EQ(result.DroppedDegenerateTriangles, 1u);
  EXPECT_EQ(result.DroppedDuplicateTriangles, 2u);
  EXPECT_EQ(result.TriangleOrder.size(), 8u);
}

TEST(CollapseEngine, CheapestCollapseOfAFlatGridIsFree)
{
  const Grid grid(5);
  const TOMBuildOptions options; // outlives the engine, which keeps its progress callback
  CollapseEngine engine(options, true);
  RunWith(engine, grid, [&] {
    const uint32_t u = engine.HeapTop();
    const uint32_t w = engine.GetTarget(u);
    EXPECT_NE(w, collapse::Invalid);
    // In the plane, an interior vertex collapses into a neighbour with no
    // quadric error: only the tiny edge-length term is left.
    EXPECT_LT(engine.GetKey(u), 1e-5f);
    EXPECT_LE(engine.GetKey(u), engine.HeapSecondKey());

    const std::vector<collapse::Candidate> candidates = engine.GatherCandidates(u);
    EXPECT_FALSE(candidates.empty());
    bool hasTarget = false;
    for (size_t k = 0; k < candidates.size(); ++k)
    {
      hasTarget = hasTarget || candidates[k].Target == w;
      if (k > 0)
      {
        EXPECT_LE(candidates[k - 1].Cost, candidates[k].Cost);
      }
    }
    EXPECT_TRUE(hasTarget);

    EXPECT_TRUE(engine.CheckCollapse(u, w));
    engine.ApplyCollapse(u, w);
    EXPECT_EQ(engine.GetRemovedCount(), 1u);
    EXPECT_EQ(engine.GetRemovedVertex(0), u);
    EXPECT_TRUE(engine.IsRemoved(u));
    EXPECT_FALSE(engine.IsRemoved(w));
    return true;
  });
}

TEST(CollapseEngine, GreedyScheduleRemovesVerticesInOrder)
{
  const Grid grid(6);
  const TOMBuildOptions options; // outlives the engine, which keeps its progress callback
  CollapseEngine engine(options, true);
  std::vector<uint32_t> removed;
  const TOMBuildResult result = RunWith(engine, grid, [&] {
    for (;;)
    {
      while (!engine.HeapEmpty())
      {
        const uint32_t u = engine.HeapTop();
        const uint32_t w = engine.GetTarget(u);
        if (!engine.CheckCollapse(u, w))
        {
          engine.Block(u);
          continue;
        }
        engine.ApplyCollapse(u, w);
        removed.push_back(u);
      }
      if (!engine.Relax())
      {
        return true;
      }
    }
  });
  ASSERT_FALSE(removed.empty());
  EXPECT_EQ(engine.GetRemovedCount(), removed.size());
  for (size_t step = 0; step < removed.size(); ++step)
  {
    EXPECT_EQ(engine.GetRemovedVertex(static_cast<uint32_t>(step)), removed[step]);
    EXPECT_TRUE(engine.IsRemoved(removed[step]));
  }
  EXPECT_LT(removed.size(), 36u); // at least the base triangle stays
  EXPECT_EQ(result.VertexOrder.size(), 36u);
  EXPECT_EQ(result.VertexCountError.size(), 37u);
  EXPECT_EQ(result.VertexCountError.back(), 0.0f);
}

TEST(CollapseEngine, AbortedScheduleStopsTheBuild)
{
  const Grid grid(3);
  const TOMBuildOptions options; // outlives the engine, which keeps its progress callback
  CollapseEngine engine(options, true);
  const TOMBuildResult result = RunWith(engine, grid, [] { return false; });
  EXPECT_TRUE(result.VertexOrder.empty());
}
}

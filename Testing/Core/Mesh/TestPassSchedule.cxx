// SPDX-License-Identifier: BSD-3-Clause
// PassSchedule (TOMBuildEngine::Passes): its radix sort of float keys, the
// passes it runs over the collapse engine, and the error of its order against
// the greedy one. TOMBuilder's own tests run over it as TestTOMBuilderPasses.

#include "CollapseEngine.h"
#include "PassSchedule.h"
#include "TOMBuilder.h"
#include "TOMValidator.h"

#include "MeshIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace
{
using namespace timecritical;
using collapse::PassSchedule;
using Entry = PassSchedule::Entry;
using timecritical::testing::TriangleMesh;

TOMBuildResult Build(const TriangleMesh& mesh, TOMBuildEngine engine)
{
  TOMBuildOptions options;
  options.Engine = engine;
  return TOMBuilder(options).Build(mesh.Points.data(), mesh.NumberOfPoints(),
    mesh.Triangles.data(), mesh.NumberOfTriangles());
}
}

TEST(PassSchedule, OrderedBitsKeepTheOrderOfFloats)
{
  const float keys[] = { -std::numeric_limits<float>::infinity(), -3.5f, -1e-30f, -0.f, 0.f,
    1e-38f, 1e-30f, 0.25f, 1.f, 3e30f, std::numeric_limits<float>::max(),
    std::numeric_limits<float>::infinity() };
  for (size_t i = 0; i + 1 < std::size(keys); ++i)
  {
    EXPECT_LE(PassSchedule::OrderedBits(keys[i]), PassSchedule::OrderedBits(keys[i + 1])) << i;
    if (keys[i] < keys[i + 1])
    {
      EXPECT_LT(PassSchedule::OrderedBits(keys[i]), PassSchedule::OrderedBits(keys[i + 1])) << i;
    }
  }
}

TEST(PassSchedule, ManyCollapsesPerPass)
{
  // Driven directly: a full TOM in passes, each pass many independent
  // collapses (a tenth of the live vertices or so), the result a valid TOM.
  const TriangleMesh mesh = timecritical::testing::MakeTorus(120, 48, 3, 0.05);
  TOMBuildOptions options;
  collapse::CollapseEngine engine(options, false);
  PassSchedule schedule(engine);
  const TOMBuildResult r = engine.Run(mesh.Points.data(), mesh.NumberOfPoints(),
    mesh.Triangles.data(), mesh.NumberOfTriangles(), [&schedule] { return schedule.Run(); });
  ASSERT_FALSE(r.Aborted);
  EXPECT_EQ(TOMValidator::Check(r.Mesh), "");
  const uint32_t removed = r.Mesh.GetNumberOfVertices() - r.Mesh.BaseVertexCount;
  EXPECT_GT(removed, 0.99 * double(mesh.NumberOfPoints()));
  EXPECT_GT(schedule.GetPassCount(), 10u);
  EXPECT_LT(schedule.GetPassCount(), removed / 20) << "too few collapses per pass";
}

TEST(PassSchedule, ErrorCloseToTheGreedyOrder)
{
  // The passes keep the cheapest-first order within a pass: the error at
  // every tested resolution stays within a small factor of the greedy one's.
  const TriangleMesh mesh = timecritical::testing::MakeTorus(160, 64, 7, 0.05);
  const TOMBuildResult greedy = Build(mesh, TOMBuildEngine::Greedy);
  const TOMBuildResult passes = Build(mesh, TOMBuildEngine::Passes);
  ASSERT_EQ(TOMValidator::Check(passes.Mesh), "");
  ASSERT_EQ(passes.Mesh.GetNumberOfVertices(), greedy.Mesh.GetNumberOfVertices());
  const uint32_t n = greedy.Mesh.GetNumberOfVertices();
  for (double fraction : { 0.5, 0.25, 0.1, 0.05, 0.02 })
  {
    const auto v = static_cast<uint32_t>(fraction * n);
    EXPECT_LE(passes.VertexCountError[v], 1.5 * greedy.VertexCountError[v]) << fraction;
    EXPECT_GT(passes.VertexCountError[v], 0.f) << fraction;
  }
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of TOMBuilder: the TOM invariants (checked independently of the
// validator as well as through it), the geometric guarantees (boundaries and
// sharp edges kept, no flipped triangles, coarsest meshes), bad inputs,
// progress and abort, determinism, the real meshes of the shared folder, and
// their quality (dense Hausdorff distance, measured with SurfaceDistance.h).
#include "SurfaceDistance.h"
#include "TOMBuilder.h"
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "TOMValidator.h"

#include "AllocationCounter.h"
#include "MeshIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace timecritical;
using timecritical::testing::TriangleMesh;

namespace
{
#define REQUIRE_SHARED_MESH(variable, name)                                                        \
  const timecritical::testing::SharedMesh variable = timecritical::testing::FindSharedMesh(name);  \
  if (!variable.Available)                                                                         \
  {                                                                                                \
    GTEST_SKIP() << "shared mesh not available: " << variable.Path;                                \
  }

struct V3
{
  double X, Y, Z;
};
V3 operator-(const V3& a, const V3& b)
{
  return { a.X - b.X, a.Y - b.Y, a.Z - b.Z };
}
V3 Cross(const V3& a, const V3& b)
{
  return { a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X };
}
double Dot(const V3& a, const V3& b)
{
  return a.X * b.X + a.Y * b.Y + a.Z * b.Z;
}

// The engine under test: the greedy one, or the pass schedule where the file
// is built a second time as TestTOMBuilderPasses (Testing/Core/Mesh/CMakeLists.txt).
#ifdef TIMECRITICAL_TEST_PASS_ENGINE
constexpr TOMBuildEngine EngineUnderTest = TOMBuildEngine::Passes;
#else
constexpr TOMBuildEngine EngineUnderTest = TOMBuildEngine::Greedy;
#endif

TOMBuildResult Build(const TriangleMesh& mesh, TOMBuildOptions options = {})
{
  options.Engine = EngineUnderTest;
  return TOMBuilder(options).Build(mesh.Points.data(), mesh.NumberOfPoints(),
    mesh.Triangles.data(), mesh.NumberOfTriangles());
}

/// Position of TOM vertex v (a new id) in the input.
V3 PointOf(const TriangleMesh& mesh, const TOMBuildResult& r, uint32_t v)
{
  const double* p = mesh.Points.data() + 3 * static_cast<size_t>(r.VertexOrder[v]);
  return { p[0], p[1], p[2] };
}

/// Unnormalised normal of a triangle given by three TOM vertex ids.
V3 NormalOf(const TriangleMesh& mesh, const TOMBuildResult& r, const uint32_t* t)
{
  const V3 a = PointOf(mesh, r, t[0]);
  return Cross(PointOf(mesh, r, t[1]) - a, PointOf(mesh, r, t[2]) - a);
}

/// The mesh of a TOM with the given vertex count (3 active ids per triangle).
std::vector<uint32_t> Extract(const TOMBuildResult& r, uint32_t vertexCount)
{
  TOMTraversal traversal(r.Mesh);
  std::vector<uint32_t> out;
  const uint32_t n = traversal.Extract(vertexCount, out);
  out.resize(3 * static_cast<size_t>(n));
  return out;
}

/// Vertex count of the finest level with at most `fraction` of the triangles.
uint32_t VertexCountAt(const TOMBuildResult& r, double fraction)
{
  TOMTraversal traversal(r.Mesh);
  return traversal.GetVertexCountForTriangles(
    static_cast<uint32_t>(fraction * r.Mesh.GetNumberOfTriangles()));
}

/**
 * Everything a TOMBuildResult promises, checked from first principles (and
 * through the validator): substitution order, triangle prefix order, the
 * mappings back to the input, the per-vertex-count arrays and the error
 * curve.
 */
void ExpectValidResult(const TriangleMesh& mesh, const TOMBuildResult& r)
{
  const TOMMesh& tom = r.Mesh;
  ASSERT_FALSE(r.Aborted);
  EXPECT_EQ(TOMValidator::Check(tom), "");
  const uint32_t n = tom.GetNumberOfVertices();
  const uint32_t t = tom.GetNumberOfTriangles();
  ASSERT_EQ(r.VertexOrder.size(), n);
  ASSERT_EQ(r.TriangleOrder.size(), t);
  ASSERT_EQ(r.VertexCountError.size(), n + size_t(1));
  ASSERT_EQ(r.TrianglesAtVertexCount.size(), n + size_t(1));
  ASSERT_GE(n, tom.BaseVertexCount);
  if (n > 0)
  {
    ASSERT_GE(tom.BaseVertexCount, 1u);
  }

  // Substitutions point lower; base vertices are fixed points.
  for (uint32_t i = 0; i < n; ++i)
  {
    if (i < tom.BaseVertexCount)
    {
      ASSERT_EQ(tom.Substitution[i], i);
    }
    else
    {
      ASSERT_LT(tom.Substitution[i], i) << "vertex " << i;
    }
  }

  // Vertices: exactly the used input points, survivors in input order.
  // Triangles: all but the degenerate ones and the repeats of an earlier
  // one's three points.
  std::vector<uint8_t> used(mesh.NumberOfPoints(), 0);
  std::vector<uint8_t> repeat(mesh.NumberOfTriangles(), 0);
  std::set<std::array<uint32_t, 3>> pointSets;
  size_t degenerate = 0, duplicates = 0;
  for (size_t k = 0; k < mesh.NumberOfTriangles(); ++k)
  {
    const uint32_t* c = mesh.Triangles.data() + 3 * k;
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
    {
      ++degenerate;
      continue;
    }
    std::array<uint32_t, 3> set = { c[0], c[1], c[2] };
    std::sort(set.begin(), set.end());
    if (!pointSets.insert(set).second)
    {
      repeat[k] = 1;
      ++duplicates;
    }
    used[c[0]] = used[c[1]] = used[c[2]] = 1;
  }
  const size_t usedCount = static_cast<size_t>(std::count(used.begin(), used.end(), 1));
  EXPECT_EQ(n, usedCount);
  EXPECT_EQ(r.UnusedPoints, mesh.NumberOfPoints() - usedCount);
  EXPECT_EQ(r.DroppedDegenerateTriangles, degenerate);
  EXPECT_EQ(r.DroppedDuplicateTriangles, duplicates);
  EXPECT_EQ(t, mesh.NumberOfTriangles() - degenerate - duplicates);
  std::vector<uint32_t> newIdOf(mesh.NumberOfPoints(), std::numeric_limits<uint32_t>::max());
  for (uint32_t i = 0; i < n; ++i)
  {
    ASSERT_LT(r.VertexOrder[i], mesh.NumberOfPoints());
    ASSERT_TRUE(used[r.VertexOrder[i]]);
    ASSERT_EQ(newIdOf[r.VertexOrder[i]], std::numeric_limits<uint32_t>::max())
      << "input point listed twice";
    newIdOf[r.VertexOrder[i]] = i;
  }
  for (uint32_t i = 1; i < tom.BaseVertexCount; ++i)
  {
    EXPECT_LT(r.VertexOrder[i - 1], r.VertexOrder[i]) << "base vertices not in input order";
  }

  // Triangles: a permutation of the non-degenerate input triangles, with the
  // original corners (and orientation) in new ids.
  std::vector<uint8_t> seen(mesh.NumberOfTriangles(), 0);
  for (uint32_t i = 0; i < t; ++i)
  {
    const uint32_t input = r.TriangleOrder[i];
    ASSERT_LT(input, mesh.NumberOfTriangles());
    ASSERT_FALSE(seen[input]) << "input triangle listed twice";
    ASSERT_FALSE(repeat[input]) << "a repeat kept instead of the first triangle on its points";
    seen[input] = 1;
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(tom.Triangles[3 * size_t(i) + k], newIdOf[mesh.Triangles[3 * size_t(input) + k]]);
    }
  }

  // Prefix order: minimum vertex counts never decrease; base triangles come first.
  TOMTraversal traversal(tom);
  uint32_t previous = 0;
  std::vector<uint32_t> aliveFrom(n + size_t(2), 0);
  for (uint32_t i = 0; i < t; ++i)
  {
    const uint32_t m = traversal.GetMinimumVertexCount(i);
    ASSERT_GE(m, previous) << "triangle " << i;
    ASSERT_LE(m, n);
    previous = m;
    ++aliveFrom[m];
    EXPECT_EQ(i < tom.BaseTriangleCount, m <= tom.BaseVertexCount) << "triangle " << i;
  }
  // Triangle counts per vertex count.
  uint32_t alive = 0;
  for (uint32_t i = 0; i <= n; ++i)
  {
    alive += aliveFrom[i];
    const uint32_t expected = i < tom.BaseVertexCount ? tom.BaseTriangleCount : alive;
    ASSERT_EQ(r.TrianglesAtVertexCount[i], expected) << "vertex count " << i;
  }
  if (n > 0)
  {
    EXPECT_EQ(r.TrianglesAtVertexCount[n], t);
  }

  // Errors: finite, non-negative, non-increasing, 0 at full resolution, the
  // base error repeated below the base.
  for (uint32_t i = 0; i <= n; ++i)
  {
    ASSERT_TRUE(std::isfinite(r.VertexCountError[i]));
    ASSERT_GE(r.VertexCountError[i], 0.f);
    if (i > 0)
    {
      ASSERT_LE(r.VertexCountError[i], r.VertexCountError[i - 1]) << "vertex count " << i;
    }
    if (i < tom.BaseVertexCount)
    {
      ASSERT_EQ(r.VertexCountError[i], r.VertexCountError[tom.BaseVertexCount]);
    }
  }
  EXPECT_EQ(r.VertexCountError[n], 0.f);
  EXPECT_EQ(tom.ErrorCurve.Check(t), "");
  if (t > 0)
  {
    EXPECT_FALSE(tom.ErrorCurve.IsEmpty());
  }
}

/// Connected components of a triangle soup given in vertex ids < n (union-find).
size_t CountComponents(const std::vector<uint32_t>& triangles, uint32_t n)
{
  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&parent](uint32_t x) {
    while (parent[x] != x)
    {
      x = parent[x] = parent[parent[x]];
    }
    return x;
  };
  std::vector<uint8_t> used(n, 0);
  for (size_t k = 0; k < triangles.size(); k += 3)
  {
    for (int c = 0; c < 3; ++c)
    {
      used[triangles[k + c]] = 1;
    }
    parent[find(triangles[k])] = find(triangles[k + 1]);
    parent[find(triangles[k + 1])] = find(triangles[k + 2]);
  }
  size_t components = 0;
  for (uint32_t v = 0; v < n; ++v)
  {
    components += used[v] && find(v) == v ? 1 : 0;
  }
  return components;
}

/// Two copies of a mesh, the second shifted along x.
TriangleMesh TwoCopies(const TriangleMesh& mesh, double shift)
{
  TriangleMesh out = mesh;
  const uint32_t offset = static_cast<uint32_t>(mesh.NumberOfPoints());
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    out.Points.insert(out.Points.end(),
      { mesh.Points[3 * i] + shift, mesh.Points[3 * i + 1], mesh.Points[3 * i + 2] });
  }
  for (uint32_t id : mesh.Triangles)
  {
    out.Triangles.push_back(id + offset);
  }
  return out;
}

/// A grid over [0,1]^2 with a smooth bump, so that collapses have a real cost.
TriangleMesh BumpyGrid(size_t n)
{
  TriangleMesh mesh = timecritical::testing::MakeGrid(n, n);
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    const double x = mesh.Points[3 * i], y = mesh.Points[3 * i + 1];
    mesh.Points[3 * i + 2] = 0.15 * std::sin(3.0 * x) * std::cos(2.0 * y);
  }
  return mesh;
}

bool SameResult(const TOMBuildResult& a, const TOMBuildResult& b)
{
  return a.Mesh.Substitution == b.Mesh.Substitution && a.Mesh.Triangles == b.Mesh.Triangles &&
    a.Mesh.BaseVertexCount == b.Mesh.BaseVertexCount &&
    a.Mesh.BaseTriangleCount == b.Mesh.BaseTriangleCount && a.VertexOrder == b.VertexOrder &&
    a.TriangleOrder == b.TriangleOrder && a.VertexCountError == b.VertexCountError &&
    a.TrianglesAtVertexCount == b.TrianglesAtVertexCount;
}
}

//------------------------------------------------------------------------------
// Invariants on generated meshes

TEST(TOMBuilder, GridWithBoundary)
{
  const TriangleMesh mesh = BumpyGrid(24);
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  // A disk simplifies down to a handful of vertices.
  EXPECT_LE(r.Mesh.BaseVertexCount, 6u);
  EXPECT_GE(r.Mesh.BaseTriangleCount, 1u);
}

TEST(TOMBuilder, IcosphereReducesToTetrahedron)
{
  const TriangleMesh mesh = timecritical::testing::MakeSphere(4); // 5120 triangles
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  // A closed genus-0 surface ends at a tetrahedron (the link condition stops there).
  EXPECT_EQ(r.Mesh.BaseVertexCount, 4u);
  EXPECT_EQ(r.Mesh.BaseTriangleCount, 4u);
  // Each collapse of a closed manifold removes exactly two triangles.
  for (uint32_t i = r.Mesh.BaseVertexCount; i < r.Mesh.GetNumberOfVertices(); ++i)
  {
    ASSERT_EQ(r.TrianglesAtVertexCount[i + 1] - r.TrianglesAtVertexCount[i], 2u);
  }
}

TEST(TOMBuilder, HighValencePoles)
{
  // Latitude/longitude sphere: two poles of valence 300.
  const TriangleMesh mesh = timecritical::testing::MakeUVSphere(40, 300);
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  EXPECT_LE(r.Mesh.BaseVertexCount, 8u);
}

TEST(TOMBuilder, NoisyTorus)
{
  const TriangleMesh mesh = timecritical::testing::MakeTorus(120, 40, 7, 0.05);
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  // Genus 1 cannot go below 7 vertices; a few more are fine.
  EXPECT_GE(r.Mesh.BaseVertexCount, 7u);
  EXPECT_LE(r.Mesh.BaseVertexCount, 16u);
}

TEST(TOMBuilder, TopologyIsPreserved)
{
  // The link condition keeps every resolution a manifold of the same
  // topology: closed, consistently oriented, same Euler characteristic, no
  // pinch vertex; the disk keeps one boundary loop.
  const std::pair<TriangleMesh, long long> cases[] = {
    { timecritical::testing::MakeSphere(3), 2 },
    { timecritical::testing::MakeTorus(90, 30, 2, 0.08), 0 },
    { BumpyGrid(20), 1 },
  };
  for (const auto& [mesh, euler] : cases)
  {
    const TOMBuildResult r = Build(mesh);
    ExpectValidResult(mesh, r);
    const uint32_t n = r.Mesh.GetNumberOfVertices();
    for (uint32_t count = n; count >= r.Mesh.BaseVertexCount; count -= std::max(1u, count / 9))
    {
      TriangleMesh level;
      level.Points.resize(3 * static_cast<size_t>(count));
      for (uint32_t v = 0; v < count; ++v)
      {
        const V3 p = PointOf(mesh, r, v);
        level.Points[3 * v] = p.X;
        level.Points[3 * v + 1] = p.Y;
        level.Points[3 * v + 2] = p.Z;
      }
      level.Triangles = Extract(r, count);
      const timecritical::testing::MeshTopology t = timecritical::testing::ComputeTopology(level);
      ASSERT_EQ(t.EulerCharacteristic, euler) << "vertex count " << count;
      ASSERT_EQ(t.NumberOfNonManifoldEdges, 0u) << count;
      ASSERT_EQ(t.NumberOfNonManifoldVertices, 0u) << count;
      ASSERT_TRUE(t.IsConsistentlyOriented()) << count;
      ASSERT_EQ(t.NumberOfUnusedPoints, 0u) << count;
      ASSERT_EQ(t.NumberOfComponents, 1u) << count;
      ASSERT_EQ(t.NumberOfBoundaryLoops, euler == 1 ? 1u : 0u) << count;
      if (count == r.Mesh.BaseVertexCount)
      {
        break;
      }
    }
  }
}

TEST(TOMBuilder, TwoComponentsStaySeparate)
{
  const TriangleMesh sphere = timecritical::testing::MakeSphere(3);
  const TriangleMesh mesh = TwoCopies(sphere, 3.0);
  TOMBuildOptions noPairs; // pair contraction joins them at the end (PairContraction*)
  noPairs.PairContractionDistance = 0.0;
  const TOMBuildResult r = Build(mesh, noPairs);
  ExpectValidResult(mesh, r);
  EXPECT_EQ(r.JoinedParts, 0u);
  // One tetrahedron per sphere.
  EXPECT_EQ(r.Mesh.BaseVertexCount, 8u);
  EXPECT_EQ(r.Mesh.BaseTriangleCount, 8u);
  // Both components survive at every resolution, and a collapse never joins them.
  const uint32_t n = r.Mesh.GetNumberOfVertices();
  for (uint32_t count : { n, n / 2, n / 8, r.Mesh.BaseVertexCount })
  {
    EXPECT_EQ(CountComponents(Extract(r, count), count), 2u) << "vertex count " << count;
  }
  for (uint32_t i = r.Mesh.BaseVertexCount; i < n; ++i)
  {
    const bool left = PointOf(mesh, r, i).X < 1.5;
    ASSERT_EQ(left, PointOf(mesh, r, r.Mesh.Substitution[i]).X < 1.5);
  }
}

//------------------------------------------------------------------------------
// Pair contraction: separate parts join close ones once no edge collapse is left

namespace
{
/// rows x cols unit icospheres (`subdivisions`) in the z = 0 plane, centres
/// `spacing` apart.
TriangleMesh SphereArray(size_t rows, size_t cols, double spacing, size_t subdivisions = 2)
{
  const TriangleMesh sphere = timecritical::testing::MakeSphere(subdivisions);
  TriangleMesh out;
  for (size_t i = 0; i < rows * cols; ++i)
  {
    const uint32_t offset = static_cast<uint32_t>(out.NumberOfPoints());
    for (size_t p = 0; p < sphere.NumberOfPoints(); ++p)
    {
      out.Points.insert(out.Points.end(), { sphere.Points[3 * p] + spacing * double(i % cols),
                                            sphere.Points[3 * p + 1] + spacing * double(i / cols),
                                            sphere.Points[3 * p + 2] });
    }
    for (uint32_t id : sphere.Triangles)
    {
      out.Triangles.push_back(id + offset);
    }
  }
  return out;
}

/// The mesh of a TOM at a vertex count, with its points (TOM ids).
TriangleMesh Level(const TriangleMesh& mesh, const TOMBuildResult& r, uint32_t count)
{
  TriangleMesh level;
  for (uint32_t v = 0; v < count; ++v)
  {
    const V3 p = PointOf(mesh, r, v);
    level.Points.insert(level.Points.end(), { p.X, p.Y, p.Z });
  }
  level.Triangles = Extract(r, count);
  return level;
}

TOMBuildOptions WithPairs(double distance)
{
  TOMBuildOptions options;
  options.PairContractionDistance = distance;
  return options;
}

/// Whether every edge of a level used other than twice ends at one of `targets`.
bool OddEdgesEndAt(const TriangleMesh& level, const std::set<uint32_t>& targets)
{
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (size_t k = 0; k < level.Triangles.size(); k += 3)
  {
    for (size_t c = 0; c < 3; ++c)
    {
      const uint32_t a = level.Triangles[k + c], b = level.Triangles[k + (c + 1) % 3];
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  for (const auto& [edge, u] : uses)
  {
    if (u != 2 && !targets.count(edge.first) && !targets.count(edge.second))
    {
      return false;
    }
  }
  return true;
}
}

TEST(TOMBuilder, PairContractionJoinsCloseParts)
{
  // 3 x 3 spheres with gaps of 0.5 (a diagonal of 7.6): without pairs each
  // keeps a tetrahedron (36 triangles at the coarsest); with them they join.
  const TriangleMesh mesh = SphereArray(3, 3, 2.5);
  const TOMBuildResult off = Build(mesh, WithPairs(0.0));
  const TOMBuildResult on = Build(mesh, WithPairs(0.5));
  ExpectValidResult(mesh, off);
  ExpectValidResult(mesh, on);
  const uint32_t n = on.Mesh.GetNumberOfVertices();
  ASSERT_EQ(off.Mesh.BaseVertexCount, 36u);
  EXPECT_EQ(off.JoinedParts, 0u);
  EXPECT_EQ(on.JoinedParts, 8u) << "all nine spheres end as one";
  EXPECT_EQ(on.Mesh.BaseVertexCount, 4u);
  EXPECT_EQ(on.Mesh.BaseTriangleCount, 4u);

  // Every resolution down to the coarsest without pairs is the same: the
  // same vertex removed at each step, the same triangle counts and errors.
  const uint32_t baseOff = off.Mesh.BaseVertexCount;
  for (uint32_t i = baseOff; i < n; ++i)
  {
    ASSERT_EQ(on.VertexOrder[i], off.VertexOrder[i]) << i;
    ASSERT_EQ(on.TrianglesAtVertexCount[i], off.TrianglesAtVertexCount[i]) << i;
    ASSERT_EQ(on.VertexCountError[i], off.VertexCountError[i]) << i;
  }
  // Below, each join substitutes a whole part: the error grows, the
  // triangles go, and the parts become fewer.
  EXPECT_GT(on.VertexCountError[on.Mesh.BaseVertexCount], off.VertexCountError[baseOff]);
  EXPECT_EQ(CountComponents(Extract(on, baseOff), baseOff), 9u);
  EXPECT_EQ(CountComponents(Extract(on, on.Mesh.BaseVertexCount), on.Mesh.BaseVertexCount), 1u);

  // Manifold where the input was, except where parts join: an edge used
  // other than twice only ever ends at a vertex a part is joining, and at
  // most one vertex is pinched at any level (one join at a time); every
  // level without a pinch is a set of closed manifold parts.
  std::set<uint32_t> targets;
  for (uint32_t i = on.Mesh.BaseVertexCount; i < baseOff; ++i)
  {
    targets.insert(on.Mesh.Substitution[i]);
  }
  for (uint32_t count = n; count >= on.Mesh.BaseVertexCount; --count)
  {
    const TriangleMesh level = Level(mesh, on, count);
    ASSERT_TRUE(OddEdgesEndAt(level, targets)) << "vertex count " << count;
    const timecritical::testing::MeshTopology t = timecritical::testing::ComputeTopology(level);
    ASSERT_LE(t.NumberOfNonManifoldVertices, 1u) << count;
    if (count >= baseOff || t.NumberOfNonManifoldVertices == 0)
    {
      ASSERT_EQ(t.NumberOfNonManifoldEdges, 0u) << count;
      ASSERT_EQ(t.NumberOfBoundaryEdges, 0u) << count;
      ASSERT_EQ(t.EulerCharacteristic,
        2 * static_cast<long long>(CountComponents(level.Triangles, count)))
        << count;
    }
    if (count == on.Mesh.BaseVertexCount)
    {
      break;
    }
  }
}

TEST(TOMBuilder, PairContractionKeepsDistantPartsApart)
{
  // Gaps of 3 (a diagonal of 11.5): no coarse vertices within 0.05 of the
  // diagonal, nothing joins; within the whole diagonal, everything does.
  const TriangleMesh mesh = SphereArray(2, 2, 5.0, 1);
  const TOMBuildResult near = Build(mesh, WithPairs(0.05));
  ExpectValidResult(mesh, near);
  EXPECT_EQ(near.JoinedParts, 0u);
  EXPECT_EQ(near.Mesh.BaseVertexCount, 16u);
  const TOMBuildResult all = Build(mesh, WithPairs(1.0));
  ExpectValidResult(mesh, all);
  EXPECT_EQ(all.JoinedParts, 3u);
  EXPECT_EQ(all.Mesh.BaseVertexCount, 4u);
}

TEST(TOMBuilder, PairContractionLeavesOnePartAlone)
{
  // One part: nothing to join, the very same TOM and work.
  for (const TriangleMesh& mesh :
    { timecritical::testing::MakeTorus(80, 30, 9, 0.08), BumpyGrid(20) })
  {
    const TOMBuildResult off = Build(mesh, WithPairs(0.0));
    const TOMBuildResult on = Build(mesh, WithPairs(0.5));
    ExpectValidResult(mesh, on);
    EXPECT_TRUE(SameResult(off, on));
    EXPECT_EQ(on.FanTrianglesVisited, off.FanTrianglesVisited);
    EXPECT_EQ(on.JoinedParts, 0u);
  }
}

TEST(TOMBuilder, PairContractionWorkStaysBounded)
{
  // 20,000 separate triangles in a unit cube, all within the distance of one
  // another: every part is a lone triangle (no edge collapse), and a lookup
  // would see every vertex. The lookup budgets keep the work linear.
  TriangleMesh fog;
  uint32_t seed = 12345;
  auto next = [&seed]() {
    seed = seed * 1664525u + 1013904223u;
    return double(seed >> 8) / double(1u << 24);
  };
  for (uint32_t t = 0; t < 20000; ++t)
  {
    const double x = next(), y = next(), z = next();
    fog.Points.insert(fog.Points.end(), { x, y, z, x + 0.01, y, z, x, y + 0.01, z });
    fog.Triangles.insert(fog.Triangles.end(), { 3 * t, 3 * t + 1, 3 * t + 2 });
  }
  const TOMBuildResult r = Build(fog, WithPairs(1.0));
  ExpectValidResult(fog, r);
  EXPECT_GT(r.JoinedParts, 100u);
  EXPECT_LT(r.FanTrianglesVisited, 1000u * fog.NumberOfTriangles());
}

TEST(TOMBuilder, BadPairContractionDistanceThrows)
{
  const TriangleMesh mesh = timecritical::testing::MakeSphere(1);
  for (double bad : { -0.1, std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::infinity() })
  {
    try
    {
      Build(mesh, WithPairs(bad));
      FAIL() << "no exception for " << bad;
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find("PairContractionDistance must be a finite number >= 0"),
        std::string::npos)
        << e.what();
    }
  }
}

namespace
{
/// Checks that every triangle of the TOM at the given fraction lies on one
/// face of the cube (within `slack` of its plane) and that the 8 corners are there.
void ExpectCubeIntact(const TriangleMesh& mesh, const TOMBuildResult& r, double fraction, double slack)
{
  const uint32_t count = VertexCountAt(r, fraction);
  const std::vector<uint32_t> tris = Extract(r, count);
  ASSERT_FALSE(tris.empty());
  for (size_t k = 0; k < tris.size(); k += 3)
  {
    bool onOneFace = false;
    for (int axis = 0; axis < 3 && !onOneFace; ++axis)
    {
      for (double sign : { -1.0, 1.0 })
      {
        bool all = true;
        for (int c = 0; c < 3; ++c)
        {
          const V3 p = PointOf(mesh, r, tris[k + c]);
          const double coordinate = axis == 0 ? p.X : (axis == 1 ? p.Y : p.Z);
          all = all && sign * coordinate >= 0.5 - slack;
        }
        onOneFace = onOneFace || all;
      }
    }
    ASSERT_TRUE(onOneFace) << "a triangle cuts a cube edge at " << fraction;
  }
  size_t corners = 0;
  for (uint32_t v = 0; v < count; ++v)
  {
    const V3 p = PointOf(mesh, r, v);
    corners += std::abs(p.X) == 0.5 && std::abs(p.Y) == 0.5 && std::abs(p.Z) == 0.5 ? 1 : 0;
  }
  EXPECT_EQ(corners, 8u) << fraction;
}
}

TEST(TOMBuilder, SharpCubeEdgesAreKept)
{
  // The hard rule alone (locked feature edges, no constraint quadrics):
  // feature vertices slide along the cube edges only and the corners stay,
  // until nothing else is left.
  const TriangleMesh cube = timecritical::testing::MakeCube(12);
  TOMBuildOptions hard;
  hard.LockFeatureEdges = true;
  hard.ConstraintWeight = 0.0;
  const TOMBuildResult r = Build(cube, hard);
  ExpectValidResult(cube, r);
  for (double fraction : { 0.5, 0.25, 0.1, 0.05, 0.02 })
  {
    ExpectCubeIntact(cube, r, fraction, 1e-12);
  }
  // The flat faces cost nothing: the error only appears once the cube itself
  // is given up, below its 8 corners.
  EXPECT_EQ(r.VertexCountError[VertexCountAt(r, 0.02)], 0.f);

  // With bumpy faces the defaults (feature edges weighted, not locked) keep
  // the edges too, where plain quadrics start cutting corners.
  const double noise = 0.6 / 16;
  const TriangleMesh noisy = timecritical::testing::MakeNoisyCube(16, noise);
  const TOMBuildResult rn = Build(noisy);
  ExpectValidResult(noisy, rn);
  for (double fraction : { 0.25, 0.1, 0.05 })
  {
    ExpectCubeIntact(noisy, rn, fraction, noise / 2 + 1e-9);
  }
  const TOMBuildResult rh = Build(noisy, hard);
  for (double fraction : { 0.25, 0.1, 0.05 })
  {
    ExpectCubeIntact(noisy, rh, fraction, noise / 2 + 1e-9);
  }
}

TEST(TOMBuilder, BoundaryStaysOnItsPolyline)
{
  auto side = [](const V3& p) {
    // Bit mask of the sides of the unit square the point lies on.
    return (p.X == 0.0 ? 1 : 0) | (p.X == 1.0 ? 2 : 0) | (p.Y == 0.0 ? 4 : 0) |
      (p.Y == 1.0 ? 8 : 0);
  };
  auto expectBoundaryKept = [&side](const TriangleMesh& mesh, const TOMBuildResult& r,
                              double fraction) {
    const uint32_t count = VertexCountAt(r, fraction);
    const std::vector<uint32_t> tris = Extract(r, count);
    // Boundary edges of the extracted mesh: used once.
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (size_t k = 0; k < tris.size(); k += 3)
    {
      for (int c = 0; c < 3; ++c)
      {
        const uint32_t a = tris[k + c], b = tris[k + (c + 1) % 3];
        ++uses[{ std::min(a, b), std::max(a, b) }];
      }
    }
    size_t boundaryEdges = 0;
    for (const auto& [edge, number] : uses)
    {
      if (number != 1)
      {
        continue;
      }
      ++boundaryEdges;
      // Both ends on the original boundary, on a common side of the square:
      // the edge runs along the original boundary polyline.
      const int sa = side(PointOf(mesh, r, edge.first));
      const int sb = side(PointOf(mesh, r, edge.second));
      ASSERT_NE(sa & sb, 0) << "boundary edge off the original boundary at " << fraction;
    }
    EXPECT_GE(boundaryEdges, 4u);
    // The four corners of the square (sharp turns of the boundary) stay.
    size_t corners = 0;
    for (uint32_t v = 0; v < count; ++v)
    {
      const int s = side(PointOf(mesh, r, v));
      corners += (s & 3) && (s & 12) ? 1 : 0;
    }
    EXPECT_EQ(corners, 4u) << fraction;
  };

  // Defaults, on a curved sheet.
  const TriangleMesh bumpy = BumpyGrid(32);
  const TOMBuildResult r = Build(bumpy);
  ExpectValidResult(bumpy, r);
  for (double fraction : { 0.5, 0.25, 0.1 })
  {
    expectBoundaryKept(bumpy, r, fraction);
  }

  // The hard rule alone (no constraint quadrics) on a flat sheet with a
  // rough interior, where eating into the boundary would be the cheapest.
  TriangleMesh rough = timecritical::testing::MakeGrid(32, 32);
  for (size_t i = 0; i < rough.NumberOfPoints(); ++i)
  {
    const double x = rough.Points[3 * i], y = rough.Points[3 * i + 1];
    const bool interior = x > 0.0 && x < 1.0 && y > 0.0 && y < 1.0;
    rough.Points[3 * i + 2] = interior ? 0.004 * std::sin(37 * x + 11 * y * y) * std::cos(23 * y) : 0;
  }
  TOMBuildOptions hard;
  hard.ConstraintWeight = 0.0;
  const TOMBuildResult rh = Build(rough, hard);
  ExpectValidResult(rough, rh);
  for (double fraction : { 0.5, 0.25, 0.1, 0.05 })
  {
    expectBoundaryKept(rough, rh, fraction);
  }
}

TEST(TOMBuilder, NoFlippedTriangles)
{
  // Sphere around the origin: every triangle faces outwards at every sampled
  // resolution down to 2% of the triangles.
  const TriangleMesh sphere = timecritical::testing::MakeSphere(4);
  const TOMBuildResult rs = Build(sphere);
  ExpectValidResult(sphere, rs);
  for (double fraction : { 1.0, 0.5, 0.25, 0.1, 0.02 })
  {
    const uint32_t count = std::max(VertexCountAt(rs, fraction), rs.Mesh.BaseVertexCount);
    const std::vector<uint32_t> tris = Extract(rs, count);
    for (size_t k = 0; k < tris.size(); k += 3)
    {
      const V3 centroid = { (PointOf(sphere, rs, tris[k]).X + PointOf(sphere, rs, tris[k + 1]).X +
                              PointOf(sphere, rs, tris[k + 2]).X) / 3.0,
        (PointOf(sphere, rs, tris[k]).Y + PointOf(sphere, rs, tris[k + 1]).Y +
          PointOf(sphere, rs, tris[k + 2]).Y) / 3.0,
        (PointOf(sphere, rs, tris[k]).Z + PointOf(sphere, rs, tris[k + 1]).Z +
          PointOf(sphere, rs, tris[k + 2]).Z) / 3.0 };
      // Not flipped. (The default MaximumNormalDeviation, 90 degrees, lets a
      // triangle stand on edge: its three corners on one great circle.)
      const V3 nrm = NormalOf(sphere, rs, &tris[k]);
      ASSERT_GE(Dot(nrm, centroid), -1e-9 * std::sqrt(Dot(nrm, nrm) * Dot(centroid, centroid)))
        << "at " << fraction;
    }
  }
  // The base is a tetrahedron of four sphere points, which need not contain
  // the centre (facing away from the centre stands for "not flipped" only
  // while the mesh is close to the sphere): it is not turned inside out.
  {
    TriangleMesh base;
    base.Triangles = Extract(rs, rs.Mesh.BaseVertexCount);
    for (uint32_t v = 0; v < rs.Mesh.BaseVertexCount; ++v)
    {
      const V3 p = PointOf(sphere, rs, v);
      base.Points.insert(base.Points.end(), { p.X, p.Y, p.Z });
    }
    ASSERT_EQ(base.NumberOfTriangles(), 4u);
    EXPECT_GT(timecritical::testing::SignedVolume(base) * timecritical::testing::SignedVolume(sphere),
      0.0);
  }
  // Bumpy height field: no triangle turns over while the boundary holds, and
  // with a tighter MaximumNormalDeviation none even stands on edge.
  const TriangleMesh grid = BumpyGrid(32);
  TOMBuildOptions tight;
  tight.MaximumNormalDeviation = 45.0;
  const TOMBuildResult rg = Build(grid);
  const TOMBuildResult rt = Build(grid, tight);
  ExpectValidResult(grid, rt);
  for (double fraction : { 0.5, 0.25, 0.1 })
  {
    const std::vector<uint32_t> tris = Extract(rg, VertexCountAt(rg, fraction));
    for (size_t k = 0; k < tris.size(); k += 3)
    {
      const V3 nrm = NormalOf(grid, rg, &tris[k]);
      ASSERT_GE(nrm.Z, -1e-9 * std::sqrt(Dot(nrm, nrm))) << "at " << fraction;
    }
    const std::vector<uint32_t> tightTris = Extract(rt, VertexCountAt(rt, fraction));
    for (size_t k = 0; k < tightTris.size(); k += 3)
    {
      const V3 nrm = NormalOf(grid, rt, &tightTris[k]);
      ASSERT_GT(nrm.Z, 0.1 * std::sqrt(Dot(nrm, nrm))) << "at " << fraction;
    }
  }
}

TEST(TOMBuilder, FlatRegionsCostNothing)
{
  // A flat grid with a fixed square boundary: half the vertices go without
  // any geometric error.
  const TriangleMesh mesh = timecritical::testing::MakeGrid(30, 30);
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  EXPECT_LT(r.VertexCountError[VertexCountAt(r, 0.5)], 1e-6f);
  // The error of the curved grid grows as the resolution drops.
  const TriangleMesh bumpy = BumpyGrid(30);
  const TOMBuildResult rb = Build(bumpy);
  const float e50 = rb.VertexCountError[VertexCountAt(rb, 0.5)];
  const float e10 = rb.VertexCountError[VertexCountAt(rb, 0.1)];
  EXPECT_GT(e50, 0.f);
  EXPECT_GT(e10, e50);
  EXPECT_LT(e10, 0.05f); // a distance in world units, well below the bump (0.15)
}

TEST(TOMBuilder, SubstitutionChainsStayShort)
{
  // Traversal follows substitution chains (Gobbetti & Bouvier 6.1.2), so they
  // must stay short. Flat regions are the trap: every collapse there is free,
  // and without a tie-breaker one vertex rolls along a row and swallows it
  // (chains as long as the row, and quadratic build time).
  const TriangleMesh meshes[] = { timecritical::testing::MakeGrid(200, 200),
    timecritical::testing::MakeCube(60), timecritical::testing::MakeTorus(200, 60, 3, 0.05) };
  for (const TriangleMesh& mesh : meshes)
  {
    const TOMBuildResult r = Build(mesh);
    ASSERT_EQ(TOMValidator::Check(r.Mesh), "");
    const std::vector<uint32_t>& s = r.Mesh.Substitution;
    std::vector<uint32_t> depth(s.size(), 0);
    uint32_t deepest = 0;
    double total = 0.0;
    for (size_t i = 0; i < s.size(); ++i)
    {
      depth[i] = s[i] == i ? 0 : depth[s[i]] + 1;
      deepest = std::max(deepest, depth[i]);
      total += depth[i];
    }
    EXPECT_LE(deepest, 48u) << mesh.NumberOfTriangles() << " triangles";
    EXPECT_LE(total / static_cast<double>(s.size()), 16.0) << mesh.NumberOfTriangles() << " triangles";
  }
}

TEST(TOMBuilder, ErrorsScaleWithTheModel)
{
  // The build works in a normalised frame: scaling the input by a power of
  // two gives the same TOM and errors scaled exactly.
  const TriangleMesh mesh = timecritical::testing::MakeTorus(60, 20, 3, 0.05);
  TriangleMesh scaled = mesh;
  for (double& c : scaled.Points)
  {
    c = c * 1024.0 + 4096.0;
  }
  const TOMBuildResult a = Build(mesh);
  const TOMBuildResult b = Build(scaled);
  ExpectValidResult(scaled, b);
  EXPECT_EQ(a.Mesh.Substitution, b.Mesh.Substitution);
  EXPECT_EQ(a.Mesh.Triangles, b.Mesh.Triangles);
  for (size_t i = 0; i < a.VertexCountError.size(); ++i)
  {
    ASSERT_NEAR(b.VertexCountError[i], 1024.f * a.VertexCountError[i],
      1e-4f * b.VertexCountError[i] + 1e-6f);
  }
}

//------------------------------------------------------------------------------
// Options

TEST(TOMBuilder, OptionsKeepTheResultValid)
{
  const TriangleMesh mesh = BumpyGrid(24);
  TOMBuildOptions free;
  free.PreserveBoundaries = false;
  free.PreserveFeatureEdges = false;
  ExpectValidResult(mesh, Build(mesh, free));

  TOMBuildOptions strict;
  strict.MaximumNormalDeviation = 30.0;
  strict.MinimumTriangleQuality = 0.3;
  strict.ErrorCurveSamples = 8;
  const TOMBuildResult r = Build(mesh, strict);
  ExpectValidResult(mesh, r);
  EXPECT_LE(r.Mesh.ErrorCurve.GetSamples().size(), 8u);
  // Relaxation still reaches the coarsest mesh.
  EXPECT_LE(r.Mesh.BaseVertexCount, 6u);

  TOMBuildOptions noNormalCheck;
  noNormalCheck.MaximumNormalDeviation = 180.0;
  ExpectValidResult(mesh, Build(mesh, noNormalCheck));
}

TEST(TOMBuilder, SliverRejectionImprovesTriangles)
{
  // Eq. 3 of Xia, El-Sana & Varshney: 4 sqrt(3) area / sum of squared edges.
  const TriangleMesh mesh = timecritical::testing::MakeTorus(90, 30, 5, 0.05);
  auto worstQuality = [&mesh](const TOMBuildResult& r, double fraction) {
    const std::vector<uint32_t> tris = Extract(r, VertexCountAt(r, fraction));
    double worst = 1.0;
    for (size_t k = 0; k < tris.size(); k += 3)
    {
      const V3 a = PointOf(mesh, r, tris[k]), b = PointOf(mesh, r, tris[k + 1]),
               c = PointOf(mesh, r, tris[k + 2]);
      const V3 n = Cross(b - a, c - a);
      const double l = Dot(b - a, b - a) + Dot(c - b, c - b) + Dot(a - c, a - c);
      worst = std::min(worst, 2.0 * std::sqrt(3.0) * std::sqrt(Dot(n, n)) / l);
    }
    return worst;
  };
  TOMBuildOptions options;
  options.MinimumTriangleQuality = 0.2;
  const TOMBuildResult plain = Build(mesh);
  const TOMBuildResult filtered = Build(mesh, options);
  ExpectValidResult(mesh, filtered);
  EXPECT_GT(worstQuality(filtered, 0.25), worstQuality(plain, 0.25));
}

//------------------------------------------------------------------------------
// Inputs

TEST(TOMBuilder, EmptyInputGivesEmptyResult)
{
  const TOMBuildResult r = TOMBuilder().Build(nullptr, 0, nullptr, 0);
  EXPECT_FALSE(r.Aborted);
  EXPECT_EQ(r.Mesh.GetNumberOfVertices(), 0u);
  EXPECT_EQ(r.Mesh.GetNumberOfTriangles(), 0u);
  EXPECT_EQ(TOMValidator::Check(r.Mesh), "");
  EXPECT_EQ(r.VertexCountError, std::vector<float>{ 0.f });
  EXPECT_EQ(r.TrianglesAtVertexCount, std::vector<uint32_t>{ 0u });

  // Points but no triangles: all unused.
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0 };
  const TOMBuildResult p = TOMBuilder().Build(points.data(), 2, nullptr, 0);
  EXPECT_EQ(p.Mesh.GetNumberOfVertices(), 0u);
  EXPECT_EQ(p.UnusedPoints, 2u);
}

TEST(TOMBuilder, AllDegenerateTrianglesAreDropped)
{
  TriangleMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  mesh.Triangles = { 0, 0, 1, 1, 2, 1, 2, 2, 2 };
  const TOMBuildResult r = Build(mesh);
  EXPECT_EQ(r.DroppedDegenerateTriangles, 3u);
  EXPECT_EQ(r.UnusedPoints, 3u);
  EXPECT_EQ(r.Mesh.GetNumberOfVertices(), 0u);
  EXPECT_EQ(TOMValidator::Check(r.Mesh), "");
}

TEST(TOMBuilder, SingleTriangleIsItsOwnBase)
{
  TriangleMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5 }; // the last point is unused
  mesh.Triangles = { 2, 0, 1, 0, 0, 3 };               // plus a degenerate one
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  EXPECT_EQ(r.Mesh.BaseVertexCount, 3u);
  EXPECT_EQ(r.Mesh.BaseTriangleCount, 1u);
  EXPECT_EQ(r.UnusedPoints, 1u);
  EXPECT_EQ(r.DroppedDegenerateTriangles, 1u);
  EXPECT_EQ(r.VertexOrder, (std::vector<uint32_t>{ 0, 1, 2 }));
  EXPECT_EQ(r.Mesh.Triangles, (std::vector<uint32_t>{ 2, 0, 1 }));
}

TEST(TOMBuilder, OutOfRangeIdsThrow)
{
  TriangleMesh mesh = timecritical::testing::MakeGrid(2, 2);
  mesh.Triangles[7] = static_cast<uint32_t>(mesh.NumberOfPoints());
  try
  {
    Build(mesh);
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("triangle 2"), std::string::npos) << e.what();
  }
  // Null arrays with non-zero counts are rejected as well.
  EXPECT_THROW(TOMBuilder().Build(nullptr, 3, mesh.Triangles.data(), 1), std::invalid_argument);
  EXPECT_THROW(TOMBuilder().Build(mesh.Points.data(), 3, nullptr, 1), std::invalid_argument);
}

TEST(TOMBuilder, NonFiniteCoordinatesOfUsedPointsThrow)
{
  TriangleMesh mesh = timecritical::testing::MakeGrid(2, 2);
  mesh.Points.insert(mesh.Points.end(), { std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0 });
  // An unused point may be anything.
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  EXPECT_EQ(r.UnusedPoints, 1u);
  // A used one may not.
  mesh.Points[3 * 4 + 1] = std::numeric_limits<double>::infinity();
  try
  {
    Build(mesh);
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 4"), std::string::npos) << e.what();
  }
  mesh.Points[3 * 4 + 1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Build(mesh), std::invalid_argument);
}

TEST(TOMBuilder, NonManifoldEdgeAndPinchVertex)
{
  // Two fins on the grid's boundary edge (0, 1), which then has three
  // triangles (one of them wound the other way), and two triangles joining
  // the fins' tips to the opposite grid corner 80, which becomes a pinch
  // vertex (two fans meet there).
  TriangleMesh mesh = BumpyGrid(8);
  const uint32_t base = static_cast<uint32_t>(mesh.NumberOfPoints());
  mesh.Points.insert(mesh.Points.end(), { 0.5, 0.5, 1.0, 0.5, 0.6, 1.0, 0.4, 0.5, 1.0 });
  mesh.Triangles.insert(mesh.Triangles.end(), { 0, 1, base, 1, 0, base + 1 });
  mesh.Triangles.insert(mesh.Triangles.end(), { 80, base, base + 2, 80, base + 2, base + 1 });
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  // Every resolution stays free of degenerate and duplicate triangles.
  const uint32_t n = r.Mesh.GetNumberOfVertices();
  for (uint32_t count = r.Mesh.BaseVertexCount; count <= n; count += 7)
  {
    const std::vector<uint32_t> tris = Extract(r, count);
    std::set<std::array<uint32_t, 3>> unique;
    for (size_t k = 0; k < tris.size(); k += 3)
    {
      std::array<uint32_t, 3> t = { tris[k], tris[k + 1], tris[k + 2] };
      ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
      std::sort(t.begin(), t.end());
      ASSERT_TRUE(unique.insert(t).second) << "duplicate triangle at vertex count " << count;
    }
  }
}

TEST(TOMBuilder, DuplicatePointsAndDuplicateTriangles)
{
  // Two grids sharing the positions of a seam but not the point ids (like an
  // unwelded OBJ), plus a triangle listed again, and another one reversed.
  TriangleMesh mesh = TwoCopies(BumpyGrid(10), 1.0);
  mesh.Triangles.insert(mesh.Triangles.end(), mesh.Triangles.begin(), mesh.Triangles.begin() + 3);
  const uint32_t reversed[3] = { mesh.Triangles[5], mesh.Triangles[4], mesh.Triangles[3] };
  mesh.Triangles.insert(mesh.Triangles.end(), reversed, reversed + 3);
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  // Ids of the same points as earlier triangles: the repeats are dropped,
  // the seam's coincident points are not merged (that is the caller's choice).
  EXPECT_EQ(r.DroppedDuplicateTriangles, 2u);
  EXPECT_EQ(r.Mesh.GetNumberOfTriangles(), mesh.NumberOfTriangles() - 2);
  EXPECT_EQ(r.DroppedDegenerateTriangles, 0u);
}

//------------------------------------------------------------------------------
// Degenerate input: coincident copies, huge fans, huge coordinates

namespace
{
/// `copies` copies of a 64-triangle sphere on the same points (what appending
/// coincident copies and merging points gives), every other one reversed.
TriangleMesh CoincidentCopies(size_t copies)
{
  const TriangleMesh sphere = timecritical::testing::MakeUVSphere(5, 8);
  TriangleMesh mesh;
  mesh.Points = sphere.Points;
  for (size_t c = 0; c < copies; ++c)
  {
    for (size_t t = 0; t < sphere.NumberOfTriangles(); ++t)
    {
      const uint32_t* v = &sphere.Triangles[3 * t];
      mesh.Triangles.insert(mesh.Triangles.end(),
        { v[0], c % 2 ? v[2] : v[1], c % 2 ? v[1] : v[2] });
    }
  }
  return mesh;
}
}

TEST(TOMBuilder, CoincidentCopiesGiveTheTOMOfOneCopy)
{
  // Without deduplication every vertex has a fan of 6,000 triangles and the
  // collapses walk them over and over: quadratic in the copies.
  const TriangleMesh one = CoincidentCopies(1);
  const TriangleMesh many = CoincidentCopies(1000);
  const TOMBuildResult a = Build(one);
  const TOMBuildResult b = Build(many);
  ExpectValidResult(many, b);
  EXPECT_EQ(b.DroppedDuplicateTriangles, 999u * 64u);
  EXPECT_TRUE(SameResult(a, b)) << "the first copy's triangles are kept, in input order";
  EXPECT_EQ(b.FanTrianglesVisited, a.FanTrianglesVisited);
  // Pair contraction at its largest distance: still one part, the same TOM.
  const TOMBuildResult c = Build(many, WithPairs(1.0));
  EXPECT_TRUE(SameResult(a, c));
  EXPECT_EQ(c.FanTrianglesVisited, a.FanTrianglesVisited);
}

TEST(TOMBuilder, WorkStaysLinearOnHugeFans)
{
  // A fan of 100,000 triangles around one vertex, and crumpled fans, where
  // nearly every collapse of the hub is illegal: checking them one by one
  // walked the hub's whole fan each time (4,000 triangles took 20 s, 16,000
  // did not finish). The work counter, not the time, is the measure: 30 to
  // 45 per triangle on real meshes; the bound on fans keeps it linear here.
  const TriangleMesh flat = timecritical::testing::MakeFan(100000, false);
  const TOMBuildResult r = Build(flat);
  ExpectValidResult(flat, r);
  EXPECT_LE(r.Mesh.BaseVertexCount, 4u);
  EXPECT_LT(r.FanTrianglesVisited, 100u * flat.NumberOfTriangles());
  for (uint32_t n : { 4000u, 16000u })
  {
    const TriangleMesh crumpled = timecritical::testing::MakeFan(n, true);
    const TOMBuildResult c = Build(crumpled);
    ExpectValidResult(crumpled, c);
    EXPECT_LT(c.FanTrianglesVisited, 4000u * crumpled.NumberOfTriangles()) << n;
    // Two crumpled fans side by side, with pair contraction: they may join.
    const TriangleMesh two = TwoCopies(crumpled, 2.5);
    const TOMBuildResult p = Build(two, WithPairs(1.0));
    ExpectValidResult(two, p);
    EXPECT_LT(p.FanTrianglesVisited, 4000u * two.NumberOfTriangles()) << n;
  }
}

TEST(TOMBuilder, CoordinatesBeyondTheLimitThrow)
{
  // Errors and merge-tree radii are stored as float: far beyond
  // MaximumCoordinateMagnitude they would overflow to infinity.
  TriangleMesh mesh = timecritical::testing::MakeGrid(2, 2);
  mesh.Points.insert(mesh.Points.end(), { 3e38, 0.0, 0.0 }); // unused: anything goes
  ExpectValidResult(mesh, Build(mesh));
  mesh.Points[3 * 4 + 2] = -2.2e38;
  try
  {
    Build(mesh);
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 4 has a coordinate of magnitude 2.2e+38, beyond "
                                         "the supported 1e+28"),
      std::string::npos)
      << e.what();
  }

  // At the limit: every error finite.
  TriangleMesh huge = BumpyGrid(12);
  for (double& x : huge.Points)
  {
    x *= MaximumCoordinateMagnitude; // [0, 1]^2 and a bump of 0.15
  }
  const TOMBuildResult r = Build(huge);
  ExpectValidResult(huge, r); // finite errors among the rest
  EXPECT_GT(r.VertexCountError[r.Mesh.BaseVertexCount], 1e24f);
}

//------------------------------------------------------------------------------
// Progress, determinism, allocations

TEST(TOMBuilder, ProgressIsReportedAndAbortWorks)
{
  const TriangleMesh mesh = timecritical::testing::MakeTorus(150, 50, 11, 0.05);
  std::vector<double> fractions;
  TOMBuildOptions options;
  options.Progress = [&fractions](double f) {
    fractions.push_back(f);
    return true;
  };
  const TOMBuildResult r = Build(mesh, options);
  ExpectValidResult(mesh, r);
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_LE(fractions.size(), 300u);
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));

  // Abort in the middle of the collapses, right at the start, and at the very end.
  for (size_t stopAt : { fractions.size() / 2, size_t(0), fractions.size() - 1 })
  {
    size_t calls = 0;
    TOMBuildOptions abort;
    abort.Progress = [&calls, stopAt](double) { return calls++ < stopAt; };
    const TOMBuildResult a = Build(mesh, abort);
    EXPECT_TRUE(a.Aborted) << stopAt;
    EXPECT_EQ(a.Mesh.GetNumberOfVertices(), 0u);
    EXPECT_EQ(a.Mesh.GetNumberOfTriangles(), 0u);
    EXPECT_TRUE(a.VertexOrder.empty());
    EXPECT_EQ(calls, stopAt + 1) << "no call after the one that said stop";
  }
}

TEST(TOMBuilder, Deterministic)
{
  const TriangleMesh mesh = TwoCopies(timecritical::testing::MakeTorus(80, 30, 9, 0.08), 3.0);
  const TOMBuildResult a = Build(mesh);
  const TOMBuildResult b = Build(mesh);
  ExpectValidResult(mesh, a);
  EXPECT_TRUE(SameResult(a, b));
}

TEST(TOMBuilder, CollapsesDoNotAllocate)
{
  // The number of allocations of a build does not depend on the number of
  // collapses (large arrays are allocated once; see also the huge-page
  // allocator, which bypasses operator new).
  auto allocations = [](const TriangleMesh& mesh) {
    const size_t before = timecritical::testing::GetAllocationCount();
    const TOMBuildResult r = Build(mesh);
    const size_t count = timecritical::testing::GetAllocationCount() - before;
    EXPECT_EQ(TOMValidator::Check(r.Mesh), "");
    return count;
  };
  const size_t small = allocations(timecritical::testing::MakeTorus(60, 20, 1, 0.05));
  const size_t large = allocations(timecritical::testing::MakeTorus(480, 160, 1, 0.05));
  EXPECT_LT(large, 200u);
  EXPECT_LT(large, small + 40u) << "small " << small << ", large " << large;
}

//------------------------------------------------------------------------------
// Real meshes (shared data folder)

namespace
{
void CheckSharedMesh(const std::string& name, size_t unused, size_t maxBase)
{
  REQUIRE_SHARED_MESH(shared, name);
  const TriangleMesh mesh = timecritical::testing::LoadMesh(shared.Path);
  const TOMBuildResult r = Build(mesh);
  ExpectValidResult(mesh, r);
  EXPECT_EQ(r.UnusedPoints, unused);
  EXPECT_LE(r.Mesh.BaseVertexCount, maxBase);
  // Errors are distances in the model's units: at half resolution a small
  // fraction of the model size.
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < mesh.NumberOfPoints(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], mesh.Points[3 * i + k]);
      hi[k] = std::max(hi[k], mesh.Points[3 * i + k]);
    }
  }
  const double size = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  EXPECT_LT(r.VertexCountError[VertexCountAt(r, 0.5)], 0.01 * size);
  EXPECT_GT(r.VertexCountError[r.Mesh.BaseVertexCount], 0.f);
}
}

TEST(TOMBuilderSharedData, Bunny)
{
  // 1,113 unused points, 5 holes.
  CheckSharedMesh("stanford-bunny.obj", 1113, 24);
}

TEST(TOMBuilderSharedData, Fandisk)
{
  CheckSharedMesh("fandisk.obj", 0, 16);
}

TEST(TOMBuilderSharedData, Teapot)
{
  // Duplicate points along patch seams, 4 components, pinch vertices:
  // boundaries and pinches stay until the constraints are released, and
  // the four open patches cannot shrink below a few triangles each.
  CheckSharedMesh("teapot.obj", 0, 200);
  REQUIRE_SHARED_MESH(shared, "teapot.obj");
  const TriangleMesh welded =
    timecritical::testing::WeldPoints(timecritical::testing::LoadMesh(shared.Path));
  ExpectValidResult(welded, Build(welded));
}

TEST(TOMBuilderSharedData, CowHomerSpot)
{
  CheckSharedMesh("cow.obj", 0, 16);
  CheckSharedMesh("homer.obj", 0, 16);
  CheckSharedMesh("spot.obj", 0, 16);
}

TEST(TOMBuilderSharedData, IgeaTriangleStrips)
{
  CheckSharedMesh("igea.ply", 0, 16);
}

//------------------------------------------------------------------------------
// Quality regression (issue 10): the TOM's dense symmetric Hausdorff distance
// at a fraction of the triangles, as TOMBenchmark section 4 measures it,
// against the best of the vertex-subset peers there (meshoptimizer 0.18 and
// OpenMesh 9's Decimater in four settings), whose errors are fixed figures
// here: the peers are deterministic and not linked into the core tests.

namespace
{
/// Dense symmetric Hausdorff distance over the bounding-box diagonal between
/// the welded mesh and its TOM at `fraction` of the triangles.
double TOMDenseError(const std::string& name, double fraction, const TOMBuildOptions& options = {})
{
  const timecritical::testing::SharedMesh shared = timecritical::testing::FindSharedMesh(name);
  if (!shared.Available)
  {
    return -1.0;
  }
  namespace tt = timecritical::testing;
  const TriangleMesh mesh = tt::RemoveUnusedPoints(tt::WeldPoints(tt::LoadMesh(shared.Path)));
  const TOMBuildResult r = Build(mesh, options);
  const TOMTraversal traversal(r.Mesh);
  const uint32_t n =
    traversal.GetVertexCountForTriangles(traversal.GetTrianglesForResolution(fraction));
  TriangleMesh simplified;
  simplified.Triangles = Extract(r, n);
  for (uint32_t v = 0; v < n; ++v)
  {
    const V3 p = PointOf(mesh, r, v);
    simplified.Points.insert(simplified.Points.end(), { p.X, p.Y, p.Z });
  }
  simplified = tt::RemoveUnusedPoints(simplified);

  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < mesh.Points.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], mesh.Points[i]);
    hi[i % 3] = std::max(hi[i % 3], mesh.Points[i]);
  }
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) +
    (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  const double spacing =
    0.5 * MeanEdgeLength(mesh.Points.data(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  const SurfaceLocator original(mesh.Points.data(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  const SurfaceLocator coarse(
    simplified.Points.data(), simplified.Triangles.data(), simplified.NumberOfTriangles());
  const double there = MaximumDistance(SampleSurface(mesh.Points.data(), mesh.NumberOfPoints(),
                                         mesh.Triangles.data(), mesh.NumberOfTriangles(), 0.0, 2),
    coarse);
  const double back = MaximumDistance(
    SampleSurface(simplified.Points.data(), simplified.NumberOfPoints(),
      simplified.Triangles.data(), simplified.NumberOfTriangles(), spacing, 1),
    original);
  return std::max(there, back) / diagonal;
}

struct QualityCase
{
  const char* Mesh;
  double Fraction;
  double BestPeer; ///< the best peer's error / diagonal (TOMBenchmark)
  const char* Peer;
};
}

TEST(TOMBuilderQuality, AtMostTheBestVertexSubsetPeer)
{
  // The default builder locked 45-degree feature edges and ordered by mean
  // squared distance: on the low-poly cow it kept the 653 flagged edges and
  // over-simplified the rest, 3.0 times the best peer's error at 10% (7.1e-2);
  // fandisk trailed OpenMesh by 1.8-3.9 times. Now at 0.56-1.03 times the
  // best peer here; the bound, 1.1 times it, leaves room for rounding
  // differences between compilers that may swap near-equal collapses. Teapot
  // and bunny (open, with holes), where the TOM was already level or ahead,
  // stay so. (Their boundaries do not decide these two figures: without
  // PreserveBoundaries the errors are the same; BoundaryStaysOnItsPolyline
  // pins the boundaries.)
  const QualityCase cases[] = {
    { "cow.obj", 0.10, 2.34e-2, "OpenMesh, normal flips 60" },
    { "cow.obj", 0.05, 4.80e-2, "OpenMesh, normal flips 90" },
    { "fandisk.obj", 0.25, 8.33e-5, "OpenMesh, normal flips 90" },
    { "fandisk.obj", 0.05, 1.37e-3, "OpenMesh, normal flips 90" },
    { "teapot.obj", 0.10, 8.64e-3, "meshoptimizer, LockBorder" },
    { "stanford-bunny.obj", 0.10, 2.59e-3, "meshoptimizer, LockBorder" },
    { "homer.obj", 0.05, 1.64e-2, "OpenMesh, normal flips 90" },
  };
  for (const QualityCase& c : cases)
  {
    const double error = TOMDenseError(c.Mesh, c.Fraction);
    if (error < 0.0)
    {
      GTEST_SKIP() << "shared mesh not available: " << c.Mesh;
    }
    // The pass engine is not yet at the greedy order's pins (fandisk at 5%
    // 1.22 times the best peer, teapot at 10% 1.15; docs/benchmarks/tom.md):
    // its own, looser bound keeps it from getting worse.
    const double bound = EngineUnderTest == TOMBuildEngine::Passes ? 1.3 : 1.1;
    EXPECT_LE(error, bound * c.BestPeer)
      << c.Mesh << " at " << c.Fraction << ": best peer " << c.Peer << " " << c.BestPeer;
  }
}

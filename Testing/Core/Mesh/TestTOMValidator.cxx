// SPDX-License-Identifier: BSD-3-Clause
// Tests of TOMValidator: acceptance of valid TOMs and one test per kind of
// corruption, each checking that the message names the right thing.
#include "TOMErrorCurve.h"
#include "TOMMesh.h"
#include "TOMTestMeshes.h"
#include "TOMTraversal.h"
#include "TOMValidator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{
using timecritical::TOMErrorCurve;
using timecritical::TOMMesh;
using timecritical::TOMTraversal;
using timecritical::TOMValidator;


/**
 * Naive minimum vertex count: replay the removals one vertex count at a time
 * and note when the triangle collapses (independent of the traversal code).
 */
std::vector<uint32_t> NaiveMinimumVertexCounts(const std::vector<uint32_t>& sub,
  const std::vector<uint32_t>& triangles, uint32_t base)
{
  const uint32_t n = static_cast<uint32_t>(sub.size());
  const size_t m = triangles.size() / 3;
  std::vector<uint32_t> active(n), minimum(m, 0);
  std::iota(active.begin(), active.end(), 0u);
  std::vector<char> dead(m, 0);
  for (uint32_t count = n; count > base; --count)
  {
    const uint32_t k = count - 1; // leaves now
    for (uint32_t& a : active)
    {
      a = a == k ? sub[k] : a;
    }
    for (size_t t = 0; t < m; ++t)
    {
      const uint32_t a = active[triangles[3 * t]], b = active[triangles[3 * t + 1]],
                     c = active[triangles[3 * t + 2]];
      if (!dead[t] && (a == b || b == c || a == c))
      {
        dead[t] = 1;
        minimum[t] = count;
      }
    }
  }
  return minimum;
}

/**
 * A random valid TOM without geometry: random substitutions to lower ids,
 * random triangles of distinct vertices, sorted by their (naively computed)
 * minimum vertex count. Valid as a TOM even though not a manifold mesh.
 */
TOMMesh MakeRandomTOM(uint32_t seed, uint32_t n, uint32_t m)
{
  std::mt19937 rng(seed);
  TOMMesh mesh;
  mesh.BaseVertexCount = 1 + rng() % std::max(1u, n / 4);
  mesh.Substitution.resize(n);
  for (uint32_t i = 0; i < n; ++i)
  {
    mesh.Substitution[i] = i < mesh.BaseVertexCount ? i : rng() % i;
  }
  std::vector<uint32_t> triangles;
  for (uint32_t t = 0; t < m; ++t)
  {
    uint32_t a = rng() % n, b = rng() % n, c = rng() % n;
    if (a != b && b != c && a != c)
    {
      triangles.insert(triangles.end(), { a, b, c });
    }
  }
  const std::vector<uint32_t> minimum =
    NaiveMinimumVertexCounts(mesh.Substitution, triangles, mesh.BaseVertexCount);
  std::vector<uint32_t> order(minimum.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
    [&](uint32_t x, uint32_t y) { return minimum[x] < minimum[y]; });
  for (uint32_t t : order)
  {
    mesh.Triangles.insert(mesh.Triangles.end(), triangles.begin() + 3 * t,
      triangles.begin() + 3 * t + 3);
    mesh.BaseTriangleCount += minimum[t] == 0 ? 1 : 0;
  }
  return mesh;
}

bool Contains(const std::string& message, const std::string& part)
{
  return message.find(part) != std::string::npos;
}

#define EXPECT_MESSAGE(message, ...)                                                              \
  do                                                                                              \
  {                                                                                               \
    const std::string text = (message);                                                           \
    for (const char* part : { __VA_ARGS__ })                                                      \
    {                                                                                             \
      EXPECT_TRUE(Contains(text, part)) << "message \"" << text << "\" lacks \"" << part << "\""; \
    }                                                                                             \
  } while (false)

TEST(TOMValidator, AcceptsValidTOMs)
{
  EXPECT_EQ(TOMValidator::Check(timecritical::testing::MakeFanTOM()), "");
  EXPECT_EQ(TOMValidator::Check(TOMMesh{}), ""); // empty
  for (uint32_t seed = 1; seed <= 20; ++seed)
  {
    const TOMMesh mesh = MakeRandomTOM(seed, 5 + seed * 3, 10 + seed * 7);
    EXPECT_EQ(TOMValidator::Check(mesh), "") << "seed " << seed;
  }
  // A mesh that was never simplified: everything is base.
  TOMMesh base;
  base.Substitution = { 0, 1, 2, 3 };
  base.BaseVertexCount = 4;
  base.Triangles = { 0, 1, 2, 0, 2, 3 };
  base.BaseTriangleCount = 2;
  EXPECT_EQ(TOMValidator::Check(base), "");
  // Isolated vertices (in no triangle) are fine.
  TOMMesh isolated;
  isolated.Substitution = { 0, 1, 2, 3 };
  isolated.BaseVertexCount = 4;
  EXPECT_EQ(TOMValidator::Check(isolated), "");
}

TEST(TOMValidator, AcceptsValidErrorCurve)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  // Triangles at vertex counts 0..5: the base (3 vertices) has 1, 4 have 2, 5 have 4.
  const std::vector<uint32_t> triangles = { 1, 1, 1, 1, 2, 4 };
  const std::vector<float> errors = { 3.f, 3.f, 3.f, 3.f, 1.f, 0.f };
  mesh.ErrorCurve = TOMErrorCurve::FromVertexErrors(errors.data(), triangles.data(), 5, 3);
  ASSERT_FALSE(mesh.ErrorCurve.IsEmpty());
  EXPECT_EQ(TOMValidator::Check(mesh), "");
}

TEST(TOMValidator, RawAndMeshOverloadsAgree)
{
  const TOMMesh mesh = MakeRandomTOM(77, 40, 120);
  EXPECT_EQ(TOMValidator::Check(mesh.Substitution.data(), mesh.Substitution.size(),
              mesh.Triangles.data(), mesh.Triangles.size() / 3, mesh.BaseVertexCount,
              mesh.BaseTriangleCount),
    "");
  TOMMesh broken = mesh;
  broken.Substitution.back() = broken.GetNumberOfVertices() - 1;
  EXPECT_EQ(TOMValidator::Check(broken),
    TOMValidator::Check(broken.Substitution.data(), broken.Substitution.size(),
      broken.Triangles.data(), broken.Triangles.size() / 3, broken.BaseVertexCount,
      broken.BaseTriangleCount));
  EXPECT_NE(TOMValidator::Check(broken), "");
}

TEST(TOMValidator, RejectsSubstitutionNotBelowOwnIndex)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.Substitution[4] = 4;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "substitution[4] = 4", "lower");
  mesh.Substitution[4] = 7; // also out of range
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "substitution[4] = 7", "lower");
}

TEST(TOMValidator, RejectsCycleAttempt)
{
  // 3 -> 4 -> 3 would loop forever in a traversal; the first upward link is named.
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.Substitution[3] = 4;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "substitution[3] = 4", "acyclic");
}

TEST(TOMValidator, RejectsBaseVertexNotSelfSubstituting)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.Substitution[1] = 0;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base vertex 1", "substitutes to 0");
}

TEST(TOMValidator, RejectsVertexIdOutOfRange)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.Triangles[7] = 5; // triangle 2, corner 1
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "triangle 2 corner 1", "vertex id 5", "out of range");
  mesh.Triangles[7] = 0xffffffffu;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "triangle 2 corner 1", "4294967295");
}

TEST(TOMValidator, RejectsDegenerateTriangle)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.Triangles[3] = 1; // triangle 1 becomes (1, 1, 4)
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "triangle 1", "degenerate");
  mesh = timecritical::testing::MakeFanTOM();
  mesh.Triangles[11] = 3; // triangle 3 becomes (3, 0, 3): first and last corners
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "triangle 3", "degenerate");
}

TEST(TOMValidator, RejectsTrianglesOutOfOrder)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  // Swap triangles 0 (base) and 2 (alive from 5): minimum counts become 5, 4, 0, 5.
  std::swap_ranges(mesh.Triangles.begin(), mesh.Triangles.begin() + 3, mesh.Triangles.begin() + 6);
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "order", "triangle 1 is alive from 4",
    "triangle 0 only from 5");
}

TEST(TOMValidator, RejectsWrongBaseTriangleCount)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.BaseTriangleCount = 2;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base triangle count 2", "1 triangles alive");
  mesh.BaseTriangleCount = 0;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base triangle count 0");
  mesh.BaseTriangleCount = 9;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base triangle count 9", "exceeds");
}

TEST(TOMValidator, RejectsBadBaseVertexCount)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.BaseVertexCount = 6;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base vertex count 6", "exceeds", "5");
  mesh.BaseVertexCount = 0;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base vertex count is 0");
  // A larger base than the substitutions say: vertex 3 claims to be removed.
  mesh.BaseVertexCount = 4;
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "base vertex 3", "substitutes to 0");
}

TEST(TOMValidator, RejectsBadErrorCurve)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.ErrorCurve = TOMErrorCurve({ { 1, 1.f }, { 2, 2.f }, { 4, 0.f } });
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "error curve", "sample 1", "increases");
  mesh.ErrorCurve = TOMErrorCurve({ { 1, 1.f }, { 3, 0.f } });
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "error curve", "not the full mesh", "4");
}

TEST(TOMValidator, RejectsSizeMismatch)
{
  TOMMesh mesh = timecritical::testing::MakeFanTOM();
  mesh.Triangles.push_back(0);
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "triangle array size 13", "multiple of 3");
  mesh = timecritical::testing::MakeFanTOM();
  mesh.Substitution.pop_back(); // vertex 4 is now out of range
  EXPECT_MESSAGE(TOMValidator::Check(mesh), "vertex id 4", "out of range");
}

TEST(TOMValidator, RejectsNullPointersWithNonzeroCounts)
{
  const TOMMesh mesh = timecritical::testing::MakeFanTOM();
  EXPECT_MESSAGE(TOMValidator::Check(nullptr, 5, mesh.Triangles.data(), 4, 3, 1),
    "substitution array is null");
  EXPECT_MESSAGE(TOMValidator::Check(mesh.Substitution.data(), 5, nullptr, 4, 3, 1),
    "triangle array is null");
  EXPECT_EQ(TOMValidator::Check(nullptr, 0, nullptr, 0, 0, 0), "");
  EXPECT_EQ(TOMValidator::Check(mesh.Substitution.data(), 5, nullptr, 0, 3, 0), "");
}

TEST(TOMValidator, RejectsCountsBeyond32Bits)
{
  // Checked before anything is read, so garbage counts cannot crash.
  const TOMMesh mesh = timecritical::testing::MakeFanTOM();
  EXPECT_MESSAGE(TOMValidator::Check(mesh.Substitution.data(), uint64_t(1) << 32,
                   mesh.Triangles.data(), 4, 3, 1),
    "number of vertices 4294967296", "32 bits");
  EXPECT_MESSAGE(TOMValidator::Check(mesh.Substitution.data(), 5, mesh.Triangles.data(),
                   uint64_t(1) << 40, 3, 1),
    "number of triangles", "32 bits");
  EXPECT_MESSAGE(
    TOMValidator::Check(nullptr, ~uint64_t(0), nullptr, ~uint64_t(0), ~uint64_t(0), ~uint64_t(0)),
    "32 bits");
}

TEST(TOMValidator, RandomCorruptionsAreCaughtOrHarmless)
{
  // Corrupt one entry at a time. The validator must never crash; whenever it
  // accepts the result, the traversal must agree with a naive replay.
  std::mt19937 rng(123);
  uint32_t rejected = 0, accepted = 0;
  for (uint32_t round = 0; round < 400; ++round)
  {
    TOMMesh mesh = MakeRandomTOM(1000 + round % 25, 24, 60);
    const uint32_t n = mesh.GetNumberOfVertices();
    switch (rng() % 5)
    {
      case 0:
        mesh.Substitution[rng() % n] = rng() % (n + 2);
        break;
      case 1:
        if (!mesh.Triangles.empty())
        {
          mesh.Triangles[rng() % mesh.Triangles.size()] = rng() % (n + 2);
        }
        break;
      case 2:
        mesh.BaseVertexCount = rng() % (n + 2);
        break;
      case 3:
        mesh.BaseTriangleCount = rng() % (mesh.GetNumberOfTriangles() + 2);
        break;
      default:
        if (mesh.GetNumberOfTriangles() >= 2)
        {
          const size_t a = rng() % mesh.GetNumberOfTriangles(), b = rng() % mesh.GetNumberOfTriangles();
          std::swap_ranges(mesh.Triangles.begin() + 3 * a, mesh.Triangles.begin() + 3 * a + 3,
            mesh.Triangles.begin() + 3 * b);
        }
        break;
    }
    if (!TOMValidator::Check(mesh).empty())
    {
      ++rejected;
      continue;
    }
    ++accepted;
    const TOMTraversal traversal(mesh);
    const std::vector<uint32_t> minimum =
      NaiveMinimumVertexCounts(mesh.Substitution, mesh.Triangles, mesh.BaseVertexCount);
    ASSERT_TRUE(std::is_sorted(minimum.begin(), minimum.end())) << "round " << round;
    ASSERT_EQ(std::count(minimum.begin(), minimum.end(), 0u), int(mesh.BaseTriangleCount));
    for (uint32_t count = mesh.BaseVertexCount; count <= n; ++count)
    {
      const auto alive =
        std::count_if(minimum.begin(), minimum.end(), [&](uint32_t x) { return x <= count; });
      ASSERT_EQ(traversal.Extract(count, nullptr, 0), uint32_t(alive)) << "round " << round;
    }
  }
  // Both outcomes happen (e.g. swapping two equal-rank triangles is harmless).
  EXPECT_GT(rejected, 100u);
  EXPECT_GT(accepted, 10u);
}
}

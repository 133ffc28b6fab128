// SPDX-License-Identifier: BSD-3-Clause
// Tests of TOMTraversal against hand-built TOMs and against a naive replay of
// the substitutions of random TOMs built by random legal edge collapses.
#include "AllocationCounter.h"
#include "TOMMesh.h"
#include "TOMTestMeshes.h"
#include "TOMTraversal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace
{
using timecritical::TOMMesh;
using timecritical::TOMTraversal;
using Triangle = std::array<uint32_t, 3>;

constexpr uint32_t NotCollapsed = std::numeric_limits<uint32_t>::max();

/// A TOM together with what its construction knows independently of traversal.
struct ReferenceTOM
{
  TOMMesh Mesh;
  std::vector<uint32_t> MinimumVertexCount;     ///< per TOM triangle
  std::vector<uint32_t> TrianglesAtVertexCount; ///< [0, N], counted while collapsing
};

/**
 * Random but valid TOM: a nx*ny grid (random diagonals) simplified by random
 * half-edge collapses u -> w that satisfy the link condition, plus (with
 * probability pairContraction) substitutions between non-adjacent vertices,
 * which remove no triangle (the paper's figure 2, right). Then vertices are
 * renumbered by removal and triangles sorted by the step that kills them.
 * Simple O(n^2) code on purpose.
 */
ReferenceTOM BuildRandomTOM(uint32_t nx, uint32_t ny, uint32_t seed, double pairContraction)
{
  std::mt19937 rng(seed);
  const uint32_t n = nx * ny;
  std::vector<Triangle> tris;
  for (uint32_t j = 0; j + 1 < ny; ++j)
  {
    for (uint32_t i = 0; i + 1 < nx; ++i)
    {
      const uint32_t v00 = j * nx + i, v10 = v00 + 1, v01 = v00 + nx, v11 = v01 + 1;
      if (rng() & 1)
      {
        tris.push_back({ v00, v10, v11 });
        tris.push_back({ v00, v11, v01 });
      }
      else
      {
        tris.push_back({ v00, v10, v01 });
        tris.push_back({ v10, v11, v01 });
      }
    }
  }
  const uint32_t m = static_cast<uint32_t>(tris.size());
  std::vector<Triangle> current = tris;
  std::vector<char> triangleAlive(m, 1), vertexAlive(n, 1);
  std::vector<uint32_t> removal, target(n, 0), deathStep(m, NotCollapsed), aliveAfterStep;
  uint32_t alive = m;
  const uint32_t baseTarget = std::max(3u, n / (3 + seed % 10));

  auto neighbors = [&](uint32_t u) {
    std::vector<uint32_t> result;
    for (uint32_t t = 0; t < m; ++t)
    {
      if (triangleAlive[t] && std::count(current[t].begin(), current[t].end(), u))
      {
        for (uint32_t x : current[t])
        {
          if (x != u && std::find(result.begin(), result.end(), x) == result.end())
          {
            result.push_back(x);
          }
        }
      }
    }
    std::sort(result.begin(), result.end());
    return result;
  };

  uint32_t failures = 0;
  while (n - removal.size() > baseTarget && failures < 20 * n)
  {
    std::vector<uint32_t> active;
    for (uint32_t v = 0; v < n; ++v)
    {
      if (vertexAlive[v])
      {
        active.push_back(v);
      }
    }
    const uint32_t u = active[rng() % active.size()];
    const std::vector<uint32_t> nu = neighbors(u);
    uint32_t w = u;
    if (std::uniform_real_distribution<double>(0, 1)(rng) < pairContraction)
    {
      const uint32_t x = active[rng() % active.size()];
      if (x != u && !std::binary_search(nu.begin(), nu.end(), x))
      {
        w = x;
      }
    }
    else if (!nu.empty())
    {
      const uint32_t x = nu[rng() % nu.size()];
      // Link condition: the common neighbours of u and x are exactly the apexes
      // of the triangles on edge (u, x); otherwise the collapse pinches the mesh.
      const std::vector<uint32_t> nx2 = neighbors(x);
      std::vector<uint32_t> common, apexes;
      std::set_intersection(
        nu.begin(), nu.end(), nx2.begin(), nx2.end(), std::back_inserter(common));
      for (uint32_t t = 0; t < m; ++t)
      {
        const Triangle& c = current[t];
        if (triangleAlive[t] && std::count(c.begin(), c.end(), u) && std::count(c.begin(), c.end(), x))
        {
          for (uint32_t y : c)
          {
            if (y != u && y != x)
            {
              apexes.push_back(y);
            }
          }
        }
      }
      std::sort(apexes.begin(), apexes.end());
      if (common == apexes)
      {
        w = x;
      }
    }
    if (w == u)
    {
      ++failures;
      continue;
    }
    const uint32_t step = static_cast<uint32_t>(removal.size());
    for (uint32_t t = 0; t < m; ++t)
    {
      if (!triangleAlive[t])
      {
        continue;
      }
      Triangle& c = current[t];
      std::replace(c.begin(), c.end(), u, w);
      if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
      {
        triangleAlive[t] = 0;
        deathStep[t] = step;
        --alive;
      }
    }
    vertexAlive[u] = 0;
    target[u] = w;
    removal.push_back(u);
    aliveAfterStep.push_back(alive);
  }

  // Renumber: the j-th removed vertex becomes n-1-j, survivors take [0, base)
  // in random order.
  const uint32_t base = n - static_cast<uint32_t>(removal.size());
  std::vector<uint32_t> newId(n, 0), survivors;
  for (uint32_t v = 0; v < n; ++v)
  {
    if (vertexAlive[v])
    {
      survivors.push_back(v);
    }
  }
  std::shuffle(survivors.begin(), survivors.end(), rng);
  for (uint32_t i = 0; i < base; ++i)
  {
    newId[survivors[i]] = i;
  }
  for (uint32_t j = 0; j < removal.size(); ++j)
  {
    newId[removal[j]] = n - 1 - j;
  }

  ReferenceTOM ref;
  TOMMesh& mesh = ref.Mesh;
  mesh.Substitution.resize(n);
  for (uint32_t v = 0; v < n; ++v)
  {
    mesh.Substitution[newId[v]] = vertexAlive[v] ? newId[v] : newId[target[v]];
  }
  mesh.BaseVertexCount = base;

  // Dying at step j means dying when vertex n-1-j leaves: alive from n-j vertices.
  std::vector<uint32_t> minimum(m);
  for (uint32_t t = 0; t < m; ++t)
  {
    minimum[t] = deathStep[t] == NotCollapsed ? 0 : n - deathStep[t];
  }
  std::vector<uint32_t> order(m);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), rng);
  std::stable_sort(order.begin(), order.end(),
    [&](uint32_t a, uint32_t b) { return minimum[a] < minimum[b]; });
  for (uint32_t t : order)
  {
    const uint32_t r = rng() % 3; // any rotation keeps the orientation
    for (uint32_t c = 0; c < 3; ++c)
    {
      mesh.Triangles.push_back(newId[tris[t][(c + r) % 3]]);
    }
    ref.MinimumVertexCount.push_back(minimum[t]);
    mesh.BaseTriangleCount += minimum[t] == 0 ? 1 : 0;
  }

  ref.TrianglesAtVertexCount.assign(n + 1, 0);
  ref.TrianglesAtVertexCount[n] = m;
  for (uint32_t j = 0; j < removal.size(); ++j)
  {
    ref.TrianglesAtVertexCount[n - 1 - j] = aliveAfterStep[j];
  }
  for (uint32_t i = 0; i < base; ++i)
  {
    ref.TrianglesAtVertexCount[i] = ref.TrianglesAtVertexCount[base];
  }
  return ref;
}

/// What the replay knows about the mesh with a given vertex count.
struct ReplayedMesh
{
  uint32_t VertexCount = 0;
  std::vector<uint32_t> Triangles; ///< 3 ids per alive triangle, in order
  uint64_t Steps = 0;              ///< chain steps over the alive triangles' corners
  std::vector<uint32_t> Active;    ///< [v]: the active vertex v maps to
};

/**
 * Calls visit(mesh) for every vertex count from N down to the base, replaying
 * the substitutions one at a time on the original triangles (no chain walk).
 */
template <typename Visit>
void Replay(const TOMMesh& mesh, Visit visit)
{
  const uint32_t n = mesh.GetNumberOfVertices();
  const uint32_t m = mesh.GetNumberOfTriangles();
  ReplayedMesh replayed;
  replayed.Active.resize(n);
  std::iota(replayed.Active.begin(), replayed.Active.end(), 0u);
  std::vector<uint32_t> depth(n, 0);
  for (uint32_t count = n; count >= mesh.BaseVertexCount && count > 0; --count)
  {
    replayed.VertexCount = count;
    replayed.Triangles.clear();
    replayed.Steps = 0;
    const std::vector<uint32_t>& current = replayed.Active;
    for (uint32_t t = 0; t < m; ++t)
    {
      const uint32_t* c = &mesh.Triangles[3 * t];
      const uint32_t a = current[c[0]], b = current[c[1]], d = current[c[2]];
      if (a != b && b != d && a != d)
      {
        replayed.Triangles.insert(replayed.Triangles.end(), { a, b, d });
        replayed.Steps += depth[c[0]] + depth[c[1]] + depth[c[2]];
      }
    }
    visit(static_cast<const ReplayedMesh&>(replayed));
    if (count == mesh.BaseVertexCount)
    {
      break;
    }
    // Vertex count-1 leaves: everything currently mapped to it moves one step on.
    const uint32_t k = count - 1;
    for (uint32_t v = 0; v < n; ++v)
    {
      if (replayed.Active[v] == k)
      {
        replayed.Active[v] = mesh.Substitution[k];
        ++depth[v];
      }
    }
  }
}

std::vector<uint32_t> ExtractAll(const TOMTraversal& traversal, uint32_t vertexCount,
  uint64_t* steps = nullptr)
{
  std::vector<uint32_t> out;
  const uint32_t count = traversal.Extract(vertexCount, out, steps);
  EXPECT_GE(out.size(), 3 * size_t(count));
  out.resize(3 * size_t(count));
  return out;
}

TEST(TOMTraversal, HandBuiltFanAtEveryVertexCount)
{
  const TOMMesh mesh = timecritical::testing::MakeFanTOM();
  const TOMTraversal traversal(mesh);
  EXPECT_EQ(traversal.GetNumberOfVertices(), 5u);
  EXPECT_EQ(traversal.GetNumberOfTriangles(), 4u);

  uint64_t steps = 99;
  EXPECT_EQ(ExtractAll(traversal, 5, &steps), mesh.Triangles);
  EXPECT_EQ(steps, 0u);
  EXPECT_EQ(ExtractAll(traversal, 4, &steps), (std::vector<uint32_t>{ 1, 2, 3, 0, 1, 3 }));
  EXPECT_EQ(steps, 2u);
  EXPECT_EQ(ExtractAll(traversal, 3, &steps), (std::vector<uint32_t>{ 1, 2, 0 }));
  EXPECT_EQ(steps, 2u); // 4 -> 3 -> 0

  EXPECT_EQ(traversal.GetMinimumVertexCount(0), 0u);
  EXPECT_EQ(traversal.GetMinimumVertexCount(1), 4u);
  EXPECT_EQ(traversal.GetMinimumVertexCount(2), 5u);
  EXPECT_EQ(traversal.GetMinimumVertexCount(3), 5u);

  EXPECT_EQ(traversal.GetVertexCountForTriangles(0), 3u); // the base mesh has 1 > 0
  EXPECT_EQ(traversal.GetVertexCountForTriangles(1), 3u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(2), 4u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(3), 4u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(4), 5u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(1000), 5u);

  EXPECT_EQ(traversal.GetActiveVertex(4, 5), 4u);
  EXPECT_EQ(traversal.GetActiveVertex(4, 4), 3u);
  EXPECT_EQ(traversal.GetActiveVertex(4, 3), 0u);
  EXPECT_EQ(traversal.GetActiveVertex(4, 0), 0u); // clamped to the base
  EXPECT_EQ(traversal.GetActiveVertex(2, 3), 2u);
}

TEST(TOMTraversal, PairContractionRemovesNoTriangle)
{
  // Two separate triangles; 5 -> 2 joins them without removing anything,
  // then 4 -> 2 collapses the second one.
  TOMMesh mesh;
  mesh.Substitution = { 0, 1, 2, 3, 2, 2 };
  mesh.BaseVertexCount = 4;
  mesh.Triangles = { 0, 1, 2, 3, 4, 5 };
  mesh.BaseTriangleCount = 1;
  const TOMTraversal traversal(mesh);
  uint64_t steps = 0;
  EXPECT_EQ(ExtractAll(traversal, 6, &steps), mesh.Triangles);
  EXPECT_EQ(ExtractAll(traversal, 5, &steps), (std::vector<uint32_t>{ 0, 1, 2, 3, 4, 2 }));
  EXPECT_EQ(steps, 1u);
  EXPECT_EQ(ExtractAll(traversal, 4, &steps), (std::vector<uint32_t>{ 0, 1, 2 }));
  EXPECT_EQ(steps, 0u);
  EXPECT_EQ(traversal.GetMinimumVertexCount(1), 5u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(0), 4u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(1), 4u);
  EXPECT_EQ(traversal.GetVertexCountForTriangles(2), 6u);
}

TEST(TOMTraversal, ClampsVertexCountToBaseAndFull)
{
  const TOMMesh mesh = timecritical::testing::MakeFanTOM();
  const TOMTraversal traversal(mesh);
  EXPECT_EQ(ExtractAll(traversal, 0), ExtractAll(traversal, 3));
  EXPECT_EQ(ExtractAll(traversal, 2), ExtractAll(traversal, 3));
  EXPECT_EQ(ExtractAll(traversal, 6), mesh.Triangles);
  EXPECT_EQ(ExtractAll(traversal, std::numeric_limits<uint32_t>::max()), mesh.Triangles);
}

TEST(TOMTraversal, EmptyAndDefault)
{
  const TOMTraversal empty;
  std::vector<uint32_t> out;
  uint64_t steps = 7;
  EXPECT_EQ(empty.Extract(0, out, &steps), 0u);
  EXPECT_EQ(empty.Extract(10, nullptr, 0, &steps), 0u);
  EXPECT_EQ(steps, 0u);
  EXPECT_EQ(empty.GetVertexCountForTriangles(0), 0u);
  EXPECT_EQ(empty.GetTrianglesForResolution(0.5), 0u);
  float result = 42.f;
  const float attribute = 1.f;
  empty.Geomorph(1, 0.5, &attribute, 1, &result);
  EXPECT_EQ(result, 42.f); // nothing to morph

  const TOMMesh mesh;
  const TOMTraversal fromMesh(mesh);
  EXPECT_EQ(fromMesh.Extract(5, out), 0u);
}

/// Every Extract variant at every vertex count against the replay.
void CheckAgainstReplay(const ReferenceTOM& ref)
{
  const TOMMesh& mesh = ref.Mesh;
  const uint32_t n = mesh.GetNumberOfVertices();
  const uint32_t m = mesh.GetNumberOfTriangles();
  ASSERT_LT(mesh.BaseVertexCount, n) << "the random build should remove vertices";
  const TOMTraversal traversal(mesh);
  for (uint32_t t = 0; t < m; ++t)
  {
    ASSERT_EQ(traversal.GetMinimumVertexCount(t), ref.MinimumVertexCount[t]) << "triangle " << t;
  }
  std::vector<uint32_t> raw(3 * size_t(m) + 3);
  std::vector<uint32_t> grown; // reused across vertex counts, like a renderer would
  uint32_t visited = 0;
  Replay(mesh, [&](const ReplayedMesh& replayed) {
    ++visited;
    const uint32_t count = replayed.VertexCount;
    SCOPED_TRACE(::testing::Message() << "vertex count " << count);
    const std::vector<uint32_t>& expected = replayed.Triangles;
    const uint32_t expectedCount = static_cast<uint32_t>(expected.size() / 3);
    ASSERT_EQ(expectedCount, ref.TrianglesAtVertexCount[count]);

    uint64_t steps = 0;
    ASSERT_EQ(ExtractAll(traversal, count, &steps), expected);
    EXPECT_EQ(steps, replayed.Steps);
    steps = 0;
    ASSERT_EQ(traversal.Extract(count, grown, &steps), expectedCount);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), grown.begin()));
    EXPECT_EQ(steps, replayed.Steps);

    // Raw overload with room to spare, with and without step counting.
    EXPECT_EQ(traversal.Extract(count, raw.data(), m + 1), expectedCount);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), raw.begin()));
    steps = 0;
    EXPECT_EQ(traversal.Extract(count, raw.data(), m + 1, &steps), expectedCount);
    EXPECT_EQ(steps, replayed.Steps) << "steps of the stopping triangle do not count";

    // Too little room: the count is still the full one, only `capacity`
    // triangles are written and nothing past them is touched.
    for (const uint32_t capacity : { 0u, 1u, expectedCount / 2, expectedCount - 1, 511u, 512u,
           513u, 1025u })
    {
      if (capacity >= expectedCount)
      {
        continue;
      }
      std::fill(raw.begin(), raw.end(), 0xdeadbeefu);
      steps = 0;
      EXPECT_EQ(traversal.Extract(count, raw.data(), capacity, &steps), expectedCount);
      EXPECT_EQ(steps, replayed.Steps);
      EXPECT_TRUE(std::equal(expected.begin(), expected.begin() + 3 * capacity, raw.begin()))
        << "capacity " << capacity;
      EXPECT_TRUE(std::all_of(raw.begin() + 3 * capacity, raw.end(),
        [](uint32_t x) { return x == 0xdeadbeefu; }))
        << "capacity " << capacity;
    }
    EXPECT_EQ(traversal.Extract(count, nullptr, 0), expectedCount);
    EXPECT_EQ(traversal.Extract(count, nullptr, 100), expectedCount); // null: nothing written

    for (uint32_t v = 0; v < n; ++v)
    {
      ASSERT_EQ(traversal.GetActiveVertex(v, count), replayed.Active[v]);
    }
  });
  EXPECT_EQ(visited, n - mesh.BaseVertexCount + 1);
}

TEST(TOMTraversal, RandomTOMMatchesReplayAtEveryVertexCount)
{
  struct Case
  {
    uint32_t nx, ny, seed;
    double pairs;
  };
  for (const Case& c : { Case{ 6, 5, 1, 0.0 }, Case{ 12, 9, 2, 0.0 }, Case{ 10, 10, 3, 0.1 },
         Case{ 15, 8, 4, 0.3 }, Case{ 2, 2, 5, 0.0 }, Case{ 14, 14, 6, 0.05 } })
  {
    SCOPED_TRACE(::testing::Message() << "grid " << c.nx << "x" << c.ny << " seed " << c.seed);
    CheckAgainstReplay(BuildRandomTOM(c.nx, c.ny, c.seed, c.pairs));
  }
}

TEST(TOMTraversal, LargerRandomTOMSpanningManyBatches)
{
  // Thousands of triangles: the extraction works in batches of several
  // hundred, so prefixes end inside, at and across batch boundaries.
  const ReferenceTOM ref = BuildRandomTOM(36, 30, 7, 0.02);
  ASSERT_GT(ref.Mesh.GetNumberOfTriangles(), 2000u);
  CheckAgainstReplay(ref);
}

TEST(TOMTraversal, VertexCountForTrianglesIsFinestWithinBudget)
{
  for (uint32_t seed = 10; seed < 16; ++seed)
  {
    const ReferenceTOM ref = BuildRandomTOM(9 + seed % 4, 7 + seed % 3, seed, 0.1 * (seed % 3));
    const TOMMesh& mesh = ref.Mesh;
    const TOMTraversal traversal(mesh);
    const uint32_t n = mesh.GetNumberOfVertices();
    const uint32_t m = mesh.GetNumberOfTriangles();
    const uint32_t base = mesh.BaseVertexCount;
    const std::vector<uint32_t>& at = ref.TrianglesAtVertexCount;
    for (uint32_t budget = 0; budget <= m + 2; ++budget)
    {
      const uint32_t count = traversal.GetVertexCountForTriangles(budget);
      ASSERT_GE(count, base);
      ASSERT_LE(count, n);
      // Brute force: the finest vertex count whose mesh fits, or the base.
      uint32_t expected = base;
      for (uint32_t k = base; k <= n; ++k)
      {
        if (at[k] <= budget)
        {
          expected = k;
        }
      }
      ASSERT_EQ(count, expected) << "seed " << seed << " budget " << budget;
      if (count > base)
      {
        EXPECT_LE(at[count], budget);
      }
      if (count < n)
      {
        EXPECT_GT(at[count + 1], budget);
      }
      EXPECT_EQ(traversal.Extract(count, nullptr, 0), at[count]);
    }
  }
}

TEST(TOMTraversal, TrianglesForResolution)
{
  const ReferenceTOM ref = BuildRandomTOM(8, 8, 21, 0.0);
  const TOMTraversal traversal(ref.Mesh);
  const uint32_t m = traversal.GetNumberOfTriangles();
  ASSERT_EQ(m, 98u);
  EXPECT_EQ(traversal.GetTrianglesForResolution(0.0), 0u);
  EXPECT_EQ(traversal.GetTrianglesForResolution(1.0), m);
  EXPECT_EQ(traversal.GetTrianglesForResolution(0.5), 49u);
  EXPECT_EQ(traversal.GetTrianglesForResolution(0.1), 10u); // 9.8 rounds up
  EXPECT_EQ(traversal.GetTrianglesForResolution(0.104), 10u); // 10.19 rounds down
  EXPECT_EQ(traversal.GetTrianglesForResolution(-0.5), 0u);
  EXPECT_EQ(traversal.GetTrianglesForResolution(2.0), m);
  EXPECT_EQ(traversal.GetTrianglesForResolution(std::numeric_limits<double>::infinity()), m);
  EXPECT_EQ(traversal.GetTrianglesForResolution(-std::numeric_limits<double>::infinity()), 0u);
  EXPECT_EQ(traversal.GetTrianglesForResolution(std::nan("")), 0u); // NaN: the coarsest
}

TEST(TOMTraversal, ExtractDoesNotAllocateWhenBufferSuffices)
{
  const ReferenceTOM ref = BuildRandomTOM(12, 12, 31, 0.0);
  const TOMTraversal traversal(ref.Mesh);
  const uint32_t n = traversal.GetNumberOfVertices();
  const uint32_t base = ref.Mesh.BaseVertexCount;

  std::vector<uint32_t> out;
  const uint32_t full = traversal.Extract(n, out);
  ASSERT_EQ(full, traversal.GetNumberOfTriangles());
  ASSERT_EQ(out.size(), 3 * size_t(full));
  const uint32_t* data = out.data();
  const size_t capacity = out.capacity();

  const size_t before = timecritical::testing::GetAllocationCount();
  uint64_t steps = 0;
  EXPECT_EQ(traversal.Extract(n, out, &steps), full);
  for (uint32_t count = base; count <= n; ++count)
  {
    traversal.Extract(count, out, &steps);
    EXPECT_EQ(out.size(), 3 * size_t(full)); // never shrunk
    traversal.Extract(count, out.data(), full, &steps);
  }
  EXPECT_EQ(timecritical::testing::GetAllocationCount(), before);
  EXPECT_EQ(out.data(), data);
  EXPECT_EQ(out.capacity(), capacity);
  EXPECT_EQ(out.size(), 3 * size_t(full)); // never shrunk

  // A coarse first call into an empty vector only grows it as needed.
  std::vector<uint32_t> coarse;
  const uint32_t few = traversal.Extract(base, coarse);
  EXPECT_GE(coarse.size(), 3 * size_t(few));
  EXPECT_EQ(traversal.Extract(n, coarse), full);
  EXPECT_GE(coarse.size(), 3 * size_t(full));
}

TEST(TOMTraversal, GeomorphEndpointsOnFan)
{
  const TOMMesh mesh = timecritical::testing::MakeFanTOM();
  const TOMTraversal traversal(mesh);
  const std::vector<float> x = { 0.f, 10.f, 20.f, 30.f, 40.f };
  float r = -1.f;
  traversal.Geomorph(5, 0.0, x.data(), 1, &r);
  EXPECT_EQ(r, 30.f); // 4 -> 3
  traversal.Geomorph(5, 1.0, x.data(), 1, &r);
  EXPECT_EQ(r, 40.f);
  traversal.Geomorph(5, 0.25, x.data(), 1, &r);
  EXPECT_FLOAT_EQ(r, 32.5f);
  traversal.Geomorph(4, 0.5, x.data(), 1, &r);
  EXPECT_FLOAT_EQ(r, 15.f); // 3 -> 0
  traversal.Geomorph(3, 0.0, x.data(), 1, &r);
  EXPECT_EQ(r, 20.f); // base vertex 2 does not move
  traversal.Geomorph(5, -3.0, x.data(), 1, &r);
  EXPECT_EQ(r, 30.f); // factor clamped
  traversal.Geomorph(5, 7.0, x.data(), 1, &r);
  EXPECT_EQ(r, 40.f);
  traversal.Geomorph(5, std::nan(""), x.data(), 1, &r);
  EXPECT_EQ(r, 40.f); // NaN shows the true vertex
  traversal.Geomorph(99, 0.0, x.data(), 1, &r);
  EXPECT_EQ(r, 30.f); // clamped to the full mesh
}

TEST(TOMTraversal, GeomorphMatchesNextCoarserMesh)
{
  const ReferenceTOM ref = BuildRandomTOM(11, 9, 41, 0.1);
  const TOMMesh& mesh = ref.Mesh;
  const TOMTraversal traversal(mesh);
  const uint32_t n = mesh.GetNumberOfVertices();
  std::vector<float> points(3 * size_t(n));
  std::mt19937 rng(5);
  for (float& p : points)
  {
    p = std::uniform_real_distribution<float>(-100.f, 100.f)(rng);
  }
  for (uint32_t count = mesh.BaseVertexCount + 1; count <= n; ++count)
  {
    const uint32_t v = count - 1;
    float at0[3], at1[3], half[3];
    traversal.Geomorph(count, 0.0, points.data(), 3, at0);
    traversal.Geomorph(count, 1.0, points.data(), 3, at1);
    traversal.Geomorph(count, 0.5, points.data(), 3, half);
    const uint32_t target = mesh.Substitution[v];
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_EQ(at0[c], points[3 * target + c]);
      EXPECT_EQ(at1[c], points[3 * v + c]);
      EXPECT_FLOAT_EQ(half[c], 0.5f * (points[3 * target + c] + points[3 * v + c]));
    }
    // Factor 0 puts v where the next coarser mesh has it: every surviving
    // triangle's corner v becomes exactly the morph target.
    const std::vector<uint32_t> fine = ExtractAll(traversal, count);
    const std::vector<uint32_t> coarse = ExtractAll(traversal, count - 1);
    for (size_t i = 0; i < coarse.size(); ++i)
    {
      if (fine[i] == v)
      {
        EXPECT_EQ(coarse[i], target);
      }
      else
      {
        EXPECT_EQ(coarse[i], fine[i]);
      }
    }
  }
}

TEST(TOMTraversal, RawConstructorMatchesMeshConstructor)
{
  const ReferenceTOM ref = BuildRandomTOM(7, 6, 51, 0.0);
  const TOMMesh& mesh = ref.Mesh;
  const TOMTraversal a(mesh);
  const TOMTraversal b(mesh.Substitution.data(), mesh.GetNumberOfVertices(), mesh.Triangles.data(),
    mesh.GetNumberOfTriangles(), mesh.BaseVertexCount);
  for (uint32_t count = 0; count <= mesh.GetNumberOfVertices() + 1; ++count)
  {
    EXPECT_EQ(ExtractAll(a, count), ExtractAll(b, count));
  }
}
}

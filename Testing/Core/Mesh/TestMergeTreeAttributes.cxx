// SPDX-License-Identifier: BSD-3-Clause
#include "MergeTreeAttributes.h"
#include "TOMBuilder.h"
#include "TOMMesh.h"
#include "TOMTestMeshes.h"
#include "MeshIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace timecritical;
namespace tct = timecritical::testing;

namespace
{
struct Built
{
  TOMMesh Mesh;
  std::vector<double> Points; // TOM order
};

Built Build(const tct::TriangleMesh& mesh)
{
  TOMBuildResult r = TOMBuilder().Build(
    mesh.Points.data(), mesh.NumberOfPoints(), mesh.Triangles.data(), mesh.NumberOfTriangles());
  Built b;
  b.Mesh = r.Mesh;
  b.Points.resize(3 * r.VertexOrder.size());
  for (size_t i = 0; i < r.VertexOrder.size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      b.Points[3 * i + k] = mesh.Points[3 * size_t(r.VertexOrder[i]) + k];
    }
  }
  return b;
}

std::vector<double> FanPoints(double centreHeight)
{
  return { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, centreHeight };
}

std::vector<uint32_t> Row(const MergeTree& tree, uint32_t v)
{
  return std::vector<uint32_t>(tree.Dependencies.begin() + tree.DependencyOffsets[v],
    tree.Dependencies.begin() + tree.DependencyOffsets[v + 1]);
}

double Distance(const double* a, const double* b)
{
  return std::sqrt(
    (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::vector<std::vector<uint32_t>> ChildrenOf(const TOMMesh& tom)
{
  std::vector<std::vector<uint32_t>> children(tom.GetNumberOfVertices());
  for (uint32_t v = tom.BaseVertexCount; v < tom.GetNumberOfVertices(); ++v)
  {
    children[tom.Substitution[v]].push_back(v); // ascending
  }
  return children;
}

/// Every event that must be split before e_v, as the refinement defines it.
std::vector<uint32_t> Requirements(
  const TOMMesh& tom, const MergeTree& tree, const std::vector<std::vector<uint32_t>>& children, uint32_t v)
{
  std::vector<uint32_t> out;
  const uint32_t u = tom.Substitution[v];
  if (u >= tom.BaseVertexCount)
  {
    out.push_back(u);
  }
  for (uint32_t c : children[u])
  {
    if (c < v)
    {
      out.push_back(c);
    }
  }
  for (uint32_t n : Row(tree, v))
  {
    if (n >= tom.BaseVertexCount)
    {
      out.push_back(n);
    }
  }
  return out;
}

std::vector<tct::TriangleMesh> ClosedMeshes()
{
  std::vector<tct::TriangleMesh> meshes = { tct::MakeSphere(3),
    tct::MakeTorus(40, 16, 7, 0.2) };
  for (const char* name : { "spot.obj", "cow.obj" })
  {
    const tct::SharedMesh shared = tct::FindSharedMesh(name);
    if (shared.Available)
    {
      meshes.push_back(
        tct::RemoveUnusedPoints(tct::WeldPoints(tct::LoadMesh(shared.Path))));
    }
  }
  return meshes;
}
}

//------------------------------------------------------------------------------
// Hand-checked on the fan TOM: square 0 1 2 3, centre 4; 4 -> 3, then 3 -> 0.
TEST(MergeTreeAttributes, FanDependencyRows)
{
  const TOMMesh tom = tct::MakeFanTOM();
  const std::vector<double> points = FanPoints(0.0);
  const MergeTree tree = ComputeMergeTree(tom, points.data(), nullptr);
  ASSERT_EQ(tree.GetNumberOfVertices(), 5u);
  ASSERT_EQ(tree.DependencyOffsets.size(), 6u);
  for (uint32_t v = 0; v < 3; ++v)
  {
    EXPECT_TRUE(Row(tree, v).empty());
  }
  // Before 4 -> 3: 4 touches 0 1 2 3, 3 touches 2 4 0.
  EXPECT_EQ(Row(tree, 4), (std::vector<uint32_t>{ 0, 1, 2 }));
  // Before 3 -> 0: triangles (1 2 3) and (0 1 3): 3 touches 0 1 2, 0 touches 1 3.
  EXPECT_EQ(Row(tree, 3), (std::vector<uint32_t>{ 1, 2 }));
  // Flat: no error while 4 slides inside the square; then boundary corner 3
  // leaves, the square shrinks to triangle (1 2 0): 3 is sqrt(0.5) off it.
  // Normal cones of zero width around +z.
  EXPECT_FLOAT_EQ(tree.Error[4], 0.0f);
  EXPECT_NEAR(tree.Error[3], std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(tree.Radius[4], std::sqrt(0.5), 1e-6);
  // Nested spheres around 0: 3 at distance 1 with its own sphere of radius sqrt(0.5).
  EXPECT_NEAR(tree.Radius[3], 1.0 + std::sqrt(0.5), 1e-6);
  for (uint32_t v = 0; v < 5; ++v)
  {
    EXPECT_NEAR(tree.ConeAxis[3 * v + 2], 1.0f, 1e-5);
    EXPECT_GT(tree.ConeCosine[v], 0.9999f);
  }
  // Derived levels: e_3 (4's parent) must be split before e_4.
  EXPECT_GT(tree.Level[3], tree.Level[4]);
  EXPECT_EQ(tree.Level[0], tree.LevelCount);
}

TEST(MergeTreeAttributes, FanRaisedCentre)
{
  const TOMMesh tom = tct::MakeFanTOM();
  const std::vector<double> points = FanPoints(0.5);
  const MergeTree tree = ComputeMergeTree(tom, points.data(), nullptr);
  // Moving the raised centre 4 onto corner 3 changes the surface: positive
  // error, bounded by the displacement of 4.
  const double displacement = Distance(&points[12], &points[9]);
  EXPECT_GT(tree.Error[4], 0.1f);
  EXPECT_LE(tree.Error[4], displacement + 1e-6);
  EXPECT_GE(tree.Error[3], tree.Error[4]); // monotone
  EXPECT_LT(tree.ConeCosine[4], 0.99f);    // faces of the tent differ
}

TEST(MergeTreeAttributes, GivenLevelsAreCopied)
{
  const TOMMesh tom = tct::MakeFanTOM();
  const std::vector<double> points = FanPoints(0.0);
  const uint16_t levels[5] = { 0, 0, 0, 3, 1 };
  const MergeTree tree = ComputeMergeTree(tom, points.data(), levels);
  EXPECT_EQ(tree.Level[3], 3);
  EXPECT_EQ(tree.Level[4], 1);
  EXPECT_EQ(tree.LevelCount, 4);
  EXPECT_EQ(tree.Level[1], 4);
}

TEST(MergeTreeAttributes, InvalidInputThrows)
{
  TOMMesh tom = tct::MakeFanTOM();
  std::vector<double> points = FanPoints(0.0);
  tom.Substitution[4] = 4; // a non-base vertex substituting to itself
  EXPECT_THROW(ComputeMergeTree(tom, points.data(), nullptr), std::invalid_argument);
  tom = tct::MakeFanTOM();
  tom.Triangles[0] = 9; // out of range
  EXPECT_THROW(ComputeMergeTree(tom, points.data(), nullptr), std::invalid_argument);
  tom = tct::MakeFanTOM();
  EXPECT_THROW(ComputeMergeTree(tom, nullptr, nullptr), std::invalid_argument);
  points[2] = std::nan("");
  EXPECT_THROW(ComputeMergeTree(tom, points.data(), nullptr), std::invalid_argument);
  points[2] = 0.0;
  points[13] = 2.2e38; // finite, but radii would overflow float
  try
  {
    ComputeMergeTree(tom, points.data(), nullptr);
    FAIL() << "no exception";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("point 4 has a coordinate of magnitude 2.2e+38"),
      std::string::npos)
      << e.what();
  }
}

TEST(MergeTreeAttributes, HugeShadingWeightKeepsErrorsFinite)
{
  // Any finite weight is allowed; the float errors saturate instead of
  // overflowing.
  const Built b = Build(tct::MakeTorus(30, 12, 5, 0.3));
  MergeTreeErrorOptions options;
  options.ShadingWeight = 1e300;
  const MergeTree tree = ComputeMergeTree(b.Mesh, b.Points.data(), nullptr, options);
  for (float e : tree.Error)
  {
    ASSERT_TRUE(std::isfinite(e));
  }
  EXPECT_EQ(tree.Error[0], std::numeric_limits<float>::max());
}

//------------------------------------------------------------------------------
// On real TOMs: rows name live neighbours only, errors and levels are
// monotone over every "split first" relation, radii and cones hold their
// whole node.
// With and without the shading term.
class MergeTreeInvariants : public ::testing::TestWithParam<double>
{
};

TEST_P(MergeTreeInvariants, OnClosedMeshes)
{
  MergeTreeErrorOptions options;
  options.ShadingWeight = GetParam();
  for (const tct::TriangleMesh& mesh : ClosedMeshes())
  {
    const Built b = Build(mesh);
    const TOMMesh& tom = b.Mesh;
    const MergeTree tree = ComputeMergeTree(tom, b.Points.data(), nullptr, options);
    const uint32_t n = tom.GetNumberOfVertices();
    const uint32_t base = tom.BaseVertexCount;
    const auto children = ChildrenOf(tom);
    size_t relations = 0;
    for (uint32_t v = base; v < n; ++v)
    {
      const std::vector<uint32_t> row = Row(tree, v);
      ASSERT_GE(row.size(), 2u) << "an edge collapse has a link";
      for (uint32_t w : row)
      {
        ASSERT_LT(w, v);
        ASSERT_NE(w, tom.Substitution[v]);
      }
      for (uint32_t w : Requirements(tom, tree, children, v))
      {
        ASSERT_GE(tree.Error[w], tree.Error[v]) << "event " << w << " before " << v;
        ASSERT_GT(tree.Level[w], tree.Level[v]);
        ++relations;
      }
      // The first child above v of each dependency needs e_v first.
      for (uint32_t d : row)
      {
        for (uint32_t c : children[d])
        {
          if (c > v)
          {
            ASSERT_GE(tree.Error[v], tree.Error[c]);
            break;
          }
        }
      }
      ASSERT_LT(tree.Level[v], tree.LevelCount);
    }
    EXPECT_GT(relations, size_t(n - base));
    // Node of e_c (c a child of u): u plus every child of u from c on, with
    // their subtrees. Walk each vertex's chain and check all nodes holding it.
    std::vector<double> faceNormal(3 * size_t(tom.GetNumberOfTriangles()));
    std::vector<std::vector<uint32_t>> faces(n);
    for (uint32_t t = 0; t < tom.GetNumberOfTriangles(); ++t)
    {
      const uint32_t* tri = &tom.Triangles[3 * size_t(t)];
      const double* p0 = &b.Points[3 * size_t(tri[0])];
      const double* p1 = &b.Points[3 * size_t(tri[1])];
      const double* p2 = &b.Points[3 * size_t(tri[2])];
      const double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
      const double e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
      double nn[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0] };
      const double len = std::sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
      for (int k = 0; k < 3; ++k)
      {
        faceNormal[3 * size_t(t) + k] = nn[k] / len;
        faces[tri[k]].push_back(t);
      }
    }
    for (uint32_t x = 0; x < n; ++x)
    {
      auto check = [&](uint32_t event, uint32_t centre) {
        const double dist = Distance(&b.Points[3 * size_t(x)], &b.Points[3 * size_t(centre)]);
        ASSERT_LE(dist, tree.Radius[event] * (1 + 1e-6) + 1e-9);
        for (uint32_t t : faces[x])
        {
          double c = 0;
          for (int k = 0; k < 3; ++k)
          {
            c += faceNormal[3 * size_t(t) + k] * tree.ConeAxis[3 * size_t(event) + k];
          }
          ASSERT_GE(c, tree.ConeCosine[event] - 1e-4);
        }
      };
      for (uint32_t y = x; y >= base; y = tom.Substitution[y])
      {
        const uint32_t u = tom.Substitution[y];
        for (uint32_t c : children[u])
        {
          if (c <= y)
          {
            check(c, u);
          }
        }
      }
      uint32_t root = x;
      while (root >= base)
      {
        root = tom.Substitution[root];
      }
      check(root, root);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(MergeTreeAttributes, MergeTreeInvariants, ::testing::Values(0.0, 1.0));

//------------------------------------------------------------------------------
// The shading term counts normals that the coarse mesh cannot show: it only
// raises errors (ties to the geometric error where interpolation reproduces
// the normals, as on a smooth sphere) and dominates on a sphere with bumps too
// small for the geometric error but not for shading; with it the errors
// stay monotone over every "split first" relation.
TEST(MergeTreeAttributes, ShadingErrorCountsLostNormals)
{
  tct::TriangleMesh bumpy = tct::MakeSphere(4);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-1.0, 1.0);
  for (size_t i = 0; i < bumpy.NumberOfPoints(); ++i)
  {
    const double f = 1.0 + 0.004 * noise(rng); // ~1/10 of an edge
    for (int k = 0; k < 3; ++k)
    {
      bumpy.Points[3 * i + k] *= f;
    }
  }
  double medians[2] = { 0.0, 0.0 };
  int m = 0;
  for (const tct::TriangleMesh& mesh : { tct::MakeSphere(4), bumpy })
  {
    const Built b = Build(mesh);
    MergeTreeErrorOptions geometric;
    geometric.ShadingWeight = 0.0;
    const MergeTree plain = ComputeMergeTree(b.Mesh, b.Points.data(), nullptr, geometric);
    MergeTreeErrorOptions unit;
    unit.ShadingWeight = 1.0;
    const MergeTree shaded = ComputeMergeTree(b.Mesh, b.Points.data(), nullptr, unit);
    MergeTreeErrorOptions heavy;
    heavy.ShadingWeight = 4.0;
    const MergeTree heavier = ComputeMergeTree(b.Mesh, b.Points.data(), nullptr, heavy);
    std::vector<double> ratio;
    for (uint32_t v = 0; v < b.Mesh.GetNumberOfVertices(); ++v)
    {
      ASSERT_GE(shaded.Error[v], plain.Error[v]);
      ASSERT_GE(heavier.Error[v], shaded.Error[v]);
      // Everything but the errors is the same.
      ASSERT_EQ(shaded.Radius[v], plain.Radius[v]);
      ASSERT_EQ(shaded.Level[v], plain.Level[v]);
      ASSERT_EQ(shaded.ConeCosine[v], plain.ConeCosine[v]);
      if (v >= b.Mesh.BaseVertexCount && plain.Error[v] > 0.0f)
      {
        ratio.push_back(shaded.Error[v] / plain.Error[v]);
      }
    }
    EXPECT_EQ(shaded.Dependencies, plain.Dependencies);
    ASSERT_FALSE(ratio.empty());
    std::nth_element(ratio.begin(), ratio.begin() + ratio.size() / 2, ratio.end());
    medians[m++] = ratio[ratio.size() / 2];
  }
  EXPECT_LT(medians[0], 1.2) << "smooth sphere: interpolated normals are right";
  EXPECT_GT(medians[1], 2.0) << "bumpy sphere: the coarse mesh loses the bumps' shading";
}

// Flat fan: normals all equal, so the shading term adds nothing.
TEST(MergeTreeAttributes, ShadingErrorVanishesOnFlatSurface)
{
  const TOMMesh tom = tct::MakeFanTOM();
  const std::vector<double> points = FanPoints(0.0);
  MergeTreeErrorOptions options;
  options.ShadingWeight = 10.0;
  const MergeTree tree = ComputeMergeTree(tom, points.data(), nullptr, options);
  EXPECT_FLOAT_EQ(tree.Error[4], 0.0f);
  EXPECT_NEAR(tree.Error[3], std::sqrt(0.5), 1e-6);
  options.ShadingWeight = -1.0;
  EXPECT_THROW(ComputeMergeTree(tom, points.data(), nullptr, options), std::invalid_argument);
}

TEST(MergeTreeAttributes, Speed)
{
  const tct::SharedMesh shared = tct::FindSharedMesh("igea.ply");
  tct::TriangleMesh mesh = shared.Available
    ? tct::RemoveUnusedPoints(tct::WeldPoints(tct::LoadMesh(shared.Path)))
    : tct::MakeSphere(6);
  const Built b = Build(mesh);
  const auto start = std::chrono::steady_clock::now();
  const MergeTree tree = ComputeMergeTree(b.Mesh, b.Points.data(), nullptr);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double perMillion = seconds * 1e6 / b.Mesh.GetNumberOfTriangles();
  std::printf("ComputeMergeTree: %u triangles in %.3f s (%.3f s per million), %u levels\n",
    b.Mesh.GetNumberOfTriangles(), seconds, perMillion, tree.LevelCount);
  EXPECT_EQ(tree.GetNumberOfVertices(), b.Mesh.GetNumberOfVertices());
  // Time is printed, not asserted: the build rate goal is checked by
  // TOMBenchmark (section 5), not by a unit test on a shared, loaded machine.
}

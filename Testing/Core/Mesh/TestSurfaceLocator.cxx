// SPDX-License-Identifier: BSD-3-Clause
// Tests of SurfaceLocator (SurfaceDistance.h): the distance from a point to
// each Voronoi region of a triangle, and the tree's answers against brute force.
#include "SurfaceDistance.h"

#include "MeshIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

using namespace timecritical;
using timecritical::testing::TriangleMesh;

namespace
{
/// Squared distance from p to the nearest of the triangles, by brute force.
double BruteForceDistance2(const TriangleMesh& mesh, const double p[3])
{
  double best = std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    TriangleMesh one;
    for (int c = 0; c < 3; ++c)
    {
      const double* q = &mesh.Points[3 * size_t(mesh.Triangles[3 * t + c])];
      one.Points.insert(one.Points.end(), q, q + 3);
    }
    one.Triangles = { 0, 1, 2 };
    const SurfaceLocator locator(one.Points.data(), one.Triangles.data(), 1);
    uint32_t hint = 0;
    best = std::min(best, locator.SquaredDistance(p, hint));
  }
  return best;
}
}

TEST(SurfaceLocator, PointTriangleRegions)
{
  // Each Voronoi region of the triangle (0,0,0), (1,0,0), (0,1,0).
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  const std::vector<uint32_t> triangle = { 0, 1, 2 };
  const SurfaceLocator locator(points.data(), triangle.data(), 1);
  const struct
  {
    double P[3];
    double Distance;
  } cases[] = {
    { { 0.2, 0.2, 1.0 }, 1.0 },                   // above the face
    { { 0.2, 0.2, -0.5 }, 0.5 },                  // below it
    { { -1.0, -1.0, 0.0 }, std::sqrt(2.0) },      // beyond corner 0
    { { 2.0, 0.0, 1.0 }, std::sqrt(2.0) },        // beyond corner 1
    { { 0.0, 3.0, 0.0 }, 2.0 },                   // beyond corner 2
    { { 0.5, -1.0, 0.0 }, 1.0 },                  // beyond edge 0-1
    { { -2.0, 0.5, 0.0 }, 2.0 },                  // beyond edge 0-2
    { { 1.0, 1.0, 0.0 }, std::sqrt(0.5) },        // beyond edge 1-2
    { { 0.25, 0.25, 0.0 }, 0.0 },                 // on the face
  };
  for (const auto& c : cases)
  {
    uint32_t hint = 0;
    EXPECT_NEAR(std::sqrt(locator.SquaredDistance(c.P, hint)), c.Distance, 1e-12)
      << c.P[0] << " " << c.P[1] << " " << c.P[2];
  }
  const SurfaceLocator empty(points.data(), triangle.data(), 0);
  uint32_t hint = 0;
  EXPECT_TRUE(std::isinf(empty.SquaredDistance(cases[0].P, hint)));
}

TEST(SurfaceLocator, TreeAgreesWithBruteForce)
{
  // A noisy torus and points around it, some far away; any hint.
  const TriangleMesh torus = timecritical::testing::MakeTorus(24, 12, 3);
  const SurfaceLocator locator(torus.Points.data(), torus.Triangles.data(), torus.NumberOfTriangles());
  ASSERT_EQ(locator.GetNumberOfTriangles(), torus.NumberOfTriangles());
  uint32_t state = 1u;
  auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / double(1u << 24);
  };
  uint32_t hint = 12345;
  for (int i = 0; i < 300; ++i)
  {
    const double scale = i % 10 == 0 ? 20.0 : 3.0;
    const double p[3] = { scale * (next() - 0.5), scale * (next() - 0.5), scale * (next() - 0.5) };
    ASSERT_EQ(locator.SquaredDistance(p, hint), BruteForceDistance2(torus, p)) << i;
  }
}

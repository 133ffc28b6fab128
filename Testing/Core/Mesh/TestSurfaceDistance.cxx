// SPDX-License-Identifier: BSD-3-Clause
// Tests of the sampling and distance functions of SurfaceDistance.h, the
// measure of TestTOMBuilder's quality tests and of TOMBenchmark: surface
// samples, mean edge length and the Hausdorff distance of a shifted sheet.
// The locator they query is tested in TestSurfaceLocator.cxx.
#include "SurfaceDistance.h"

#include "MeshIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

using namespace timecritical;
using timecritical::testing::TriangleMesh;

TEST(SurfaceDistance, SamplesAndHausdorffOfAShiftedSheet)
{
  // One triangle with k divisions: 3 corners and the (k+1)(k+2)/2 - 3 other
  // grid points, plus the centroid when k < 3.
  const std::vector<double> points = { 0, 0, 0, 1, 0, 0, 0, 1, 0 };
  const std::vector<uint32_t> triangle = { 0, 1, 2 };
  EXPECT_EQ(SampleSurface(points.data(), 3, triangle.data(), 1, 0.0, 1).size(), 3u * 4);
  EXPECT_EQ(SampleSurface(points.data(), 3, triangle.data(), 1, 0.0, 2).size(), 3u * 7);
  // The longest edge is sqrt(2): spacing 0.36 gives k = 4, 15 grid points.
  EXPECT_EQ(SampleSurface(points.data(), 3, triangle.data(), 1, 0.36, 1).size(), 3u * 15);
  EXPECT_NEAR(MeanEdgeLength(points.data(), triangle.data(), 1), (2.0 + std::sqrt(2.0)) / 3, 1e-15);

  // A grid and a coarser copy lifted by 0.1 over part of it: 0.1 apart.
  const TriangleMesh fine = timecritical::testing::MakeGrid(16, 16);
  TriangleMesh lifted = timecritical::testing::MakeGrid(4, 4);
  for (size_t i = 0; i < lifted.NumberOfPoints(); ++i)
  {
    lifted.Points[3 * i + 2] = lifted.Points[3 * i] > 0.5 ? 0.1 : 0.0;
  }
  const SurfaceLocator toFine(fine.Points.data(), fine.Triangles.data(), fine.NumberOfTriangles());
  const SurfaceLocator toLifted(
    lifted.Points.data(), lifted.Triangles.data(), lifted.NumberOfTriangles());
  const std::vector<double> fineSamples = SampleSurface(
    fine.Points.data(), fine.NumberOfPoints(), fine.Triangles.data(), fine.NumberOfTriangles(), 0.0, 2);
  const std::vector<double> liftedSamples = SampleSurface(lifted.Points.data(),
    lifted.NumberOfPoints(), lifted.Triangles.data(), lifted.NumberOfTriangles(), 0.02, 1);
  EXPECT_NEAR(MaximumDistance(liftedSamples, toFine), 0.1, 1e-12);
  EXPECT_NEAR(MaximumDistance(fineSamples, toLifted), 0.1, 1e-12);
  EXPECT_LT(MaximumDistance(fineSamples, toFine), 1e-15); // grid points on the grid
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of ViewHeuristics: culling, projected coverage, eccentricity and
// velocity against hand-computed values for simple projections.
#include "ViewHeuristics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using timecritical::ViewHeuristics;

// Orthographic-like: clip = (x, y, z, 1) so NDC = data coordinates.
const double Identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

// Perspective looking down -z from the origin, 90 degree field of view,
// near 1, far 100 (OpenGL convention).
void Perspective(double m[16])
{
  const double n = 1.0, f = 100.0;
  const double values[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -(f + n) / (f - n),
    -2.0 * f * n / (f - n), 0, 0, -1, 0 };
  for (int i = 0; i < 16; ++i)
  {
    m[i] = values[i];
  }
}

TEST(ViewHeuristics, CoverageOfABoxInsideTheView)
{
  const double box[6] = { -0.5, 0.5, -0.25, 0.25, -0.1, 0.1 };
  const auto p = ViewHeuristics::Project(Identity, box, 200.0, 100.0);
  EXPECT_FALSE(p.Culled);
  EXPECT_FALSE(p.CrossesNear);
  // x: [-0.5, 0.5] -> [50, 150] px; y: [-0.25, 0.25] -> [37.5, 62.5] px.
  EXPECT_DOUBLE_EQ(p.Pixels, 100.0 * 25.0);
  EXPECT_DOUBLE_EQ(p.CenterX, 100.0);
  EXPECT_DOUBLE_EQ(p.CenterY, 50.0);
}

TEST(ViewHeuristics, CoverageIsClippedToTheViewport)
{
  const double box[6] = { 0.5, 3.0, -3.0, 3.0, 0.0, 0.0 };
  const auto p = ViewHeuristics::Project(Identity, box, 100.0, 100.0);
  EXPECT_FALSE(p.Culled);
  EXPECT_DOUBLE_EQ(p.Pixels, 25.0 * 100.0); // x from 75 to 100, all of y
  EXPECT_GT(p.CenterX, 100.0);              // the centre is not clipped
}

TEST(ViewHeuristics, CullsBoxesOutsideAnyPlane)
{
  const double left[6] = { -3.0, -1.5, -0.1, 0.1, 0.0, 0.0 };
  const double beyondFar[6] = { -0.1, 0.1, -0.1, 0.1, 1.5, 2.0 };
  const double straddling[6] = { -3.0, -0.9, -0.1, 0.1, 0.0, 0.0 };
  EXPECT_TRUE(ViewHeuristics::Project(Identity, left, 100, 100).Culled);
  EXPECT_TRUE(ViewHeuristics::Project(Identity, beyondFar, 100, 100).Culled);
  EXPECT_FALSE(ViewHeuristics::Project(Identity, straddling, 100, 100).Culled);
  double m[16];
  Perspective(m);
  const double behindEye[6] = { -1.0, 1.0, -1.0, 1.0, 2.0, 5.0 };
  EXPECT_TRUE(ViewHeuristics::Project(m, behindEye, 100, 100).Culled);
}

TEST(ViewHeuristics, PerspectiveShrinksWithDistance)
{
  double m[16];
  Perspective(m);
  const double nearBox[6] = { -1.0, 1.0, -1.0, 1.0, -5.0, -5.0 };
  const double farBox[6] = { -1.0, 1.0, -1.0, 1.0, -10.0, -10.0 };
  const auto a = ViewHeuristics::Project(m, nearBox, 100, 100);
  const auto b = ViewHeuristics::Project(m, farBox, 100, 100);
  // Half the distance: twice the size, four times the area.
  EXPECT_NEAR(a.Pixels, 4.0 * b.Pixels, 1e-9);
  EXPECT_NEAR(a.Pixels, 20.0 * 20.0, 1e-9); // 2/5 of the NDC range = 20 px
}

TEST(ViewHeuristics, BoxAroundTheEyeCoversTheViewport)
{
  double m[16];
  Perspective(m);
  const double around[6] = { -1.0, 1.0, -1.0, 1.0, -3.0, 3.0 };
  const auto p = ViewHeuristics::Project(m, around, 320, 200);
  EXPECT_FALSE(p.Culled);
  EXPECT_TRUE(p.CrossesNear);
  EXPECT_DOUBLE_EQ(p.Pixels, 320.0 * 200.0);
}

TEST(ViewHeuristics, DegenerateViewportCulls)
{
  const double box[6] = { -0.5, 0.5, -0.5, 0.5, 0.0, 0.0 };
  EXPECT_TRUE(ViewHeuristics::Project(Identity, box, 0.0, 100.0).Culled);
}

TEST(ViewHeuristics, Eccentricity)
{
  ViewHeuristics::Projection p;
  p.MinX = 10;
  p.MaxX = 20;
  p.MinY = 30;
  p.MaxY = 40;
  EXPECT_DOUBLE_EQ(ViewHeuristics::Eccentricity(p, 15, 35), 0.0); // inside
  EXPECT_DOUBLE_EQ(ViewHeuristics::Eccentricity(p, 25, 35), 5.0);
  EXPECT_DOUBLE_EQ(ViewHeuristics::Eccentricity(p, 23, 44), 5.0); // 3-4-5 from the corner
  EXPECT_DOUBLE_EQ(ViewHeuristics::Eccentricity(p, 15, 0), 30.0);
}

TEST(ViewHeuristics, Velocity)
{
  EXPECT_DOUBLE_EQ(ViewHeuristics::Velocity(0, 0, 3, 4, 0.5), 10.0);
  EXPECT_DOUBLE_EQ(ViewHeuristics::Velocity(0, 0, 3, 4, 0.0), 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_DOUBLE_EQ(ViewHeuristics::Velocity(nan, 0, 3, 4, 0.1), 0.0);
}
}

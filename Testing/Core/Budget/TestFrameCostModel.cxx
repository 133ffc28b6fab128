// SPDX-License-Identifier: BSD-3-Clause
// Tests of FrameCostModel: eq. 2-4 with the paper's Table 3 coefficients, the
// additive (software rasterizer) mode, draw-call batching, ordinary actors,
// and the calibration feature mapping.
#include "FrameCostModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
using timecritical::FrameCostModel;

FrameCostModel PaperModel()
{
  // Table 3 of Gobbetti & Bouvier (SGI 320): 13889 us per frame, 1.064 us per
  // triangle, 0.005 us per pixel, 49.14 us per object.
  FrameCostModel::Coefficients c;
  c.Frame = 13889e-6;
  c.Triangle = 1.064e-6;
  c.Pixel = 0.005e-6;
  c.Object = 49.14e-6;
  return FrameCostModel(c);
}

TEST(FrameCostModel, Equation2)
{
  const FrameCostModel m = PaperModel();
  // Cow (5804 triangles) at half resolution over 10000 pixels: geometry-bound.
  EXPECT_NEAR(m.ObjectCost(5804, 10000, 0.5), 49.14e-6 + 1.064e-6 * 0.5 * 5804, 1e-15);
  // At 1 % it is fill-bound: max() picks the pixels.
  EXPECT_NEAR(m.ObjectCost(5804, 100000, 0.01), 49.14e-6 + 0.005e-6 * 100000, 1e-15);
}

TEST(FrameCostModel, Equation3MinimumResolution)
{
  const FrameCostModel m = PaperModel();
  const double rmin = 0.005e-6 * 100000 / (1.064e-6 * 5804);
  EXPECT_NEAR(m.MinimumResolution(5804, 100000, 0.0), rmin, 1e-15);
  // At rmin both terms of eq. 2 agree: lowering r saves nothing.
  EXPECT_NEAR(m.ObjectCost(5804, 100000, rmin), m.ObjectCost(5804, 100000, 0.5 * rmin), 1e-15);
  // Clamps: never below the coarsest resolution nor a tiny positive floor, never above 1.
  EXPECT_EQ(m.MinimumResolution(5804, 100000, 0.2), 0.2);
  EXPECT_EQ(m.MinimumResolution(5804, 0, 0.0), FrameCostModel::TinyResolution);
  EXPECT_EQ(m.MinimumResolution(10, 1e9, 0.0), 1.0);
  EXPECT_EQ(m.MinimumResolution(0, 100, 0.0), 1.0); // nothing to reduce
  EXPECT_EQ(m.MinimumResolution(5804, std::numeric_limits<double>::quiet_NaN(), 0.0),
    FrameCostModel::TinyResolution);
}

TEST(FrameCostModel, Equation4IsTheLinearizationAboveRmin)
{
  const FrameCostModel m = PaperModel();
  const std::vector<double> triangles = { 5804, 69451, 12946 }, pixels = { 1000, 50000, 3000 };
  std::vector<double> tmax(3), rmin(3);
  m.Evaluate(3, triangles.data(), pixels.data(), nullptr, tmax.data(), rmin.data());
  FrameCostModel::FrameLoad load;
  load.DrawCalls = 3;
  load.Objects = 3;
  const double fixed = m.FixedTime(load, 54000);
  EXPECT_NEAR(fixed, 13889e-6 + 3 * 49.14e-6, 1e-15); // t_fixed = init + final + sum t_setup
  for (double s : { 0.0, 0.3, 1.0 })
  {
    std::vector<double> r(3);
    double linear = fixed;
    for (int i = 0; i < 3; ++i)
    {
      r[i] = rmin[i] + s * (1.0 - rmin[i]);
      linear += tmax[i] * r[i];
    }
    EXPECT_NEAR(m.PredictFrameTime(load, 3, triangles.data(), pixels.data(), r.data()), linear,
      1e-12);
  }
}

TEST(FrameCostModel, DrawCallsAndBatching)
{
  // llvmpipe-like: 0.3 ms per draw call, no per-object setup, 2 us per triangle.
  FrameCostModel::Coefficients c;
  c.Frame = 2e-3;
  c.DrawCall = 0.3e-3;
  c.Triangle = 2e-6;
  const FrameCostModel m(c, FrameCostModel::PixelMode::Additive);
  FrameCostModel::FrameLoad separate, batched;
  separate.DrawCalls = 529;
  separate.Objects = 529;
  batched.DrawCalls = 1;
  batched.Objects = 529;
  // 529 actors cost 159 ms of draw calls alone; one batched call 0.3 ms.
  EXPECT_NEAR(m.FixedTime(separate, 0) - m.FixedTime(batched, 0), 528 * 0.3e-3, 1e-12);
}

TEST(FrameCostModel, AdditiveModeMovesFillToFixedTime)
{
  FrameCostModel::Coefficients c;
  c.Triangle = 1e-6;
  c.Pixel = 1e-8;
  const FrameCostModel m(c, FrameCostModel::PixelMode::Additive);
  EXPECT_EQ(m.MinimumResolution(1000, 1e6, 0.05), 0.05); // no fill-bound rmin
  const double triangles[] = { 1000, 2000 }, pixels[] = { 5e4, 1e5 }, r[] = { 0.5, 0.25 };
  FrameCostModel::FrameLoad load;
  const double expected = 1e-6 * (500 + 500) + 1e-8 * 1.5e5;
  EXPECT_NEAR(m.PredictFrameTime(load, 2, triangles, pixels, r), expected, 1e-15);
  EXPECT_NEAR(m.FixedTime(load, 1.5e5), 1e-8 * 1.5e5, 1e-15);
}

TEST(FrameCostModel, OrdinaryActorsAndMargin)
{
  FrameCostModel::Coefficients c;
  c.Frame = 1e-3;
  c.Triangle = 1e-6;
  c.Pixel = 1e-9;
  c.Margin = 2e-3;
  const FrameCostModel m(c);
  FrameCostModel::FrameLoad load;
  load.OtherTriangles = 10000;
  load.OtherPixels = 1000;
  load.OtherTime = 0.5e-3;
  EXPECT_NEAR(m.FixedTime(load, 0), 1e-3 + 2e-3 + 0.5e-3 + 1e-2, 1e-15);
}

TEST(FrameCostModel, SanitizesCoefficients)
{
  FrameCostModel::Coefficients c;
  c.Frame = -1.0;
  c.Triangle = std::numeric_limits<double>::quiet_NaN();
  c.Pixel = std::numeric_limits<double>::infinity();
  const FrameCostModel m(c);
  EXPECT_EQ(m.GetCoefficients().Frame, 0.0);
  EXPECT_EQ(m.GetCoefficients().Triangle, 0.0);
  EXPECT_EQ(m.GetCoefficients().Pixel, 0.0);
}

TEST(FrameCostModel, MinimumCoefficientsKeepEveryPredictionPositive)
{
  // A fit that drove triangles and pixels to 0 (the collapse the bounds stop).
  FrameCostModel::Coefficients collapsed;
  collapsed.Frame = 0.0;
  collapsed.Triangle = 0.0;
  collapsed.Pixel = -1.0;
  FrameCostModel m(collapsed, FrameCostModel::PixelMode::Additive);
  EXPECT_EQ(m.MaxTime(1e6), 0.0); // premise: without bounds an object is free

  const FrameCostModel::Coefficients physical = FrameCostModel::PhysicalMinimum();
  EXPECT_GT(physical.Frame, 0.0);
  EXPECT_GT(physical.Triangle, 0.0);
  EXPECT_GT(physical.Pixel, 0.0);
  m.SetMinimumCoefficients(physical);
  EXPECT_EQ(m.GetCoefficients().Triangle, physical.Triangle); // raised at once
  EXPECT_EQ(m.GetCoefficients().Pixel, physical.Pixel);
  m.SetCoefficients(collapsed);
  EXPECT_EQ(m.GetCoefficients().Triangle, physical.Triangle);
  EXPECT_GT(m.MaxTime(1.0), 0.0);
  EXPECT_GT(m.FixedTime(FrameCostModel::FrameLoad(), 0.0), 0.0);
  const double triangles[] = { 1.0, 5804.0 }, pixels[] = { 0.0, 1e4 }, r[] = { 1e-6, 1.0 };
  EXPECT_GT(m.PredictFrameTime(FrameCostModel::FrameLoad(), 2, triangles, pixels, r), 0.0);

  // Bounds relative to a calibration: coefficients above them pass unchanged,
  // those below are raised; bad bounds count as 0.
  FrameCostModel::Coefficients floor;
  floor.Triangle = 1e-7;
  floor.Pixel = std::numeric_limits<double>::quiet_NaN();
  m.SetMinimumCoefficients(floor);
  EXPECT_EQ(m.GetMinimumCoefficients().Pixel, 0.0);
  FrameCostModel::Coefficients fitted;
  fitted.Triangle = 3e-7;
  fitted.Pixel = 2e-9;
  m.SetCoefficients(fitted);
  EXPECT_EQ(m.GetCoefficients().Triangle, 3e-7);
  EXPECT_EQ(m.GetCoefficients().Pixel, 2e-9);
  fitted.Triangle = 1e-12;
  double w[FrameCostModel::FeatureCount];
  m.SetCoefficients(fitted);
  m.GetFeatureWeights(w);
  EXPECT_EQ(w[FrameCostModel::FeatureTriangles], 1e-7);
  w[FrameCostModel::FeatureTriangles] = 0.0; // the calibrator's path
  m.SetFeatureWeights(w);
  EXPECT_DOUBLE_EQ(m.MaxTime(1000.0), 1e-4);
}

TEST(FrameCostModel, FeaturesMatchThePrediction)
{
  FrameCostModel::Coefficients c;
  c.Frame = 1e-3;
  c.DrawCall = 3e-4;
  c.Object = 1e-5;
  c.Triangle = 2e-6;
  c.Pixel = 4e-9;
  FrameCostModel m(c, FrameCostModel::PixelMode::Additive);
  FrameCostModel::FrameLoad load;
  load.DrawCalls = 4;
  load.Objects = 2;
  load.OtherTriangles = 100;
  const double triangles[] = { 1000, 2000 }, pixels[] = { 5e4, 1e5 }, r[] = { 0.5, 0.25 };
  double x[FrameCostModel::FeatureCount], w[FrameCostModel::FeatureCount];
  m.GetFeatures(load, 1000, 1.5e5, x);
  m.GetFeatureWeights(w);
  double dot = 0.0;
  for (std::size_t j = 0; j < FrameCostModel::FeatureCount; ++j)
  {
    dot += w[j] * x[j];
  }
  EXPECT_NEAR(dot, m.PredictFrameTime(load, 2, triangles, pixels, r), 1e-15);
  w[FrameCostModel::FeatureTriangles] = 3e-6;
  m.SetFeatureWeights(w);
  EXPECT_EQ(m.GetCoefficients().Triangle, 3e-6);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of AlgorithmCostModel: one algorithm is today's FrameCostModel, the
// linear tuple form matches the exact cost, bad coefficients throw, and
// CostModelCalibrator fits every algorithm's coefficients online from
// synthetic frames that mix them.
#include "AlgorithmCostModel.h"

#include "CostModelCalibrator.h"
#include "FrameCostModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using timecritical::AlgorithmCostModel;
using timecritical::FrameCostModel;
using timecritical::RenderingAlgorithm;

TEST(AlgorithmCostModel, OneAlgorithmIsTodaysModel)
{
  for (auto mode : { FrameCostModel::PixelMode::Overlapped, FrameCostModel::PixelMode::Additive })
  {
    FrameCostModel::Coefficients c;
    c.Frame = 5e-3;
    c.DrawCall = 3e-4;
    c.Triangle = 2e-7;
    c.Pixel = 2e-8;
    const FrameCostModel today(c, mode);
    const AlgorithmCostModel model(today);
    ASSERT_EQ(model.GetAlgorithmCount(), 1u);
    EXPECT_EQ(model.GetAlgorithm(0), RenderingAlgorithm::PerFragmentLit);
    EXPECT_EQ(model.GetFrameTime(), 5e-3);
    EXPECT_DOUBLE_EQ(model.DrawCallTime(), 5e-3 + 3e-4);
    const std::vector<double> triangles = { 1000.0, 20000.0, 5000.0 };
    const std::vector<double> pixels = { 100.0, 5e4, 1e4 };
    const std::vector<double> coarsest = { 0.05, 0.01, 0.2 };
    std::vector<double> tmax(3), rmin(3), t(3), f(3), lo(3);
    today.Evaluate(3, triangles.data(), pixels.data(), coarsest.data(), tmax.data(), rmin.data());
    model.Evaluate(3, triangles.data(), nullptr, pixels.data(), coarsest.data(), t.data(), f.data(),
      lo.data());
    for (std::size_t i = 0; i < 3; ++i)
    {
      EXPECT_DOUBLE_EQ(t[i], tmax[i]);
      EXPECT_DOUBLE_EQ(lo[i], rmin[i]);
      // Additive: the fill is the tuple's fixed part (FrameCostModel puts it in t_fixed).
      EXPECT_DOUBLE_EQ(f[i], mode == FrameCostModel::PixelMode::Additive ? c.Pixel * pixels[i] : 0.0);
      EXPECT_NEAR(model.TupleCost(0, triangles[i], 0.0, pixels[i]),
        today.ObjectCost(triangles[i], pixels[i], 1.0), 1e-18);
    }
  }
}

TEST(AlgorithmCostModel, LinearFormMatchesTheExactCost)
{
  AlgorithmCostModel model;
  model.SetAlgorithm(RenderingAlgorithm::PerVertexLit, { 1e-4, 2e-7, 1e-7, 1.5e-8 });
  model.SetAlgorithm(RenderingAlgorithm::Unlit, { 1e-4, 1.5e-7, 0.0, 5e-9 });
  for (auto mode : { FrameCostModel::PixelMode::Overlapped, FrameCostModel::PixelMode::Additive })
  {
    model.SetPixelMode(mode);
    const double triangles[] = { 4000.0, 300.0 }, vertices[] = { 2100.0, 160.0 };
    const double pixels[] = { 3e4, 2e5 }, coarsest[] = { 0.02, 0.1 };
    double t[4], f[4], lo[4];
    model.Evaluate(2, triangles, vertices, pixels, coarsest, t, f, lo);
    for (std::size_t i = 0; i < 2; ++i)
    {
      for (std::size_t a = 0; a < 2; ++a)
      {
        const std::size_t k = i * 2 + a;
        for (double r : { 0.0, lo[k], 0.5 * (lo[k] + 1.0), 1.0 })
        {
          const double rr = std::max(r, lo[k]);
          // At or above lo the linear form is exact.
          EXPECT_NEAR(f[k] + t[k] * rr,
            model.TupleCost(a, rr * triangles[i], rr * vertices[i], pixels[i]), 1e-15)
            << "object " << i << " algorithm " << a << " r " << r;
        }
      }
    }
  }
  // Object 1 is fill-bound in full when overlapped: lo = 1 and the fill is its cost.
  model.SetPixelMode(FrameCostModel::PixelMode::Overlapped);
  const double triangles[] = { 300.0 }, vertices[] = { 160.0 }, pixels[] = { 2e5 };
  double t[2], f[2], lo[2];
  model.Evaluate(1, triangles, vertices, pixels, nullptr, t, f, lo);
  EXPECT_EQ(lo[0], 1.0);
  EXPECT_NEAR(f[0] + t[0], 1.5e-8 * 2e5, 1e-15);
}

TEST(AlgorithmCostModel, SetRemoveAndBadCoefficients)
{
  AlgorithmCostModel model;
  EXPECT_EQ(model.GetAlgorithmCount(), 0u);
  double t = 0, f = 0, lo = 0;
  const double one = 1000.0, pix = 10.0;
  try
  {
    model.Evaluate(1, &one, nullptr, &pix, nullptr, &t, &f, &lo);
    ADD_FAILURE() << "no exception for an empty set";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
  model.SetAlgorithm(RenderingAlgorithm::Flat, { 0.0, 1e-7, 0.0, 1e-9 });
  model.SetAlgorithm(RenderingAlgorithm::Unlit, { 0.0, 1e-7, 0.0, 1e-9 });
  model.SetAlgorithm(RenderingAlgorithm::Flat, { 0.0, 2e-7, 0.0, 1e-9 }); // replaces
  EXPECT_EQ(model.GetAlgorithmCount(), 2u);
  EXPECT_EQ(model.IndexOf(RenderingAlgorithm::Flat), 0);
  EXPECT_EQ(model.GetCoefficients(0).Triangle, 2e-7);
  model.RemoveAlgorithm(RenderingAlgorithm::Flat);
  EXPECT_EQ(model.IndexOf(RenderingAlgorithm::Unlit), 0);
  EXPECT_EQ(model.IndexOf(RenderingAlgorithm::Flat), -1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(model.SetAlgorithm(RenderingAlgorithm::Flat, { 0.0, -1e-7, 0.0, 0.0 }),
    std::invalid_argument);
  EXPECT_THROW(model.SetAlgorithm(RenderingAlgorithm::Flat, { nan, 1e-7, 0.0, 0.0 }),
    std::invalid_argument);
  EXPECT_THROW(model.SetAlgorithm(RenderingAlgorithm::Flat,
                 { 0.0, 1e-7, std::numeric_limits<double>::infinity(), 0.0 }),
    std::invalid_argument);
  EXPECT_THROW(model.SetFrameTime(-1.0), std::invalid_argument);
  EXPECT_EQ(model.GetAlgorithmCount(), 1u); // the bad ones were not added
  EXPECT_STREQ(timecritical::GetRenderingAlgorithmName(RenderingAlgorithm::PerVertexLit),
    "per-vertex lit");
  EXPECT_STREQ(
    timecritical::GetRenderingAlgorithmName(static_cast<RenderingAlgorithm>(9)), "unknown");
}

TEST(AlgorithmCostModel, CalibratorConvergesPerAlgorithm)
{
  // Four algorithms (17 features), frames that mix them at random, 1% noise.
  AlgorithmCostModel truth;
  truth.SetFrameTime(4e-3);
  truth.SetAlgorithm(RenderingAlgorithm::PerFragmentLit, { 3e-4, 2e-7, 0.0, 4e-8 });
  truth.SetAlgorithm(RenderingAlgorithm::PerVertexLit, { 3e-4, 2e-7, 1e-7, 1.5e-8 });
  truth.SetAlgorithm(RenderingAlgorithm::Flat, { 2e-4, 2.4e-7, 0.0, 1e-8 });
  truth.SetAlgorithm(RenderingAlgorithm::Unlit, { 1e-4, 1.5e-7, 3e-8, 5e-9 });
  const std::size_t d = truth.GetFeatureCount();
  ASSERT_EQ(d, 17u);
  std::vector<double> w(d), x(d), fitted(d);
  truth.GetFeatureWeights(w.data());
  timecritical::CostModelCalibratorOptions options;
  options.Forgetting = 0.999;
  timecritical::CostModelCalibrator calibrator(d, options);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int frame = 0; frame < 4000; ++frame)
  {
    double drawCalls[4], triangles[4], vertices[4], pixels[4];
    for (std::size_t a = 0; a < 4; ++a)
    {
      const bool used = unit(rng) < 0.75;
      drawCalls[a] = used ? 1.0 + std::floor(3.0 * unit(rng)) : 0.0;
      triangles[a] = used ? 2e4 + 1.5e5 * unit(rng) : 0.0;
      vertices[a] = triangles[a] * (0.3 + 0.5 * unit(rng));
      pixels[a] = used ? 1e4 + 3e5 * unit(rng) : 0.0;
    }
    truth.GetFeatures(drawCalls, triangles, vertices, pixels, x.data());
    double time = 0.0;
    for (std::size_t j = 0; j < d; ++j)
    {
      time += w[j] * x[j];
    }
    calibrator.Update(x.data(), time * (1.0 + noise(rng)));
  }
  calibrator.GetCoefficients(fitted.data());
  AlgorithmCostModel model = truth;
  model.SetFeatureWeights(fitted.data());
  double worst = 0.0;
  for (std::size_t a = 0; a < 4; ++a)
  {
    const auto& got = model.GetCoefficients(a);
    const auto& want = truth.GetCoefficients(a);
    SCOPED_TRACE(timecritical::GetRenderingAlgorithmName(truth.GetAlgorithm(a)));
    EXPECT_NEAR(got.Triangle, want.Triangle, 0.1 * want.Triangle);
    EXPECT_NEAR(got.Pixel, want.Pixel, 0.1 * want.Pixel);
    EXPECT_NEAR(got.Vertex, want.Vertex, 0.2 * std::max(want.Vertex, 1e-7));
    EXPECT_NEAR(got.DrawCall, want.DrawCall, 0.5 * want.DrawCall);
    std::printf("  %s: draw %.3g/%.3g tri %.3g/%.3g vert %.3g/%.3g pix %.3g/%.3g\n",
      timecritical::GetRenderingAlgorithmName(truth.GetAlgorithm(a)), got.DrawCall, want.DrawCall,
      got.Triangle, want.Triangle, got.Vertex, want.Vertex, got.Pixel, want.Pixel);
    worst = std::max({ worst, std::abs(got.Triangle / want.Triangle - 1.0),
      std::abs(got.Pixel / want.Pixel - 1.0) });
  }
  std::printf("per-algorithm calibration, 4000 frames, 1%% noise: worst triangle/pixel error %.2f%%\n",
    100.0 * worst);
}
}

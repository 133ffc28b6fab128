// SPDX-License-Identifier: BSD-3-Clause
// Tests of AlgorithmDegradation: Funkhouser's accuracy factor per algorithm
// (m = 1 flat, 2 Gouraud, samples capped at the pixels) as TupleProblem
// terms, the measured family (table of image errors), the levels below the
// coarsest mesh, and bad settings.
#include "AlgorithmDegradation.h"

#include "TupleProblem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using timecritical::AlgorithmDegradation;
using timecritical::RenderingAlgorithm;
using timecritical::TupleProblem;

const RenderingAlgorithm All[4] = { RenderingAlgorithm::PerFragmentLit,
  RenderingAlgorithm::PerVertexLit, RenderingAlgorithm::Flat, RenderingAlgorithm::Unlit };

/// A one-object TupleProblem over the four algorithms from Evaluate().
struct OneObject
{
  std::vector<double> Alpha = std::vector<double>(4), Weight = std::vector<double>(4),
                      Offset = std::vector<double>(4), Hi = std::vector<double>(4),
                      Time = std::vector<double>(4, 1e-3);
  double Box = 0.0, Drop = 0.0;

  OneObject(const AlgorithmDegradation& model, const AlgorithmDegradation::ObjectInput& object)
  {
    model.Evaluate(1, &object, All, 4, this->Alpha.data(), this->Weight.data(),
      this->Offset.data(), this->Hi.data(), &this->Box, &this->Drop);
  }
  TupleProblem View() const
  {
    TupleProblem p;
    p.Count = 1;
    p.AlgorithmCount = 4;
    p.Alpha = this->Alpha.data();
    p.Weight = this->Weight.data();
    p.Offset = this->Offset.data();
    p.MaxTime = this->Time.data();
    p.MaxResolution = this->Hi.data();
    p.BoxDegradation = &this->Box;
    p.DropDegradation = &this->Drop;
    return p;
  }
};

TEST(AlgorithmDegradation, FunkhouserAccuracyAsTupleTerms)
{
  const AlgorithmDegradation model; // Funkhouser's family
  AlgorithmDegradation::ObjectInput object;
  object.Interest = 0.5;
  object.Pixels = 20000.0;
  object.MaxTriangles = 4000.0;
  object.MaxVertices = 2100.0;
  const OneObject one(model, object);
  const TupleProblem p = one.View();
  EXPECT_NO_THROW(p.Validate());
  EXPECT_EQ(one.Alpha[1], 2.0); // Gouraud: m = 2
  EXPECT_EQ(one.Alpha[2], 1.0); // flat: m = 1
  const double size = 0.5 * 20000.0;
  for (double r : { 0.01, 0.1, 0.5, 1.0 })
  {
    for (std::size_t a = 0; a < 4; ++a)
    {
      // D = Size Interest (1 - Accuracy).
      EXPECT_NEAR(p.Degradation(0, static_cast<int>(a), r),
        size * (1.0 - model.FunkhouserAccuracy(All[a], object, r)), 1e-12 * size)
        << timecritical::GetRenderingAlgorithmName(All[a]) << " r " << r;
    }
    // The paper's formula itself: flat 1 - 0.5 / (r Ntri), Gouraud 1 - 0.5 / (r Nvert)^2.
    EXPECT_NEAR(model.FunkhouserAccuracy(RenderingAlgorithm::Flat, object, r),
      1.0 - 0.5 / (r * 4000.0), 1e-15);
    EXPECT_NEAR(model.FunkhouserAccuracy(RenderingAlgorithm::PerVertexLit, object, r),
      1.0 - 0.5 / std::pow(r * 2100.0, 2.0), 1e-15);
  }
  // More accurate algorithms degrade less at a resolution with enough samples.
  const double r = 0.2;
  EXPECT_LT(p.Degradation(0, 0, r), p.Degradation(0, 1, r));
  EXPECT_LT(p.Degradation(0, 1, r), p.Degradation(0, 2, r));
  EXPECT_LT(p.Degradation(0, 2, r), p.Degradation(0, 3, r));
  EXPECT_DOUBLE_EQ(one.Box, 0.9 * size);
  EXPECT_DOUBLE_EQ(one.Drop, size);
  EXPECT_GT(one.Drop, one.Box);
  EXPECT_GT(one.Box, p.Degradation(0, 3, 0.001)); // a box is worse than the coarsest drawing here
}

TEST(AlgorithmDegradation, SamplesNeverMoreThanPixels)
{
  const AlgorithmDegradation model;
  AlgorithmDegradation::ObjectInput object;
  object.Pixels = 400.0;
  object.MaxTriangles = 4000.0; // flat: 400 samples at r = 0.1
  const OneObject one(model, object);
  const TupleProblem p = one.View();
  EXPECT_DOUBLE_EQ(one.Hi[2], 0.1);
  EXPECT_DOUBLE_EQ(p.Degradation(0, 2, 0.1), p.Degradation(0, 2, 1.0));
  EXPECT_GT(p.Degradation(0, 2, 0.05), p.Degradation(0, 2, 0.1));
  EXPECT_DOUBLE_EQ(model.FunkhouserAccuracy(RenderingAlgorithm::Flat, object, 1.0), 1.0 - 0.5 / 400.0);
}

TEST(AlgorithmDegradation, MeasuredFamilyAddsTheTable)
{
  AlgorithmDegradation model(AlgorithmDegradation::Family::Measured);
  model.SetGeometricAlpha(1.0);
  AlgorithmDegradation::ObjectInput object;
  object.Interest = 0.8;
  object.Pixels = 1000.0;
  object.MaxTriangles = 500.0;
  object.GeometricWeight = 0.8 * 1000.0 / 500.0;
  // Every algorithm used needs its measured error.
  EXPECT_THROW((void)OneObject(model, object), std::invalid_argument);
  const double errors[4] = { 0.0, 0.01, 0.05, 0.2 };
  for (std::size_t a = 0; a < 4; ++a)
  {
    model.SetMeasuredError(All[a], errors[a]);
  }
  EXPECT_TRUE(model.HasMeasuredError(RenderingAlgorithm::Flat));
  const OneObject one(model, object);
  const TupleProblem p = one.View();
  for (std::size_t a = 0; a < 4; ++a)
  {
    EXPECT_EQ(one.Alpha[a], 1.0);
    EXPECT_EQ(one.Hi[a], 1.0);
    // Geometric c / r plus Interest Npix error.
    EXPECT_NEAR(p.Degradation(0, static_cast<int>(a), 0.5),
      object.GeometricWeight / 0.5 + 800.0 * errors[a], 1e-12);
  }
}

TEST(AlgorithmDegradation, BadSettingsThrow)
{
  AlgorithmDegradation model;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(model.SetMeasuredError(RenderingAlgorithm::Flat, 1.5), std::invalid_argument);
  EXPECT_THROW(model.SetMeasuredError(RenderingAlgorithm::Flat, nan), std::invalid_argument);
  EXPECT_THROW(model.SetAccuracy(RenderingAlgorithm::Flat, { AlgorithmDegradation::SampleKind::Triangles, -1.0, 0.5 }),
    std::invalid_argument);
  EXPECT_THROW(model.SetAccuracy(RenderingAlgorithm::Flat, { AlgorithmDegradation::SampleKind::Triangles, 1.0, 0.0 }),
    std::invalid_argument);
  EXPECT_THROW(model.SetGeometricAlpha(-1.0), std::invalid_argument);
  EXPECT_THROW(model.SetBoxError(nan), std::invalid_argument);
  EXPECT_THROW(model.GetAccuracy(static_cast<RenderingAlgorithm>(7)), std::invalid_argument);
  AlgorithmDegradation::ObjectInput object;
  double alpha = 0, weight = 0, offset = 0, hi = 0;
  try
  {
    model.Evaluate(1, &object, All, 0, &alpha, &weight, &offset, &hi, nullptr, nullptr);
    ADD_FAILURE() << "no exception for an empty set";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
  }
  // The settings that were refused left the defaults alone.
  EXPECT_EQ(model.GetAccuracy(RenderingAlgorithm::Flat).Exponent, 1.0);
  EXPECT_EQ(model.GetBoxError(), 0.9);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of DegradationModel: Reddy's factors (eq. 7), pixels per degree
// (eq. 8), the eq. 10 families, and Yang et al.'s model as a configuration.
#include "DegradationModel.h"
#include "ResolutionProblem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using timecritical::DegradationModel;
using timecritical::ResolutionProblem;
using Family = DegradationModel::Family;

TEST(DegradationModel, ReddyVelocity)
{
  EXPECT_EQ(DegradationModel::ReddyVelocityFactor(0.0), 1.0);
  EXPECT_EQ(DegradationModel::ReddyVelocityFactor(0.825), 1.0);
  // Decimal logarithm: both branches meet at 0.825 deg/s.
  EXPECT_NEAR(DegradationModel::ReddyVelocityFactor(0.8251), 1.0, 1e-3);
  EXPECT_NEAR(DegradationModel::ReddyVelocityFactor(10.0), 0.9615 - 0.463, 1e-12);
  EXPECT_NEAR(DegradationModel::ReddyVelocityFactor(100.0), 0.9615 - 2 * 0.463, 1e-12);
  DegradationModel model;
  double previous = 2.0;
  for (double v = 0.0; v < 500.0; v += 1.0)
  {
    const double w = model.VelocityFactor(v);
    EXPECT_LE(w, previous);
    EXPECT_GE(w, model.GetConfig().MinimumFactor); // floored where Reddy's line goes negative
    previous = w;
  }
}

TEST(DegradationModel, ReddyEccentricity)
{
  EXPECT_EQ(DegradationModel::ReddyEccentricityFactor(5.79), 1.0);
  EXPECT_NEAR(DegradationModel::ReddyEccentricityFactor(5.7901), 1.0, 1e-3);
  EXPECT_NEAR(DegradationModel::ReddyEccentricityFactor(20.0), 7.49 / 49.0, 1e-12);
  EXPECT_LT(DegradationModel::ReddyEccentricityFactor(40.0),
    DegradationModel::ReddyEccentricityFactor(20.0));
}

TEST(DegradationModel, PixelsPerDegree)
{
  DegradationModel::DisplayParameters d;
  d.ResolutionX = 1920;
  d.ResolutionY = 1080;
  d.SizeX = 0.531;
  d.SizeY = 0.299;
  d.ViewingDistance = 0.6;
  const double expected =
    2 * 0.6 * std::tan(0.5 * 3.14159265358979323846 / 180.0) * std::min(1920 / 0.531, 1080 / 0.299);
  EXPECT_NEAR(DegradationModel::PixelsPerDegree(d), expected, 1e-12);
  EXPECT_NEAR(expected, 37.8, 0.1); // about 38 pixels per degree
  DegradationModel model;
  model.SetDisplay(d);
  EXPECT_NEAR(model.PixelsToDegrees(expected * 3.0), 3.0, 1e-12);
  // Twice the distance: twice the pixels per degree.
  d.ViewingDistance = 1.2;
  EXPECT_NEAR(DegradationModel::PixelsPerDegree(d), 2 * expected, 1e-9);
}

TEST(DegradationModel, Equation10Families)
{
  DegradationModel::ObjectView v;
  v.Pixels = 4000;
  v.MaxTriangles = 5804;
  v.Importance = 2.0;
  v.VelocityDegrees = 10.0;
  v.EccentricityDegrees = 20.0;
  const double interest = (0.9615 - 0.463) * (7.49 / 49.0) * 2.0;
  struct Case
  {
    Family F;
    double Alpha, Wi;
  };
  const Case cases[] = { { Family::Hitchner, 1.0, 4000.0 / 5804.0 },
    { Family::Funkhouser, 2.0, 4000.0 / (5804.0 * 5804.0) },
    { Family::GobbettiBouvier1999, -0.5, 4000.0 * std::sqrt(5804.0) } };
  for (const Case& c : cases)
  {
    const DegradationModel model(DegradationModel::MakeConfig(c.F));
    EXPECT_EQ(model.GetAlpha(), c.Alpha);
    EXPECT_NEAR(model.ResolutionWeight(v), c.Wi, 1e-12 * c.Wi);
    EXPECT_NEAR(model.InterestWeight(v), interest, 1e-12);
    EXPECT_NEAR(model.Weight(v), interest * c.Wi, 1e-9 * interest * c.Wi);
    EXPECT_NEAR(model.Degradation(v, 0.3),
      interest * c.Wi / c.Alpha * std::pow(0.3, -c.Alpha), 1e-9 * std::abs(model.Degradation(v, 0.3)));
    // The loss against full resolution is positive and grows with coverage
    // (for alpha < 0 the terms themselves are negative: minus a benefit).
    DegradationModel::ObjectView bigger = v;
    bigger.Pixels *= 2;
    const double loss = model.Degradation(v, 0.3) - model.Degradation(v, 1.0);
    EXPECT_GT(loss, 0.0);
    EXPECT_NEAR(model.Degradation(bigger, 0.3) - model.Degradation(bigger, 1.0), 2.0 * loss, 1e-9 * loss);
  }
}

TEST(DegradationModel, YangGuKangIsMinusTheirRepresentation)
{
  const DegradationModel model(DegradationModel::MakeConfig(Family::YangGuKang));
  EXPECT_EQ(model.GetAlpha(), -0.5);
  EXPECT_EQ(model.GetConfig().Velocity, DegradationModel::VelocityModel::None);
  EXPECT_EQ(model.GetConfig().Eccentricity, DegradationModel::EccentricityModel::Linear);
  DegradationModel::ObjectView v;
  v.Pixels = 2500;
  v.MaxTriangles = 5804;
  v.MaxVertices = 2904;
  v.Importance = 1.5;
  v.EccentricityDegrees = 6.0;
  v.VelocityDegrees = 50.0; // ignored by Yang et al.
  const double focus = 1.0 - 6.0 / model.GetConfig().LinearFalloffDegrees;
  for (double r : { 0.05, 0.5, 1.0 })
  {
    // representation = coverage * focus * semantics * sqrt(Nmaxvert r)
    const double representation = 2500 * focus * 1.5 * std::sqrt(2904 * r);
    EXPECT_NEAR(model.Degradation(v, r), -representation, 1e-9 * representation);
  }
}

TEST(DegradationModel, LinearFocusAndFloors)
{
  DegradationModel::Config config;
  config.Eccentricity = DegradationModel::EccentricityModel::Linear;
  config.LinearFalloffDegrees = 20.0;
  config.MinimumFactor = 0.1;
  const DegradationModel model(config);
  EXPECT_EQ(model.EccentricityFactor(0.0), 1.0);
  EXPECT_NEAR(model.EccentricityFactor(5.0), 0.75, 1e-12);
  EXPECT_EQ(model.EccentricityFactor(100.0), 0.1);
}

TEST(DegradationModel, UnmeasurableObjectsGetNoWeight)
{
  const DegradationModel model;
  DegradationModel::ObjectView v;
  v.MaxTriangles = 1000;
  v.Pixels = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(model.Weight(v), 0.0);
  v.Pixels = -5;
  EXPECT_EQ(model.Weight(v), 0.0);
  v.Pixels = 100;
  v.Importance = std::numeric_limits<double>::infinity();
  EXPECT_EQ(model.Weight(v), 0.0);
  v.Importance = 1.0;
  v.VelocityDegrees = std::numeric_limits<double>::quiet_NaN(); // unknown velocity: no penalty
  EXPECT_NEAR(model.Weight(v), 0.1, 1e-15);
  const DegradationModel::ObjectView views[2] = { v, v };
  double c[2];
  model.Evaluate(2, views, c);
  EXPECT_EQ(c[0], c[1]);
}
}

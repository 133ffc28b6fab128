// SPDX-License-Identifier: BSD-3-Clause
// Tests of AccuracyCurveComposition (Pasman & Jansen, section 3.2): the
// configurations of Figures 5-7 computed by hand (the paper's figures carry
// no numbers), crossing minima, relative rescaling (section 3.4), and both
// rules checked pointwise against their definitions on random curves.
#include "AccuracyCurveComposition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace
{
using timecritical::AccuracyCurve;
using timecritical::AccuracyCurveComposition;
using Piece = AccuracyCurve::Piece;
constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

void ExpectPieces(const AccuracyCurve& curve, const std::vector<Piece>& expected, double end)
{
  ASSERT_EQ(curve.GetPieces().size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i)
  {
    EXPECT_DOUBLE_EQ(curve.GetPieces()[i].A, expected[i].A) << "piece " << i;
    EXPECT_DOUBLE_EQ(curve.GetPieces()[i].R, expected[i].R) << "piece " << i;
    EXPECT_DOUBLE_EQ(curve.GetPieces()[i].K, expected[i].K) << "piece " << i;
  }
  EXPECT_EQ(curve.GetMaximumAccuracy(), end);
}

void ExpectNear(double actual, double expected, const char* what, double a)
{
  if (std::isinf(expected))
  {
    EXPECT_EQ(actual, expected) << what << " at a = " << a;
  }
  else
  {
    EXPECT_NEAR(actual, expected, 1e-9 * std::max(1.0, std::abs(expected)))
      << what << " at a = " << a;
  }
}

/// A random valid curve: 1-6 pieces, jumps and flat pieces, bounded or not, some single points.
AccuracyCurve RandomCurve(std::mt19937& random)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (unit(random) < 0.15)
  {
    return AccuracyCurve::SinglePoint(10.0 * unit(random), 100.0 * unit(random));
  }
  const int n = 1 + static_cast<int>(random() % 6);
  std::vector<Piece> pieces;
  double a = 5.0 * unit(random);
  double r = 50.0 * unit(random);
  for (int i = 0; i < n; ++i)
  {
    const double k = unit(random) < 0.2 ? 0.0 : 40.0 * unit(random);
    pieces.push_back({ a, r - k * a, k });
    const double next = a + 0.1 + 3.0 * unit(random);
    r = r + k * (next - a) + (unit(random) < 0.5 ? 0.0 : 30.0 * unit(random));
    a = next;
  }
  const double end = unit(random) < 0.25 ? Inf : a;
  return AccuracyCurve(std::move(pieces), end);
}

/// Accuracies to test a composition at: every breakpoint, points around them, and beyond.
std::vector<double> Probes(const std::vector<AccuracyCurve>& curves)
{
  std::vector<double> probes{ 0.0 };
  for (const AccuracyCurve& c : curves)
  {
    for (const Piece& p : c.GetPieces())
    {
      probes.insert(probes.end(), { p.A, p.A * 0.999, p.A * 1.001 + 1e-6 });
    }
    if (std::isfinite(c.GetMaximumAccuracy()))
    {
      probes.insert(probes.end(), { c.GetMaximumAccuracy(), c.GetMaximumAccuracy() * 1.0001 });
    }
  }
  for (double a = 0.0; a < 40.0; a += 0.173)
  {
    probes.push_back(a);
  }
  return probes;
}
}

TEST(AccuracyCurveComposition, Figure5GroupAddsWithHorizontalExtensions)
{
  // Child 1 covers accuracies [1, 4] (r = 10a), child 2 [2, 6] (r = 20 + 5a).
  // Below 2 child 2 renders its cheapest version (30), above 4 child 1 its finest (40).
  const AccuracyCurve child1({ { 1.0, 0.0, 10.0 } }, 4.0);
  const AccuracyCurve child2({ { 2.0, 20.0, 5.0 } }, 6.0);
  const AccuracyCurve group = AccuracyCurveComposition::Sum({ child1, child2 });
  ExpectPieces(group, { { 1.0, 30.0, 10.0 }, { 2.0, 20.0, 15.0 }, { 4.0, 60.0, 5.0 } }, 6.0);
  EXPECT_EQ(group.GetResources(0.5), 40.0);
  EXPECT_EQ(group.GetResources(1.0), 40.0);
  EXPECT_EQ(group.GetResources(2.0), 50.0);
  EXPECT_EQ(group.GetResources(3.0), 65.0);
  EXPECT_EQ(group.GetResources(4.0), 80.0);
  EXPECT_EQ(group.GetResources(6.0), 90.0);
  EXPECT_EQ(group.GetResources(6.5), Inf);
  // The same group in either order.
  EXPECT_TRUE(AccuracyCurveComposition::Sum({ child2, child1 }).IsNear(group));
  // The best accuracy for 65 triangles in all: 3 (30 + 35).
  EXPECT_EQ(group.GetAccuracy(65.0), 3.0);
}

TEST(AccuracyCurveComposition, Figure6MinimumSplitsCrossingPieces)
{
  // Child 1: r = 10a on [1, 5]; child 2: r = 20 + 2a on [1, 8]. They cross at
  // a = 2.5 (r = 25): below it child 1 is cheaper, above it child 2.
  const AccuracyCurve child1({ { 1.0, 0.0, 10.0 } }, 5.0);
  const AccuracyCurve child2({ { 1.0, 20.0, 2.0 } }, 8.0);
  const auto lod = AccuracyCurveComposition::Minimum({ child1, child2 });
  ExpectPieces(lod.Curve, { { 1.0, 0.0, 10.0 }, { 2.5, 20.0, 2.0 } }, 8.0);
  EXPECT_EQ(lod.PieceChild, (std::vector<std::size_t>{ 0, 1 }));
  EXPECT_EQ(lod.Curve.GetResources(2.5), 25.0); // no crack at the crossing
  EXPECT_EQ(lod.Curve.GetResources(2.0), 20.0);
  EXPECT_EQ(lod.Curve.GetResources(4.0), 28.0);
  EXPECT_EQ(lod.GetCheapestChild(2.0), 0u);
  EXPECT_EQ(lod.GetCheapestChild(3.0), 1u);
  EXPECT_EQ(lod.GetCheapestChild(8.0), 1u);
  EXPECT_EQ(lod.GetCheapestChild(8.5), AccuracyCurve::npos);
  // Quotas: 15 triangles reach 1.5 with child 1; 27 reach 3.5 with child 2.
  EXPECT_EQ(lod.Curve.GetAccuracy(15.0), 1.5);
  EXPECT_EQ(lod.GetChildForQuota(15.0), 0u);
  EXPECT_EQ(lod.Curve.GetAccuracy(27.0), 3.5);
  EXPECT_EQ(lod.GetChildForQuota(27.0), 1u);
  EXPECT_EQ(lod.GetChildForQuota(9.0), AccuracyCurve::npos); // nothing is that cheap
}

TEST(AccuracyCurveComposition, Figure7MinimumIsNeverExtendedToTheRight)
{
  // Child 1 is cheap but valid only up to 3 (r = 2a, 6 at its end); child 2
  // reaches 10 (r = 10 + 5a). At a = 8 only child 2 qualifies: 50, not the 6
  // that a horizontally extended child 1 would claim.
  const AccuracyCurve child1({ { 1.0, 0.0, 2.0 } }, 3.0);
  const AccuracyCurve child2({ { 1.0, 10.0, 5.0 } }, 10.0);
  const auto lod = AccuracyCurveComposition::Minimum({ child1, child2 });
  ExpectPieces(lod.Curve, { { 1.0, 0.0, 2.0 }, { 3.0, 10.0, 5.0 } }, 10.0);
  EXPECT_EQ(lod.Curve.GetResources(3.0), 6.0);
  EXPECT_EQ(lod.Curve.GetResources(8.0), 50.0);
  EXPECT_EQ(lod.GetCheapestChild(8.0), 1u);
  EXPECT_EQ(lod.GetCheapestChild(0.5), 0u); // extended to the left: more accurate than asked
  // The wrong (extended) minimum would be min(6, 50) = 6; the group rule does extend.
  EXPECT_EQ(std::min(child1.GetSaturatedResources(8.0), child2.GetResources(8.0)), 6.0);
  EXPECT_EQ(lod.Curve.GetAccuracy(20.0), 3.0); // 20 triangles: child 1 at its end
}

TEST(AccuracyCurveComposition, MinimumOfSeveralCrossingLines)
{
  // Three lines on [0, 10] cross pairwise: 4a (0..), 6 + a, 12 + 0.25a.
  // The envelope: 4a up to 2, 6 + a up to 8, then 12 + 0.25a.
  const AccuracyCurve steep({ { 0.0, 0.0, 4.0 } }, 10.0);
  const AccuracyCurve middle({ { 0.0, 6.0, 1.0 } }, 10.0);
  const AccuracyCurve flat({ { 0.0, 12.0, 0.25 } }, 10.0);
  const auto lod = AccuracyCurveComposition::Minimum({ flat, middle, steep });
  ExpectPieces(
    lod.Curve, { { 0.0, 0.0, 4.0 }, { 2.0, 6.0, 1.0 }, { 8.0, 12.0, 0.25 } }, 10.0);
  EXPECT_EQ(lod.PieceChild, (std::vector<std::size_t>{ 2, 1, 0 }));
  // Three lines through one point (a = 4, r = 10): the flattest wins after it.
  const AccuracyCurve a({ { 0.0, 2.0, 2.0 } }, 10.0);
  const AccuracyCurve b({ { 0.0, 6.0, 1.0 } }, 10.0);
  const AccuracyCurve c({ { 0.0, 8.0, 0.5 } }, 10.0);
  const auto concurrent = AccuracyCurveComposition::Minimum({ a, b, c });
  ExpectPieces(concurrent.Curve, { { 0.0, 2.0, 2.0 }, { 4.0, 8.0, 0.5 } }, 10.0);
  EXPECT_EQ(concurrent.PieceChild, (std::vector<std::size_t>{ 0, 2 }));
  // Equal children: the first one is chosen.
  const auto equal = AccuracyCurveComposition::Minimum({ b, b });
  EXPECT_EQ(equal.PieceChild, (std::vector<std::size_t>{ 0 }));
}

TEST(AccuracyCurveComposition, SinglePointRepresentations)
{
  // Classic LODs of one object, each a fixed accuracy and cost: the LOD node
  // is a staircase; a group of two such objects adds them.
  const auto lod = AccuracyCurveComposition::Minimum({ AccuracyCurve::SinglePoint(40.0, 1000.0),
    AccuracyCurve::SinglePoint(10.0, 100.0), AccuracyCurve::SinglePoint(20.0, 300.0) });
  // The cheapest reaches only 10: a constant piece from 0 holds it (no zero-width piece).
  ExpectPieces(lod.Curve, { { 0.0, 100.0, 0.0 }, { 10.0, 300.0, 0.0 }, { 20.0, 1000.0, 0.0 } },
    40.0);
  EXPECT_EQ(lod.PieceChild, (std::vector<std::size_t>{ 1, 2, 0 }));
  EXPECT_EQ(lod.Curve.GetResources(5.0), 100.0);
  EXPECT_EQ(lod.Curve.GetResources(10.0), 100.0);
  EXPECT_EQ(lod.Curve.GetResources(15.0), 300.0);
  EXPECT_EQ(lod.Curve.GetResources(40.0), 1000.0);
  EXPECT_EQ(lod.GetCheapestChild(15.0), 2u);
  EXPECT_EQ(lod.Curve.GetAccuracy(999.0), 20.0);
  const AccuracyCurve same = AccuracyCurveComposition::Sum(
    { AccuracyCurve::SinglePoint(10.0, 100.0), AccuracyCurve::SinglePoint(10.0, 50.0) });
  ExpectPieces(same, { { 10.0, 150.0, 0.0 } }, 10.0);
}

TEST(AccuracyCurveComposition, EmptyCurvesAreLeftOut)
{
  const AccuracyCurve c({ { 1.0, 0.0, 10.0 } }, 4.0);
  EXPECT_TRUE(AccuracyCurveComposition::Sum({}).IsEmpty());
  EXPECT_TRUE(AccuracyCurveComposition::Sum({ AccuracyCurve() }).IsEmpty());
  EXPECT_TRUE(AccuracyCurveComposition::Minimum({}).Curve.IsEmpty());
  EXPECT_EQ(AccuracyCurveComposition::Minimum({}).GetCheapestChild(1.0), AccuracyCurve::npos);
  EXPECT_TRUE(AccuracyCurveComposition::Sum({ AccuracyCurve(), c }).IsNear(c));
  const auto lod = AccuracyCurveComposition::Minimum({ AccuracyCurve(), c });
  EXPECT_TRUE(lod.Curve.IsNear(c));
  EXPECT_EQ(lod.GetCheapestChild(2.0), 1u); // indices count the empty child
}

TEST(AccuracyCurveComposition, RelativeGroupsRescaleTheirMembers)
{
  // Section 3.4: members of radii d_i in a group of diameter D; (a d_i / D, r_i)
  // on the members' curves gives (a, sum r_i) on the group's.
  const AccuracyCurve small = AccuracyCurve::FromPoints({ { 10.0, 100.0 }, { 50.0, 900.0 } });
  const AccuracyCurve large({ { 5.0, 20.0, 8.0 }, { 30.0, 300.0, 1.0 } }, 90.0);
  const std::vector<double> sizes{ 1.0, 4.0 };
  const double groupSize = 6.0;
  const AccuracyCurve group =
    AccuracyCurveComposition::SumRelative({ small, large }, sizes, groupSize);
  EXPECT_DOUBLE_EQ(group.GetMinimumAccuracy(), 7.5);  // 5 * 6 / 4
  EXPECT_DOUBLE_EQ(group.GetMaximumAccuracy(), 300.0); // 50 * 6 / 1
  for (double a = 0.0; a <= 300.0; a += 1.37)
  {
    const double expected = small.GetSaturatedResources(a * sizes[0] / groupSize) +
      large.GetSaturatedResources(a * sizes[1] / groupSize);
    ExpectNear(group.GetResources(a), expected, "relative group", a);
  }
  // Relative LOD node: two representations of slightly different sizes.
  const auto lod = AccuracyCurveComposition::MinimumRelative({ small, large }, { 4.0, 5.0 }, 5.0);
  for (double a = 0.0; a <= 90.0; a += 0.91)
  {
    const double expected =
      std::min(small.GetResources(a * 4.0 / 5.0), large.GetResources(a));
    ExpectNear(lod.Curve.GetResources(a), expected, "relative LOD", a);
  }
  EXPECT_THROW(AccuracyCurveComposition::SumRelative({ small }, { 1.0, 2.0 }, 3.0),
    std::invalid_argument);
  EXPECT_THROW(AccuracyCurveComposition::SumRelative({ small }, { 0.0 }, 3.0),
    std::invalid_argument);
  EXPECT_THROW(AccuracyCurveComposition::MinimumRelative({ small }, { 1.0 }, NaN),
    std::invalid_argument);
}

TEST(AccuracyCurveComposition, AbsoluteGroupFromRelativeMembers)
{
  // Two objects of the same relative curve, one near and one far: the far one
  // reaches a given angle with a lower relative accuracy, so costs less.
  const AccuracyCurve relative = AccuracyCurve::FromPoints({ { 10.0, 100.0 }, { 100.0, 1000.0 } });
  const AccuracyCurve nearObject = relative.ToAbsolute(2.0, 5.0);  // a_abs = 2.5 a_rel
  const AccuracyCurve farObject = relative.ToAbsolute(2.0, 50.0);  // a_abs = 25 a_rel
  const AccuracyCurve scene = AccuracyCurveComposition::Sum({ nearObject, farObject });
  // Angular accuracy 250 (4 mrad): relative 100 near (1000), 10 far (100).
  EXPECT_DOUBLE_EQ(scene.GetResources(250.0), 1100.0);
  EXPECT_DOUBLE_EQ(nearObject.GetResources(250.0), 1000.0);
  EXPECT_DOUBLE_EQ(farObject.GetResources(250.0), 100.0);
}

TEST(AccuracyCurveComposition, RandomCurvesFollowTheDefinitions)
{
  std::mt19937 random(20021224);
  for (int trial = 0; trial < 300; ++trial)
  {
    std::vector<AccuracyCurve> curves;
    const int n = 1 + trial % 5;
    for (int i = 0; i < n; ++i)
    {
      curves.push_back(RandomCurve(random));
    }
    const AccuracyCurve group = AccuracyCurveComposition::Sum(curves);
    const auto lod = AccuracyCurveComposition::Minimum(curves);
    for (double a : Probes(curves))
    {
      double sum = 0.0;
      double minimum = Inf;
      for (const AccuracyCurve& c : curves)
      {
        sum += c.GetSaturatedResources(a);
        minimum = std::min(minimum, c.GetResources(a));
      }
      ExpectNear(group.GetResources(a), a > group.GetMaximumAccuracy() ? Inf : sum, "sum", a);
      ExpectNear(lod.Curve.GetResources(a), minimum, "minimum", a);
      const std::size_t child = lod.GetCheapestChild(a);
      if (std::isinf(minimum))
      {
        EXPECT_EQ(child, AccuracyCurve::npos);
      }
      else
      {
        ASSERT_LT(child, curves.size());
        ExpectNear(curves[child].GetResources(a), minimum, "cheapest child", a);
      }
    }
    if (HasFailure())
    {
      FAIL() << "trial " << trial;
    }
  }
}

TEST(AccuracyCurveComposition, LargeGroup)
{
  // A W3-sized scene: 2,000 TOM-like curves of 48 samples each.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.5, 2.0);
  std::vector<AccuracyCurve> objects;
  for (int i = 0; i < 2000; ++i)
  {
    std::vector<AccuracyCurve::ErrorSample> samples;
    const double full = std::round(2000.0 + 10000.0 * unit(random));
    const double scale = 0.1 * unit(random);
    for (int s = 0; s < 47; ++s)
    {
      const double t = (s + 1) / 48.0;
      samples.push_back({ std::round(full * t), scale * (1.0 - t) * (1.0 - t) + 1e-7 });
    }
    samples.push_back({ full, 0.0 });
    objects.push_back(AccuracyCurve::FromErrorSamples(samples, unit(random)));
  }
  const AccuracyCurve scene = AccuracyCurveComposition::Sum(objects);
  EXPECT_EQ(scene.GetMaximumAccuracy(), Inf);
  for (double a : { 1.0, 30.0, 1e3, 1e5, 1e7, 1e9 })
  {
    double sum = 0.0;
    for (const AccuracyCurve& c : objects)
    {
      sum += c.GetSaturatedResources(a);
    }
    ExpectNear(scene.GetResources(a), sum, "scene", a);
    EXPECT_LE(scene.GetResources(scene.GetAccuracy(sum)), sum);
  }
}

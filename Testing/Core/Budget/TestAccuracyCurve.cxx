// SPDX-License-Identifier: BSD-3-Clause
// Tests of AccuracyCurve (Pasman & Jansen, section 3.1): evaluation with the
// horizontal left extension and no value past the end, the inverse (best
// accuracy for a quota) and its round trips, curves from points and from error
// samples, accuracy scaling, relative <-> absolute conversion, and every
// rejected input.
#include "AccuracyCurve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace
{
using timecritical::AccuracyCurve;
using Piece = AccuracyCurve::Piece;
constexpr double Inf = std::numeric_limits<double>::infinity();
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// Two pieces with a jump: r = 2a on [10, 50], r = 60 + 2a on (50, 100].
AccuracyCurve Jumping()
{
  return AccuracyCurve({ { 10.0, 0.0, 2.0 }, { 50.0, 60.0, 2.0 } }, 100.0);
}
}

TEST(AccuracyCurve, EmptyCurve)
{
  const AccuracyCurve empty;
  EXPECT_TRUE(empty.IsEmpty());
  EXPECT_EQ(empty.GetMaximumAccuracy(), 0.0);
  EXPECT_EQ(empty.GetMinimumResources(), 0.0);
  EXPECT_EQ(empty.GetResources(1.0), Inf);
  EXPECT_EQ(empty.GetSaturatedResources(1.0), 0.0);
  EXPECT_EQ(empty.GetAccuracy(1e9), 0.0);
  EXPECT_EQ(empty.FindPiece(0.0), AccuracyCurve::npos);
  EXPECT_TRUE(AccuracyCurve({}, 0.0).IsEmpty());
}

TEST(AccuracyCurve, EvaluationIsLeftExtendedAndEndsAtTheMaximum)
{
  const AccuracyCurve c = Jumping();
  EXPECT_EQ(c.GetMinimumAccuracy(), 10.0);
  EXPECT_EQ(c.GetMaximumAccuracy(), 100.0);
  EXPECT_EQ(c.GetMinimumResources(), 20.0);
  EXPECT_EQ(c.GetMaximumResources(), 260.0);
  EXPECT_EQ(c.GetResources(0.0), 20.0); // below the curve: its cheapest representation
  EXPECT_EQ(c.GetResources(5.0), 20.0);
  EXPECT_EQ(c.GetResources(10.0), 20.0);
  EXPECT_EQ(c.GetResources(30.0), 60.0);
  // The breakpoint belongs to the piece that ends there (least resources reaching 50).
  EXPECT_EQ(c.GetResources(50.0), 100.0);
  EXPECT_NEAR(c.GetResources(50.0 + 1e-9), 160.0, 1e-6);
  EXPECT_EQ(c.GetResources(75.0), 210.0);
  EXPECT_EQ(c.GetResources(100.0), 260.0);
  EXPECT_EQ(c.GetResources(100.5), Inf); // never extended to the right
  EXPECT_EQ(c.GetSaturatedResources(100.5), 260.0);
  EXPECT_EQ(c.GetSaturatedResources(Inf), 260.0);
  EXPECT_EQ(c.FindPiece(0.0), 0u);
  EXPECT_EQ(c.FindPiece(50.0), 0u);
  EXPECT_EQ(c.FindPiece(50.5), 1u);
  EXPECT_EQ(c.FindPiece(100.0), 1u);
  EXPECT_EQ(c.FindPiece(101.0), AccuracyCurve::npos);
}

TEST(AccuracyCurve, BestAccuracyForAQuota)
{
  const AccuracyCurve c = Jumping();
  EXPECT_EQ(c.GetAccuracy(0.0), 0.0); // nothing fits
  EXPECT_EQ(c.GetAccuracy(19.999), 0.0);
  EXPECT_EQ(c.GetAccuracy(20.0), 10.0);
  EXPECT_EQ(c.GetAccuracy(60.0), 30.0);
  EXPECT_EQ(c.GetAccuracy(100.0), 50.0);
  EXPECT_EQ(c.GetAccuracy(130.0), 50.0); // inside the jump: the accuracy before it
  EXPECT_EQ(c.GetAccuracy(160.0), 50.0);
  EXPECT_EQ(c.GetAccuracy(200.0), 70.0);
  EXPECT_EQ(c.GetAccuracy(260.0), 100.0);
  EXPECT_EQ(c.GetAccuracy(1e12), 100.0);
  EXPECT_EQ(c.GetAccuracy(Inf), 100.0);
}

TEST(AccuracyCurve, RoundTrips)
{
  // A curve with awkward numbers: the inverse must never overshoot the quota,
  // and a quota of exactly r(a) must reach a.
  const AccuracyCurve c = AccuracyCurve::FromPoints(
    { { 0.3, 7.1 }, { 1.7, 13.3 }, { 2.9, 13.3 }, { 11.3, 1000.7 }, { 47.9, 1e6 / 3.0 } });
  for (double q = 0.0; q < 4e5; q = q * 1.07 + 0.37)
  {
    const double a = c.GetAccuracy(q);
    if (a > 0.0)
    {
      EXPECT_LE(c.GetResources(a), q) << "quota " << q;
    }
  }
  for (double a = 0.3; a <= 47.9; a += 0.0731)
  {
    EXPECT_GE(c.GetAccuracy(c.GetResources(a)), a * (1.0 - 1e-12)) << "accuracy " << a;
  }
}

TEST(AccuracyCurve, SinglePoint)
{
  // A fixed representation: accuracy 40 for 500 triangles.
  const AccuracyCurve c = AccuracyCurve::SinglePoint(40.0, 500.0);
  EXPECT_EQ(c.GetResources(1.0), 500.0);
  EXPECT_EQ(c.GetResources(40.0), 500.0);
  EXPECT_EQ(c.GetResources(40.1), Inf);
  EXPECT_EQ(c.GetAccuracy(499.0), 0.0);
  EXPECT_EQ(c.GetAccuracy(500.0), 40.0);
}

TEST(AccuracyCurve, FromPointsIsThePolylineThroughThem)
{
  // Figure 4: a cow "so linear that it could be modelled with a single part".
  const AccuracyCurve cow = AccuracyCurve::FromPoints({ { 10.0, 100.0 }, { 110.0, 5100.0 } });
  ASSERT_EQ(cow.GetPieces().size(), 1u);
  EXPECT_EQ(cow.GetPieces()[0].A, 10.0);
  EXPECT_EQ(cow.GetPieces()[0].K, 50.0);
  EXPECT_EQ(cow.GetPieces()[0].R, -400.0);
  EXPECT_EQ(cow.GetResources(60.0), 2600.0);
  EXPECT_EQ(cow.GetAccuracy(2600.0), 60.0);
  EXPECT_TRUE(AccuracyCurve::FromPoints({}).IsEmpty());
  const AccuracyCurve three =
    AccuracyCurve::FromPoints({ { 1.0, 10.0 }, { 2.0, 30.0 }, { 4.0, 40.0 } });
  ASSERT_EQ(three.GetPieces().size(), 2u);
  EXPECT_EQ(three.GetResources(1.5), 20.0);
  EXPECT_EQ(three.GetResources(3.0), 35.0);
  EXPECT_EQ(three.GetMaximumAccuracy(), 4.0);
}

TEST(AccuracyCurve, FromErrorSamples)
{
  // A TOM of size 2: 100 triangles at error 0.5, 400 at 0.1 (twice: the
  // cheaper one counts), 1000 at error 0 (the full mesh).
  const AccuracyCurve c = AccuracyCurve::FromErrorSamples(
    { { 100.0, 0.5 }, { 400.0, 0.1 }, { 450.0, 0.1 }, { 1000.0, 0.0 } }, 2.0);
  ASSERT_EQ(c.GetPieces().size(), 2u);
  EXPECT_EQ(c.GetMinimumAccuracy(), 4.0);
  EXPECT_EQ(c.GetMaximumAccuracy(), Inf);
  EXPECT_EQ(c.GetResources(4.0), 100.0);
  EXPECT_DOUBLE_EQ(c.GetResources(20.0), 400.0);
  EXPECT_DOUBLE_EQ(c.GetResources(12.0), 250.0);
  EXPECT_EQ(c.GetResources(20.5), 1000.0); // only the full mesh is finer than error 0.1
  EXPECT_EQ(c.GetResources(1e30), 1000.0);
  EXPECT_DOUBLE_EQ(c.GetAccuracy(999.0), 20.0);
  EXPECT_EQ(c.GetAccuracy(1000.0), Inf);

  // Without the full mesh, the curve ends at the finest sample.
  const AccuracyCurve open =
    AccuracyCurve::FromErrorSamples({ { 100.0, 0.5 }, { 400.0, 0.1 } }, 2.0);
  EXPECT_EQ(open.GetMaximumAccuracy(), 20.0);
  EXPECT_EQ(open.GetResources(21.0), Inf);
  // One coarse sample and the full mesh.
  const AccuracyCurve two = AccuracyCurve::FromErrorSamples({ { 100.0, 0.5 }, { 300.0, 0.0 } }, 1.0);
  EXPECT_EQ(two.GetResources(2.0), 100.0);
  EXPECT_EQ(two.GetResources(2.5), 300.0);
  // Only the exact mesh: every accuracy at its cost.
  const AccuracyCurve exact = AccuracyCurve::FromErrorSamples({ { 300.0, 0.0 } }, 1.0);
  EXPECT_EQ(exact.GetResources(0.0), 300.0);
  EXPECT_EQ(exact.GetResources(1e300), 300.0);
  EXPECT_TRUE(AccuracyCurve::FromErrorSamples({}, 1.0).IsEmpty());
}

TEST(AccuracyCurve, ScaleAndRescale)
{
  const AccuracyCurve c = Jumping();
  const AccuracyCurve s = c.ScaleAccuracy(4.0);
  EXPECT_EQ(s.GetMinimumAccuracy(), 40.0);
  EXPECT_EQ(s.GetMaximumAccuracy(), 400.0);
  for (double a = 0.0; a <= 100.0; a += 0.5)
  {
    EXPECT_DOUBLE_EQ(s.GetResources(4.0 * a), c.GetResources(a)) << a;
  }
  EXPECT_TRUE(s.ScaleAccuracy(0.25).IsNear(c));
  // A member of size 1 in a group of size 3 (section 3.4): its distortion
  // 1/a is 1/(3a) of the group's size, so its relative accuracy a is 3a for the group.
  const AccuracyCurve member = AccuracyCurve::SinglePoint(10.0, 100.0);
  EXPECT_EQ(member.Rescale(1.0, 3.0).GetMaximumAccuracy(), 30.0);
  EXPECT_DOUBLE_EQ(member.Rescale(3.0, 1.0).GetMaximumAccuracy(), 10.0 / 3.0);
}

TEST(AccuracyCurve, RelativeAndAbsoluteAccuracy)
{
  // Section 3.1: relative accuracy 50 is a distortion of 2% of the object's
  // size. An object of size 2 at distance 10: a distortion of 0.04 subtends
  // 0.004 rad, an absolute accuracy of 250.
  EXPECT_DOUBLE_EQ(AccuracyCurve::RelativeToAbsolute(50.0, 2.0, 10.0), 250.0);
  EXPECT_DOUBLE_EQ(AccuracyCurve::AbsoluteToRelative(250.0, 2.0, 10.0), 50.0);
  // Nearer, the same object needs a higher relative accuracy for the same angle.
  EXPECT_DOUBLE_EQ(AccuracyCurve::AbsoluteToRelative(250.0, 2.0, 5.0), 100.0);
  const AccuracyCurve relative = Jumping();
  const AccuracyCurve absolute = relative.ToAbsolute(2.0, 10.0);
  EXPECT_DOUBLE_EQ(absolute.GetMinimumAccuracy(), 50.0);
  EXPECT_DOUBLE_EQ(absolute.GetResources(AccuracyCurve::RelativeToAbsolute(30.0, 2.0, 10.0)),
    relative.GetResources(30.0));
  EXPECT_TRUE(absolute.ToRelative(2.0, 10.0).IsNear(relative));
  EXPECT_FALSE(absolute.IsNear(relative));
  // The nearest distance to a bounding sphere, floored.
  EXPECT_EQ(AccuracyCurve::NearestDistance(10.0, 1.0, 0.01), 9.0);
  EXPECT_EQ(AccuracyCurve::NearestDistance(0.5, 1.0, 0.01), 0.01); // inside the sphere
}

TEST(AccuracyCurve, RejectsBadCurves)
{
  using Pieces = std::vector<Piece>;
  auto rejects = [](Pieces pieces, double end) {
    EXPECT_THROW(AccuracyCurve(std::move(pieces), end), std::invalid_argument);
  };
  rejects({ { NaN, 0.0, 1.0 } }, 10.0);
  rejects({ { -1.0, 0.0, 1.0 } }, 10.0);    // negative accuracy
  rejects({ { Inf, 0.0, 1.0 } }, Inf);      // pieces start at finite accuracies
  rejects({ { 1.0, NaN, 1.0 } }, 10.0);
  rejects({ { 1.0, 0.0, Inf } }, 10.0);
  rejects({ { 1.0, 0.0, -1.0 } }, 10.0);    // decreasing piece
  rejects({ { 1.0, -5.0, 1.0 } }, 10.0);    // negative resources
  rejects({ { 1.0, 0.0, 1.0 }, { 1.0, 5.0, 1.0 } }, 10.0); // A not increasing
  rejects({ { 2.0, 0.0, 1.0 }, { 1.0, 5.0, 1.0 } }, 10.0);
  rejects({ { 1.0, 0.0, 10.0 }, { 2.0, 0.0, 1.0 } }, 10.0); // drops from 20 to 2 at a = 2
  rejects({ { 1.0, 0.0, 1.0 } }, NaN);
  rejects({ { 1.0, 0.0, 1.0 } }, 0.5);                       // ends before it starts
  rejects({ { 1.0, 0.0, 1.0 }, { 2.0, 5.0, 1.0 } }, 2.0);    // empty last piece
  rejects({}, 3.0);
  EXPECT_NO_THROW(AccuracyCurve({ { 1.0, 0.0, 1.0 } }, 1.0)); // a single point
  // A drop within rounding is accepted (pieces meeting at a computed crossing).
  EXPECT_NO_THROW(AccuracyCurve({ { 1.0, 0.0, 10.0 }, { 2.0, 20.0 - 1e-12, 0.0 } }, 3.0));
}

TEST(AccuracyCurve, RejectsBadArguments)
{
  const AccuracyCurve c = Jumping();
  EXPECT_THROW(c.GetResources(NaN), std::invalid_argument);
  EXPECT_THROW(c.GetResources(-1.0), std::invalid_argument);
  EXPECT_THROW(c.GetSaturatedResources(NaN), std::invalid_argument);
  EXPECT_THROW(c.GetAccuracy(NaN), std::invalid_argument);
  EXPECT_THROW(c.GetAccuracy(-1.0), std::invalid_argument);
  EXPECT_THROW(c.FindPiece(NaN), std::invalid_argument);
  EXPECT_THROW(c.ScaleAccuracy(0.0), std::invalid_argument);
  EXPECT_THROW(c.ScaleAccuracy(-2.0), std::invalid_argument);
  EXPECT_THROW(c.ScaleAccuracy(Inf), std::invalid_argument);
  EXPECT_THROW(c.Rescale(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(c.Rescale(1.0, NaN), std::invalid_argument);
  EXPECT_THROW(c.ToAbsolute(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(c.ToRelative(-1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::RelativeToAbsolute(NaN, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::AbsoluteToRelative(1.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::NearestDistance(1.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::NearestDistance(NaN, 1.0, 1.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::NearestDistance(Inf, 1.0, 1.0), std::invalid_argument);
  // Points and samples.
  EXPECT_THROW(AccuracyCurve::FromPoints({ { 1.0, 1.0 }, { 1.0, 2.0 } }), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromPoints({ { 1.0, 2.0 }, { 2.0, 1.0 } }), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromPoints({ { 1.0, 2.0 }, { NaN, 3.0 } }), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromPoints({ { -1.0, 2.0 } }), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromErrorSamples({ { 1.0, 1.0 } }, 0.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromErrorSamples({ { 1.0, 1.0 } }, NaN), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromErrorSamples({ { 1.0, -1.0 } }, 1.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromErrorSamples({ { NaN, 1.0 } }, 1.0), std::invalid_argument);
  EXPECT_THROW(AccuracyCurve::FromErrorSamples({ { 2.0, 1.0 }, { 1.0, 0.5 } }, 1.0),
    std::invalid_argument); // fewer triangles for a smaller error
  EXPECT_THROW(AccuracyCurve::FromErrorSamples({ { 1.0, 0.5 }, { 2.0, 1.0 } }, 1.0),
    std::invalid_argument); // the error grows with the triangles
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of TOMErrorCurve: construction from per-vertex errors, the sample
// bound and coverage, interpolation, its inverse and Check.
#include "TOMErrorCurve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using timecritical::TOMErrorCurve;
using Sample = TOMErrorCurve::Sample;

/// Per-vertex-count inputs of FromVertexErrors, as a builder would produce them.
struct Sequence
{
  uint32_t Vertices = 0;
  uint32_t Base = 0;
  std::vector<float> Error;        ///< [0, Vertices]
  std::vector<uint32_t> Triangles; ///< [0, Vertices]

  TOMErrorCurve Curve(unsigned maxSamples = 48) const
  {
    return TOMErrorCurve::FromVertexErrors(
      this->Error.data(), this->Triangles.data(), this->Vertices, this->Base, maxSamples);
  }
};

/**
 * A closed-mesh-like sequence: about two triangles per vertex (each removal
 * kills two, every `flat`-th one none, like a pair contraction) and an error
 * falling like 1/i, i.e. steeply near the base and slowly near the full mesh.
 */
Sequence MakeSequence(uint32_t vertices, uint32_t base, uint32_t flat = 0)
{
  Sequence s;
  s.Vertices = vertices;
  s.Base = base;
  s.Error.resize(vertices + 1);
  s.Triangles.resize(vertices + 1);
  uint32_t triangles = 2 * base;
  for (uint32_t i = 0; i <= vertices; ++i)
  {
    if (i > base)
    {
      triangles += (flat != 0 && i % flat == 0) ? 0 : 2;
    }
    s.Triangles[i] = i <= base ? 2 * base : triangles;
    const double at = std::max(i, base);
    s.Error[i] = static_cast<float>(1000.0 * (1.0 / at - 1.0 / vertices));
  }
  return s;
}

/// The error of the coarsest mesh with at most t triangles, like traversal picks it.
double TrueError(const Sequence& s, uint32_t t)
{
  double error = s.Error[s.Base];
  for (uint32_t i = s.Base; i <= s.Vertices; ++i)
  {
    if (s.Triangles[i] <= t)
    {
      error = s.Error[i];
    }
  }
  return error;
}

void ExpectWellFormed(const TOMErrorCurve& curve, uint32_t numberOfTriangles)
{
  EXPECT_EQ(curve.Check(numberOfTriangles), "");
  const std::vector<Sample>& samples = curve.GetSamples();
  ASSERT_FALSE(samples.empty());
  for (size_t i = 1; i < samples.size(); ++i)
  {
    EXPECT_LT(samples[i - 1].Triangles, samples[i].Triangles) << "sample " << i;
    EXPECT_GE(samples[i - 1].Error, samples[i].Error) << "sample " << i;
  }
  EXPECT_EQ(samples.back().Triangles, numberOfTriangles);
  EXPECT_EQ(samples.back().Error, 0.f);
}

TEST(TOMErrorCurve, KeepsEveryCandidateWhenFew)
{
  const Sequence s = MakeSequence(20, 8);
  const TOMErrorCurve curve = s.Curve();
  ExpectWellFormed(curve, s.Triangles[20]);
  ASSERT_EQ(curve.GetSamples().size(), 13u); // vertex counts 8..20
  for (uint32_t i = 8; i <= 20; ++i)
  {
    const Sample& sample = curve.GetSamples()[i - 8];
    EXPECT_EQ(sample.Triangles, s.Triangles[i]);
    EXPECT_EQ(sample.Error, s.Error[i]);
  }
  // Exact at every vertex count: the polyline goes through all of them.
  for (uint32_t i = 8; i <= 20; ++i)
  {
    EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(s.Triangles[i]), s.Error[i]);
  }
}

TEST(TOMErrorCurve, EqualTriangleCountsKeepTheFinestMesh)
{
  // Removals that kill no triangle (pair contractions) repeat a triangle
  // count; the finest mesh with that count (lowest error) is the one traversal
  // would pick, so it is the one kept.
  const Sequence s = MakeSequence(30, 5, 3);
  const TOMErrorCurve curve = s.Curve();
  ExpectWellFormed(curve, s.Triangles[30]);
  for (const Sample& sample : curve.GetSamples())
  {
    uint32_t finest = s.Base;
    for (uint32_t i = s.Base; i <= s.Vertices; ++i)
    {
      finest = s.Triangles[i] == sample.Triangles ? i : finest;
    }
    EXPECT_EQ(sample.Error, finest == s.Vertices ? 0.f : s.Error[finest]);
  }
}

TEST(TOMErrorCurve, SampleBoundAndCoverage)
{
  const Sequence s = MakeSequence(100000, 100, 7);
  const uint32_t full = s.Triangles[s.Vertices];
  const uint32_t base = s.Triangles[s.Base];
  for (const unsigned maxSamples : { 0u, 1u, 2u, 3u, 5u, 10u, 24u, 48u, 64u })
  {
    SCOPED_TRACE(::testing::Message() << "maxSamples " << maxSamples);
    const TOMErrorCurve curve = s.Curve(maxSamples);
    ExpectWellFormed(curve, full);
    const std::vector<Sample>& samples = curve.GetSamples();
    EXPECT_LE(samples.size(), std::max(2u, maxSamples));
    EXPECT_EQ(samples.front().Triangles, base);
    EXPECT_EQ(samples.front().Error, s.Error[s.Base]);
    if (maxSamples >= 10)
    {
      EXPECT_EQ(samples.size(), maxSamples); // the budget is used
    }
  }

  const TOMErrorCurve curve = s.Curve(48);
  const std::vector<Sample>& samples = curve.GetSamples();
  // Triangle count covered: no gap wider than a constant ratio, so the
  // fine end (tiny errors, most of the triangles) is not a single segment.
  for (size_t i = 1; i < samples.size(); ++i)
  {
    EXPECT_LE(double(samples[i].Triangles) / samples[i - 1].Triangles, 1.6) << "sample " << i;
  }
  // Error covered: no segment drops more than a tenth of the range, so the
  // steep coarse end is refined.
  for (size_t i = 1; i < samples.size(); ++i)
  {
    EXPECT_LE(samples[i - 1].Error - samples[i].Error, 0.1 * samples.front().Error)
      << "sample " << i;
  }
  // And the polyline stays close to the true (step) curve everywhere.
  double worst = 0.0;
  for (uint32_t i = s.Base; i <= s.Vertices; i += 37)
  {
    worst = std::max(worst,
      std::abs(curve.GetErrorForTriangles(s.Triangles[i]) - TrueError(s, s.Triangles[i])));
  }
  EXPECT_LT(worst, 0.02 * samples.front().Error);
}

TEST(TOMErrorCurve, RepairsMalformedInput)
{
  Sequence s = MakeSequence(200, 10);
  s.Error[50] = std::numeric_limits<float>::quiet_NaN();
  s.Error[60] = 1e6f;  // an increase
  s.Error[70] = -1.f;  // negative
  s.Error[200] = 5.f;  // the full mesh is the reference: forced to 0
  s.Triangles[80] = 3; // a triangle count going down
  const TOMErrorCurve curve = s.Curve(16);
  ExpectWellFormed(curve, s.Triangles[200]);
  EXPECT_LE(curve.GetSamples().size(), 16u);

  EXPECT_TRUE(TOMErrorCurve::FromVertexErrors(nullptr, s.Triangles.data(), 200, 10).IsEmpty());
  EXPECT_TRUE(TOMErrorCurve::FromVertexErrors(s.Error.data(), nullptr, 200, 10).IsEmpty());
}

TEST(TOMErrorCurve, DegenerateSequences)
{
  // Nothing was simplified: the base is the full mesh, a single sample.
  const std::vector<float> error = { 7.f, 7.f, 7.f };
  const std::vector<uint32_t> triangles = { 1, 1, 1 };
  const TOMErrorCurve same = TOMErrorCurve::FromVertexErrors(error.data(), triangles.data(), 2, 2);
  ASSERT_EQ(same.GetSamples().size(), 1u);
  EXPECT_EQ(same.GetSamples()[0].Triangles, 1u);
  EXPECT_EQ(same.GetSamples()[0].Error, 0.f);
  EXPECT_EQ(same.Check(1), "");
  EXPECT_EQ(same.GetTrianglesForError(0.0), 1u);
  EXPECT_EQ(same.GetErrorForTriangles(0), 0.0);

  // Base vertex count above the vertex count is clamped.
  const TOMErrorCurve clamped =
    TOMErrorCurve::FromVertexErrors(error.data(), triangles.data(), 2, 9);
  EXPECT_EQ(clamped.GetSamples().size(), 1u);
}

TEST(TOMErrorCurve, Interpolation)
{
  const TOMErrorCurve curve({ { 10, 4.f }, { 20, 2.f }, { 40, 0.f } });
  EXPECT_EQ(curve.Check(40), "");
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(0), 4.0); // clamped below the base
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(10), 4.0);
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(15), 3.0);
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(20), 2.0);
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(30), 1.0);
  EXPECT_NEAR(curve.GetErrorForTriangles(39), 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(40), 0.0);
  EXPECT_DOUBLE_EQ(curve.GetErrorForTriangles(1000), 0.0); // clamped above the full mesh

  const TOMErrorCurve empty;
  EXPECT_TRUE(empty.IsEmpty());
  EXPECT_EQ(empty.GetErrorForTriangles(5), 0.0);
  EXPECT_EQ(empty.GetTrianglesForError(1.0), 0u);
  EXPECT_EQ(empty.Check(100), "");
}

TEST(TOMErrorCurve, Inverse)
{
  const TOMErrorCurve curve({ { 10, 4.f }, { 20, 2.f }, { 40, 0.f } });
  EXPECT_EQ(curve.GetTrianglesForError(4.0), 10u); // the base meets it
  EXPECT_EQ(curve.GetTrianglesForError(100.0), 10u);
  EXPECT_EQ(curve.GetTrianglesForError(3.0), 15u);
  EXPECT_EQ(curve.GetTrianglesForError(2.5), 18u); // 17.5 -> the next whole count
  EXPECT_EQ(curve.GetTrianglesForError(2.0), 20u);
  EXPECT_EQ(curve.GetTrianglesForError(1.0), 30u);
  EXPECT_EQ(curve.GetTrianglesForError(0.0), 40u);
  EXPECT_EQ(curve.GetTrianglesForError(-1.0), 40u);
  EXPECT_EQ(curve.GetTrianglesForError(std::nan("")), 40u);
  EXPECT_EQ(curve.GetTrianglesForError(-std::numeric_limits<double>::infinity()), 40u);
  EXPECT_EQ(curve.GetTrianglesForError(std::numeric_limits<double>::infinity()), 10u);
}

TEST(TOMErrorCurve, InverseIsTheSmallestCountWithinTheBound)
{
  const Sequence s = MakeSequence(5000, 40, 5);
  const TOMErrorCurve curve = s.Curve(32);
  const std::vector<Sample>& samples = curve.GetSamples();
  const uint32_t first = samples.front().Triangles;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> pick(0.0, 1.2 * samples.front().Error);
  for (int trial = 0; trial < 5000; ++trial)
  {
    const double bound = trial < 100 ? samples[trial % samples.size()].Error : pick(rng);
    const uint32_t t = curve.GetTrianglesForError(bound);
    ASSERT_LE(curve.GetErrorForTriangles(t), bound) << "bound " << bound;
    if (t > first)
    {
      ASSERT_GT(curve.GetErrorForTriangles(t - 1), bound) << "bound " << bound;
    }
  }
}

TEST(TOMErrorCurve, Monotonicity)
{
  const Sequence s = MakeSequence(3000, 30);
  const TOMErrorCurve curve = s.Curve(20);
  const uint32_t full = s.Triangles[s.Vertices];
  double previous = std::numeric_limits<double>::infinity();
  for (uint32_t t = 0; t <= full + 10; ++t)
  {
    const double e = curve.GetErrorForTriangles(t);
    ASSERT_LE(e, previous) << "triangles " << t;
    previous = e;
  }
  uint32_t previousCount = 0;
  for (double e = 1.1 * curve.GetSamples().front().Error; e >= 0.0; e -= 0.01)
  {
    const uint32_t t = curve.GetTrianglesForError(e);
    ASSERT_GE(t, previousCount) << "error " << e;
    previousCount = t;
  }
}

TEST(TOMErrorCurve, CheckRejectsMalformedCurves)
{
  auto check = [](std::vector<Sample> samples, uint32_t triangles) {
    return TOMErrorCurve(std::move(samples)).Check(triangles);
  };
  auto has = [](const std::string& message, const char* part) {
    return message.find(part) != std::string::npos;
  };
  EXPECT_EQ(check({ { 5, 2.f }, { 9, 1.f }, { 12, 0.f } }, 12), "");

  std::string m = check({ { 9, 2.f }, { 5, 1.f }, { 12, 0.f } }, 12);
  EXPECT_TRUE(has(m, "sample 1") && has(m, "does not increase")) << m;
  m = check({ { 5, 2.f }, { 5, 1.f }, { 12, 0.f } }, 12);
  EXPECT_TRUE(has(m, "sample 1") && has(m, "does not increase")) << m;
  m = check({ { 5, 1.f }, { 9, 2.f }, { 12, 0.f } }, 12);
  EXPECT_TRUE(has(m, "sample 1") && has(m, "increases")) << m;
  m = check({ { 5, std::numeric_limits<float>::quiet_NaN() }, { 12, 0.f } }, 12);
  EXPECT_TRUE(has(m, "sample 0") && has(m, "finite non-negative")) << m;
  m = check({ { 5, std::numeric_limits<float>::infinity() }, { 12, 0.f } }, 12);
  EXPECT_TRUE(has(m, "sample 0") && has(m, "finite non-negative")) << m;
  m = check({ { 5, 1.f }, { 12, -0.5f } }, 12);
  EXPECT_TRUE(has(m, "sample 1") && has(m, "finite non-negative")) << m;
  m = check({ { 5, 1.f }, { 20, 0.f } }, 12);
  EXPECT_TRUE(has(m, "sample 1") && has(m, "more than the mesh's 12")) << m;
  m = check({ { 5, 1.f }, { 10, 0.f } }, 12);
  EXPECT_TRUE(has(m, "last sample") && has(m, "not the full mesh's 12")) << m;
  m = check({ { 5, 1.f }, { 12, 0.25f } }, 12);
  EXPECT_TRUE(has(m, "last sample") && has(m, "not 0")) << m;
}
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of the benchmark support library's pieces that have no rendering:
// statistics, policy comparison, JSON output, argument parsing, the W1 specification and Loop
// subdivision.
#include "BenchmarkArguments.h"
#include "BenchmarkJson.h"
#include "BenchmarkStatistics.h"
#include "LoopSubdivision.h"
#include "PolicyComparison.h"
#include "W1SceneSpecification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using namespace timecritical::benchmark;

TEST(BenchmarkStatistics, MedianMeanPercentile)
{
  EXPECT_DOUBLE_EQ(Median({ 3.0, 1.0, 2.0 }), 2.0);
  EXPECT_DOUBLE_EQ(Median({ 4.0, 1.0, 3.0, 2.0 }), 2.5);
  EXPECT_DOUBLE_EQ(Mean({ 1.0, 2.0, 6.0 }), 3.0);
  EXPECT_DOUBLE_EQ(Percentile({ 10.0, 0.0, 20.0 }, 50.0), 10.0);
  EXPECT_DOUBLE_EQ(Percentile({ 0.0, 10.0 }, 25.0), 2.5);
  EXPECT_DOUBLE_EQ(Percentile({ 5.0, 1.0 }, 100.0), 5.0);
  EXPECT_DOUBLE_EQ(Maximum({ 5.0, 7.0, 1.0 }), 7.0);
  EXPECT_TRUE(std::isnan(Median({})));
  EXPECT_TRUE(std::isnan(Mean({})));
  EXPECT_TRUE(std::isnan(Percentile({}, 50.0)));
  EXPECT_THROW(Percentile({ 1.0 }, 101.0), std::invalid_argument);
}

TEST(BenchmarkJson, TextPieces)
{
  EXPECT_EQ(Number(0.125), "0.125");
  EXPECT_EQ(Number(std::nan("")), "null");
  EXPECT_EQ(Quoted("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
  const std::vector<int> records = { 1, 2 };
  EXPECT_EQ(Array(records, [](int r) { return 0.5 * r; }), "[0.5,1]");
}

TEST(BenchmarkJson, OrderedTree)
{
  JsonValue tree = JsonValue::Object();
  tree.Set("b", 1).Set("a", JsonValue::Array().Push(true).Push("x")).Set("n", std::nan(""));
  std::ostringstream out;
  tree.Write(out);
  EXPECT_EQ(out.str(), "{\n  \"b\": 1,\n  \"a\": [\n    true,\n    \"x\"\n  ],\n  \"n\": null\n}");
  JsonValue number(2.0);
  EXPECT_THROW(number.Set("k", 1), std::logic_error);
  EXPECT_THROW(JsonValue::Object().Push(1), std::logic_error);
}

struct Parsed
{
  bool Quick = false, FramesGiven = false;
  int Frames = 240;
  unsigned Seed = 7;
  double Target = 0.1;
  std::string Output = "out";
  std::vector<std::string> Meshes;
  std::string File;
};

Parsed Parse(std::vector<std::string> words)
{
  words.insert(words.begin(), "program");
  std::vector<char*> argv;
  for (auto& word : words)
  {
    argv.push_back(&word[0]);
  }
  Parsed parsed;
  BenchmarkArguments arguments(static_cast<int>(argv.size()), argv.data());
  arguments.AddFlag("--quick", parsed.Quick);
  arguments.AddInteger("--frames", parsed.Frames, 10, 1000, &parsed.FramesGiven);
  arguments.AddUnsigned("--seed", parsed.Seed);
  arguments.AddNumber("--target", parsed.Target, [](double x) { return x > 0.0; });
  arguments.AddText("--output", parsed.Output);
  arguments.AddRepeatedText("--mesh", parsed.Meshes);
  arguments.AddPositional(parsed.File);
  arguments.Parse();
  return parsed;
}

std::string ErrorOf(const std::vector<std::string>& words)
{
  try
  {
    Parse(words);
  }
  catch (const std::runtime_error& error)
  {
    return error.what();
  }
  return "no error";
}

TEST(BenchmarkArguments, SetsWhatIsGiven)
{
  const Parsed defaults = Parse({});
  EXPECT_FALSE(defaults.Quick);
  EXPECT_FALSE(defaults.FramesGiven);
  EXPECT_EQ(defaults.Frames, 240);
  const Parsed p =
    Parse({ "--quick", "--frames", "30", "--seed", "5", "--target", "0.05", "--output", "d" });
  EXPECT_TRUE(p.Quick);
  EXPECT_TRUE(p.FramesGiven);
  EXPECT_EQ(p.Frames, 30);
  EXPECT_EQ(p.Seed, 5u);
  EXPECT_DOUBLE_EQ(p.Target, 0.05);
  EXPECT_EQ(p.Output, "d");
  EXPECT_EQ(Parse({ "--mesh", "a", "--mesh", "b" }).Meshes, (std::vector<std::string>{ "a", "b" }));
  EXPECT_EQ(Parse({ "--quick", "mesh.obj" }).File, "mesh.obj");
}

TEST(BenchmarkArguments, NamesTheMistake)
{
  EXPECT_EQ(ErrorOf({ "--frames" }), "missing value after --frames");
  EXPECT_EQ(ErrorOf({ "--frames", "9" }), "bad value for --frames: 9");
  EXPECT_EQ(ErrorOf({ "--frames", "12x" }), "bad value for --frames: 12x");
  EXPECT_EQ(ErrorOf({ "--target", "0" }), "bad value for --target: 0");
  EXPECT_EQ(ErrorOf({ "--target", "inf" }), "bad value for --target: inf");
  EXPECT_EQ(ErrorOf({ "--seed", "-1" }), "bad value for --seed: -1");
  EXPECT_EQ(ErrorOf({ "--fram", "30" }), "unknown option --fram (see --help)");
  EXPECT_EQ(ErrorOf({ "one", "two" }), "unknown option two (see --help)");
}

TEST(W1SceneSpecification, CompiledInFileIsComplete)
{
  const W1SceneSpecification& spec = W1SceneSpecification::Get();
  EXPECT_EQ(spec.DefaultObjects, 529);
  EXPECT_EQ(spec.DefaultFrames, 240);
  EXPECT_EQ(spec.DefaultSeed, 20001u);
  EXPECT_EQ(spec.WindowSize, 512);
  EXPECT_GT(spec.Gap, 0.0);
  EXPECT_GT(spec.KeyB, 0.0);
  EXPECT_LT(spec.KeyB, 1.0);
}

TEST(W1SceneSpecification, RejectsBadText)
{
  EXPECT_THROW(W1SceneSpecification::Parse("not json"), std::runtime_error);
  EXPECT_THROW(W1SceneSpecification::Parse("{}"), std::runtime_error);
  // One field of the right name but the wrong type.
  std::string text = "{\"defaults\": {\"seed\": \"x\", \"objects\": 1, \"frames\": 2}}";
  try
  {
    W1SceneSpecification::Parse(text);
    FAIL() << "a string seed was accepted";
  }
  catch (const std::runtime_error& error)
  {
    EXPECT_NE(std::string(error.what()).find("defaults.seed"), std::string::npos) << error.what();
  }
}

TEST(LoopSubdivision, QuadruplesTheTriangles)
{
  const auto sphere = timecritical::testing::MakeUVSphere(6, 8);
  const auto once = LoopSubdivide(sphere, 1);
  EXPECT_EQ(once.NumberOfTriangles(), 4 * sphere.NumberOfTriangles());
  // A closed mesh gains one point per edge: E = 3T/2.
  EXPECT_EQ(once.NumberOfPoints(), sphere.NumberOfPoints() + 3 * sphere.NumberOfTriangles() / 2);
  EXPECT_EQ(LoopSubdivide(sphere, 0).NumberOfTriangles(), sphere.NumberOfTriangles());
  EXPECT_THROW(LoopSubdivide(sphere, -1), std::invalid_argument);
}

struct ExtendedFrame : PolicyFrame
{
  double Extra = 0.0;
};

TEST(PolicyComparison, StatisticsOfTheCommonFields)
{
  std::vector<ExtendedFrame> frames(4);
  const double measured[] = { 0.10, 0.20, 0.05, 0.15 };
  for (size_t i = 0; i < frames.size(); ++i)
  {
    frames[i].Measured = measured[i];
    frames[i].Triangles = 100.0 * static_cast<double>(i + 1);
  }
  frames[0].Predicted = 0.11; // error 10%
  frames[1].Predicted = 0.10; // error 50%
  frames[2].PSNR = 30.0;
  frames[3].PSNR = 99.0;
  frames[3].Identical = true;
  const PolicyStatistics s = ComputePolicyStatistics(frames, 0.1);
  EXPECT_EQ(s.Frames, 4);
  EXPECT_DOUBLE_EQ(s.Mean, 0.125);
  EXPECT_DOUBLE_EQ(s.Median, 0.125);
  EXPECT_DOUBLE_EQ(s.Min, 0.05);
  EXPECT_DOUBLE_EQ(s.Max, 0.20);
  EXPECT_NEAR(s.CV, std::sqrt(0.0125 / 4.0) / 0.125, 1e-12);
  EXPECT_DOUBLE_EQ(s.ShareWithin, 0.5); // 0.10 and 0.05 are <= 0.11
  EXPECT_NEAR(s.PredictionError, 0.30, 1e-12);
  EXPECT_NEAR(s.PredictionErrorMax, 0.50, 1e-12);
  EXPECT_DOUBLE_EQ(s.TrianglesMean, 250.0);
  EXPECT_DOUBLE_EQ(s.TrianglesMedian, 250.0);
  EXPECT_EQ(s.PSNRFrames, 2);
  EXPECT_EQ(s.IdenticalFrames, 1);
  EXPECT_DOUBLE_EQ(s.PSNRMean, 64.5);
  EXPECT_DOUBLE_EQ(s.PSNRMin, 30.0);
}

TEST(PolicyComparison, EmptyRunIsNaN)
{
  const PolicyStatistics s = ComputePolicyStatistics(std::vector<PolicyFrame>(), 0.1);
  EXPECT_EQ(s.Frames, 0);
  EXPECT_TRUE(std::isnan(s.Mean));
  EXPECT_TRUE(std::isnan(s.ShareWithin));
  EXPECT_NE(PolicyStatisticsJsonFields(s).find("\"mean\": null"), std::string::npos);
}

TEST(PolicyComparison, CellsAndFrameArrays)
{
  EXPECT_EQ(MillisecondsCell(0.0123), "12.3");
  EXPECT_EQ(MillisecondsCell(0.0123, 3), "12.300");
  EXPECT_EQ(MillisecondsCell(std::nan("")), "-");
  EXPECT_EQ(PercentCell(0.256), "25.6%");
  EXPECT_EQ(DecibelCell(41.234), "41.23");
  EXPECT_EQ(DecibelCell(std::nan("")), "-");
  std::vector<PolicyFrame> frames(1);
  frames[0].Measured = 0.5;
  frames[0].Triangles = 7.0;
  const std::string json = PolicyFramesJsonFields(frames, ", ");
  EXPECT_EQ(json.find("\"measured\": [0.5]"), 0u);
  EXPECT_NE(json.find(", \"triangles\": [7]"), std::string::npos);
  EXPECT_NE(json.find(", \"psnr\": [null]"), std::string::npos);
}
}

// SPDX-License-Identifier: BSD-3-Clause
// ProgressReporter: forwards fractions clamped to [0, 1], and once the
// callback asks to stop, stops calling it and keeps answering "stop".

#include "ProgressReporter.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

namespace
{
using timecritical::collapse::ProgressReporter;

TEST(ProgressReporter, WithoutCallbackNeverStops)
{
  const std::function<bool(double)> none;
  ProgressReporter progress(none);
  EXPECT_TRUE(progress.Report(0.5));
  EXPECT_FALSE(progress.WasStopped());
}

TEST(ProgressReporter, ClampsTheFraction)
{
  std::vector<double> seen;
  const std::function<bool(double)> callback = [&seen](double f) {
    seen.push_back(f);
    return true;
  };
  ProgressReporter progress(callback);
  EXPECT_TRUE(progress.Report(-1.0));
  EXPECT_TRUE(progress.Report(0.25));
  EXPECT_TRUE(progress.Report(7.0));
  EXPECT_EQ(seen, (std::vector<double>{ 0.0, 0.25, 1.0 }));
}

TEST(ProgressReporter, StopIsRememberedAndTheCallbackNotCalledAgain)
{
  int calls = 0;
  const std::function<bool(double)> callback = [&calls](double) { return ++calls < 2; };
  ProgressReporter progress(callback);
  EXPECT_TRUE(progress.Report(0.1));
  EXPECT_FALSE(progress.Report(0.2));
  EXPECT_TRUE(progress.WasStopped());
  EXPECT_FALSE(progress.Report(0.3));
  EXPECT_EQ(calls, 2);
}
}

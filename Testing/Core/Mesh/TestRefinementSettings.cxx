// SPDX-License-Identifier: BSD-3-Clause
// Tests of RefinementSettings: the one numbering of the modes, the defaults,
// and the checker's rule and message for every setting.
#include "RefinementSettings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace timecritical;

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();
}

TEST(RefinementSettings, ModesAreNumberedBudgetFirst)
{
  EXPECT_EQ(RefinementModeBudget, 0);
  EXPECT_EQ(RefinementModeFixedAccuracy, 1);
  EXPECT_EQ(static_cast<int>(RefinementMode::Budget), 0);
  EXPECT_EQ(static_cast<int>(RefinementMode::FixedAccuracy), 1);
  EXPECT_STREQ(RefinementModeName(RefinementMode::Budget), "BUDGET");
  EXPECT_STREQ(RefinementModeName(RefinementMode::FixedAccuracy), "FIXED_ACCURACY");
}

TEST(RefinementSettings, DefaultsAreValid)
{
  const RefinementSettings settings;
  EXPECT_EQ(settings.Mode, RefinementMode::Budget);
  EXPECT_EQ(settings.PixelThreshold, 1.0);
  EXPECT_TRUE(settings.BackFaceSimplification);
  EXPECT_TRUE(settings.SilhouetteRefinement);
  EXPECT_EQ(settings.SilhouetteFactor, 0.25);
  EXPECT_TRUE(settings.HighlightRefinement);
  EXPECT_EQ(settings.HighlightFactor, 0.5);
  EXPECT_EQ(settings.TimeLimit, 0.0);
  EXPECT_EQ(settings.TriangleBudget, 10000);
  const SettingCheck check = CheckRefinementSettings(settings);
  EXPECT_TRUE(check.Valid);
  EXPECT_TRUE(check.Message.empty());
}

TEST(RefinementSettings, NonNegativeRejectsNegativeNaNAndInfinity)
{
  for (double value : { 0.0, 1e-300, 1.0, 1e300 })
  {
    EXPECT_TRUE(CheckNonNegative("PixelThreshold", value)) << value;
  }
  for (double value : { -1.0, -1e-300, NaN, Inf, -Inf })
  {
    const SettingCheck check = CheckNonNegative("PixelThreshold", value);
    EXPECT_FALSE(check) << value;
    EXPECT_EQ(check.Message.rfind("PixelThreshold must be a finite number >= 0, not ", 0), 0u)
      << check.Message;
  }
  EXPECT_EQ(CheckNonNegative("TimeLimit", -2.5).Message,
    "TimeLimit must be a finite number >= 0, not -2.5");
}

TEST(RefinementSettings, PositiveRejectsZero)
{
  EXPECT_TRUE(CheckPositive("ViewingDistance", 0.5));
  for (double value : { 0.0, -1.0, NaN, Inf })
  {
    EXPECT_FALSE(CheckPositive("ViewingDistance", value)) << value;
  }
  EXPECT_EQ(CheckPositive("ViewingDistance", 0.0).Message,
    "ViewingDistance must be a finite number > 0, not 0");
}

TEST(RefinementSettings, RangeIsClosed)
{
  EXPECT_TRUE(CheckRange("SafetyFactor", 0.0, 0.0, 10.0));
  EXPECT_TRUE(CheckRange("SafetyFactor", 10.0, 0.0, 10.0));
  EXPECT_FALSE(CheckRange("SafetyFactor", 10.5, 0.0, 10.0));
  EXPECT_FALSE(CheckRange("SafetyFactor", NaN, 0.0, 10.0));
  EXPECT_EQ(CheckRange("SafetyFactor", -1.0, 0.0, 10.0).Message,
    "SafetyFactor must be in [0, 10], not -1");
}

TEST(RefinementSettings, FactorsAreInHalfOpenUnitInterval)
{
  for (double value : { 1e-9, 0.01, 0.25, 1.0 })
  {
    EXPECT_TRUE(CheckFactor("SilhouetteFactor", value)) << value;
  }
  for (double value : { 0.0, -0.5, 1.5, NaN, Inf })
  {
    EXPECT_FALSE(CheckFactor("HighlightFactor", value)) << value;
  }
  EXPECT_EQ(
    CheckFactor("HighlightFactor", 1.5).Message, "HighlightFactor must be in (0, 1], not 1.5");
}

TEST(RefinementSettings, TriangleBudgetIsANonNegative32BitCount)
{
  EXPECT_TRUE(CheckTriangleBudget("TriangleBudget", 0));
  EXPECT_TRUE(CheckTriangleBudget("TriangleBudget", MaximumTriangleBudget));
  EXPECT_FALSE(CheckTriangleBudget("TriangleBudget", -1));
  EXPECT_FALSE(CheckTriangleBudget("TriangleBudget", MaximumTriangleBudget + 1));
  EXPECT_EQ(CheckTriangleBudget("TriangleBudget", -1).Message,
    "TriangleBudget must be an integer in [0, 2147483647], not -1");
}

TEST(RefinementSettings, ModesAreCheckedAndClamped)
{
  EXPECT_TRUE(CheckRefinementMode("RefinementMode", 0));
  EXPECT_TRUE(CheckRefinementMode("RefinementMode", 1));
  EXPECT_FALSE(CheckRefinementMode("RefinementMode", 2));
  EXPECT_EQ(CheckRefinementMode("RefinementMode", -1).Message,
    "RefinementMode must be 0 (budget) or 1 (fixed accuracy), not -1");
  EXPECT_EQ(ClampRefinementMode(-5), RefinementMode::Budget);
  EXPECT_EQ(ClampRefinementMode(0), RefinementMode::Budget);
  EXPECT_EQ(ClampRefinementMode(1), RefinementMode::FixedAccuracy);
  EXPECT_EQ(ClampRefinementMode(7), RefinementMode::FixedAccuracy);
}

TEST(RefinementSettings, WholeSettingsReportTheFirstBadValue)
{
  RefinementSettings settings;
  settings.SilhouetteFactor = 0.0;
  settings.TimeLimit = -1.0;
  SettingCheck check = CheckRefinementSettings(settings);
  EXPECT_FALSE(check);
  EXPECT_EQ(check.Message, "SilhouetteFactor must be in (0, 1], not 0");
  settings.SilhouetteFactor = 1.0;
  check = CheckRefinementSettings(settings);
  EXPECT_EQ(check.Message, "TimeLimit must be a finite number >= 0, not -1");
  settings.TimeLimit = 0.0;
  settings.PixelThreshold = NaN;
  EXPECT_FALSE(CheckRefinementSettings(settings));
  settings.PixelThreshold = 0.0;
  settings.TriangleBudget = -3;
  EXPECT_EQ(CheckRefinementSettings(settings).Message,
    "TriangleBudget must be an integer in [0, 2147483647], not -3");
  settings.TriangleBudget = 0;
  EXPECT_TRUE(CheckRefinementSettings(settings));
}

// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_TestImageCompare_h
#define timecritical_TestImageCompare_h

#include <string>

namespace timecritical
{
namespace testing
{
/// Outcome of comparing an image with its baseline (OpenImageIO's compare).
struct ImageComparison
{
  bool Loaded = false;         ///< both images read and of equal size
  std::string Message;         ///< why not, when !Loaded
  double RMS = 0.0;            ///< root mean square channel difference, in [0,1]
  double PSNR = 0.0;           ///< dB
  double MaxError = 0.0;       ///< largest channel difference, in [0,1]
  double FailingFraction = 0.0; ///< share of channel values differing by more than the threshold
};

/// Thresholds of an image-baseline test.
struct ImageTolerance
{
  double PixelThreshold = 0.0;  ///< a channel differing by more than this counts as failing
  double MaxFailingFraction = 0.0;
  double MaxRMS = 0.0;
};

/// Compares two image files with OpenImageIO.
ImageComparison CompareImages(const std::string& image, const std::string& baseline,
  double pixelThreshold);

/// True when the comparison is within the tolerance.
bool Passes(const ImageComparison& result, const ImageTolerance& tolerance);

/// One line describing a comparison, for test failure messages.
std::string Describe(const ImageComparison& result);

/// True when TIMECRITICAL_UPDATE_BASELINES=1: the tests (re)write their baselines.
bool UpdatingBaselines();
}
}

#endif

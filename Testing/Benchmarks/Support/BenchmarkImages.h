// SPDX-License-Identifier: BSD-3-Clause
#ifndef timecritical_BenchmarkImages_h
#define timecritical_BenchmarkImages_h

/**
 * Frame capture, comparison (PSNR with OpenImageIO) and PNG key frames of the
 * rendering benchmarks, all on WindowSize x WindowSize RGB images.
 */
#include "BenchmarkTiming.h"

#include <filesystem>
#include <vector>

class vtkRenderWindow;

namespace timecritical
{
namespace benchmark
{
/// Identical images have infinite PSNR; a finite cap keeps means meaningful.
constexpr double PSNRCap = 99.0;

using Image = std::vector<unsigned char>; ///< WindowSize^2 RGB, bottom row first

/// The front or back buffer of `window`; throws when it is not WindowSize^2 RGB.
Image Capture(vtkRenderWindow* window, bool front);

struct Comparison
{
  double PSNR = NaN; ///< capped at PSNRCap
  bool Identical = false;
};

Comparison Compare(Image& image, Image& reference);

void WritePNG(Image& image, const std::filesystem::path& path);
}
}

#endif

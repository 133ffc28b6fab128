// SPDX-License-Identifier: BSD-3-Clause
#include "TestImageCompare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdlib>
#include <sstream>

namespace timecritical
{
namespace testing
{
ImageComparison CompareImages(
  const std::string& image, const std::string& baseline, double pixelThreshold)
{
  ImageComparison result;
  OIIO::ImageBuf a(image);
  OIIO::ImageBuf b(baseline);
  if (!a.read() || !b.read())
  {
    result.Message = "cannot read " + (a.has_error() ? image : baseline) + ": " +
      (a.has_error() ? a.geterror() : b.geterror());
    return result;
  }
  if (a.spec().width != b.spec().width || a.spec().height != b.spec().height ||
    a.nchannels() != b.nchannels())
  {
    std::ostringstream msg;
    msg << "size differs: " << a.spec().width << "x" << a.spec().height << "x" << a.nchannels()
        << " against " << b.spec().width << "x" << b.spec().height << "x" << b.nchannels();
    result.Message = msg.str();
    return result;
  }
  const auto stats = OIIO::ImageBufAlgo::compare(a, b, static_cast<float>(pixelThreshold),
    static_cast<float>(pixelThreshold), 0.0f, 0.0f);
  // stats.error only says that some value exceeded the failure threshold,
  // which is for the caller to judge; a real failure shows on the buffers.
  if (a.has_error() || b.has_error())
  {
    result.Message = "OpenImageIO compare failed: " + a.geterror() + b.geterror();
    return result;
  }
  result.Loaded = true;
  result.RMS = stats.rms_error;
  result.PSNR = stats.PSNR;
  result.MaxError = stats.maxerror;
  const double values = static_cast<double>(a.spec().width) * a.spec().height * a.nchannels();
  result.FailingFraction = values > 0 ? static_cast<double>(stats.nfail) / values : 0.0;
  return result;
}

bool Passes(const ImageComparison& result, const ImageTolerance& tolerance)
{
  return result.Loaded && result.FailingFraction <= tolerance.MaxFailingFraction &&
    result.RMS <= tolerance.MaxRMS;
}

std::string Describe(const ImageComparison& result)
{
  if (!result.Loaded)
  {
    return result.Message;
  }
  std::ostringstream msg;
  msg << "RMS " << result.RMS << ", PSNR " << result.PSNR << " dB, max " << result.MaxError
      << ", failing " << 100.0 * result.FailingFraction << "%";
  return msg.str();
}

bool UpdatingBaselines()
{
  const char* update = std::getenv("TIMECRITICAL_UPDATE_BASELINES");
  return update && std::string(update) == "1";
}
}
}

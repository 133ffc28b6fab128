// SPDX-License-Identifier: BSD-3-Clause
#include "BenchmarkImages.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
Image Capture(vtkRenderWindow* window, bool front)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  window->GetPixelData(0, 0, WindowSize - 1, WindowSize - 1, front ? 1 : 0, pixels);
  if (pixels->GetNumberOfComponents() != 3 ||
    pixels->GetNumberOfTuples() != static_cast<vtkIdType>(WindowSize) * WindowSize)
  {
    throw std::runtime_error("GetPixelData returned an unexpected image");
  }
  const unsigned char* data = pixels->GetPointer(0);
  return Image(data, data + 3 * static_cast<size_t>(WindowSize) * WindowSize);
}

Comparison Compare(Image& image, Image& reference)
{
  const OIIO::ImageSpec spec(WindowSize, WindowSize, 3, OIIO::TypeDesc::UINT8);
  const OIIO::ImageBuf a(spec, image.data());
  const OIIO::ImageBuf b(spec, reference.data());
  // One thread: the comparison runs between timed frames and must not leave
  // a pool of busy threads behind on a 2-core machine.
  const auto result = OIIO::ImageBufAlgo::compare(a, b, 1.0f, 1.0f, OIIO::ROI(), 1);
  if (a.has_error() || b.has_error())
  {
    throw std::runtime_error("OpenImageIO compare failed: " + a.geterror() + b.geterror());
  }
  Comparison comparison;
  comparison.Identical = result.rms_error == 0.0;
  comparison.PSNR = comparison.Identical ? PSNRCap : std::min(result.PSNR, PSNRCap);
  return comparison;
}

void WritePNG(Image& image, const std::filesystem::path& path)
{
  vtkNew<vtkUnsignedCharArray> pixels;
  pixels->SetNumberOfComponents(3);
  pixels->SetArray(image.data(), static_cast<vtkIdType>(image.size()), 1); // 1: do not free
  vtkNew<vtkImageData> data;
  data->SetDimensions(WindowSize, WindowSize, 1);
  data->GetPointData()->SetScalars(pixels);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.string().c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    throw std::runtime_error("cannot write " + path.string());
  }
}
}
}

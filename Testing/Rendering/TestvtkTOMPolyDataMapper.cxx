// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTOMPolyDataMapper: image baselines of TOM resolutions, rendered
// two ways, by vtkTOMPolyDataMapper (index buffer from the traversal core) and
// by vtkExtractTOMResolution feeding VTK's own mapper; both must match the same
// baseline. Then the thresholds' sensitivity, and non-TOM input.
//
// Thresholds: a channel value differing by more than 0.05 (13 of 255 levels)
// counts as failing; at most 0.1% of channel values may fail and the RMS must
// stay below 0.005. The same Mesa llvmpipe renders identically run to run, so
// a pass needs no slack at all here; the margin absorbs rasterization
// differences of other Mesa versions along silhouettes. A wrong resolution
// changes thousands of silhouette and shading pixels: the test below checks
// that neighbouring resolutions (50% against 25%) do fail these thresholds.
#include "RenderTestSupport.h"
#include "TestImageCompare.h"
#include "vtkExtractTOMResolution.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMPolyDataMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace
{
const timecritical::testing::ImageTolerance Tolerance{ 0.05, 0.001, 0.005 };
constexpr double PixelThreshold = 0.05;

// A deterministic bumpy sphere: enough detail for every resolution to show.
vtkSmartPointer<vtkPolyData> MakeBumpySphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(160);
  sphere->SetPhiResolution(120);
  sphere->Update();
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->DeepCopy(sphere->GetOutput());
  vtkPoints* points = data->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    const double bump = 1.0 + 0.08 * std::sin(9.0 * p[0]) * std::sin(7.0 * p[1]) * std::cos(5.0 * p[2]);
    points->SetPoint(i, p[0] * bump, p[1] * bump, p[2] * bump);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(data);
  normals->SplittingOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

vtkPolyData* SharedTOM()
{
  static vtkSmartPointer<vtkPolyData> tom;
  if (!tom)
  {
    vtkNew<vtkTOMBuilder> builder;
    builder->SetInputData(MakeBumpySphere());
    builder->Update();
    tom = builder->GetOutput();
  }
  return tom;
}

// Renders a mapper's output at 300x300 with a fixed camera into a PNG file.
void RenderToPNG(vtkMapper* mapper, const std::string& path)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.7, 0.45);
  actor->GetProperty()->SetSpecular(0.3);
  // Flat shading shows every triangle, so a wrong resolution cannot hide
  // behind smooth normals.
  actor->GetProperty()->SetInterpolationToFlat();
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(0.1, 0.1, 0.15);
  renderer->GetActiveCamera()->SetPosition(1.5, 1.1, 2.0);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->GetActiveCamera()->SetViewUp(0, 1, 0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  window->Render();
  timecritical::testing::WriteWindowPNG(window, path, true);
}

std::string BaselinePath(double r)
{
  char name[64];
  std::snprintf(name, sizeof(name), "/TOMBumpySphere_r%03d.png", static_cast<int>(std::lround(r * 100)));
  return std::string(TIMECRITICAL_BASELINE_DIR) + name;
}

std::string OutputPath(const std::string& what, double r)
{
  char name[96];
  std::snprintf(name, sizeof(name), "/%s_r%03d.png", what.c_str(), static_cast<int>(std::lround(r * 100)));
  return std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + name;
}

class TOMBaseline : public ::testing::TestWithParam<double>
{
};
}

TEST_P(TOMBaseline, MapperAndExtractionMatchBaseline)
{
  const double r = GetParam();
  vtkNew<vtkTOMPolyDataMapper> tomMapper;
  tomMapper->SetInputData(SharedTOM());
  tomMapper->SetResolution(r);
  const std::string mapperImage = OutputPath("mapper", r);
  RenderToPNG(tomMapper, mapperImage);
  ASSERT_TRUE(tomMapper->GetInputIsTOM());

  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetInputData(SharedTOM());
  extract->SetResolution(r);
  vtkNew<vtkPolyDataMapper> plainMapper;
  plainMapper->SetInputConnection(extract->GetOutputPort());
  const std::string extractImage = OutputPath("extract", r);
  RenderToPNG(plainMapper, extractImage);
  EXPECT_EQ(tomMapper->GetRenderedTriangles(), extract->GetExtractedTriangleCount());

  const std::string baseline = BaselinePath(r);
  if (timecritical::testing::UpdatingBaselines())
  {
    std::ifstream src(extractImage, std::ios::binary);
    std::ofstream dst(baseline, std::ios::binary);
    dst << src.rdbuf();
  }
  const auto mapperResult = timecritical::testing::CompareImages(mapperImage, baseline, PixelThreshold);
  EXPECT_TRUE(timecritical::testing::Passes(mapperResult, Tolerance))
    << "vtkTOMPolyDataMapper at r=" << r << ": " << timecritical::testing::Describe(mapperResult)
    << " (image " << mapperImage << ", baseline " << baseline << ")";
  const auto extractResult = timecritical::testing::CompareImages(extractImage, baseline, PixelThreshold);
  EXPECT_TRUE(timecritical::testing::Passes(extractResult, Tolerance))
    << "vtkExtractTOMResolution at r=" << r << ": " << timecritical::testing::Describe(extractResult)
    << " (image " << extractImage << ", baseline " << baseline << ")";
}

INSTANTIATE_TEST_SUITE_P(Resolutions, TOMBaseline, ::testing::Values(1.0, 0.5, 0.25, 0.1, 0.05));

TEST(TOMBaselineSensitivity, NeighbouringResolutionsFailTheThresholds)
{
  const auto result = timecritical::testing::CompareImages(BaselinePath(0.5), BaselinePath(0.25), PixelThreshold);
  ASSERT_TRUE(result.Loaded) << result.Message;
  EXPECT_FALSE(timecritical::testing::Passes(result, Tolerance))
    << "50% and 25% should be told apart: " << timecritical::testing::Describe(result);
}

TEST(TOMMapper, NonTOMInputRendersAtFullResolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkTOMPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetResolution(0.1);
  RenderToPNG(mapper, std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/nontom.png");
  EXPECT_FALSE(mapper->GetInputIsTOM());
  EXPECT_EQ(mapper->GetRenderedTriangles(), sphere->GetOutput()->GetNumberOfPolys());
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTimeCriticalRenderer's focus (vtkTimeCriticalRendererFocus.cxx):
// for each focus mode (a fixed point, the screen centre, the interactor's
// cursor) and each fall-off (Reddy's eccentricity model, Funkhouser &
// Séquin's linear one), the sphere under the focus gets more resolution than
// an equal sphere far from it; the cursor mode without an interactor uses the
// fixed point; bad values are rejected.
#include "RenderTestSupport.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTimeCriticalRenderer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"

#include <gtest/gtest.h>

#include <limits>

namespace
{
/// Two equal spheres at x = -4 and x = +4 (or 0 and +6 with centre), seen
/// from the front with a pinned cost model and a budget of about 40%.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  double Centers[2];

  Scene(double left, double right)
    : Centers{ left, right }
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    double triangles = 0.0;
    for (unsigned int j = 0; j < 2; ++j)
    {
      vtkNew<vtkTOMBuilder> builder;
      builder->SetInputData(
        timecritical::testing::MakeBumpySurface(1.0, 40, 30, this->Centers[j], 0.0, 0.0, 9.0));
      builder->Update();
      auto tom = vtkSmartPointer<vtkPolyData>::New();
      tom->ShallowCopy(builder->GetOutput());
      triangles += static_cast<double>(tom->GetNumberOfPolys());
      blocks->SetBlock(j, tom);
    }
    this->Mapper->SetInputDataObject(blocks);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(400, 200);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->GetActiveCamera()->SetPosition(0.0, 0.0, 14.0);
    this->Renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
    this->Renderer->ResetCameraClippingRange();
    this->Renderer->AutomaticCalibrationOff();
    this->Renderer->OnlineCalibrationOff();
    this->Renderer->SetCostCoefficients(1e-3, 0.0, 1e-6, 0.0);
    this->Renderer->SetNewObjectCostFactor(1.0);
    this->Renderer->UseVelocityOff();
    // A close display: the spheres lie many visual degrees apart.
    this->Renderer->SetViewingDistance(0.1);
    this->Renderer->SetTargetFrameTime(1e-3 + 0.4e-6 * triangles);
  }

  /// Window pixel of sphere j's centre.
  void Pixel(int j, int& x, int& y)
  {
    this->Renderer->SetWorldPoint(this->Centers[j], 0.0, 0.0, 1.0);
    this->Renderer->WorldToDisplay();
    const double* display = this->Renderer->GetDisplayPoint();
    x = static_cast<int>(display[0] + 0.5);
    y = static_cast<int>(display[1] + 0.5);
  }

  /// Resolution of sphere 0 minus that of sphere 1 after one frame.
  double Difference()
  {
    this->Window->Render();
    return this->Renderer->GetObjectResolution(0) - this->Renderer->GetObjectResolution(1);
  }
};

const int Falloffs[] = { vtkTimeCriticalRenderer::REDDY, vtkTimeCriticalRenderer::LINEAR };

TEST(TimeCriticalRendererFocus, FixedPoint)
{
  for (int falloff : Falloffs)
  {
    SCOPED_TRACE(falloff);
    Scene scene(-4.0, 4.0);
    scene.Renderer->SetFocusFalloff(falloff);
    scene.Renderer->SetFocusModeToFixedPoint();
    int x, y;
    scene.Pixel(0, x, y);
    scene.Renderer->SetFocusPoint(x / 400.0, 0.5);
    EXPECT_GT(scene.Difference(), 0.05);
    scene.Pixel(1, x, y);
    scene.Renderer->SetFocusPoint(x / 400.0, 0.5);
    EXPECT_LT(scene.Difference(), -0.05);
    EXPECT_DOUBLE_EQ(scene.Renderer->GetLastFocus()[0], x / 400.0);
  }
}

TEST(TimeCriticalRendererFocus, ScreenCenter)
{
  for (int falloff : Falloffs)
  {
    SCOPED_TRACE(falloff);
    Scene scene(0.0, 6.0); // sphere 0 in the centre
    scene.Renderer->SetFocusFalloff(falloff);
    scene.Renderer->SetFocusModeToScreenCenter();
    scene.Renderer->SetFocusPoint(0.9, 0.5); // not used in this mode
    EXPECT_GT(scene.Difference(), 0.05);
    EXPECT_DOUBLE_EQ(scene.Renderer->GetLastFocus()[0], 0.5);
  }
}

TEST(TimeCriticalRendererFocus, Cursor)
{
  for (int falloff : Falloffs)
  {
    SCOPED_TRACE(falloff);
    Scene scene(-4.0, 4.0);
    scene.Renderer->SetFocusFalloff(falloff);
    scene.Renderer->SetFocusModeToCursor();
    // No interactor: the fixed point.
    int x, y;
    scene.Pixel(1, x, y);
    scene.Renderer->SetFocusPoint(x / 400.0, 0.5);
    EXPECT_LT(scene.Difference(), -0.05);
    // The cursor over sphere 0, then over sphere 1.
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(scene.Window);
    scene.Pixel(0, x, y);
    interactor->SetEventPosition(x, y);
    EXPECT_GT(scene.Difference(), 0.05);
    EXPECT_NEAR(scene.Renderer->GetLastFocus()[0], x / 400.0, 1e-12);
    scene.Pixel(1, x, y);
    interactor->SetEventPosition(x, y);
    EXPECT_LT(scene.Difference(), -0.05);
  }
}

TEST(TimeCriticalRendererFocus, NoEccentricityNoPreference)
{
  Scene scene(-4.0, 4.0);
  scene.Renderer->UseEccentricityOff();
  int x, y;
  scene.Pixel(0, x, y);
  scene.Renderer->SetFocusPoint(x / 400.0, 0.5);
  EXPECT_NEAR(scene.Difference(), 0.0, 0.02);
}

TEST(TimeCriticalRendererFocus, BadValuesAreRejected)
{
  vtkNew<vtkTimeCriticalRenderer> renderer;
  EXPECT_EQ(renderer->GetFocusMode(), vtkTimeCriticalRenderer::FIXED_POINT);
  EXPECT_EQ(renderer->GetFocusFalloff(), vtkTimeCriticalRenderer::FAMILY_DEFAULT);
  vtkNew<vtkTest::ErrorObserver> errors;
  renderer->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int mode : { -1, 3, 17 })
  {
    errors->Clear();
    renderer->SetFocusMode(mode);
    EXPECT_TRUE(errors->GetError()) << mode;
    EXPECT_EQ(renderer->GetFocusMode(), vtkTimeCriticalRenderer::FIXED_POINT);
    errors->Clear();
    renderer->SetFocusFalloff(mode);
    EXPECT_TRUE(errors->GetError()) << mode;
    EXPECT_EQ(renderer->GetFocusFalloff(), vtkTimeCriticalRenderer::FAMILY_DEFAULT);
  }
  for (double degrees : { 0.0, -5.0, std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::infinity() })
  {
    errors->Clear();
    renderer->SetLinearFalloffDegrees(degrees);
    EXPECT_TRUE(errors->GetError()) << degrees;
    EXPECT_EQ(renderer->GetLinearFalloffDegrees(), 30.0);
  }
}
}

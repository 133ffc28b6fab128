// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTimeCriticalDrawingPass and the renderer's side of it
// (MarkDrawingFinished, MeasuredDrawingTime, CompositingTime): a frame that
// goes on after the drawing (a pass that sleeps, standing for parallel
// compositing and its wait) is measured apart from its drawing, the cost
// model learns the drawing alone, and the compositing time is planned as
// fixed cost.
#include "RenderTestSupport.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTimeCriticalDrawingPass.h"
#include "vtkTimeCriticalRenderer.h"

#include "vtkActor.h"
#include "vtkCameraPass.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkSequencePass.h"
#include "vtkTestErrorObserver.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace
{
namespace tt = timecritical::testing;
constexpr double Pause = 0.06; // seconds the frame goes on after the drawing

/// Stands for compositing: the frame goes on for a while after the drawing.
class PausePass : public vtkRenderPass
{
public:
  static PausePass* New();
  vtkTypeMacro(PausePass, vtkRenderPass);
  void Render(const vtkRenderState*) override
  {
    std::this_thread::sleep_for(std::chrono::duration<double>(Pause));
  }
};
vtkStandardNewMacro(PausePass);

/// A window whose renderer draws through camera -> [drawing pass, pause].
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  vtkNew<vtkCameraPass> Camera;
  vtkNew<vtkSequencePass> Sequence;
  vtkNew<vtkTimeCriticalDrawingPass> Drawing;
  vtkNew<vtkRenderStepsPass> Steps;
  vtkNew<PausePass> Pause;

  explicit Scene(bool withDrawingPass)
  {
    vtkNew<vtkTOMBuilder> builder;
    builder->SetInputData(tt::MakeBumpySurface(1.0, 60, 40, 0.0, 0.0, 0.0, 5.0));
    builder->Update();
    this->Mapper->SetInputDataObject(builder->GetOutput());
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Renderer->AutomaticCalibrationOff();
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(200, 200);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
    vtkNew<vtkRenderPassCollection> passes;
    this->Drawing->SetDelegatePass(this->Steps);
    passes->AddItem(withDrawingPass ? static_cast<vtkRenderPass*>(this->Drawing.GetPointer())
                                    : static_cast<vtkRenderPass*>(this->Steps.GetPointer()));
    passes->AddItem(this->Pause);
    this->Sequence->SetPasses(passes);
    this->Camera->SetDelegatePass(this->Sequence);
    this->Renderer->SetPass(this->Camera);
  }
};
}

TEST(TimeCriticalDrawingPass, MeasuresTheDrawingApartFromWhatFollows)
{
  Scene scene(true);
  EXPECT_TRUE(std::isnan(scene.Renderer->GetMeasuredDrawingTime()));
  scene.Window->Render();
  scene.Window->Render();
  const double frame = scene.Renderer->GetMeasuredFrameTime();
  const double drawing = scene.Renderer->GetMeasuredDrawingTime();
  EXPECT_GT(drawing, 0.0);
  EXPECT_GE(frame - drawing, 0.9 * Pause) << "frame " << frame << " s, drawing " << drawing << " s";
  EXPECT_GT(tt::CountForegroundPixels(scene.Window), 1000) << "the delegate drew the surface";
}

TEST(TimeCriticalDrawingPass, WithoutItTheDrawingIsTheWholeFrame)
{
  Scene scene(false);
  scene.Window->Render();
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetMeasuredDrawingTime(), scene.Renderer->GetMeasuredFrameTime());
  EXPECT_GE(scene.Renderer->GetMeasuredFrameTime(), 0.9 * Pause);
}

TEST(TimeCriticalDrawingPass, TheCostModelLearnsTheDrawingAlone)
{
  // Budgeted frames with online calibration: the predictions follow the
  // drawing, not the frame with its pause (which would make the scene look
  // many times costlier than it is).
  Scene scene(true);
  scene.Renderer->SetTargetFrameTime(1.0);
  for (int frame = 0; frame < 20; ++frame)
  {
    scene.Window->Render();
  }
  const double predicted = scene.Renderer->GetPredictedFrameTime();
  const double drawing = scene.Renderer->GetMeasuredDrawingTime();
  const double frame = scene.Renderer->GetMeasuredFrameTime();
  EXPECT_LT(std::abs(predicted - drawing), std::abs(predicted - frame))
    << "predicted " << predicted << " s, drawing " << drawing << " s, frame " << frame << " s";

  // The compositing time is planned as fixed cost, on top of the drawing.
  const double fixedBefore = scene.Renderer->GetFixedFrameTime();
  scene.Renderer->SetCompositingTime(Pause);
  scene.Window->Render();
  EXPECT_NEAR(scene.Renderer->GetFixedFrameTime() - fixedBefore, Pause, 0.5 * Pause);
  EXPECT_GE(scene.Renderer->GetPredictedFrameTime(), Pause);
}

TEST(TimeCriticalDrawingPass, CompositingTimeLeavesLessForTheObjects)
{
  // Pinned costs: 1 us per triangle; a compositing time of half the target
  // leaves the objects about half the triangles.
  Scene scene(true);
  scene.Renderer->OnlineCalibrationOff();
  scene.Renderer->SetCostCoefficients(0.0, 0.0, 1e-6, 0.0);
  scene.Renderer->SetNewObjectCostFactor(1.0);
  const double triangles = static_cast<double>(scene.Mapper->GetObjectNumberOfTriangles(0));
  scene.Renderer->SetTargetFrameTime(1e-6 * 0.8 * triangles);
  scene.Window->Render();
  const double alone = static_cast<double>(scene.Renderer->GetObjectTrianglesDrawn());
  scene.Renderer->SetCompositingTime(1e-6 * 0.4 * triangles);
  scene.Window->Render();
  const double shared = static_cast<double>(scene.Renderer->GetObjectTrianglesDrawn());
  EXPECT_NEAR(alone, 0.8 * triangles, 0.05 * triangles);
  EXPECT_NEAR(shared, 0.4 * triangles, 0.05 * triangles);
}

TEST(TimeCriticalDrawingPass, WithoutDelegateNothingIsDrawn)
{
  Scene scene(true);
  scene.Drawing->SetDelegatePass(nullptr);
  scene.Window->Render();
  EXPECT_EQ(tt::CountForegroundPixels(scene.Window), 0);
  EXPECT_EQ(scene.Drawing->GetNumberOfRenderedProps(), 0);
}

TEST(TimeCriticalDrawingPass, BadCompositingTimesAreRejected)
{
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkTest::ErrorObserver> errors;
  renderer->AddObserver(vtkCommand::ErrorEvent, errors);
  renderer->SetCompositingTime(0.01);
  for (double bad : { -0.001, std::numeric_limits<double>::quiet_NaN(),
         std::numeric_limits<double>::infinity() })
  {
    errors->Clear();
    renderer->SetCompositingTime(bad);
    EXPECT_TRUE(errors->GetError()) << bad;
    EXPECT_EQ(renderer->GetCompositingTime(), 0.01);
  }
}

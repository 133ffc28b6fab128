// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTimeCriticalRenderer's "no polygons" level
// (vtkTimeCriticalRendererDropping.cxx): an overloaded scene (the coarsest
// levels alone cost three times the target) drops objects and holds the
// predicted time within the target, with both policies that drop; the
// dropped are the least valuable (no object dropped while a less valuable
// one whose coarsest level costs more is drawn; the top 10% by projected
// area drawn); dropped objects are not drawn; still frames, the other
// policies, the setting turned off and a fixed part over the target draw
// everything; bad indices.
#include "RenderTestSupport.h"
#include "TimeCriticalRendererTestSupport.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTimeCriticalRenderer.h"

#include "vtkActor.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
// A bumpy-sphere TOM of the given tessellation, built once per tessellation.
vtkPolyData* SphereTOM(int theta)
{
  static vtkSmartPointer<vtkPolyData> toms[2];
  vtkSmartPointer<vtkPolyData>& tom = toms[theta > 30 ? 1 : 0];
  if (!tom)
  {
    tom = timecritical::testing::MakeBumpySphereTOM(theta, 2 * theta / 3);
  }
  return tom;
}

// k x k spheres 3 units apart, of scales from 0.2 to 1.3 in a scrambled
// order and of two tessellations (so their coarsest levels cost different
// amounts): objects of many values and two costs.
vtkSmartPointer<vtkMultiBlockDataSet> MixedGrid(int k)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  const int n = k * k;
  for (int j = 0; j < n; ++j)
  {
    const double scale = 0.2 + 1.1 * static_cast<double>((j * 37) % n) / static_cast<double>(n - 1);
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->DeepCopy(SphereTOM(j % 3 == 0 ? 24 : 60));
    vtkPoints* points = copy->GetPoints();
    const double dx = 3.0 * (j % k - 0.5 * (k - 1)), dy = 3.0 * (j / k - 0.5 * (k - 1));
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      points->SetPoint(i, scale * p[0] + dx, scale * p[1] + dy, scale * p[2]);
    }
    blocks->SetBlock(static_cast<unsigned int>(j), copy);
  }
  return blocks;
}

/// An offscreen window with a time-critical renderer showing one composite actor.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
  static constexpr double TriangleCost = 1e-6;
  static constexpr double FrameCost = 2e-3;

  explicit Scene(int k)
  {
    this->Mapper->SetInputDataObject(MixedGrid(k));
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(300, 300);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
    // Deterministic: pinned costs, no measurement feeding back, and the
    // value of an object is its projected area alone.
    this->Renderer->AutomaticCalibrationOff();
    this->Renderer->OnlineCalibrationOff();
    this->Renderer->SetCostCoefficients(FrameCost, 0.0, TriangleCost, 0.0);
    this->Renderer->SetNewObjectCostFactor(1.0);
    this->Renderer->UseVelocityOff();
    this->Renderer->UseEccentricityOff();
    this->Mapper->UpdateObjects();
  }

  /// Triangles of object i's coarsest level.
  double Coarsest(vtkIdType i) const
  {
    return this->Mapper->GetObjectCoarsestResolution(i) *
      static_cast<double>(this->Mapper->GetObjectNumberOfTriangles(i));
  }

  /// A target at which the coarsest levels alone cost `overload` times what it leaves the objects.
  double OverloadedTarget(double overload) const
  {
    double coarsest = 0.0;
    for (vtkIdType i = 0; i < this->Mapper->GetNumberOfObjects(); ++i)
    {
      coarsest += this->Coarsest(i);
    }
    return FrameCost + TriangleCost * coarsest / overload;
  }
};

/// Checks what a frame that dropped must hold: within the target, the
/// dropped ones not drawn and the least valuable, the top 10% drawn.
void ExpectLeastValuableDropped(Scene& scene, double target)
{
  vtkTimeCriticalRenderer* renderer = scene.Renderer;
  const vtkIdType n = renderer->GetNumberOfObjects();
  ASSERT_GT(renderer->GetNumberOfDroppedObjects(), n / 3);
  ASSERT_LT(renderer->GetNumberOfDroppedObjects(), n);
  EXPECT_LE(renderer->GetPredictedFrameTime(), target * (1 + 1e-9));
  EXPECT_GE(renderer->GetPredictedFrameTime(), 0.5 * target) << "budget left unused";
  vtkIdType dropped = 0;
  std::vector<double> pixels;
  for (vtkIdType i = 0; i < n; ++i)
  {
    pixels.push_back(renderer->GetObjectPixels(i));
    if (renderer->GetObjectDropped(i))
    {
      ++dropped;
      EXPECT_EQ(renderer->GetObjectResolution(i), 0.0) << i;
      EXPECT_EQ(renderer->GetObjectTriangles(i), 0) << i << " is dropped but drawn";
      EXPECT_EQ(scene.Mapper->GetObjectRenderedTriangles(i), 0) << i;
    }
    else
    {
      EXPECT_GT(renderer->GetObjectTriangles(i), 0) << i;
    }
  }
  EXPECT_EQ(dropped, renderer->GetNumberOfDroppedObjects());
  // The value order: no object dropped while a less valuable one whose
  // coarsest level costs more is drawn.
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (vtkIdType j = 0; renderer->GetObjectDropped(i) && j < n; ++j)
    {
      EXPECT_FALSE(!renderer->GetObjectDropped(j) && pixels[i] > pixels[j] &&
        scene.Coarsest(i) < scene.Coarsest(j))
        << "object " << i << " (" << pixels[i] << " pixels) dropped, " << j << " ("
        << pixels[j] << " pixels, a costlier coarsest level) drawn";
    }
  }
  std::vector<double> sorted = pixels;
  std::sort(sorted.begin(), sorted.end());
  const double top10 = sorted[static_cast<std::size_t>(n - n / 10)];
  for (vtkIdType i = 0; i < n; ++i)
  {
    EXPECT_FALSE(pixels[i] >= top10 && renderer->GetObjectDropped(i))
      << "object " << i << " in the top 10% by projected area is dropped";
  }
}
}

TEST(TimeCriticalRendererDropping, OverloadedFramesDropTheLeastValuable)
{
  Scene scene(8);
  const double target = scene.OverloadedTarget(3.0);
  scene.Renderer->SetTargetFrameTime(target);
  EXPECT_TRUE(scene.Renderer->GetDropObjectsWhenOverloaded()); // the default
  for (int policy : { vtkTimeCriticalRenderer::ACTIVE_SET, vtkTimeCriticalRenderer::GREEDY_LOD })
  {
    SCOPED_TRACE(policy);
    scene.Renderer->SetPolicy(policy);
    scene.Window->Render();
    ExpectLeastValuableDropped(scene, target);
    // The next frame (warm) too.
    scene.Window->Render();
    ExpectLeastValuableDropped(scene, target);
  }
}

TEST(TimeCriticalRendererDropping, FramesThatFitDropNothing)
{
  Scene scene(6);
  scene.Renderer->SetTargetFrameTime(scene.OverloadedTarget(0.5)); // twice the coarsest levels
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetNumberOfDroppedObjects(), 0);
  for (vtkIdType i = 0; i < scene.Renderer->GetNumberOfObjects(); ++i)
  {
    EXPECT_FALSE(scene.Renderer->GetObjectDropped(i));
    EXPECT_GT(scene.Renderer->GetObjectTriangles(i), 0);
  }
}

TEST(TimeCriticalRendererDropping, StillFramesOtherPoliciesAndTheSettingOffDrawEverything)
{
  Scene scene(6);
  const double target = scene.OverloadedTarget(3.0);
  scene.Renderer->SetTargetFrameTime(target);
  const vtkIdType n = scene.Renderer->GetNumberOfObjects();
  auto expectAllDrawn = [&](const char* what) {
    EXPECT_EQ(scene.Renderer->GetNumberOfDroppedObjects(), 0) << what;
    for (vtkIdType i = 0; i < n; ++i)
    {
      EXPECT_FALSE(scene.Renderer->GetObjectDropped(i)) << what << ": " << i;
      EXPECT_GT(scene.Renderer->GetObjectTriangles(i), 0) << what << ": " << i;
    }
  };
  scene.Window->Render();
  ASSERT_GT(scene.Renderer->GetNumberOfDroppedObjects(), 0);
  scene.Renderer->StillRender();
  expectAllDrawn("still frame");
  for (vtkIdType i = 0; i < n; ++i)
  {
    EXPECT_EQ(scene.Renderer->GetObjectResolution(i), 1.0);
  }
  scene.Renderer->StillRenderingOn();
  scene.Window->Render();
  expectAllDrawn("StillRendering");
  scene.Renderer->StillRenderingOff();
  scene.Renderer->SetPolicyToStaticThreshold();
  scene.Window->Render();
  expectAllDrawn("static threshold");
  scene.Renderer->SetPolicyToActiveSet();
  scene.Renderer->DropObjectsWhenOverloadedOff();
  scene.Window->Render();
  expectAllDrawn("setting off");
  // Every object at its coarsest level: the objects take three times what the target leaves them.
  const double objects = scene.Renderer->GetPredictedFrameTime() - Scene::FrameCost;
  EXPECT_NEAR(objects, 3.0 * (target - Scene::FrameCost), 1e-6 * objects);
  scene.Renderer->DropObjectsWhenOverloadedOn();
  scene.Window->Render();
  EXPECT_GT(scene.Renderer->GetNumberOfDroppedObjects(), 0);
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), target * (1 + 1e-9));
}

TEST(TimeCriticalRendererDropping, AFixedPartOverTheTargetDropsNothing)
{
  // Clear and swap alone take more than the target: dropping cannot hold
  // it, and the view is not emptied for nothing.
  Scene scene(4);
  scene.Renderer->SetTargetFrameTime(0.5 * Scene::FrameCost);
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetNumberOfDroppedObjects(), 0);
  EXPECT_GT(scene.Renderer->GetObjectTrianglesDrawn(), 0);
  // Just above it, the objects share what is left.
  scene.Renderer->SetTargetFrameTime(scene.OverloadedTarget(3.0));
  scene.Window->Render();
  EXPECT_GT(scene.Renderer->GetNumberOfDroppedObjects(), 0);
}

TEST(TimeCriticalRendererDropping, BadIndicesAreNotDropped)
{
  Scene scene(3);
  EXPECT_FALSE(scene.Renderer->GetObjectDropped(0)); // before any frame
  scene.Renderer->SetTargetFrameTime(scene.OverloadedTarget(3.0));
  scene.Window->Render();
  EXPECT_GT(scene.Renderer->GetNumberOfDroppedObjects(), 0);
  EXPECT_FALSE(scene.Renderer->GetObjectDropped(-1));
  EXPECT_FALSE(scene.Renderer->GetObjectDropped(scene.Renderer->GetNumberOfObjects()));
  EXPECT_FALSE(scene.Renderer->GetObjectDropped(1000000));
}

TEST(TimeCriticalRendererDropping, AModelNeverMeasuredDropsNothing)
{
  // Default coefficients (no calibration, none given, no still frame) may
  // overestimate several times: dropping by them would empty the view.
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  mapper->SetInputDataObject(MixedGrid(8));
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  window->SetOffScreenRendering(1);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->AutomaticCalibrationOff();
  renderer->SetTargetFrameTime(1e-5); // nothing fits
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
    EXPECT_EQ(renderer->GetNumberOfDroppedObjects(), 0) << "frame " << frame;
  }
  // Measured coefficients (given here; a calibration or a still frame too): it drops.
  renderer->SetCostCoefficients(Scene::FrameCost, 0.0, Scene::TriangleCost, 0.0);
  renderer->SetTargetFrameTime(Scene::FrameCost + 1e-4);
  window->Render();
  EXPECT_GT(renderer->GetNumberOfDroppedObjects(), 0);
}

TEST(TimeCriticalRendererDropping, DroppingNeverEmptiesTheView)
{
  // One object whose coarsest level exceeds what the fixed part leaves: it
  // is drawn at its coarsest level (over the target), not dropped.
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  vtkNew<vtkMultiBlockDataSet> one;
  one->SetBlock(0, MixedGrid(2)->GetBlock(0));
  mapper->SetInputDataObject(one);
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  window->SetOffScreenRendering(1);
  window->SetSize(300, 300);
  window->AddRenderer(renderer);
  renderer->ResetCamera();
  renderer->AutomaticCalibrationOff();
  renderer->OnlineCalibrationOff();
  renderer->SetCostCoefficients(Scene::FrameCost, 0.0, Scene::TriangleCost, 0.0);
  renderer->SetTargetFrameTime(Scene::FrameCost + 1e-7); // the fixed part fits, the object does not
  window->Render();
  ASSERT_EQ(renderer->GetNumberOfObjects(), 1);
  EXPECT_EQ(renderer->GetNumberOfDroppedObjects(), 0);
  EXPECT_FALSE(renderer->GetObjectDropped(0));
  EXPECT_GT(renderer->GetObjectTriangles(0), 0);
  EXPECT_NEAR(renderer->GetObjectResolution(0), mapper->GetObjectCoarsestResolution(0), 1e-6);
  EXPECT_GT(renderer->GetPredictedFrameTime(), renderer->GetTargetFrameTime());
}

// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTimeCriticalRenderer: objects of composite input, ordinary
// actors next to them, culling, the statistics it reports, the budget it
// keeps with pinned cost coefficients (deterministic), still rendering, the
// heuristics' effect, bad settings, calibration, and image baselines of a
// frame and its resolution map.
#include "RenderTestSupport.h"
#include "TimeCriticalRendererTestSupport.h"
#include "TestImageCompare.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTimeCriticalRenderer.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCullerCollection.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

// One bumpy-sphere TOM (about 4,700 triangles), built once.
vtkPolyData* SphereTOM()
{
  static vtkSmartPointer<vtkPolyData> tom = tt::MakeBumpySphereTOM(60, 40);
  return tom;
}

// A copy of the sphere TOM moved by (dx, dy, dz): the TOM arrays travel with it.
vtkSmartPointer<vtkPolyData> MovedSphere(double dx, double dy, double dz)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(SphereTOM());
  vtkPoints* points = copy->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + dx, p[1] + dy, p[2] + dz);
  }
  return copy;
}

// k x k spheres on the z = 0 plane, 3 units apart, centred on the origin.
vtkSmartPointer<vtkMultiBlockDataSet> SphereGrid(int k)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  for (int j = 0; j < k; ++j)
  {
    for (int i = 0; i < k; ++i)
    {
      blocks->SetBlock(static_cast<unsigned int>(j * k + i),
        MovedSphere(3.0 * (i - 0.5 * (k - 1)), 3.0 * (j - 0.5 * (k - 1)), 0.0));
    }
  }
  return blocks;
}

/// A window with a time-critical renderer showing one composite actor.
struct Scene
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;

  explicit Scene(vtkDataObject* input, int size = 300)
  {
    this->Mapper->SetInputDataObject(input);
    this->Actor->SetMapper(this->Mapper);
    this->Actor->GetProperty()->SetColor(0.85, 0.7, 0.45);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }

  /// Deterministic choices: fixed coefficients, no measurement feeding back.
  void PinCosts(double triangleCost = 1e-6)
  {
    this->Renderer->AutomaticCalibrationOff();
    this->Renderer->OnlineCalibrationOff();
    this->Renderer->SetCostCoefficients(2e-3, 0.0, triangleCost, 0.0);
    this->Renderer->SetNewObjectCostFactor(1.0);
  }

  vtkIdType TotalTriangles() const
  {
    vtkIdType total = 0;
    for (vtkIdType i = 0; i < this->Mapper->GetNumberOfObjects(); ++i)
    {
      total += this->Mapper->GetObjectNumberOfTriangles(i);
    }
    return total;
  }
};

}

TEST(TimeCriticalRenderer, CompositeInputIsSplitIntoObjects)
{
  Scene scene(SphereGrid(3));
  scene.PinCosts();
  scene.Renderer->SetPolicyToFullResolution();
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetNumberOfObjects(), 9);
  EXPECT_EQ(scene.Renderer->GetNumberOfCulledObjects(), 0);
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());
  for (vtkIdType o = 0; o < 9; ++o)
  {
    EXPECT_EQ(scene.Renderer->GetObjectResolution(o), 1.0);
    EXPECT_EQ(scene.Renderer->GetObjectActor(o), scene.Actor.GetPointer());
    EXPECT_EQ(scene.Renderer->GetObjectIndex(o), o);
    EXPECT_EQ(scene.Renderer->GetObjectTriangles(o), scene.Mapper->GetObjectNumberOfTriangles(o));
    EXPECT_GT(scene.Renderer->GetObjectPixels(o), 0.0);
  }
  EXPECT_EQ(scene.Renderer->GetObjectTriangles(9), -1);
  EXPECT_TRUE(std::isnan(scene.Renderer->GetObjectResolution(-1)));
  EXPECT_EQ(scene.Renderer->GetObjectActor(42), nullptr);
}

TEST(TimeCriticalRenderer, KeepsThePredictedTimeWithinTheTarget)
{
  Scene scene(SphereGrid(4));
  scene.PinCosts(1e-6); // 1 us per triangle, 2 ms per frame
  const vtkIdType total = scene.TotalTriangles();
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.3 * static_cast<double>(total));
  scene.Window->Render();
  const double target = scene.Renderer->GetTargetFrameTime();
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), target * (1 + 1e-9));
  EXPECT_GE(scene.Renderer->GetPredictedFrameTime(), 0.95 * target) << "budget left unused";
  EXPECT_NEAR(scene.Renderer->GetFixedFrameTime(), 0.002, 1e-12);
  // About 30% of the triangles, within the rounding of per-object counts.
  EXPECT_NEAR(static_cast<double>(scene.Renderer->GetObjectTrianglesDrawn()),
    0.3 * static_cast<double>(total), 0.02 * static_cast<double>(total));
  EXPECT_TRUE(scene.Renderer->GetOptimizationConverged());
  EXPECT_GT(scene.Renderer->GetOptimizationIterations(), 0);
  EXPECT_GE(scene.Renderer->GetOptimizationTime(), 0.0);
  EXPECT_LT(scene.Renderer->GetOptimizationTime(), 0.05);

  // A smaller target draws fewer triangles.
  const vtkIdType before = scene.Renderer->GetObjectTrianglesDrawn();
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.1 * static_cast<double>(total));
  scene.Window->Render();
  EXPECT_LT(scene.Renderer->GetObjectTrianglesDrawn(), before);
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), scene.Renderer->GetTargetFrameTime() * (1 + 1e-9));

  // A generous target draws everything.
  scene.Renderer->SetTargetFrameTime(10.0);
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), total);
}

TEST(TimeCriticalRenderer, NewlyVisibleObjectsArePlannedAtAHigherCost)
{
  Scene scene(SphereGrid(3));
  scene.PinCosts(1e-6);
  scene.Renderer->SetNewObjectCostFactor(2.0);
  const double variable = 1e-6 * 0.3 * static_cast<double>(scene.TotalTriangles());
  scene.Renderer->SetTargetFrameTime(0.002 + variable);
  scene.Window->Render(); // every object is new: half the triangles of a warm frame
  const vtkIdType cold = scene.Renderer->GetObjectTrianglesDrawn();
  scene.Window->Render();
  const vtkIdType warm = scene.Renderer->GetObjectTrianglesDrawn();
  EXPECT_NEAR(static_cast<double>(cold), 0.5 * static_cast<double>(warm), 0.03 * static_cast<double>(warm));
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), scene.Renderer->GetTargetFrameTime() * (1 + 1e-9));
}

TEST(TimeCriticalRenderer, DataChangedInAFrameIsPlannedAsSpentTime)
{
  // A frame whose mappers read their objects again (new data, swapped-in
  // hierarchies) has that much less time to draw: the read counts as fixed
  // time, and the frames after it do not.
  auto grid = SphereGrid(3);
  Scene scene(grid);
  scene.PinCosts(1e-6);
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.3 * static_cast<double>(scene.TotalTriangles()));
  scene.Window->Render(); // the objects were read by ResetCamera(), outside the frame
  EXPECT_EQ(scene.Renderer->GetDataChangeTime(), 0.0);
  EXPECT_NEAR(scene.Renderer->GetFixedFrameTime(), 0.002, 1e-12);

  grid->SetBlock(4, MovedSphere(0.0, 0.0, 0.5));
  const vtkIdType reads = scene.Mapper->GetNumberOfObjectReads();
  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetNumberOfObjectReads(), reads + 1);
  const double change = scene.Renderer->GetDataChangeTime();
  EXPECT_GT(change, 0.0);
  EXPECT_GT(scene.Renderer->GetFixedFrameTime(), 0.002);
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), scene.Renderer->GetTargetFrameTime() * (1 + 1e-9));

  scene.Window->Render();
  EXPECT_EQ(scene.Mapper->GetNumberOfObjectReads(), reads + 1);
  EXPECT_EQ(scene.Renderer->GetDataChangeTime(), 0.0);
  EXPECT_NEAR(scene.Renderer->GetFixedFrameTime(), 0.002, 1e-12);
}

TEST(TimeCriticalRenderer, MeasuresFrameTimes)
{
  Scene scene(SphereGrid(2));
  scene.PinCosts();
  EXPECT_TRUE(std::isnan(scene.Renderer->GetMeasuredFrameTime()));
  scene.Window->Render();
  scene.Window->Render();
  const double measured = scene.Renderer->GetMeasuredFrameTime();
  EXPECT_GT(measured, 0.0);
  EXPECT_LT(measured, 10.0);
}

TEST(TimeCriticalRenderer, CullsObjectsOutsideTheView)
{
  Scene scene(SphereGrid(3));
  scene.PinCosts();
  scene.Renderer->SetPolicyToFullResolution();
  // Look closely at the centre sphere only.
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, 4);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  scene.Renderer->ResetCameraClippingRange();
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetNumberOfObjects(), 9);
  EXPECT_EQ(scene.Renderer->GetNumberOfCulledObjects(), 8);
  EXPECT_EQ(scene.Renderer->GetObjectResolution(4), 1.0);
  for (vtkIdType o = 0; o < 9; ++o)
  {
    if (o != 4)
    {
      EXPECT_EQ(scene.Renderer->GetObjectResolution(o), 0.0) << o;
      EXPECT_EQ(scene.Renderer->GetObjectTriangles(o), 0) << o;
    }
  }
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), scene.Mapper->GetObjectNumberOfTriangles(4));
}

TEST(TimeCriticalRenderer, OrdinaryActorsAreDrawnAndCountAsFixedCost)
{
  Scene scene(SphereGrid(2));
  scene.PinCosts(1e-6);
  scene.Renderer->SetCostCoefficients(2e-3, 1e-3, 1e-6, 0.0);
  scene.Renderer->SetTargetFrameTime(0.5);
  scene.Window->Render();
  const double fixedAlone = scene.Renderer->GetFixedFrameTime();
  EXPECT_NEAR(fixedAlone, 2e-3 + 1e-3, 1e-12); // frame + one draw call

  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0, 0, 3);
  ball->SetThetaResolution(50);
  ball->SetPhiResolution(50);
  ball->Update();
  const vtkIdType ballTriangles = ball->GetOutput()->GetNumberOfPolys();
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputConnection(ball->GetOutputPort());
  vtkNew<vtkActor> ordinary;
  ordinary->SetMapper(plain);
  ordinary->GetProperty()->SetColor(0, 1, 0);
  scene.Renderer->AddActor(ordinary);
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  EXPECT_NEAR(scene.Renderer->GetFixedFrameTime(),
    fixedAlone + 1e-3 + 1e-6 * static_cast<double>(ballTriangles), 1e-9);
  EXPECT_EQ(scene.Renderer->GetTrianglesDrawn(),
    scene.Renderer->GetObjectTrianglesDrawn() + ballTriangles);
  EXPECT_EQ(scene.Renderer->GetNumberOfObjects(), 4);

  // The ordinary actor is in the image: some pixels are pure-ish green.
  vtkNew<vtkUnsignedCharArray> pixels;
  scene.Window->GetRGBACharPixelData(0, 0, 299, 299, 0, pixels);
  int green = 0;
  for (vtkIdType i = 0; i < pixels->GetNumberOfTuples(); ++i)
  {
    const unsigned char* p = pixels->GetPointer(4 * i);
    green += (p[1] > 100 && p[0] < 40 && p[2] < 40) ? 1 : 0;
  }
  EXPECT_GT(green, 100);
}

TEST(TimeCriticalRenderer, StillRenderDrawsFullResolution)
{
  Scene scene(SphereGrid(3));
  scene.PinCosts(1e-6);
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.2 * static_cast<double>(scene.TotalTriangles()));
  scene.Window->Render();
  EXPECT_LT(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());
  EXPECT_FALSE(scene.Renderer->GetLastRenderWasStill());
  scene.Renderer->StillRender();
  EXPECT_TRUE(scene.Renderer->GetLastRenderWasStill());
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());
  scene.Window->Render();
  EXPECT_LT(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());

  // The interactors' convention: a still update rate means a still frame,
  // an interactive one sets the target.
  scene.Renderer->UseDesiredUpdateRateOn();
  scene.Window->SetDesiredUpdateRate(0.0001);
  scene.Window->Render();
  EXPECT_TRUE(scene.Renderer->GetLastRenderWasStill());
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());
  scene.Window->SetDesiredUpdateRate(1.0 / (0.002 + 1e-6 * 0.2 * static_cast<double>(scene.TotalTriangles())));
  scene.Window->Render();
  EXPECT_FALSE(scene.Renderer->GetLastRenderWasStill());
  EXPECT_LT(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());
}

TEST(TimeCriticalRenderer, ImportanceAndFocusShiftDetail)
{
  // Two identical spheres side by side, seen symmetrically.
  vtkNew<vtkMultiBlockDataSet> pair;
  pair->SetBlock(0, MovedSphere(-1.5, 0, 0));
  pair->SetBlock(1, MovedSphere(1.5, 0, 0));
  Scene scene(pair);
  scene.PinCosts(1e-6);
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.3 * static_cast<double>(scene.TotalTriangles()));
  scene.Renderer->UseVelocityOff();
  scene.Window->Render();
  EXPECT_NEAR(scene.Renderer->GetObjectResolution(0), scene.Renderer->GetObjectResolution(1), 1e-6);

  // Focus on the left one (screen x = 0.25): it gets more detail. Reddy's
  // acuity falls only beyond 5.79 degrees, so view the 300-pixel window as a
  // small display seen from close by (eq. 8: about 1.7 pixels per degree).
  scene.Renderer->SetDisplayResolution(300, 300);
  scene.Renderer->SetDisplaySize(0.3, 0.3);
  scene.Renderer->SetViewingDistance(0.1);
  scene.Renderer->SetFocusPoint(0.25, 0.5);
  scene.Window->Render();
  EXPECT_GT(scene.Renderer->GetObjectResolution(0), 1.2 * scene.Renderer->GetObjectResolution(1));

  // Importance is per actor: two actors, the second one ten times as important.
  vtkNew<vtkMultiBlockDataSet> right;
  right->SetBlock(0, MovedSphere(1.5, 0, 0));
  vtkNew<vtkMultiBlockDataSet> left;
  left->SetBlock(0, MovedSphere(-1.5, 0, 0));
  scene.Mapper->SetInputDataObject(left);
  vtkNew<vtkMultiresolutionPolyDataMapper> rightMapper;
  rightMapper->SetInputDataObject(right);
  vtkNew<vtkActor> rightActor;
  rightActor->SetMapper(rightMapper);
  scene.Renderer->AddActor(rightActor);
  scene.Renderer->SetFocusPoint(0.5, 0.5);
  scene.Renderer->SetImportance(rightActor, 10.0);
  EXPECT_EQ(scene.Renderer->GetImportance(rightActor), 10.0);
  EXPECT_EQ(scene.Renderer->GetImportance(scene.Actor), 1.0);
  // The first frame reads the new inputs, time it plans as spent (slow under
  // sanitizers): the second compares the shares of the budget.
  scene.Window->Render();
  scene.Window->Render();
  ASSERT_EQ(scene.Renderer->GetNumberOfObjects(), 2);
  ASSERT_EQ(scene.Renderer->GetObjectActor(1), rightActor.GetPointer());
  EXPECT_GT(scene.Renderer->GetObjectResolution(1), 1.5 * scene.Renderer->GetObjectResolution(0));
}

TEST(TimeCriticalRenderer, EveryPolicyRuns)
{
  Scene scene(SphereGrid(3));
  scene.PinCosts(1e-6);
  const vtkIdType total = scene.TotalTriangles();
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.3 * static_cast<double>(total));
  const char* names[] = { "active-set", "none", "static", "feedback", "greedy" };
  for (int policy = vtkTimeCriticalRenderer::ACTIVE_SET;
       policy <= vtkTimeCriticalRenderer::GREEDY_LOD; ++policy)
  {
    scene.Renderer->SetPolicy(policy);
    EXPECT_STREQ(scene.Renderer->GetPolicyAsString(), names[policy]);
    for (int frame = 0; frame < 3; ++frame)
    {
      scene.Window->Render();
    }
    EXPECT_GT(scene.Renderer->GetObjectTrianglesDrawn(), 0) << names[policy];
    EXPECT_LE(scene.Renderer->GetObjectTrianglesDrawn(), total) << names[policy];
    if (policy == vtkTimeCriticalRenderer::ACTIVE_SET || policy == vtkTimeCriticalRenderer::GREEDY_LOD)
    {
      EXPECT_LE(scene.Renderer->GetPredictedFrameTime(),
        scene.Renderer->GetTargetFrameTime() * (1 + 1e-9))
        << names[policy];
    }
  }
  scene.Renderer->SetPolicyToFullResolution();
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), total);
}

TEST(TimeCriticalRenderer, BadSettingsAreRejected)
{
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkTest::ErrorObserver> errors;
  renderer->AddObserver(vtkCommand::ErrorEvent, errors);
  const double bad[] = { 0.0, -0.1, NaN, std::numeric_limits<double>::infinity() };
  for (double value : bad)
  {
    errors->Clear();
    renderer->SetTargetFrameTime(value);
    EXPECT_TRUE(errors->GetError()) << value;
    EXPECT_EQ(renderer->GetTargetFrameTime(), 0.1);
  }
  errors->Clear();
  renderer->SetOptimizationTimeLimit(-1.0);
  EXPECT_TRUE(errors->GetError());
  EXPECT_EQ(renderer->GetOptimizationTimeLimit(), 0.001);
  errors->Clear();
  renderer->SetPolicy(17);
  EXPECT_TRUE(errors->GetError());
  EXPECT_EQ(renderer->GetPolicy(), vtkTimeCriticalRenderer::ACTIVE_SET);
  errors->Clear();
  renderer->SetDegradationFamily(-2);
  EXPECT_TRUE(errors->GetError());
  errors->Clear();
  renderer->SetStaticPixelsPerTriangle(0.0);
  EXPECT_TRUE(errors->GetError());
  errors->Clear();
  renderer->SetImportance(nullptr, 1.0);
  EXPECT_TRUE(errors->GetError());
  errors->Clear();
  renderer->SetCostCoefficients(1e-3, -1.0, 1e-6, 0.0);
  EXPECT_TRUE(errors->GetError());
  EXPECT_GT(renderer->GetTriangleCost(), 0.0);
  // A triangle is never free: a zero triangle cost is refused, the previous
  // coefficients stay (the others are used as given).
  renderer->SetCostCoefficients(1e-3, 0.0, 3e-7, 0.0);
  errors->Clear();
  renderer->SetCostCoefficients(1e-3, 0.0, 0.0, 1e-9);
  EXPECT_TRUE(errors->GetError());
  EXPECT_EQ(renderer->GetTriangleCost(), 3e-7);
  EXPECT_EQ(renderer->GetPixelCost(), 0.0);
  errors->Clear();
  renderer->StillRender(); // no window
  EXPECT_TRUE(errors->GetError());
  errors->Clear();
  EXPECT_FALSE(renderer->Calibrate());
  EXPECT_TRUE(errors->GetError());
}

TEST(TimeCriticalRenderer, NumericSettersRejectNaNAndOutOfRange)
{
  // Every numeric setting: NaN, infinities and out-of-range values give an
  // error and keep the previous value (NaN once passed the clamp macros and
  // made every object coarsest).
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkTest::ErrorObserver> errors;
  renderer->AddObserver(vtkCommand::ErrorEvent, errors);
  const double inf = std::numeric_limits<double>::infinity();
  auto expectRejected = [&](const char* what, double value, auto set, auto get) {
    const double before = get();
    errors->Clear();
    set(value);
    EXPECT_TRUE(errors->GetError()) << what << " accepted " << value;
    EXPECT_EQ(get(), before) << what << " changed on " << value;
  };
  auto expectAccepted = [&](const char* what, double value, auto set, auto get) {
    errors->Clear();
    set(value);
    EXPECT_FALSE(errors->GetError()) << what << " rejected " << value;
    EXPECT_EQ(get(), value) << what;
  };
  auto* r = renderer.Get();
  struct Setting
  {
    const char* Name;
    std::function<void(double)> Set;
    std::function<double()> Get;
    std::vector<double> Bad;
    double Good;
  };
  const std::vector<Setting> settings = {
    { "SafetyFactor", [r](double v) { r->SetSafetyFactor(v); },
      [r] { return r->GetSafetyFactor(); }, { NaN, -0.5, 11.0, inf }, 2.0 },
    { "NewObjectCostFactor", [r](double v) { r->SetNewObjectCostFactor(v); },
      [r] { return r->GetNewObjectCostFactor(); }, { NaN, 0.5, 11.0, -inf }, 3.0 },
    { "FocusPoint x", [r](double v) { r->SetFocusPoint(v, 0.5); },
      [r] { return r->GetFocusPoint()[0]; }, { NaN, -0.1, 1.5, inf }, 0.25 },
    { "FocusPoint y", [r](double v) { r->SetFocusPoint(0.25, v); },
      [r] { return r->GetFocusPoint()[1]; }, { NaN, -0.1, 1.5, inf }, 0.75 },
    { "DisplayResolution x", [r](double v) { r->SetDisplayResolution(v, 1080.0); },
      [r] { return r->GetDisplayResolution()[0]; }, { NaN, 0.0, -1.0, inf }, 1920.0 },
    { "DisplayResolution y", [r](double v) { r->SetDisplayResolution(1920.0, v); },
      [r] { return r->GetDisplayResolution()[1]; }, { NaN, 0.0, -1.0, inf }, 1200.0 },
    { "DisplaySize x", [r](double v) { r->SetDisplaySize(v, 0.3); },
      [r] { return r->GetDisplaySize()[0]; }, { NaN, 0.0, -0.5, inf }, 0.6 },
    { "DisplaySize y", [r](double v) { r->SetDisplaySize(0.6, v); },
      [r] { return r->GetDisplaySize()[1]; }, { NaN, 0.0, -0.5, inf }, 0.35 },
    { "ViewingDistance", [r](double v) { r->SetViewingDistance(v); },
      [r] { return r->GetViewingDistance(); }, { NaN, 0.0, -0.5, inf }, 0.8 },
    { "StillUpdateRateThreshold", [r](double v) { r->SetStillUpdateRateThreshold(v); },
      [r] { return r->GetStillUpdateRateThreshold(); }, { NaN, -1.0, inf }, 0.5 },
  };
  for (const Setting& setting : settings)
  {
    for (double bad : setting.Bad)
    {
      expectRejected(setting.Name, bad, setting.Set, setting.Get);
    }
    expectAccepted(setting.Name, setting.Good, setting.Set, setting.Get);
    expectRejected(setting.Name, NaN, setting.Set, setting.Get); // keeps the good value
  }
  // A rejected component leaves both components as they were.
  r->SetFocusPoint(0.5, 0.5);
  errors->Clear();
  r->SetFocusPoint(0.2, NaN);
  EXPECT_TRUE(errors->GetError());
  EXPECT_EQ(r->GetFocusPoint()[0], 0.5);
}

TEST(TimeCriticalRenderer, EmptySceneAndEmptyBlocks)
{
  // No actor at all.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(64, 64);
  vtkNew<vtkTimeCriticalRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  EXPECT_EQ(renderer->GetNumberOfObjects(), 0);
  EXPECT_EQ(renderer->GetTrianglesDrawn(), 0);

  // A composite with only empty leaves and null blocks.
  vtkNew<vtkMultiBlockDataSet> empty;
  empty->SetBlock(0, nullptr);
  vtkNew<vtkPolyData> nothing;
  empty->SetBlock(1, nothing);
  Scene scene(empty, 64);
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetNumberOfObjects(), 0);
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), 0);
}

TEST(TimeCriticalRenderer, CalibratesInTheStartUpFrameNotInTheFirstInteraction)
{
  // The interactors' pattern: still frames until the first drag. The
  // calibration belongs to the first of them (the start-up frame); frames
  // after it, interactive or still, render nothing hidden.
  Scene scene(SphereGrid(4));
  scene.Renderer->UseDesiredUpdateRateOn();
  scene.Window->SetDesiredUpdateRate(0.0001);
  EXPECT_EQ(scene.Renderer->GetCalibrationRenders(), 0);
  EXPECT_EQ(scene.Renderer->GetCalibrationTime(), 0.0);
  scene.Window->Render();
  EXPECT_TRUE(scene.Renderer->GetLastRenderWasStill());
  EXPECT_EQ(scene.Renderer->GetObjectTrianglesDrawn(), scene.TotalTriangles());
  EXPECT_TRUE(scene.Renderer->GetCalibrated());
  const int renders = scene.Renderer->GetCalibrationRenders();
  EXPECT_GE(renders, 7); // probe and at least the first zoom's samples
  EXPECT_LE(renders, 2 * 14 + 1);
  EXPECT_GT(scene.Renderer->GetCalibrationTime(), 0.0);
  // Sized to the target: no more than 30 targets' worth, plus the first upload.
  EXPECT_LT(scene.Renderer->GetCalibrationTime(), 30 * 0.1 + 5.0);
  scene.Window->Render(); // still again
  scene.Window->SetDesiredUpdateRate(20.0);
  for (int frame = 0; frame < 4; ++frame)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(5.0);
    scene.Window->Render();
    EXPECT_FALSE(scene.Renderer->GetLastRenderWasStill());
  }
  scene.Window->SetDesiredUpdateRate(0.0001);
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetCalibrationRenders(), renders);

  // Without UseDesiredUpdateRate the first frame calibrates too, and a
  // full-resolution policy never does.
  Scene plain(SphereGrid(2));
  plain.Window->Render();
  EXPECT_TRUE(plain.Renderer->GetCalibrated());
  Scene full(SphereGrid(2));
  full.Renderer->SetPolicyToFullResolution();
  full.Window->Render();
  EXPECT_FALSE(full.Renderer->GetCalibrated());
  EXPECT_EQ(full.Renderer->GetCalibrationRenders(), 0);
}

TEST(TimeCriticalRenderer, CalibrationWaitsUntilSomethingIsInView)
{
  // A script's first render may come before its camera is reset (ParaView's
  // simple.Render does so): nothing in view is no reason to give the
  // calibration up, nor to warn; the first frame with objects in view runs it.
  Scene scene(SphereGrid(3));
  scene.Renderer->GetCullers()->RemoveAllItems(); // as ParaView: the objects stay in the frame
  vtkNew<vtkTest::ErrorObserver> warnings;
  scene.Renderer->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  double focal[3], position[3];
  camera->GetFocalPoint(focal);
  camera->GetPosition(position);
  camera->SetFocalPoint(focal[0] + 1000.0, focal[1], focal[2]); // far from every object
  camera->SetPosition(position[0] + 1000.0, position[1], position[2]);
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetNumberOfCulledObjects(), 9);
  EXPECT_FALSE(scene.Renderer->GetCalibrated());
  EXPECT_FALSE(warnings->GetWarning()) << warnings->GetWarningMessage();
  scene.Renderer->ResetCamera();
  scene.Window->Render();
  EXPECT_TRUE(scene.Renderer->GetCalibrated());
  EXPECT_GT(scene.Renderer->GetCalibrationRenders(), 0);
}

TEST(TimeCriticalRenderer, CalibrationBeforeTheFirstCameraResetRunsAgainAfterIt)
{
  // ParaView's simple.Render draws its first frame before resetting the
  // camera: a calibration of whatever that camera sees (here one object, up
  // close) is provisional; the reset to the data calibrates again, once.
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  vtkNew<vtkActor> actor;
  mapper->SetInputDataObject(SphereGrid(3));
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  window->SetOffScreenRendering(1);
  window->SetSize(200, 200);
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 4.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  window->Render();
  ASSERT_TRUE(renderer->GetCalibrated());
  const int first = renderer->GetCalibrationRenders();
  window->Render();
  EXPECT_EQ(renderer->GetCalibrationRenders(), first) << "no calibration without a reset";
  renderer->ResetCamera();
  window->Render();
  const int second = renderer->GetCalibrationRenders();
  EXPECT_GT(second, first) << "the reset to the data calibrates again";
  renderer->ResetCamera();
  window->Render();
  EXPECT_EQ(renderer->GetCalibrationRenders(), second) << "only the first reset does";
}

TEST(TimeCriticalRenderer, EffectiveTargetFollowsTheDesiredUpdateRate)
{
  Scene scene(SphereGrid(3));
  scene.PinCosts(1e-6);
  EXPECT_EQ(scene.Renderer->GetEffectiveTargetFrameTime(), 0.1);
  scene.Renderer->UseDesiredUpdateRateOn();
  const double total = static_cast<double>(scene.TotalTriangles());
  const double target = 0.002 + 1e-6 * 0.3 * total;
  scene.Window->SetDesiredUpdateRate(1.0 / target);
  EXPECT_NEAR(scene.Renderer->GetEffectiveTargetFrameTime(), target, 1e-15);
  EXPECT_EQ(scene.Renderer->GetTargetFrameTime(), 0.1); // the setting, not the plan
  scene.Window->Render();
  EXPECT_NEAR(scene.Renderer->GetLastTargetFrameTime(), target, 1e-15);
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), target * (1 + 1e-9));
  EXPECT_GE(scene.Renderer->GetPredictedFrameTime(), 0.95 * target);
  scene.Window->SetDesiredUpdateRate(0.0001);
  EXPECT_TRUE(std::isinf(scene.Renderer->GetEffectiveTargetFrameTime()));
  scene.Window->Render();
  EXPECT_TRUE(std::isinf(scene.Renderer->GetLastTargetFrameTime()));
  EXPECT_TRUE(scene.Renderer->GetLastRenderWasStill());
  // A still frame is predicted too: every object in full.
  EXPECT_NEAR(scene.Renderer->GetPredictedFrameTime(), 0.002 + 1e-6 * total, 1e-9);
}

TEST(TimeCriticalRenderer, StillFramesLeaveTheCoefficientsAlone)
{
  // A run of still frames (ParaView draws one after every interaction; the
  // W1 example's full-resolution pass drew 240) used to fade everything but
  // the full-resolution direction out of the online fit: the next budgeted
  // frame was planned with a fixed part of 0.1-0.4 s where 0.03 s was real.
  Scene scene(SphereGrid(4));
  scene.Renderer->AutomaticCalibrationOff();
  scene.Renderer->OnlineCalibrationOn();
  // Far from this machine's real costs, so that any learning moves them.
  scene.Renderer->SetCostCoefficients(0.05, 0.0, 1e-9, 0.0);
  scene.Renderer->StillRenderingOn();
  for (int frame = 0; frame < 40; ++frame)
  {
    scene.Window->Render();
    EXPECT_TRUE(scene.Renderer->GetLastRenderWasStill());
  }
  EXPECT_EQ(scene.Renderer->GetFrameCost(), 0.05);
  EXPECT_EQ(scene.Renderer->GetTriangleCost(), 1e-9);
  // Budgeted frames do teach it.
  scene.Renderer->StillRenderingOff();
  for (int frame = 0; frame < 40; ++frame)
  {
    scene.Window->Render();
  }
  EXPECT_NE(scene.Renderer->GetFrameCost(), 0.05);
}

TEST(TimeCriticalRenderer, LargeMarginCoarsensInsteadOfEmptyingTheFrame)
{
  // The soak's flicker: a large fixed part and a margin of half the 100 ms
  // target left nothing, and every object went to its coarsest level. The
  // margin is now at most a quarter of the target and at most half of what
  // the fixed part and the coarsest levels leave; the objects get the rest.
  Scene scene(SphereGrid(5));
  scene.Renderer->AutomaticCalibrationOff();
  scene.Renderer->SetCostCoefficients(0.08, 0.0, 1e-6, 0.0);
  scene.Renderer->SetNewObjectCostFactor(1.0);
  scene.Renderer->SetSafetyFactor(10.0); // 10 x the initial spread: more than any cap
  scene.Renderer->SetTargetFrameTime(0.1);
  scene.Window->Render(); // online calibration on, no frame measured yet: deterministic
  const double fixed = scene.Renderer->GetFixedFrameTime();
  EXPECT_NEAR(fixed, 0.08, 1e-6);
  double coarsest = 0.0;
  for (vtkIdType o = 0; o < scene.Mapper->GetNumberOfObjects(); ++o)
  {
    coarsest += scene.Mapper->GetObjectCoarsestResolution(o) *
      static_cast<double>(scene.Mapper->GetObjectNumberOfTriangles(o));
  }
  const double room = 0.1 - fixed - 1e-6 * coarsest; // what is left above the coarsest levels
  const double margin = scene.Renderer->GetSafetyMargin();
  EXPECT_GT(margin, 0.0);
  EXPECT_NEAR(margin, 0.5 * room, 1e-9); // the cap of the room binds, not the quarter
  const double drawn = static_cast<double>(scene.Renderer->GetObjectTrianglesDrawn());
  EXPECT_GT(drawn, 3.0 * coarsest);
  // The coarsest levels plus half the room, at 1 us per triangle, within rounding.
  EXPECT_GT(drawn, 0.9 * (coarsest + 0.5 * room / 1e-6));
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime() + margin, 0.1 * (1 + 1e-9));

  // With a small fixed part the quarter of the target binds.
  scene.Renderer->SetCostCoefficients(0.002, 0.0, 1e-6, 0.0);
  scene.Window->Render();
  EXPECT_NEAR(scene.Renderer->GetSafetyMargin(), 0.25 * 0.1, 1e-12);
}

TEST(TimeCriticalRenderer, NoOptimizationTimeStillUsesTheBudget)
{
  Scene scene(SphereGrid(4));
  scene.PinCosts(1e-6);
  const double total = static_cast<double>(scene.TotalTriangles());
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * total / 3.0);
  scene.Renderer->SetOptimizationTimeLimit(0.0);
  scene.Window->Render();
  EXPECT_EQ(scene.Renderer->GetOptimizationIterations(), 0);
  EXPECT_LE(scene.Renderer->GetPredictedFrameTime(), scene.Renderer->GetTargetFrameTime() * (1 + 1e-9));
  // A third of the scene, not every object at its coarsest level.
  EXPECT_GT(static_cast<double>(scene.Renderer->GetObjectTrianglesDrawn()), 0.9 * total / 3.0);
}

TEST(TimeCriticalRenderer, CalibratesItsCostModel)
{
  Scene scene(SphereGrid(4));
  EXPECT_FALSE(scene.Renderer->GetCalibrated());
  scene.Window->Render(); // automatic calibration before the first adaptive frame
  EXPECT_TRUE(scene.Renderer->GetCalibrated());
  EXPECT_GT(scene.Renderer->GetTriangleCost(), 0.0);
  EXPECT_LT(scene.Renderer->GetTriangleCost(), 1e-3);
  const double calibrated = scene.Renderer->GetTriangleCost();
  for (int frame = 0; frame < 5; ++frame)
  {
    scene.Window->Render();
    // Online refinement stays within half the calibrated triangle cost.
    EXPECT_GE(scene.Renderer->GetTriangleCost(), 0.5 * calibrated * (1 - 1e-12));
  }
  // Nothing is free after a fit, not even a pixel or a frame.
  EXPECT_GT(scene.Renderer->GetPixelCost(), 0.0);
  EXPECT_GT(scene.Renderer->GetFrameCost(), 0.0);
  EXPECT_GT(scene.Renderer->GetPredictedFrameTime(), 0.0);
  EXPECT_TRUE(std::isfinite(scene.Renderer->GetMeasuredFrameTime()));
  EXPECT_TRUE(scene.Renderer->Calibrate());
}

// Image baselines: with pinned costs the resolutions, and so the images, are
// deterministic. The resolution map shows each object's grey level.
class RendererBaseline : public ::testing::TestWithParam<bool>
{
};

TEST_P(RendererBaseline, MatchesBaseline)
{
  const bool resolutionMap = GetParam();
  Scene scene(SphereGrid(3));
  scene.PinCosts(1e-6);
  scene.Actor->GetProperty()->SetInterpolationToFlat();
  scene.Mapper->SetColorByResolution(resolutionMap);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(-2.0, -9.0, 7.0);
  camera->SetViewUp(0, 0, 1);
  camera->SetViewAngle(40);
  scene.Renderer->ResetCameraClippingRange();
  scene.Renderer->UseVelocityOff();
  scene.Renderer->SetFocusPoint(0.3, 0.4);
  scene.Renderer->SetDisplayResolution(300, 300);
  scene.Renderer->SetDisplaySize(0.3, 0.3);
  scene.Renderer->SetViewingDistance(0.1);
  scene.Renderer->SetTargetFrameTime(0.002 + 1e-6 * 0.25 * static_cast<double>(scene.TotalTriangles()));
  scene.Window->Render();
  // Resolutions differ between objects (the image would not show a bug otherwise).
  double lo = 1.0, hi = 0.0;
  for (vtkIdType o = 0; o < 9; ++o)
  {
    lo = std::min(lo, scene.Renderer->GetObjectResolution(o));
    hi = std::max(hi, scene.Renderer->GetObjectResolution(o));
  }
  EXPECT_GT(hi, 2.0 * lo);

  const std::string name = resolutionMap ? "TimeCriticalRenderer_map" : "TimeCriticalRenderer";
  const std::string image = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/" + name + ".png";
  const std::string baseline = std::string(TIMECRITICAL_BASELINE_DIR) + "/" + name + ".png";
  tt::WriteWindowPNG(scene.Window, image, false);
  if (tt::UpdatingBaselines())
  {
    std::ifstream src(image, std::ios::binary);
    std::ofstream dst(baseline, std::ios::binary);
    dst << src.rdbuf();
  }
  const timecritical::testing::ImageTolerance tolerance{ 0.05, 0.001, 0.005 };
  const auto result = timecritical::testing::CompareImages(image, baseline, 0.05);
  EXPECT_TRUE(timecritical::testing::Passes(result, tolerance))
    << timecritical::testing::Describe(result) << " (image " << image << ", baseline " << baseline
    << ")";

  // Sensitivity: the same frame at full resolution must not pass.
  if (!resolutionMap)
  {
    scene.Renderer->StillRender();
    const std::string full = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/" + name + "_full.png";
    tt::WriteWindowPNG(scene.Window, full, false);
    const auto differs = timecritical::testing::CompareImages(full, baseline, 0.05);
    ASSERT_TRUE(differs.Loaded) << differs.Message;
    EXPECT_FALSE(timecritical::testing::Passes(differs, tolerance))
      << "full resolution should differ from the budgeted frame: "
      << timecritical::testing::Describe(differs);
  }
}

INSTANTIATE_TEST_SUITE_P(Frames, RendererBaseline, ::testing::Values(false, true));

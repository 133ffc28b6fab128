// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMultiresolutionPolyDataMapper's background hierarchy builds
// (vtkMultiresolutionPolyDataMapperBackground.cxx): frames drawn while a
// build is held on purpose, the hierarchy swapped in once done, stale builds
// cancelled by a new input, waiting (mapper and renderer), a failed build,
// merge trees, no allocation per frame while builds run, off by default.
#include "MultiresolutionMapperTestSupport.h"
#include "vtkHierarchyBuildCache.h"
#include "vtkHierarchyBuildQueue.h"
#include "vtkTimeCriticalRenderer.h"

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <thread>

namespace
{
/// Holds every build at its start until released: the test's "slow build".
class Gate
{
public:
  explicit Gate(vtkMultiresolutionPolyDataMapper* mapper)
    : Queue(mapper->GetBuildQueue())
  {
    this->Queue->SetProgressHook([this](uint64_t, double progress) {
      if (progress == 0.0)
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        ++this->Arrived;
        this->Changed.notify_all();
        this->Changed.wait(lock, [this] { return this->Open; });
      }
    });
  }
  void WaitForArrivals(int count)
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Changed.wait(lock, [this, count] { return this->Arrived >= count; });
  }
  void Release()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Open = true;
    this->Changed.notify_all();
  }

  ~Gate()
  {
    // No worker may still be inside this gate's hook once it is gone.
    this->Release();
    this->Queue->WaitAll();
    this->Queue->SetProgressHook(nullptr);
  }

private:
  vtkSmartPointer<vtkHierarchyBuildQueue> Queue;
  std::mutex Mutex;
  std::condition_variable Changed;
  int Arrived = 0;
  bool Open = false;
};

/// The mapper's errors and warnings.
struct Log
{
  explicit Log(vtkObject* object)
    : Errors(object, vtkCommand::ErrorEvent)
    , Warnings(object, vtkCommand::WarningEvent)
  {
  }
  EventCounter Errors;
  EventCounter Warnings;
};

vtkSmartPointer<vtkPolyData> Surface(double cx = 0.0, int theta = 48)
{
  return tt::MakeBumpySurface(0.8, theta, theta / 2, cx, 0, 0, 9.0);
}

/// Every test starts with an empty process cache: the mappers' builds share
/// it, and a hit would finish a build that a test holds on purpose.
class MultiresolutionMapperBackground : public ::testing::Test
{
protected:
  void SetUp() override { vtkHierarchyBuildCache::GetSharedInstance()->Clear(); }
};

TEST_F(MultiresolutionMapperBackground, OffByDefault)
{
  auto surface = Surface();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EXPECT_FALSE(mapper->GetBackgroundBuilds());
  mapper->SetInputData(surface);
  Log log(mapper);
  Scene scene(mapper);
  scene.Render();
  EXPECT_FALSE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 0);
  EXPECT_EQ(log.Warnings.Count, 1); // not a TOM: drawn in full, as before
  mapper->WaitForHierarchies();       // nothing to wait for
  EXPECT_FALSE(mapper->GetObjectIsTOM(0));
}

TEST_F(MultiresolutionMapperBackground, DrawsWhileBuildingThenSwapsTheHierarchyIn)
{
  auto surface = Surface();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->BackgroundBuildsOn();
  Gate gate(mapper);
  Log log(mapper);
  Scene scene(mapper);

  // Frames while the build is held: the leaf in full, as a fixed-cost object.
  scene.Render();
  gate.WaitForArrivals(1);
  ASSERT_EQ(mapper->GetNumberOfObjects(), 1);
  EXPECT_FALSE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 1);
  const vtkIdType full = mapper->GetObjectNumberOfTriangles(0);
  EXPECT_EQ(full, surface->GetNumberOfPolys());
  EXPECT_EQ(mapper->GetRenderedTriangles(), full);
  const int pixels = scene.CountForeground();
  EXPECT_GT(pixels, 1000);
  mapper->SetObjectResolution(0, 0.2); // no hierarchy yet: still in full
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), full);
  EXPECT_EQ(mapper->GetNumberOfSwappedHierarchies(), 0);
  EXPECT_EQ(mapper->GetNumberOfBackgroundBuilds(), 0);

  // Once done, the next render swaps the hierarchy in, without a pipeline update.
  gate.Release();
  mapper->GetBuildQueue()->WaitAll();
  const vtkIdType vertexBuilds = mapper->GetVertexBufferBuildCount();
  scene.Render();
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 0);
  EXPECT_EQ(mapper->GetNumberOfSwappedHierarchies(), 1);
  EXPECT_EQ(mapper->GetNumberOfBackgroundBuilds(), 1);
  EXPECT_EQ(mapper->GetNumberOfBackgroundCacheHits(), 0);
  EXPECT_EQ(mapper->GetObjectNumberOfTriangles(0), full);
  EXPECT_LT(mapper->GetObjectCoarsestResolution(0), 0.2);
  EXPECT_GT(mapper->GetVertexBufferBuildCount(), vertexBuilds); // reordered vertices uploaded
  EXPECT_LT(mapper->GetRenderedTriangles(), full / 4 + 8);
  EXPECT_GT(mapper->GetRenderedTriangles(), full / 8);
  mapper->SetObjectResolution(0, 1.0);
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), full);
  EXPECT_NEAR(scene.CountForeground(), pixels, 0.01 * pixels); // the same surface
  EXPECT_TRUE(log.Warnings.Count == 0);
  EXPECT_TRUE(log.Errors.Count == 0);
  EXPECT_EQ(mapper->GetBuildQueue()->GetNumberOfBuilds(), 1);
}

TEST_F(MultiresolutionMapperBackground, NewInputCancelsTheStaleBuild)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, Surface(-1.0));
  blocks->SetBlock(1, Surface(1.0, 40));
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->BackgroundBuildsOn();
  vtkHierarchyBuildQueue* queue = mapper->GetBuildQueue();
  queue->SetNumberOfThreads(1);
  Gate gate(mapper);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 5);
  scene.Render();
  gate.WaitForArrivals(1); // block 0 builds (held), block 1 waits
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 2);

  // A new time step replaces block 1: its build is cancelled before it ran.
  auto replacement = Surface(1.0, 44);
  blocks->SetBlock(1, replacement);
  scene.Render();
  EXPECT_EQ(queue->GetNumberOfCancelledBuilds(), 1);
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 2);
  gate.Release();
  mapper->WaitForHierarchies();
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 0);
  ASSERT_EQ(mapper->GetNumberOfObjects(), 2);
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_TRUE(mapper->GetObjectIsTOM(1));
  EXPECT_EQ(mapper->GetObjectNumberOfTriangles(1), replacement->GetNumberOfPolys());
  EXPECT_EQ(queue->GetNumberOfBuilds(), 2);

  // Another new input whose leaves are both gone while their builds run.
  Gate second(mapper);
  vtkNew<vtkMultiBlockDataSet> next;
  next->SetNumberOfBlocks(1);
  next->SetBlock(0, Surface(0.0, 36));
  mapper->SetInputDataObject(next);
  scene.Render();
  second.WaitForArrivals(1);
  // Back to the first input: the running build of the second is cancelled;
  // the first one's leaves come from the process's cache, unbuilt.
  mapper->SetInputDataObject(blocks);
  scene.Render();
  EXPECT_EQ(queue->GetNumberOfCancelledBuilds(), 2);
  second.Release();
  mapper->WaitForHierarchies();
  EXPECT_EQ(queue->GetNumberOfFinished(), 0);
  EXPECT_EQ(queue->GetNumberOfBuilds(), 2);
  EXPECT_EQ(queue->GetNumberOfStoreHits(), 2);
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_TRUE(mapper->GetObjectIsTOM(1));
}

TEST_F(MultiresolutionMapperBackground, ContentShownAgainComesFromTheSharedCache)
{
  // A time step or an edit shown again (a new leaf object, the same content)
  // is not built again: the first mapper's build went to the process's cache.
  auto surface = Surface();
  vtkNew<vtkMultiresolutionPolyDataMapper> first;
  first->SetInputData(surface);
  first->BackgroundBuildsOn();
  Scene scene(first);
  scene.Render();
  first->WaitForHierarchies();
  scene.Render();
  ASSERT_TRUE(first->GetObjectIsTOM(0));
  EXPECT_EQ(first->GetBuildQueue()->GetNumberOfBuilds(), 1);

  auto again = vtkSmartPointer<vtkPolyData>::New();
  again->DeepCopy(surface);
  vtkNew<vtkMultiresolutionPolyDataMapper> second;
  second->SetInputData(again);
  second->BackgroundBuildsOn();
  Scene other(second);
  other.Render();
  // In the first frame: no stand-in drawn, no build queued.
  EXPECT_TRUE(second->GetObjectIsTOM(0));
  EXPECT_EQ(second->GetNumberOfPendingHierarchies(), 0);
  other.Render();
  EXPECT_TRUE(second->GetObjectIsTOM(0));
  EXPECT_EQ(second->GetBuildQueue()->GetNumberOfBuilds(), 0);
  EXPECT_EQ(second->GetBuildQueue()->GetNumberOfStoreHits(), 1);
  EXPECT_EQ(second->GetNumberOfBackgroundCacheHits(), 1);
  EXPECT_EQ(second->GetNumberOfBackgroundBuilds(), 0);
}

TEST_F(MultiresolutionMapperBackground, EqualLeavesAreBuiltOnce)
{
  auto surface = Surface();
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(surface);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, surface);
  blocks->SetBlock(1, copy);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->BackgroundBuildsOn();
  mapper->WaitForHierarchies();
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_TRUE(mapper->GetObjectIsTOM(1));
  EXPECT_EQ(mapper->GetBuildQueue()->GetNumberOfBuilds(), 1);
}

TEST_F(MultiresolutionMapperBackground, FinishedBuildsWaitForTheRestOrForTheSwapInterval)
{
  // Each swap reads every object again, so builds that finish one by one are
  // swapped in together: when the last one is done, or after the interval.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, Surface(0.0));
  blocks->SetBlock(1, Surface(3.0));
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->BackgroundBuildsOn();
  vtkHierarchyBuildQueue* queue = mapper->GetBuildQueue();
  std::mutex mutex;
  std::condition_variable changed;
  std::optional<uint64_t> firstKey; // a build reports progress more than once
  bool open = false;
  queue->SetProgressHook([&](uint64_t key, double) {
    std::unique_lock<std::mutex> lock(mutex);
    if (!firstKey)
    {
      firstKey = key;
    }
    if (key != *firstKey)
    {
      changed.wait(lock, [&open] { return open; }); // the second build is held
    }
  });
  Scene scene(mapper);
  const auto beforeRender = std::chrono::steady_clock::now();
  scene.Render();
  const auto rendered = std::chrono::steady_clock::now();
  for (int i = 0; i < 1000 && queue->GetNumberOfFinished() < 1; ++i)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_EQ(queue->GetNumberOfFinished(), 1);
  auto countTOMs = [&mapper] {
    return int(mapper->GetObjectIsTOM(0)) + int(mapper->GetObjectIsTOM(1));
  };
  if (std::chrono::steady_clock::now() - beforeRender < std::chrono::milliseconds(1500))
  {
    scene.Render(); // within the interval, with a build still running: no swap
    EXPECT_EQ(countTOMs(), 0);
    EXPECT_EQ(mapper->GetNumberOfSwappedHierarchies(), 0);
  }
  // The builds were submitted during the first render: its end is after them
  // (slow builds, such as the sanitizers', make that render long).
  std::this_thread::sleep_until(rendered + std::chrono::milliseconds(2100));
  scene.Render(); // the interval passed: the finished one comes in
  EXPECT_EQ(countTOMs(), 1);
  EXPECT_EQ(mapper->GetNumberOfSwappedHierarchies(), 1);
  {
    std::lock_guard<std::mutex> lock(mutex);
    open = true;
  }
  changed.notify_all();
  mapper->WaitForHierarchies();
  EXPECT_EQ(countTOMs(), 2);
  EXPECT_EQ(mapper->GetNumberOfSwappedHierarchies(), 2);
  queue->SetProgressHook(nullptr);
}

TEST_F(MultiresolutionMapperBackground, RendererWaitsForItsMappers)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> first;
  first->SetInputData(Surface(-1.0));
  first->BackgroundBuildsOn();
  vtkNew<vtkMultiresolutionPolyDataMapper> second;
  second->SetInputData(Surface(1.0));
  second->BackgroundBuildsOn();
  second->SetBackgroundHierarchy(vtkHierarchyBuildQueue::MERGE_TREE);
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkActor> a, b;
  a->SetMapper(first);
  b->SetMapper(second);
  renderer->AddActor(a);
  renderer->AddActor(b);
  first->UpdateObjects();
  second->UpdateObjects();
  EXPECT_EQ(renderer->GetNumberOfPendingHierarchies(), 2);
  renderer->WaitForHierarchies();
  EXPECT_EQ(renderer->GetNumberOfPendingHierarchies(), 0);
  EXPECT_TRUE(first->GetObjectIsTOM(0));
  EXPECT_FALSE(first->GetObjectIsViewDependent(0));
  EXPECT_TRUE(second->GetObjectIsTOM(0));
  EXPECT_TRUE(second->GetObjectIsViewDependent(0)); // a merge tree
}

TEST_F(MultiresolutionMapperBackground, FailedBuildStaysInFullWithOneError)
{
  // Drawable, but beyond what a hierarchy stores: the builder refuses it.
  auto surface = Surface();
  double p[3];
  surface->GetPoints()->GetPoint(3, p);
  p[0] = 1e30;
  surface->GetPoints()->SetPoint(3, p);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->BackgroundBuildsOn();
  Log log(mapper);
  Scene scene(mapper);
  scene.Render();
  mapper->WaitForHierarchies();
  scene.Render();
  scene.Render();
  EXPECT_FALSE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetRenderedTriangles(), surface->GetNumberOfPolys());
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 0);
  EXPECT_EQ(log.Errors.Count, 1);
  EXPECT_NE(log.Errors.Last.find("no hierarchy built"), std::string::npos) << log.Errors.Last;
  EXPECT_TRUE(log.Warnings.Count == 0);
  EXPECT_EQ(mapper->GetBuildQueue()->GetNumberOfBuilds(), 1); // not resubmitted
}

TEST_F(MultiresolutionMapperBackground, NothingAllocatedPerFrameWhileBuildsRun)
{
  auto surface = Surface();
  vtkNew<vtkMultiresolutionPolyDataMapper> plain;
  plain->SetInputData(surface);
  std::size_t plainFrame = 0;
  {
    Scene scene(plain);
    scene.Render();
    scene.Render();
    const std::size_t before = tt::GetAllocationCount();
    scene.Render();
    plainFrame = tt::GetAllocationCount() - before;
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->BackgroundBuildsOn();
  Gate gate(mapper);
  Scene scene(mapper);
  scene.Render();
  gate.WaitForArrivals(1);
  scene.Render();
  const std::size_t before = tt::GetAllocationCount();
  scene.Render();
  EXPECT_LE(tt::GetAllocationCount() - before, plainFrame);
  gate.Release();
}

TEST_F(MultiresolutionMapperBackground, SwitchingOffKeepsWhatIsDrawnUntilTheInputChanges)
{
  auto surface = Surface();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  Log log(mapper);
  Scene scene(mapper);
  scene.Render();
  EXPECT_EQ(log.Warnings.Count, 1); // not a TOM, drawn in full (background off)
  mapper->BackgroundBuildsOn();     // the current leaf is read again and submitted
  mapper->WaitForHierarchies();
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  mapper->BackgroundBuildsOff();
  scene.Render();
  EXPECT_TRUE(mapper->GetObjectIsTOM(0)); // kept: no re-read for the setting alone
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 0);
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(surface);
  mapper->SetInputData(copy);
  scene.Render();
  EXPECT_FALSE(mapper->GetObjectIsTOM(0)); // a new input, drawn as it is
  EXPECT_EQ(mapper->GetNumberOfPendingHierarchies(), 0);
  EXPECT_EQ(mapper->GetBuildQueue()->GetNumberOfPending(), 0);
  EXPECT_EQ(log.Errors.Count, 0);
}

TEST_F(MultiresolutionMapperBackground, LargeLeavesAreDrawnFromAStandInWhileBuilding)
{
  auto surface = Surface(0.0, 240); // about 57K triangles: large enough for a stand-in
  const vtkIdType full = surface->GetNumberOfPolys();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputData(surface);
  mapper->BackgroundBuildsOn();
  EXPECT_EQ(mapper->GetBackgroundInterimDivisions(), 64);
  Gate gate(mapper);
  Log log(mapper);
  Scene scene(mapper);
  scene.Render();
  gate.WaitForArrivals(1);
  // The stand-in: far fewer triangles on the leaf's own points, the same silhouette.
  EXPECT_FALSE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetObjectNumberOfVertices(0), surface->GetNumberOfPoints());
  EXPECT_LT(mapper->GetRenderedTriangles(), full / 4);
  EXPECT_GT(mapper->GetRenderedTriangles(), full / 50);
  const int interimPixels = scene.CountForeground();
  gate.Release();
  mapper->WaitForHierarchies();
  scene.Render();
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetRenderedTriangles(), full);
  EXPECT_NEAR(interimPixels, scene.CountForeground(), 0.03 * interimPixels);
  EXPECT_EQ(log.Warnings.Count, 0);
  EXPECT_EQ(log.Errors.Count, 0);

  // Off (0): a pending leaf is drawn in full.
  vtkNew<vtkMultiresolutionPolyDataMapper> plain;
  plain->SetInputData(surface);
  plain->BackgroundBuildsOn();
  plain->SetBackgroundInterimDivisions(0);
  Gate held(plain);
  Scene other(plain);
  other.Render();
  EXPECT_EQ(plain->GetRenderedTriangles(), full);
}

TEST_F(MultiresolutionMapperBackground, BadSettingIsAnError)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  Log log(mapper);
  mapper->SetBackgroundHierarchy(5);
  EXPECT_EQ(mapper->GetBackgroundHierarchy(), 0);
  EXPECT_EQ(log.Errors.Count, 1);
}
}

namespace
{
/// A time-critical renderer drawing `mapper`, whose builds a gate holds.
struct CalibrationScene
{
  explicit CalibrationScene(vtkMultiresolutionPolyDataMapper* mapper)
  {
    this->Actor->SetMapper(mapper);
    this->Renderer->AddActor(this->Actor);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(200, 200);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->ResetCamera();
  }
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkActor> Actor;
};
}

TEST_F(MultiresolutionMapperBackground, CalibrationHeldBackByBuildsLeavesItToTheFrames)
{
  // The automatic calibration does not run while builds are pending, nor
  // later (the frame in which they end may come while the user drags): the
  // frames themselves fit the model, which then counts as measured (what
  // dropping objects needs).
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputData(Surface());
  mapper->BackgroundBuildsOn();
  std::optional<Gate> gate(std::in_place, mapper);
  CalibrationScene scene(mapper);
  scene.Renderer->SetTargetFrameTime(0.1);
  scene.Window->Render();
  scene.Window->Render();
  EXPECT_FALSE(scene.Renderer->GetCostModelMeasured());
  gate.reset(); // the build goes on and finishes
  mapper->GetBuildQueue()->WaitAll();
  for (int frame = 0; frame < 20; ++frame)
  {
    scene.Renderer->GetActiveCamera()->Azimuth(3.0);
    scene.Window->Render();
  }
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_FALSE(scene.Renderer->GetCalibrated());
  EXPECT_EQ(scene.Renderer->GetCalibrationRenders(), 0);
  // Fitted from the frames: measured now (an overloaded frame may drop objects).
  EXPECT_TRUE(scene.Renderer->GetCostModelMeasured());
  // Without background builds the first render calibrates, as before.
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputData(Surface());
  builder->Update();
  vtkNew<vtkMultiresolutionPolyDataMapper> built;
  built->SetInputData(builder->GetOutput());
  CalibrationScene plain(built);
  plain.Window->Render();
  EXPECT_TRUE(plain.Renderer->GetCalibrated());
  EXPECT_TRUE(plain.Renderer->GetCostModelMeasured());
  EXPECT_GT(plain.Renderer->GetCalibrationRenders(), 0);
}

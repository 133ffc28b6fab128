// SPDX-License-Identifier: BSD-3-Clause
// View-dependent rendering of merge trees by vtkMultiresolutionPolyDataMapper
// and vtkTimeCriticalRenderer: the index buffer against the fronts of
// vtkExtractViewDependentMesh (fixed accuracy and budget, actor transforms,
// horizontal view angles), fixed-accuracy and budget behaviour, index-only
// updates on camera moves, no allocation, cell data of the front, wireframe
// and points, refinement off, bad settings and bad trees, the renderer's
// settings, statistics and cost accounting, and image baselines.
//
// Image thresholds are those of TestvtkMultiresolutionPolyDataMapper: a channel value
// differing by more than 0.05 fails; at most 0.1% may fail, RMS below 0.005.
#include "TOMTraversal.h"
#include "RenderTestSupport.h"
#include "TestImageCompare.h"
#include "vtkExtractViewDependentMesh.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"
#include "vtkTimeCriticalRenderer.h"

#include "AllocationCounter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkLookupTable.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
const tt::ImageTolerance Tolerance{ 0.05, 0.001, 0.005 };
constexpr double ChannelThreshold = 0.05;
constexpr int ImageSize = 300;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Inf = std::numeric_limits<double>::infinity();

// Xvfb resets when a window closes; see tt::KeepDisplayOpen.
::testing::Environment* const KeepDisplay =
  ::testing::AddGlobalTestEnvironment(new tt::KeepDisplayOpen);

std::string OutputPath(const std::string& name)
{
  return std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/ViewDependent_" + name + ".png";
}

std::string BaselinePath(const std::string& name)
{
  return std::string(TIMECRITICAL_BASELINE_DIR) + "/ViewDependent_" + name + ".png";
}

// The merge tree of a surface, with each point's own id in the point array
// "TOMVertex": vtkExtractViewDependentMesh keeps point data, so its fronts can
// be mapped back to the ids in the mapper's index buffer.
vtkSmartPointer<vtkPolyData> BuildTree(vtkPolyData* surface)
{
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetInputData(surface);
  builder->Update();
  auto tree = vtkSmartPointer<vtkPolyData>::New();
  tree->ShallowCopy(builder->GetOutput());
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("TOMVertex");
  ids->SetNumberOfValues(tree->GetNumberOfPoints());
  for (vtkIdType i = 0; i < tree->GetNumberOfPoints(); ++i)
  {
    ids->SetValue(i, i);
  }
  tree->GetPointData()->AddArray(ids);
  return tree;
}

vtkSmartPointer<vtkPolyData> MakeTree(double radius, int theta, int phi, double cx = 0,
  double cy = 0, double cz = 0, double frequency = 9.0)
{
  return BuildTree(tt::MakeBumpySurface(radius, theta, phi, cx, cy, cz, frequency));
}

// The tree most tests use (about 4,700 triangles), built once.
vtkPolyData* SphereTree()
{
  static vtkSmartPointer<vtkPolyData> tree = MakeTree(1.0, 60, 40);
  return tree;
}

vtkSmartPointer<vtkPolyData> MakeTOM(double radius, int theta, int phi, double cx, double cy,
  double cz)
{
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputData(tt::MakeBumpySurface(radius, theta, phi, cx, cy, cz, 6.0));
  builder->Update();
  auto tom = vtkSmartPointer<vtkPolyData>::New();
  tom->ShallowCopy(builder->GetOutput());
  return tom;
}

vtkIdType BaseTriangles(vtkPolyData* tom)
{
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  return reader->GetBaseTriangleCount();
}

// Triangles of a TOM at resolution r from the traversal core (leaf point ids).
std::vector<uint32_t> TraversalTriangles(vtkPolyData* tom, double r)
{
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  timecritical::TOMTraversal traversal(reader->GetMesh());
  const uint32_t count =
    traversal.GetVertexCountForTriangles(traversal.GetTrianglesForResolution(r));
  std::vector<uint32_t> triangles;
  const uint32_t m = traversal.Extract(count, triangles);
  triangles.resize(3 * static_cast<size_t>(m));
  return triangles;
}

using tt::EventCounter;

// One actor in an offscreen window; the camera is set by LookAt() with a fixed
// clipping range that holds every object of these tests.
struct Scene
{
  explicit Scene(vtkMapper* mapper, int width = ImageSize, int height = ImageSize)
  {
    this->Actor->SetMapper(mapper);
    this->Actor->GetProperty()->SetColor(0.85, 0.7, 0.45);
    this->Actor->GetProperty()->SetSpecular(0.3);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(width, height);
    this->Window->AddRenderer(this->Renderer);
    this->LookAt(0, 0, 3.5);
  }
  void LookAt(double x, double y, double z, double fx = 0, double fy = 0, double fz = 0)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(x, y, z);
    camera->SetFocalPoint(fx, fy, fz);
    camera->SetViewUp(0, 1, 0);
    camera->SetClippingRange(0.05, 60.0);
  }
  void Render() { this->Window->Render(); }
  void Save(const std::string& path)
  {
    this->Render();
    tt::WriteWindowPNG(this->Window, path, false);
  }
  // Pixels that are not background in the last render.
  int CountForeground() { return tt::CountForegroundPixels(this->Window); }
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
};

using Triangle = std::array<uint32_t, 3>;

// A triangle rotated so that its smallest id comes first (orientation kept).
Triangle Rotated(uint32_t a, uint32_t b, uint32_t c)
{
  if (b < a && b < c)
  {
    return { b, c, a };
  }
  if (c < a && c < b)
  {
    return { c, a, b };
  }
  return { a, b, c };
}

// Surface triangles [first, first + count) of the last index buffer, minus `offset`.
std::vector<Triangle> MapperTriangles(
  vtkMultiresolutionPolyDataMapper* mapper, vtkIdType first, vtkIdType count, uint32_t offset)
{
  std::vector<Triangle> triangles;
  const unsigned int* ids = mapper->GetLastIndices() + 3 * first;
  for (vtkIdType t = 0; t < count; ++t)
  {
    triangles.push_back(
      Rotated(ids[3 * t] - offset, ids[3 * t + 1] - offset, ids[3 * t + 2] - offset));
  }
  return triangles;
}

// Triangles of object i of a surface render, in the leaf's point ids.
std::vector<Triangle> ObjectTriangles(vtkMultiresolutionPolyDataMapper* mapper, vtkIdType i)
{
  vtkIdType first = 0;
  for (vtkIdType j = 0; j < i; ++j)
  {
    first += mapper->GetObjectRenderedTriangles(j);
  }
  return MapperTriangles(mapper, first, mapper->GetObjectRenderedTriangles(i),
    static_cast<uint32_t>(mapper->GetObjectVertexOffset(i)));
}

// The triangles of a front extracted by the filter, in TOM vertex ids.
std::vector<Triangle> FilterTriangles(vtkPolyData* front)
{
  vtkDataArray* ids = front->GetPointData()->GetArray("TOMVertex");
  EXPECT_NE(ids, nullptr);
  std::vector<Triangle> triangles;
  if (!ids)
  {
    return triangles;
  }
  vtkIdType npts = 0;
  const vtkIdType* pts = nullptr;
  for (vtkIdType c = 0; c < front->GetNumberOfPolys(); ++c)
  {
    front->GetPolys()->GetCellAtId(c, npts, pts);
    EXPECT_EQ(npts, 3);
    triangles.push_back(Rotated(static_cast<uint32_t>(ids->GetTuple1(pts[0])),
      static_cast<uint32_t>(ids->GetTuple1(pts[1])), static_cast<uint32_t>(ids->GetTuple1(pts[2]))));
  }
  return triangles;
}

std::vector<Triangle> Sorted(std::vector<Triangle> triangles)
{
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

// Closed, consistently oriented 2-manifold: every directed edge once and its
// reverse once; returns the Euler characteristic V - E + F (V = used vertices).
struct Topology
{
  bool ClosedManifold = true;
  long Euler = 0;
};

Topology Analyze(const std::vector<Triangle>& triangles)
{
  Topology result;
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  std::set<uint32_t> vertices;
  for (const Triangle& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
      vertices.insert(t[k]);
    }
  }
  for (const auto& edge : directed)
  {
    const auto reverse = directed.find({ edge.first.second, edge.first.first });
    if (edge.second != 1 || reverse == directed.end() || reverse->second != 1)
    {
      result.ClosedManifold = false;
    }
  }
  result.Euler = static_cast<long>(vertices.size()) - static_cast<long>(directed.size() / 2) +
    static_cast<long>(triangles.size());
  return result;
}

// Sets `extract` to refine `tree` as `mapper` does for the view of `scene`:
// the camera taken into the actor's coordinates, the renderer's headlight, the
// window's size, the mapper's settings and, in budget mode, its budget.
void MatchFilter(vtkExtractViewDependentMesh* extract, vtkMultiresolutionPolyDataMapper* mapper,
  Scene& scene, vtkIdType objectTriangles)
{
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  double toObject[16];
  vtkMatrix4x4::Invert(scene.Actor->GetMatrix()->GetData(), toObject);
  auto transform = [&](const double* w, double* o, double h)
  {
    for (int r = 0; r < 3; ++r)
    {
      o[r] = toObject[4 * r] * w[0] + toObject[4 * r + 1] * w[1] + toObject[4 * r + 2] * w[2] +
        h * toObject[4 * r + 3];
    }
  };
  double eye[3], focal[3], up[3];
  transform(camera->GetPosition(), eye, 1.0);
  transform(camera->GetFocalPoint(), focal, 1.0);
  transform(camera->GetViewUp(), up, 0.0);
  const double scale = std::cbrt(scene.Actor->GetMatrix()->Determinant());
  extract->SetCameraPosition(eye[0], eye[1], eye[2]);
  extract->SetCameraFocalPoint(focal[0], focal[1], focal[2]);
  extract->SetCameraViewUp(up[0], up[1], up[2]);
  extract->SetCameraViewAngle(camera->GetViewAngle());
  extract->GetCamera()->SetUseHorizontalViewAngle(camera->GetUseHorizontalViewAngle());
  extract->SetCameraParallelProjection(camera->GetParallelProjection() != 0);
  extract->SetCameraParallelScale(camera->GetParallelScale() / scale);
  const int* size = scene.Window->GetSize();
  extract->SetViewportSize(size[0], size[1]);
  // The renderer's automatic light is a headlight: towards the eye.
  extract->SetLightDirection(eye[0] - focal[0], eye[1] - focal[1], eye[2] - focal[2]);
  extract->SetPixelThreshold(mapper->GetPixelThreshold());
  extract->SetBackFaceSimplification(mapper->GetBackFaceSimplification());
  extract->SetSilhouetteRefinement(mapper->GetSilhouetteRefinement());
  extract->SetSilhouetteFactor(mapper->GetSilhouetteFactor());
  extract->SetHighlightRefinement(mapper->GetHighlightRefinement());
  extract->SetHighlightFactor(mapper->GetHighlightFactor());
  if (mapper->GetRefinementMode() == vtkMultiresolutionPolyDataMapper::BUDGET)
  {
    extract->SetRefinementModeToTriangleBudget();
    extract->SetTriangleBudget(static_cast<vtkIdType>(
      std::lround(mapper->GetObjectResolution(0) * static_cast<double>(objectTriangles))));
  }
  else
  {
    extract->SetRefinementModeToFixedAccuracy();
  }
}

struct View
{
  double Eye[3];
  double Focal[3];
};

// Views of the unit sphere: far, oblique, close (partly outside the frustum),
// from above, and looking past it (its limb at the side of the view).
const View Views[] = {
  { { 0, 0, 3.5 }, { 0, 0, 0 } },
  { { 2.5, 1.2, 1.0 }, { 0, 0, 0 } },
  { { 0.4, 0.3, 1.7 }, { 0.2, 0.1, 0 } },
  { { 0.3, 6.0, 0.2 }, { 0, 0, 0 } },
  { { 0.0, 0.0, 2.5 }, { 1.2, 0.0, 0.0 } },
};

void ExpectSameFront(vtkMultiresolutionPolyDataMapper* mapper, vtkExtractViewDependentMesh* extract)
{
  vtkPolyData* front = extract->GetOutput();
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(0), extract->GetNumberOfDisplayTriangles());
  EXPECT_EQ(mapper->GetObjectRenderedVertices(0), extract->GetNumberOfDisplayVertices());
  ASSERT_EQ(mapper->GetLastIndexCount(), 3 * mapper->GetObjectRenderedTriangles(0));
  const auto drawn = Sorted(ObjectTriangles(mapper, 0));
  const auto expected = Sorted(FilterTriangles(front));
  EXPECT_EQ(drawn.size(), expected.size());
  EXPECT_TRUE(drawn == expected) << "the index buffer is not the filter's front";
}
}

//------------------------------------------------------------------------------
// The index buffer against the filter, for the same camera, viewport and settings.

TEST(ViewDependentMapper, FrontEqualsTheExtractionFilter)
{
  vtkPolyData* tree = SphereTree();
  const vtkIdType triangles = tree->GetNumberOfPolys();
  for (bool budget : { false, true })
  {
    for (bool transformed : { false, true })
    {
      SCOPED_TRACE(std::string(budget ? "budget" : "fixed accuracy") +
        (transformed ? ", transformed actor" : ""));
      vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
      mapper->SetInputDataObject(tree);
      mapper->UpdateObjects();
      ASSERT_EQ(mapper->GetNumberOfObjects(), 1);
      ASSERT_TRUE(mapper->GetObjectIsViewDependent(0));
      if (budget)
      {
        mapper->SetRefinementModeToBudget();
        mapper->SetResolution(0.3);
      }
      else
      {
        mapper->SetRefinementModeToFixedAccuracy();
        mapper->SetPixelThreshold(1.5);
      }
      Scene scene(mapper);
      if (transformed)
      {
        // The view must be taken into the leaf's coordinates (uniform scale,
        // rotation, translation).
        scene.Actor->SetScale(0.6);
        scene.Actor->RotateWXYZ(35, 0.3, 1.0, 0.2);
        scene.Actor->SetPosition(0.1, -0.2, 0.3);
      }
      // One filter for the whole camera path: the budget mode depends on the
      // previous front, and both start from the coarsest one.
      vtkNew<vtkExtractViewDependentMesh> extract;
      extract->SetInputData(tree);
      std::set<std::vector<Triangle>> fronts;
      for (const View& view : Views)
      {
        SCOPED_TRACE("eye " + std::to_string(view.Eye[0]) + " " + std::to_string(view.Eye[1]) +
          " " + std::to_string(view.Eye[2]));
        scene.LookAt(view.Eye[0], view.Eye[1], view.Eye[2], view.Focal[0], view.Focal[1],
          view.Focal[2]);
        scene.Render();
        EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
        MatchFilter(extract, mapper, scene, triangles);
        extract->Update();
        ExpectSameFront(mapper, extract);
        fronts.insert(Sorted(ObjectTriangles(mapper, 0)));
        if (budget)
        {
          EXPECT_LE(mapper->GetObjectRenderedTriangles(0),
            std::lround(0.3 * static_cast<double>(triangles)) + 16);
        }
      }
      // The views give different fronts (or the comparison would prove little).
      EXPECT_GE(fronts.size(), 4u);
    }
  }
}

TEST(ViewDependentMapper, HorizontalViewAngleAndWideViewport)
{
  // VTK's horizontal view angle spans the width: the vertical one, which the
  // projected error needs, follows from the aspect ratio.
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->SetRefinementModeToFixedAccuracy();
  mapper->SetPixelThreshold(1.0);
  Scene scene(mapper, 420, 200);
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(tree);
  for (bool horizontal : { false, true })
  {
    SCOPED_TRACE(horizontal ? "horizontal view angle" : "vertical view angle");
    scene.LookAt(0.5, 0.4, 2.6);
    scene.Renderer->GetActiveCamera()->SetUseHorizontalViewAngle(horizontal);
    scene.Render();
    MatchFilter(extract, mapper, scene, tree->GetNumberOfPolys());
    extract->Update();
    ExpectSameFront(mapper, extract);
  }
}

TEST(ViewDependentMapper, ParallelProjection)
{
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->SetRefinementModeToFixedAccuracy();
  mapper->SetPixelThreshold(1.0);
  Scene scene(mapper);
  scene.Actor->SetScale(1.5);
  vtkNew<vtkExtractViewDependentMesh> extract;
  extract->SetInputData(tree);
  vtkIdType previous = 0;
  // Zooming from 3 to 2 keeps the object in view (at 1 the frustum would
  // cut away more than the zoom adds: its visible half is nearly fully
  // refined already, the shading error counting fine bumps).
  for (double parallelScale : { 3.0, 2.0 })
  {
    scene.LookAt(1.0, 0.5, 4.0);
    scene.Renderer->GetActiveCamera()->ParallelProjectionOn();
    scene.Renderer->GetActiveCamera()->SetParallelScale(parallelScale);
    scene.Render();
    MatchFilter(extract, mapper, scene, tree->GetNumberOfPolys());
    extract->Update();
    ExpectSameFront(mapper, extract);
    EXPECT_GT(mapper->GetObjectRenderedTriangles(0), previous) << "smaller scale = more pixels";
    previous = mapper->GetObjectRenderedTriangles(0);
  }
}

//------------------------------------------------------------------------------
// Fixed accuracy and budget behaviour, seen through the index buffer.

TEST(ViewDependentMapper, FixedAccuracyFollowsThresholdAndZoomWithClosedFronts)
{
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->SetRefinementModeToFixedAccuracy();
  Scene scene(mapper);
  scene.LookAt(1.2, 0.8, 2.6);
  std::vector<vtkIdType> counts;
  for (double tau : { 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 128.0, 1e6 })
  {
    SCOPED_TRACE("tau " + std::to_string(tau));
    mapper->SetPixelThreshold(tau);
    EXPECT_EQ(mapper->GetPixelThreshold(), tau);
    scene.Render();
    const vtkIdType count = mapper->GetRenderedTriangles();
    EXPECT_EQ(mapper->GetLastIndexCount(), 3 * count);
    if (!counts.empty())
    {
      EXPECT_LE(count, counts.back());
    }
    counts.push_back(count);
    const Topology topology = Analyze(ObjectTriangles(mapper, 0));
    EXPECT_TRUE(topology.ClosedManifold);
    EXPECT_EQ(topology.Euler, 2);
  }
  EXPECT_LT(counts[6], counts[0] / 2) << "128 pixels should simplify much more than 1/4 pixel";
  // Close by, the eye lies in the bounding spheres of a few coarse nodes,
  // which are then always split; from afar an enormous threshold gives the
  // coarsest mesh.
  scene.LookAt(0, 0, 40.0);
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), BaseTriangles(tree));

  // Closer, or zoomed in, with the whole sphere in view: more detail for the
  // same threshold.
  mapper->SetPixelThreshold(2.0);
  scene.LookAt(0, 0, 12.0);
  scene.Render();
  const vtkIdType far = mapper->GetRenderedTriangles();
  scene.LookAt(0, 0, 6.0);
  scene.Render();
  const vtkIdType near = mapper->GetRenderedTriangles();
  scene.LookAt(0, 0, 12.0);
  scene.Renderer->GetActiveCamera()->Zoom(2.0);
  scene.Render();
  const vtkIdType zoomed = mapper->GetRenderedTriangles();
  EXPECT_GT(near, far);
  EXPECT_GT(zoomed, far);
  EXPECT_TRUE(Analyze(ObjectTriangles(mapper, 0)).ClosedManifold);
}

TEST(ViewDependentMapper, BudgetFollowsTheResolution)
{
  vtkPolyData* tree = SphereTree();
  const vtkIdType triangles = tree->GetNumberOfPolys();
  const vtkIdType base = BaseTriangles(tree);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->UpdateObjects(); // resolutions are per object: read them first
  EXPECT_EQ(mapper->GetRefinementMode(), vtkMultiresolutionPolyDataMapper::BUDGET);
  // PixelThreshold is a floor in budget mode too (no sub-threshold detail is
  // bought), and back faces are never wanted: without either, every node in
  // view competes for the budget.
  mapper->SetPixelThreshold(0.0);
  mapper->BackFaceSimplificationOff();
  Scene scene(mapper);
  scene.LookAt(1.2, 0.8, 2.6);
  vtkIdType previous = 0;
  for (double r : { 0.02, 0.05, 0.1, 0.25, 0.5, 0.8, 1.0 })
  {
    SCOPED_TRACE("resolution " + std::to_string(r));
    mapper->SetResolution(r);
    scene.Render();
    const vtkIdType budget = std::lround(r * static_cast<double>(triangles));
    const vtkIdType count = mapper->GetRenderedTriangles();
    // Forced splits may overshoot by a few triangles (ViewDependentRefinement::UpdateBudget).
    EXPECT_LE(count, std::max(budget, base) + 16);
    EXPECT_LE(count, triangles);
    EXPECT_GT(count, previous);
    if (budget > base)
    {
      EXPECT_GT(count, budget * 3 / 4);
    }
    EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
    const Topology topology = Analyze(ObjectTriangles(mapper, 0));
    EXPECT_TRUE(topology.ClosedManifold);
    EXPECT_EQ(topology.Euler, 2);
    previous = count;
  }
  // Resolution 0 culls: nothing drawn, no draw call, no refinement.
  mapper->SetResolution(0.0);
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), 0);
  EXPECT_EQ(mapper->GetObjectRenderedVertices(0), 0);
  EXPECT_EQ(mapper->GetLastIndexCount(), 0);
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 0);
  EXPECT_EQ(mapper->GetObjectSplits(0) + mapper->GetObjectMerges(0), 0);
  EXPECT_EQ(scene.CountForeground(), 0);
  // Resolution 0 culls in fixed-accuracy mode too.
  mapper->SetRefinementModeToFixedAccuracy();
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), 0);
  EXPECT_EQ(scene.CountForeground(), 0);
}

//------------------------------------------------------------------------------
// A composite of merge trees, TOMs and a plain surface: camera moves rewrite
// only the index buffer, all in one draw call.
namespace
{
TEST(ViewDependentMapper, TimeLimitedBudgetsMoveByBoundedStepsAndConverge)
{
  vtkPolyData* tree = SphereTree();
  const vtkIdType triangles = tree->GetNumberOfPolys();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->UpdateObjects();
  mapper->SetPixelThreshold(0.0);
  mapper->BackFaceSimplificationOff();
  Scene scene(mapper);
  scene.LookAt(1.2, 0.8, 2.6);
  // The front of the whole budget, reached at once without a limit (parts
  // out of view stay coarse, so it is less than the whole mesh).
  mapper->SetResolution(1.0);
  scene.Render();
  const vtkIdType unlimited = mapper->GetRenderedTriangles();
  EXPECT_LE(unlimited, triangles);
  mapper->SetResolution(0.0001); // the coarsest front
  scene.Render();
  const vtkIdType coarsest = mapper->GetRenderedTriangles();
  ASSERT_LT(coarsest + 1000, unlimited);

  // 10 us per render: the step is what fits at the rate measured so far
  // (tens of thousands of splits per second), far less than the change.
  mapper->SetRefinementTimeLimit(1e-5);
  EXPECT_EQ(mapper->GetRefinementTimeLimit(), 1e-5);
  mapper->SetResolution(1.0);
  scene.Render();
  vtkIdType previous = mapper->GetRenderedTriangles();
  EXPECT_GT(previous, coarsest);
  EXPECT_LT(previous - coarsest, (unlimited - coarsest) / 2);
  // Then steps follow the measured rate, and the front reaches the same
  // front in a bounded number of renders, never shrinking; a step too small
  // for the next split's forced splits grows until it fits (a few renders
  // without change at most).
  int renders = 1;
  int unchanged = 0;
  for (; previous < unlimited && renders < 2000; ++renders)
  {
    scene.Render();
    const vtkIdType count = mapper->GetRenderedTriangles();
    ASSERT_GE(count, previous) << "render " << renders;
    unchanged = count == previous ? unchanged + 1 : 0;
    ASSERT_LT(unchanged, 12) << "render " << renders;
    previous = count;
  }
  EXPECT_EQ(previous, unlimited);
  EXPECT_GT(renders, 2);
  // Without a limit the same change happens at once.
  mapper->SetRefinementTimeLimit(0.0);
  mapper->SetResolution(0.0001);
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), coarsest);
  // Bad limits are errors and ignored.
  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  mapper->SetRefinementTimeLimit(-1.0);
  mapper->SetRefinementTimeLimit(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(errors.Count, 2);
  EXPECT_NE(errors.Last.find("RefinementTimeLimit"), std::string::npos);
  EXPECT_EQ(mapper->GetRefinementTimeLimit(), 0.0);
}

struct MixedComposite
{
  MixedComposite()
  {
    this->Leaves = { MakeTree(0.5, 40, 30, -1.2, 0, 0), MakeTOM(0.4, 24, 16, 0, 0, 0),
      MakeTree(0.45, 48, 32, 1.2, 0, 0), MakeTOM(0.3, 16, 12, 0, 1.0, 0) };
    vtkNew<vtkSphereSource> plain;
    plain->SetCenter(0, -1.0, 0);
    plain->SetRadius(0.35);
    plain->Update();
    this->Leaves.push_back(plain->GetOutput());
    this->Leaves.push_back(MakeTree(0.3, 30, 20, 0.0, 0.0, 1.0));
    this->Input->SetNumberOfBlocks(static_cast<unsigned int>(this->Leaves.size()));
    for (size_t i = 0; i < this->Leaves.size(); ++i)
    {
      this->Input->SetBlock(static_cast<unsigned int>(i), this->Leaves[i]);
    }
  }
  bool IsTree(vtkIdType i) const { return i == 0 || i == 2 || i == 5; }
  std::vector<vtkSmartPointer<vtkPolyData>> Leaves;
  vtkNew<vtkMultiBlockDataSet> Input;
};

const View Path[] = {
  { { 0, 0, 5 }, { 0, 0, 0 } },
  { { 1.5, 0.5, 3.0 }, { 0.3, 0, 0 } },
  { { -2.0, 1.0, 2.0 }, { -0.6, 0, 0 } },
  { { -0.5, 0.2, 1.8 }, { -1.0, 0, 0 } },
  { { 2.5, -1.0, 1.2 }, { 1.0, 0, 0 } },
  { { 0, 3.0, 3.0 }, { 0, 0, 0 } },
};
}

TEST(ViewDependentMapper, CameraMovesRewriteOnlyTheIndexBuffer)
{
  MixedComposite data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter warnings(mapper, vtkCommand::WarningEvent); // the plain leaf: one warning
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 6);
  for (vtkIdType i = 0; i < 6; ++i)
  {
    EXPECT_EQ(mapper->GetObjectIsViewDependent(i), data.IsTree(i)) << "object " << i;
    EXPECT_EQ(mapper->GetObjectIsTOM(i), i != 4) << "object " << i;
  }
  const double resolutions[6] = { 0.4, 0.3, 0.6, 0.5, 1.0, 0.25 };
  mapper->SetObjectResolutions(resolutions, 6);
  mapper->SetPixelThreshold(1.0);
  Scene scene(mapper);
  scene.LookAt(Path[0].Eye[0], Path[0].Eye[1], Path[0].Eye[2]);
  scene.Render();
  EXPECT_EQ(warnings.Count, 1);
  const vtkIdType vertexBuilds = mapper->GetVertexBufferBuildCount();
  const vtkMTimeType positions = mapper->GetVertexBufferUploadTime("vertexMC");
  const vtkMTimeType normals = mapper->GetVertexBufferUploadTime("normalMC");
  ASSERT_GT(positions, 0u);
  ASSERT_GT(normals, 0u);

  for (int mode : { vtkMultiresolutionPolyDataMapper::BUDGET,
         vtkMultiresolutionPolyDataMapper::FIXED_ACCURACY })
  {
    SCOPED_TRACE(mode == vtkMultiresolutionPolyDataMapper::BUDGET ? "budget" : "fixed accuracy");
    if (mode != mapper->GetRefinementMode())
    {
      // Render state: the index buffer follows, nothing else.
      const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
      mapper->SetRefinementMode(mode);
      scene.Render();
      EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds + 1);
    }
    const vtkIdType modeVertexBuilds = mapper->GetVertexBufferBuildCount();
    int changedFrames = 0;
    for (const View& view : Path)
    {
      const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
      scene.LookAt(view.Eye[0], view.Eye[1], view.Eye[2], view.Focal[0], view.Focal[1],
        view.Focal[2]);
      scene.Render();
      EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
      EXPECT_EQ(mapper->GetVertexBufferBuildCount(), modeVertexBuilds);
      EXPECT_EQ(mapper->GetVertexBufferUploadTime("vertexMC"), positions);
      EXPECT_EQ(mapper->GetVertexBufferUploadTime("normalMC"), normals);
      // The index buffer is rewritten exactly when a front changed.
      vtkIdType changes = 0;
      for (vtkIdType i = 0; i < 6; ++i)
      {
        changes += mapper->GetObjectSplits(i) + mapper->GetObjectMerges(i);
        if (!data.IsTree(i))
        {
          EXPECT_EQ(mapper->GetObjectSplits(i) + mapper->GetObjectMerges(i), 0);
          EXPECT_EQ(mapper->GetObjectRefinementTime(i), 0.0);
        }
      }
      EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds + (changes > 0 ? 1 : 0));
      changedFrames += changes > 0 ? 1 : 0;

      // Per object: fronts are closed and in their own vertex range; TOMs keep
      // their uniform prefix, the plain leaf is drawn in full.
      vtkIdType total = 0;
      for (vtkIdType i = 0; i < 6; ++i)
      {
        const auto triangles = ObjectTriangles(mapper, i);
        total += static_cast<vtkIdType>(triangles.size());
        const uint32_t n = static_cast<uint32_t>(mapper->GetObjectNumberOfVertices(i));
        for (const Triangle& t : triangles)
        {
          ASSERT_LT(std::max({ t[0], t[1], t[2] }), n) << "object " << i;
        }
        if (data.IsTree(i))
        {
          EXPECT_TRUE(Analyze(triangles).ClosedManifold) << "object " << i;
        }
        else if (i != 4)
        {
          const auto prefix = TraversalTriangles(data.Leaves[i], resolutions[i]);
          EXPECT_EQ(3 * triangles.size(), prefix.size()) << "object " << i;
        }
        else
        {
          EXPECT_EQ(static_cast<vtkIdType>(triangles.size()),
            data.Leaves[4]->GetNumberOfPolys());
        }
      }
      EXPECT_EQ(3 * total, mapper->GetLastIndexCount());
    }
    EXPECT_GE(changedFrames, 4) << "the camera path should move the fronts";
  }
  // Camera moves and refinement settings are render state: the mapper is not
  // modified by them, the vertex buffers stay, the index buffer follows.
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
  const vtkMTimeType settled = mapper->GetMTime();
  scene.LookAt(1, 1, 4);
  scene.Render();
  using Setter = void (vtkMultiresolutionPolyDataMapper::*)(bool);
  for (Setter set : { &vtkMultiresolutionPolyDataMapper::SetViewDependentRefinement,
         &vtkMultiresolutionPolyDataMapper::SetBackFaceSimplification,
         &vtkMultiresolutionPolyDataMapper::SetSilhouetteRefinement,
         &vtkMultiresolutionPolyDataMapper::SetHighlightRefinement })
  {
    for (bool on : { false, true })
    {
      const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
      (mapper->*set)(on);
      scene.Render();
      EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds + 1);
    }
  }
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("vertexMC"), positions);
  EXPECT_EQ(mapper->GetMTime(), settled);
  EXPECT_EQ(warnings.Count, 1);
}

TEST(ViewDependentMapper, CameraMovesDoNotAllocate)
{
  // Refinement and index fill must not allocate after warm-up. VTK's own
  // frame may allocate (uniform look-ups and the like), so the measure is the
  // same frames drawn with refinement off, where camera moves change nothing
  // in the mapper: the refined frames may not allocate more.
  MixedComposite data;
  auto run = [&](bool refine, int mode, std::size_t& allocations, vtkIdType& changes)
  {
    vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
    mapper->SetInputDataObject(data.Input);
    mapper->UpdateObjects();
    mapper->SetViewDependentRefinement(refine);
    mapper->SetRefinementMode(mode);
    mapper->SetResolution(0.5);
    Scene scene(mapper);
    // Grow every buffer: full resolution, then the path once.
    mapper->SetPixelThreshold(0.0);
    mapper->SetResolution(1.0);
    scene.Render();
    mapper->SetPixelThreshold(1.0);
    mapper->SetResolution(0.5);
    for (int pass = 0; pass < 2; ++pass)
    {
      for (const View& view : Path)
      {
        scene.LookAt(view.Eye[0], view.Eye[1], view.Eye[2], view.Focal[0], view.Focal[1],
          view.Focal[2]);
        scene.Render();
      }
    }
    allocations = 0;
    changes = 0;
    for (const View& view : Path)
    {
      scene.LookAt(view.Eye[0], view.Eye[1], view.Eye[2], view.Focal[0], view.Focal[1],
        view.Focal[2]);
      const std::size_t before = tt::GetAllocationCount();
      scene.Render();
      allocations += tt::GetAllocationCount() - before;
      for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
      {
        changes += mapper->GetObjectSplits(i) + mapper->GetObjectMerges(i);
      }
    }
  };
  for (int mode : { vtkMultiresolutionPolyDataMapper::BUDGET,
         vtkMultiresolutionPolyDataMapper::FIXED_ACCURACY })
  {
    SCOPED_TRACE(mode == vtkMultiresolutionPolyDataMapper::BUDGET ? "budget" : "fixed accuracy");
    std::size_t plain = 0, refined = 0;
    vtkIdType plainChanges = 0, refinedChanges = 0;
    run(false, mode, plain, plainChanges);
    run(true, mode, refined, refinedChanges);
    EXPECT_EQ(plainChanges, 0);
    EXPECT_GT(refinedChanges, 0) << "the measured frames must refine";
    EXPECT_LE(refined, plain) << "refined frames allocate " << refined << " times, plain ones "
                              << plain;
  }
}

//------------------------------------------------------------------------------
// Cell data, representations, refinement off.
namespace
{
void ConfigureCellColoring(vtkMapper* mapper, bool rotatePatches = false)
{
  // Same vertex values on the GPU for both mappers (no shift and scale).
  if (auto gl = vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    gl->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  }
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.0, 0.7);
  lut->Build();
  mapper->SetLookupTable(lut);
  mapper->ScalarVisibilityOn();
  mapper->SetScalarModeToUseCellFieldData();
  mapper->SelectColorArray(rotatePatches ? "RotatedPatch" : "Patch");
  mapper->SetScalarRange(0, 4);
}

// The mapper's drawn triangles, in its order and orientation, over all the
// tree's points, with the cell array "Patch" of the filter's triangle that
// has the same corners: drawn by a plain mapper this is the image the
// multiresolution mapper must give if its cell data follow the triangles.
// "RotatedPatch" holds the next patch value, for a sensitivity check.
vtkSmartPointer<vtkPolyData> ReferenceFront(
  vtkPolyData* tree, vtkMultiresolutionPolyDataMapper* mapper, vtkPolyData* front)
{
  std::map<Triangle, int> patchOf;
  const auto filtered = FilterTriangles(front);
  vtkDataArray* patch = front->GetCellData()->GetArray("Patch");
  EXPECT_NE(patch, nullptr);
  for (size_t c = 0; patch && c < filtered.size(); ++c)
  {
    patchOf[filtered[c]] = static_cast<int>(patch->GetTuple1(static_cast<vtkIdType>(c)));
  }
  auto reference = vtkSmartPointer<vtkPolyData>::New();
  reference->SetPoints(tree->GetPoints());
  reference->GetPointData()->SetNormals(tree->GetPointData()->GetNormals());
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> patches;
  patches->SetName("Patch");
  vtkNew<vtkIntArray> rotated;
  rotated->SetName("RotatedPatch");
  const unsigned int* ids = mapper->GetLastIndices();
  const vtkIdType count = mapper->GetObjectRenderedTriangles(0);
  for (vtkIdType t = 0; t < count; ++t)
  {
    const vtkIdType corners[3] = { ids[3 * t], ids[3 * t + 1], ids[3 * t + 2] };
    polys->InsertNextCell(3, corners);
    const auto found = patchOf.find(Rotated(ids[3 * t], ids[3 * t + 1], ids[3 * t + 2]));
    EXPECT_TRUE(found != patchOf.end()) << "triangle " << t << " is not in the filter's front";
    const int value = found != patchOf.end() ? found->second : -1;
    patches->InsertNextValue(value);
    rotated->InsertNextValue((value + 1) % 5);
  }
  reference->SetPolys(polys);
  reference->GetCellData()->AddArray(patches);
  reference->GetCellData()->AddArray(rotated);
  return reference;
}
}

TEST(ViewDependentMapper, CellScalarsStayWithTheirTriangles)
{
  vtkPolyData* tree = SphereTree();
  for (int representation : { VTK_SURFACE, VTK_WIREFRAME, VTK_POINTS })
  {
    const std::string name = representation == VTK_SURFACE ? "CellScalars"
      : representation == VTK_WIREFRAME                    ? "CellScalarsWireframe"
                                                           : "CellScalarsPoints";
    SCOPED_TRACE(name);
    vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
    mapper->SetInputDataObject(tree);
    mapper->SetRefinementModeToFixedAccuracy();
    mapper->SetPixelThreshold(2.0);
    ConfigureCellColoring(mapper);
    Scene scene(mapper);
    scene.LookAt(0.6, 0.5, 1.9, 0.1, 0.1, 0);
    scene.Actor->GetProperty()->SetPointSize(3);
    // The triangles first, as surfaces (the index buffer then holds them).
    scene.Render();
    vtkNew<vtkExtractViewDependentMesh> extract;
    extract->SetInputData(tree);
    MatchFilter(extract, mapper, scene, tree->GetNumberOfPolys());
    extract->Update();
    ExpectSameFront(mapper, extract);
    auto reference = ReferenceFront(tree, mapper, extract->GetOutput());
    ASSERT_EQ(reference->GetNumberOfPolys(), mapper->GetRenderedTriangles());
    ASSERT_LT(reference->GetNumberOfPolys(), tree->GetNumberOfPolys());

    scene.Actor->GetProperty()->SetRepresentation(representation);
    const std::string image = OutputPath(name + "_multires");
    scene.Save(image);

    for (bool rotated : { false, true })
    {
      vtkNew<vtkPolyDataMapper> plain;
      plain->SetInputData(reference);
      ConfigureCellColoring(plain, rotated);
      Scene other(plain);
      other.LookAt(0.6, 0.5, 1.9, 0.1, 0.1, 0);
      other.Actor->GetProperty()->DeepCopy(scene.Actor->GetProperty());
      const std::string expected = OutputPath(name + (rotated ? "_rotated" : "_reference"));
      other.Save(expected);
      const auto result = tt::CompareImages(image, expected, ChannelThreshold);
      ASSERT_TRUE(result.Loaded) << result.Message;
      if (rotated)
      {
        // Sensitivity: the same triangles with the wrong cell values differ.
        EXPECT_FALSE(tt::Passes(result, Tolerance)) << tt::Describe(result);
      }
      else
      {
        EXPECT_TRUE(tt::Passes(result, Tolerance))
          << tt::Describe(result) << " (" << image << " against " << expected << ")";
      }
    }
  }
}

TEST(ViewDependentMapper, WireframeAndPointsDrawTheFront)
{
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->SetRefinementModeToFixedAccuracy();
  mapper->SetPixelThreshold(1.5);
  Scene scene(mapper);
  scene.LookAt(1.0, 0.6, 2.4);
  scene.Render();
  const auto surface = ObjectTriangles(mapper, 0);
  const vtkIdType triangles = mapper->GetRenderedTriangles();
  const vtkIdType vertices = mapper->GetRenderedVertices();
  const int surfacePixels = scene.CountForeground();
  std::set<std::pair<uint32_t, uint32_t>> edges;
  std::set<uint32_t> corners;
  for (const Triangle& t : surface)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
      corners.insert(t[k]);
    }
  }
  EXPECT_EQ(static_cast<vtkIdType>(corners.size()), vertices);

  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), triangles);
  ASSERT_EQ(mapper->GetLastIndexCount(), 6 * triangles);
  std::set<std::pair<uint32_t, uint32_t>> drawnEdges;
  for (vtkIdType k = 0; k < mapper->GetLastIndexCount(); k += 2)
  {
    drawnEdges.insert(std::minmax(mapper->GetLastIndices()[k], mapper->GetLastIndices()[k + 1]));
  }
  EXPECT_TRUE(drawnEdges == edges) << "wireframe edges are not the front's edges";
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
  const int wirePixels = scene.CountForeground();

  scene.Actor->GetProperty()->SetRepresentationToPoints();
  scene.Actor->GetProperty()->SetPointSize(2);
  scene.Render();
  ASSERT_EQ(mapper->GetLastIndexCount(), vertices);
  const std::set<uint32_t> drawnPoints(
    mapper->GetLastIndices(), mapper->GetLastIndices() + mapper->GetLastIndexCount());
  EXPECT_TRUE(drawnPoints == corners) << "points are not the front's vertices";
  EXPECT_EQ(mapper->GetRenderedVertices(), vertices);
  const int pointPixels = scene.CountForeground();
  EXPECT_GT(surfacePixels, 10000);
  EXPECT_GT(wirePixels, 1000);
  EXPECT_LT(wirePixels, surfacePixels);
  EXPECT_GT(pointPixels, 300);
  EXPECT_LT(pointPixels, surfacePixels);

  // Vertex visibility on a surface: the front's vertices again.
  scene.Actor->GetProperty()->SetRepresentationToSurface();
  scene.Actor->GetProperty()->VertexVisibilityOn();
  scene.Render();
  EXPECT_EQ(mapper->GetLastIndexCount(), 3 * triangles);
  EXPECT_EQ(mapper->GetRenderedVertices(), vertices);
  EXPECT_GT(scene.CountForeground(), surfacePixels / 2);
}

TEST(ViewDependentMapper, RefinementOffDrawsTheUniformPrefix)
{
  vtkPolyData* tree = SphereTree();
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tree);
  mapper->UpdateObjects();
  mapper->SetResolution(0.2);
  // Fixed accuracy: the front depends on the view only, so it can be compared
  // after a detour (a budget front keeps improving from its previous state).
  mapper->SetRefinementModeToFixedAccuracy();
  mapper->SetPixelThreshold(2.0);
  Scene scene(mapper);
  scene.LookAt(0.5, 0.4, 2.2);
  scene.Render();
  EXPECT_TRUE(mapper->GetObjectIsViewDependent(0));
  EXPECT_GT(mapper->GetObjectSplits(0), 0);
  const auto front = Sorted(ObjectTriangles(mapper, 0));

  mapper->ViewDependentRefinementOff();
  scene.Render();
  EXPECT_FALSE(mapper->GetObjectIsViewDependent(0));
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_EQ(mapper->GetObjectSplits(0), 0);
  EXPECT_EQ(mapper->GetRefinementTime(), 0.0);
  const std::vector<uint32_t> prefix = TraversalTriangles(tree, 0.2);
  const std::vector<uint32_t> drawn(
    mapper->GetLastIndices(), mapper->GetLastIndices() + mapper->GetLastIndexCount());
  EXPECT_EQ(drawn, prefix);
  // Moving the camera changes nothing then.
  const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
  scene.LookAt(-2, 1, 1);
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds);

  // On again: the front of this view, not the prefix.
  mapper->ViewDependentRefinementOn();
  scene.LookAt(0.5, 0.4, 2.2);
  scene.Render();
  EXPECT_TRUE(mapper->GetObjectIsViewDependent(0));
  EXPECT_TRUE(Sorted(ObjectTriangles(mapper, 0)) == front);
  std::vector<Triangle> uniform;
  for (size_t k = 0; k < prefix.size(); k += 3)
  {
    uniform.push_back(Rotated(prefix[k], prefix[k + 1], prefix[k + 2]));
  }
  EXPECT_FALSE(front == Sorted(uniform)) << "the front should differ from the uniform prefix";
}

//------------------------------------------------------------------------------
// Bad settings and bad trees.

TEST(ViewDependentMapper, BadSettingsAreErrorsAndIgnored)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  int expected = 0;
  for (double tau : { NaN, -1.0, -Inf, Inf })
  {
    mapper->SetPixelThreshold(tau);
    EXPECT_EQ(errors.Count, ++expected) << tau;
    EXPECT_EQ(mapper->GetPixelThreshold(), 1.0);
  }
  mapper->SetPixelThreshold(0.0);
  EXPECT_EQ(mapper->GetPixelThreshold(), 0.0);
  EXPECT_EQ(errors.Count, expected);
  for (double factor : { 0.0, -0.5, 1.5, NaN, Inf })
  {
    mapper->SetSilhouetteFactor(factor);
    EXPECT_EQ(errors.Count, ++expected) << factor;
    mapper->SetHighlightFactor(factor);
    EXPECT_EQ(errors.Count, ++expected) << factor;
  }
  EXPECT_EQ(mapper->GetSilhouetteFactor(), 0.25);
  EXPECT_EQ(mapper->GetHighlightFactor(), 0.5);
  mapper->SetSilhouetteFactor(1.0);
  mapper->SetHighlightFactor(0.1);
  EXPECT_EQ(mapper->GetSilhouetteFactor(), 1.0);
  EXPECT_EQ(mapper->GetHighlightFactor(), 0.1);
  EXPECT_EQ(errors.Count, expected);
  // Modes are clamped (VTK's clamp macro), as the other enumerations.
  mapper->SetRefinementMode(7);
  EXPECT_EQ(mapper->GetRefinementMode(), vtkMultiresolutionPolyDataMapper::FIXED_ACCURACY);
  // Statistics of objects that do not exist are errors, not crashes.
  EXPECT_FALSE(mapper->GetObjectIsViewDependent(0));
  EXPECT_EQ(mapper->GetObjectSplits(3), 0);
  EXPECT_GT(errors.Count, expected);

  std::ostringstream print;
  mapper->PrintSelf(print, vtkIndent());
  EXPECT_NE(print.str().find("RefinementMode: FIXED_ACCURACY"), std::string::npos);
  EXPECT_NE(print.str().find("HighlightRefinement: 1 (factor 0.1)"), std::string::npos);
}

TEST(ViewDependentMapper, InvalidMergeTreeIsDrawnAsATOMWithOneWarning)
{
  // Two corrupted trees (a base vertex below the top level) and a good one.
  auto bad = vtkSmartPointer<vtkPolyData>::New();
  bad->DeepCopy(MakeTree(0.5, 30, 20, -1.2, 0, 0));
  bad->GetPointData()->GetArray(vtkMergeTreeFieldData::LevelArrayName())->SetTuple1(0, 0);
  auto missing = vtkSmartPointer<vtkPolyData>::New();
  missing->DeepCopy(MakeTree(0.5, 30, 20, 1.2, 0, 0));
  missing->GetPointData()->RemoveArray(vtkMergeTreeFieldData::ErrorArrayName());
  ASSERT_TRUE(vtkMergeTreeFieldData::HasMergeTreeArrays(bad));
  ASSERT_TRUE(vtkMergeTreeFieldData::HasMergeTreeArrays(missing));
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, bad);
  blocks->SetBlock(1, missing);
  blocks->SetBlock(2, MakeTree(0.4, 24, 16, 0, 1.0, 0));

  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter warnings(mapper, vtkCommand::WarningEvent);
  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 3);
  EXPECT_EQ(warnings.Count, 1);
  EXPECT_NE(warnings.Last.find("invalid merge-tree arrays"), std::string::npos) << warnings.Last;
  EXPECT_TRUE(mapper->GetObjectIsTOM(0));
  EXPECT_TRUE(mapper->GetObjectIsTOM(1));
  EXPECT_FALSE(mapper->GetObjectIsViewDependent(0));
  EXPECT_FALSE(mapper->GetObjectIsViewDependent(1));
  EXPECT_TRUE(mapper->GetObjectIsViewDependent(2));
  mapper->SetResolution(0.3);
  Scene scene(mapper);
  scene.LookAt(0, 0.3, 4);
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
  for (vtkIdType i = 0; i < 2; ++i)
  {
    const auto drawn = ObjectTriangles(mapper, i);
    const auto prefix = TraversalTriangles(vtkPolyData::SafeDownCast(blocks->GetBlock(i)), 0.3);
    EXPECT_EQ(3 * drawn.size(), prefix.size()) << "object " << i;
    EXPECT_EQ(mapper->GetObjectSplits(i), 0);
  }
  EXPECT_GT(mapper->GetObjectSplits(2), 0);
  EXPECT_GT(scene.CountForeground(), 1000);
  // Read again (input modified): no new warning.
  blocks->Modified();
  scene.Render();
  EXPECT_EQ(warnings.Count, 1);
  EXPECT_EQ(errors.Count, 0);
}

//------------------------------------------------------------------------------
// Image baselines: a view-dependent front of a bumpy sphere and its resolution
// map (merge-tree level per vertex, lighter = finer).
namespace
{
vtkPolyData* BaselineTree()
{
  static vtkSmartPointer<vtkPolyData> tree = MakeTree(1.0, 120, 90, 0, 0, 0, 11.0);
  return tree;
}

std::string RenderFront(double tau, bool map, bool refine, const std::string& name)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(BaselineTree());
  mapper->UpdateObjects();
  mapper->SetRefinementModeToFixedAccuracy();
  mapper->SetPixelThreshold(tau);
  mapper->SetColorByResolution(map);
  mapper->SetViewDependentRefinement(refine);
  mapper->SetResolution(0.1); // for the uniform TOM only
  Scene scene(mapper);
  scene.Actor->GetProperty()->SetInterpolationToFlat();
  scene.LookAt(2.0, 1.4, 3.6);
  const std::string path = OutputPath(name);
  scene.Save(path);
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
  EXPECT_GT(scene.CountForeground(), 20000);
  return path;
}

void CheckBaseline(const std::string& image, const std::string& name)
{
  const std::string baseline = BaselinePath(name);
  if (tt::UpdatingBaselines())
  {
    std::ifstream src(image, std::ios::binary);
    std::ofstream dst(baseline, std::ios::binary);
    dst << src.rdbuf();
  }
  const auto result = tt::CompareImages(image, baseline, ChannelThreshold);
  EXPECT_TRUE(tt::Passes(result, Tolerance)) << name << ": " << tt::Describe(result) << " (image "
                                             << image << ", baseline " << baseline << ")";
}

void CheckDiffers(const std::string& image, const std::string& name)
{
  const auto result = tt::CompareImages(image, BaselinePath(name), ChannelThreshold);
  ASSERT_TRUE(result.Loaded) << result.Message;
  EXPECT_FALSE(tt::Passes(result, Tolerance)) << name << ": " << tt::Describe(result);
}
}

TEST(ViewDependentBaseline, Front)
{
  CheckBaseline(RenderFront(3.0, false, true, "Front"), "Front");
}

TEST(ViewDependentBaseline, ResolutionMap)
{
  CheckBaseline(RenderFront(3.0, true, true, "ResolutionMap"), "ResolutionMap");
}

TEST(ViewDependentBaseline, OtherFrontsFailTheThresholds)
{
  CheckDiffers(RenderFront(12.0, false, true, "FrontCoarser"), "Front");
  CheckDiffers(RenderFront(12.0, true, true, "ResolutionMapCoarser"), "ResolutionMap");
  // The uniform TOM's map is one grey per object: not the per-vertex levels.
  CheckDiffers(RenderFront(3.0, true, false, "ResolutionMapUniform"), "ResolutionMap");
}

//------------------------------------------------------------------------------
// vtkTimeCriticalRenderer with merge-tree objects.
namespace
{
// One merge tree (object 0) and three TOMs in one composite.
vtkSmartPointer<vtkMultiBlockDataSet> MixedObjects()
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetBlock(0, MakeTree(0.8, 60, 40, 0, 0, 0));
  blocks->SetBlock(1, MakeTOM(0.5, 40, 30, -2.0, 0, 0));
  blocks->SetBlock(2, MakeTOM(0.5, 40, 30, 2.0, 0, 0));
  blocks->SetBlock(3, MakeTOM(0.5, 40, 30, 0, 2.0, 0));
  return blocks;
}

struct RendererScene
{
  explicit RendererScene(vtkDataObject* input)
  {
    this->Mapper->SetInputDataObject(input);
    this->Actor->SetMapper(this->Mapper);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(ImageSize, ImageSize);
    this->Window->AddRenderer(this->Renderer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.5, 0.6, 6.0);
    camera->SetFocalPoint(0, 0.5, 0);
    camera->SetViewUp(0, 1, 0);
    this->Renderer->ResetCameraClippingRange();
    // Deterministic choices: fixed coefficients, no measurement feeding back.
    this->Renderer->AutomaticCalibrationOff();
    this->Renderer->OnlineCalibrationOff();
    this->Renderer->SetCostCoefficients(2e-3, 0.0, 1e-6, 0.0);
    this->Renderer->SetNewObjectCostFactor(1.0);
    this->Renderer->UseVelocityOff();
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
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkTimeCriticalRenderer> Renderer;
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
};
}

TEST(ViewDependentRenderer, SettingsReachTheMappers)
{
  RendererScene scene(MixedObjects());
  vtkTimeCriticalRenderer* renderer = scene.Renderer;
  // Defaults agree with the mapper's.
  EXPECT_EQ(renderer->GetRefinementMode(), vtkTimeCriticalRenderer::BUDGET);
  EXPECT_TRUE(renderer->GetViewDependentRefinement());
  EXPECT_EQ(renderer->GetPixelThreshold(), scene.Mapper->GetPixelThreshold());
  EXPECT_EQ(renderer->GetSilhouetteFactor(), scene.Mapper->GetSilhouetteFactor());
  EXPECT_EQ(renderer->GetHighlightFactor(), scene.Mapper->GetHighlightFactor());

  renderer->SetRefinementModeToFixedAccuracy();
  renderer->SetPixelThreshold(2.5);
  renderer->BackFaceSimplificationOff();
  renderer->SilhouetteRefinementOff();
  renderer->SetSilhouetteFactor(0.3);
  renderer->HighlightRefinementOff();
  renderer->SetHighlightFactor(0.7);
  // A mapper setting is overridden by the renderer's.
  scene.Mapper->SetPixelThreshold(9.0);
  scene.Window->Render();
  vtkMultiresolutionPolyDataMapper* mapper = scene.Mapper;
  EXPECT_EQ(mapper->GetRefinementMode(), vtkMultiresolutionPolyDataMapper::FIXED_ACCURACY);
  EXPECT_EQ(mapper->GetPixelThreshold(), 2.5);
  EXPECT_FALSE(mapper->GetBackFaceSimplification());
  EXPECT_FALSE(mapper->GetSilhouetteRefinement());
  EXPECT_EQ(mapper->GetSilhouetteFactor(), 0.3);
  EXPECT_FALSE(mapper->GetHighlightRefinement());
  EXPECT_EQ(mapper->GetHighlightFactor(), 0.7);
  EXPECT_TRUE(mapper->GetViewDependentRefinement());
  EXPECT_TRUE(renderer->GetObjectIsViewDependent(0));

  renderer->ViewDependentRefinementOff();
  scene.Window->Render();
  EXPECT_FALSE(mapper->GetViewDependentRefinement());
  EXPECT_FALSE(renderer->GetObjectIsViewDependent(0));
  EXPECT_EQ(renderer->GetRefinementTime(), 0.0);

  std::ostringstream print;
  renderer->PrintSelf(print, vtkIndent());
  EXPECT_NE(print.str().find("RefinementMode: FIXED_ACCURACY"), std::string::npos);
  EXPECT_NE(print.str().find("PixelThreshold: 2.5"), std::string::npos);
}

TEST(ViewDependentRenderer, StatisticsAndCostAccounting)
{
  RendererScene scene(MixedObjects());
  vtkTimeCriticalRenderer* renderer = scene.Renderer;
  vtkMultiresolutionPolyDataMapper* mapper = scene.Mapper;
  renderer->SetTargetFrameTime(10.0);
  scene.Window->Render();
  ASSERT_EQ(renderer->GetNumberOfObjects(), 4);
  EXPECT_TRUE(renderer->GetObjectIsViewDependent(0));
  EXPECT_GT(renderer->GetObjectSplits(0), 0) << "the first frame refines from the coarsest front";
  EXPECT_GT(renderer->GetObjectRefinementTime(0), 0.0);
  EXPECT_GT(renderer->GetRefinementTime(), 0.0);
  EXPECT_EQ(renderer->GetRefinementTime(), mapper->GetRefinementTime());
  for (vtkIdType o = 0; o < 4; ++o)
  {
    EXPECT_EQ(renderer->GetObjectVertices(o), mapper->GetObjectRenderedVertices(o)) << o;
    EXPECT_GT(renderer->GetObjectVertices(o), 0) << o;
    EXPECT_EQ(renderer->GetObjectTriangles(o), mapper->GetObjectRenderedTriangles(o)) << o;
    if (o > 0)
    {
      EXPECT_FALSE(renderer->GetObjectIsViewDependent(o));
      EXPECT_EQ(renderer->GetObjectSplits(o), 0);
      EXPECT_EQ(renderer->GetObjectMerges(o), 0);
      EXPECT_EQ(renderer->GetObjectRefinementTime(o), 0.0);
    }
  }
  EXPECT_EQ(renderer->GetObjectVertices(4), -1);
  EXPECT_EQ(renderer->GetObjectSplits(-1), -1);
  EXPECT_EQ(renderer->GetObjectMerges(4), -1);
  EXPECT_TRUE(std::isnan(renderer->GetObjectRefinementTime(4)));
  EXPECT_FALSE(renderer->GetObjectIsViewDependent(4));
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);

  // Budget mode: the refinement time, smoothed over frames (estimate = half
  // the previous estimate + half the last frame's time), is fixed cost (frame
  // cost 2 ms, no draw-call or pixel cost, no correction with online
  // calibration off).
  double estimate = renderer->GetFixedFrameTime() - 2e-3;
  double refinement = renderer->GetRefinementTime();
  EXPECT_GT(refinement, 0.0);
  scene.Window->Render();
  EXPECT_NEAR(renderer->GetFixedFrameTime(), 2e-3 + 0.5 * estimate + 0.5 * refinement, 1e-12);
  EXPECT_EQ(renderer->GetObjectSplits(0) + renderer->GetObjectMerges(0), 0) << "same view";

  // Fixed accuracy: the front's last triangles are fixed cost as well.
  renderer->SetRefinementModeToFixedAccuracy();
  scene.Window->Render();
  const vtkIdType front = renderer->GetObjectTriangles(0);
  estimate = renderer->GetFixedFrameTime() - 2e-3 - 1e-6 * static_cast<double>(front);
  refinement = renderer->GetRefinementTime();
  scene.Window->Render();
  EXPECT_NEAR(renderer->GetFixedFrameTime(),
    2e-3 + 1e-6 * static_cast<double>(front) + 0.5 * estimate + 0.5 * refinement, 1e-12);
}

TEST(ViewDependentRenderer, FixedAccuracyIgnoresTheTargetBudgetFollowsIt)
{
  RendererScene scene(MixedObjects());
  vtkTimeCriticalRenderer* renderer = scene.Renderer;
  const vtkIdType total = scene.TotalTriangles();
  const double loose = 10.0;
  const double tight = 2e-3 + 1e-6 * 0.15 * static_cast<double>(total);

  renderer->SetRefinementModeToFixedAccuracy();
  renderer->SetPixelThreshold(1.0);
  renderer->SetTargetFrameTime(loose);
  scene.Window->Render();
  const vtkIdType frontLoose = renderer->GetObjectTriangles(0);
  const vtkIdType othersLoose = renderer->GetObjectTrianglesDrawn() - frontLoose;
  renderer->SetTargetFrameTime(tight);
  scene.Window->Render();
  scene.Window->Render();
  EXPECT_EQ(renderer->GetObjectTriangles(0), frontLoose);
  EXPECT_GT(renderer->GetObjectResolution(0), 0.0) << "never culled for its cost";
  EXPECT_LT(renderer->GetObjectTrianglesDrawn() - renderer->GetObjectTriangles(0), othersLoose)
    << "the TOMs pay for the tight target";
  EXPECT_LT(frontLoose, scene.Mapper->GetObjectNumberOfTriangles(0));

  renderer->SetRefinementModeToBudget();
  renderer->SetTargetFrameTime(loose);
  scene.Window->Render();
  const vtkIdType budgetLoose = renderer->GetObjectTriangles(0);
  renderer->SetTargetFrameTime(tight);
  scene.Window->Render();
  scene.Window->Render();
  const vtkIdType budgetTight = renderer->GetObjectTriangles(0);
  EXPECT_LT(budgetTight, budgetLoose);
  EXPECT_LE(static_cast<double>(budgetTight),
    renderer->GetObjectResolution(0) * static_cast<double>(scene.Mapper->GetObjectNumberOfTriangles(0)) +
      16.0);
  EXPECT_LE(renderer->GetPredictedFrameTime(), tight * (1 + 1e-9));
}

TEST(ViewDependentRenderer, MixedSceneOneDrawCallPerMapper)
{
  RendererScene scene(MixedObjects());
  // A second actor: a merge tree, two TOMs and a plain surface.
  vtkNew<vtkMultiBlockDataSet> second;
  second->SetBlock(0, MakeTOM(0.4, 30, 20, -1.5, -1.5, 0));
  second->SetBlock(1, MakeTree(0.4, 30, 20, 0, -1.5, 0));
  second->SetBlock(2, MakeTOM(0.4, 30, 20, 1.5, -1.5, 0));
  vtkNew<vtkSphereSource> plain;
  plain->SetCenter(0, -2.5, 0);
  plain->SetRadius(0.3);
  plain->Update();
  second->SetBlock(3, plain->GetOutput());
  vtkNew<vtkMultiresolutionPolyDataMapper> secondMapper;
  secondMapper->SetInputDataObject(second);
  vtkNew<vtkActor> secondActor;
  secondActor->SetMapper(secondMapper);
  scene.Renderer->AddActor(secondActor);
  scene.Renderer->ResetCamera();
  scene.Renderer->SetTargetFrameTime(2e-3 + 1e-6 * 0.3 * static_cast<double>(scene.TotalTriangles()));
  // The fronts' measured refinement time is fixed time: under sanitizers it
  // can overload the frame, which would drop the plain surface this test counts.
  scene.Renderer->DropObjectsWhenOverloadedOff();
  for (int mode : { vtkTimeCriticalRenderer::BUDGET, vtkTimeCriticalRenderer::FIXED_ACCURACY })
  {
    scene.Renderer->SetRefinementMode(mode);
    for (int frame = 0; frame < 3; ++frame)
    {
      scene.Renderer->GetActiveCamera()->Azimuth(10);
      scene.Window->Render();
      EXPECT_EQ(scene.Mapper->GetNumberOfDrawCalls(), 1);
      EXPECT_EQ(secondMapper->GetNumberOfDrawCalls(), 1);
    }
    ASSERT_EQ(scene.Renderer->GetNumberOfObjects(), 8);
    EXPECT_TRUE(scene.Renderer->GetObjectIsViewDependent(0));
    EXPECT_TRUE(scene.Renderer->GetObjectIsViewDependent(5));
    EXPECT_FALSE(scene.Renderer->GetObjectIsViewDependent(7));
    EXPECT_EQ(scene.Renderer->GetObjectTriangles(7), plain->GetOutput()->GetNumberOfPolys());
    EXPECT_GT(scene.Renderer->GetObjectTrianglesDrawn(), 0);
  }
}

TEST(ViewDependentRenderer, BadSettingsAreErrorsAndIgnored)
{
  vtkNew<vtkTimeCriticalRenderer> renderer;
  EventCounter errors(renderer, vtkCommand::ErrorEvent);
  int expected = 0;
  for (double tau : { NaN, -0.5, Inf, -Inf })
  {
    renderer->SetPixelThreshold(tau);
    EXPECT_EQ(errors.Count, ++expected) << tau;
  }
  EXPECT_EQ(renderer->GetPixelThreshold(), 1.0);
  for (double factor : { 0.0, -1.0, 1.01, NaN, Inf })
  {
    renderer->SetSilhouetteFactor(factor);
    EXPECT_EQ(errors.Count, ++expected) << factor;
    renderer->SetHighlightFactor(factor);
    EXPECT_EQ(errors.Count, ++expected) << factor;
  }
  EXPECT_EQ(renderer->GetSilhouetteFactor(), 0.25);
  EXPECT_EQ(renderer->GetHighlightFactor(), 0.5);
  for (double limit : { NaN, -1e-3, Inf })
  {
    renderer->SetRefinementTimeLimit(limit);
    EXPECT_EQ(errors.Count, ++expected) << limit;
  }
  EXPECT_EQ(renderer->GetRefinementTimeLimit(), 0.01);
  renderer->SetPixelThreshold(0.0);
  renderer->SetSilhouetteFactor(1.0);
  EXPECT_EQ(renderer->GetPixelThreshold(), 0.0);
  EXPECT_EQ(renderer->GetSilhouetteFactor(), 1.0);
  EXPECT_EQ(errors.Count, expected);
}

TEST(ViewDependentRenderer, StatisticsOfAnActorCulledAsAWhole)
{
  // Looking away from every object: VTK's culler removes the actor before the
  // renderer gathers objects, so the frame has none, and its statistics must
  // say that nothing was drawn or refined (not repeat the previous frame's).
  RendererScene scene(MixedObjects());
  vtkTimeCriticalRenderer* renderer = scene.Renderer;
  renderer->SetTargetFrameTime(10.0);
  scene.Window->Render();
  ASSERT_GT(renderer->GetObjectTrianglesDrawn(), 0);
  ASSERT_GT(renderer->GetObjectSplits(0), 0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.5, 0.6, 20.0);
  scene.Window->Render();
  EXPECT_EQ(renderer->GetNumberOfObjects(), 0);
  EXPECT_EQ(renderer->GetObjectTrianglesDrawn(), 0);
  EXPECT_EQ(renderer->GetTrianglesDrawn(), 0);
  EXPECT_EQ(renderer->GetRefinementTime(), 0.0);
  EXPECT_EQ(renderer->GetObjectTriangles(0), -1);
  EXPECT_EQ(renderer->GetObjectVertices(0), -1);
  EXPECT_EQ(renderer->GetObjectSplits(0), -1);
  EXPECT_FALSE(renderer->GetObjectIsViewDependent(0));
  // Back in view: the front was kept, and this view is its previous one.
  camera->SetFocalPoint(0, 0.5, 0);
  scene.Window->Render();
  EXPECT_EQ(renderer->GetNumberOfObjects(), 4);
  EXPECT_TRUE(renderer->GetObjectIsViewDependent(0));
  EXPECT_GT(renderer->GetObjectTriangles(0), 0);
  EXPECT_GT(renderer->GetObjectVertices(0), 0);
  EXPECT_GT(renderer->GetRefinementTime(), 0.0);
}

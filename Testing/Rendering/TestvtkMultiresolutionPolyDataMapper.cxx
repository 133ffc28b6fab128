// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: index data against the traversal core,
// one draw call for many objects, index-only updates, culling, bad input,
// non-TOM leaves, polydata and partitioned input, coloring and representations,
// picking, image baselines (normal colors and the resolution map), and the
// index slots (only changed objects rewritten, padding invisible, same result
// as a full rebuild, no allocation).
//
// Image thresholds are those of TestTOMImageBaselines: a channel value
// differing by more than 0.05 fails; at most 0.1% may fail, RMS below 0.005.
#include "TOMMesh.h"
#include "TOMTraversal.h"
#include "RenderTestSupport.h"
#include "TestImageCompare.h"
#include "vtkExtractTOMResolution.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMultiresolutionPolyDataMapper.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"
#include "vtkTOMPolyDataMapper.h"

#include "AllocationCounter.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellPicker.h"
#include "vtkCompositeDataIterator.h"
#include "vtkFloatArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLVertexBufferObject.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropPicker.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTestErrorObserver.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <malloc.h>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace
{
namespace tt = timecritical::testing;
const tt::ImageTolerance Tolerance{ 0.05, 0.001, 0.005 };
constexpr double PixelThreshold = 0.05;
constexpr int ImageSize = 300;

// Xvfb resets when a window closes; see tt::KeepDisplayOpen.
::testing::Environment* const KeepDisplay =
  ::testing::AddGlobalTestEnvironment(new tt::KeepDisplayOpen);

std::string OutputPath(const std::string& name)
{
  return std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/" + name + ".png";
}

std::string BaselinePath(const std::string& name)
{
  return std::string(TIMECRITICAL_BASELINE_DIR) + "/MultiresolutionMapper_" + name + ".png";
}

vtkSmartPointer<vtkPolyData> BuildTOM(vtkPolyData* surface)
{
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputData(surface);
  builder->Update();
  auto tom = vtkSmartPointer<vtkPolyData>::New();
  tom->ShallowCopy(builder->GetOutput());
  return tom;
}

vtkSmartPointer<vtkPolyData> MakeTOM(double radius, int theta, int phi, double cx = 0,
  double cy = 0, double cz = 0, double frequency = 9.0)
{
  return BuildTOM(tt::MakeBumpySurface(radius, theta, phi, cx, cy, cz, frequency));
}

using tt::EventCounter;

// One actor in an offscreen window with a fixed camera.
struct Scene
{
  explicit Scene(vtkMapper* mapper, int size = ImageSize)
  {
    this->Actor->SetMapper(mapper);
    this->Actor->GetProperty()->SetColor(0.85, 0.7, 0.45);
    this->Actor->GetProperty()->SetSpecular(0.3);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->SetBackground(0.1, 0.1, 0.15);
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(size, size);
    this->Window->AddRenderer(this->Renderer);
    this->SetCamera(1.5, 1.1, 2.0);
  }
  void SetCamera(double x, double y, double z, double fx = 0, double fy = 0, double fz = 0)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(x, y, z);
    camera->SetFocalPoint(fx, fy, fz);
    camera->SetViewUp(0, 1, 0);
    // A fixed clipping range, not one from the bounds: images of different
    // mappers of the same triangles must have the same depth values, or lines
    // shared by two triangles may take the other triangle's color.
    camera->SetClippingRange(0.5, 20.0);
  }
  void Render() { this->Window->Render(); }
  void Save(const std::string& path)
  {
    this->Render();
    tt::WriteWindowPNG(this->Window, path, true);
  }
  // Pixels that are not background in the last render.
  int CountForeground() { return tt::CountForegroundPixels(this->Window); }
  vtkNew<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
};

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

vtkIdType ExtractedTriangles(vtkPolyData* tom, double r)
{
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetInputData(tom);
  extract->SetResolution(r);
  extract->Update();
  return extract->GetExtractedTriangleCount();
}

// Four TOMs of different sizes in nested blocks, with a null block and an
// empty leaf in between: objects are the non-empty leaves in iteration order.
struct NestedScene
{
  NestedScene()
  {
    this->Leaves = { MakeTOM(0.5, 40, 30, -1.2, 0, 0), MakeTOM(0.4, 24, 16, 0, 0, 0),
      MakeTOM(0.45, 60, 40, 1.2, 0, 0), MakeTOM(0.3, 16, 12, 0, 1.0, 0) };
    vtkNew<vtkMultiBlockDataSet> inner;
    inner->SetNumberOfBlocks(4);
    inner->SetBlock(0, this->Leaves[1]);
    inner->SetBlock(1, nullptr);
    vtkNew<vtkPolyData> empty;
    inner->SetBlock(2, empty);
    inner->SetBlock(3, this->Leaves[2]);
    this->Input->SetNumberOfBlocks(4);
    this->Input->SetBlock(0, this->Leaves[0]);
    this->Input->SetBlock(1, inner);
    this->Input->SetBlock(2, nullptr);
    this->Input->SetBlock(3, this->Leaves[3]);
  }
  std::vector<vtkSmartPointer<vtkPolyData>> Leaves;
  vtkNew<vtkMultiBlockDataSet> Input;
};
}

//------------------------------------------------------------------------------
TEST(MultiresolutionMapper, IndicesMatchTheTraversalCorePerObject)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 4);

  // Flat indices are those of the composite iterator, empty leaf skipped.
  std::vector<unsigned int> flat;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(data.Input->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    auto poly = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    if (poly && poly->GetNumberOfPoints() > 0)
    {
      flat.push_back(it->GetCurrentFlatIndex());
    }
  }
  ASSERT_EQ(flat.size(), 4u);

  const double resolutions[4] = { 1.0, 0.5, 0.2, 0.05 };
  for (vtkIdType i = 0; i < 4; ++i)
  {
    EXPECT_EQ(mapper->GetObjectFlatIndex(i), flat[i]);
    EXPECT_TRUE(mapper->GetObjectIsTOM(i));
    EXPECT_EQ(mapper->GetObjectNumberOfVertices(i), data.Leaves[i]->GetNumberOfPoints());
    EXPECT_EQ(mapper->GetObjectNumberOfTriangles(i), data.Leaves[i]->GetNumberOfPolys());
    EXPECT_GT(mapper->GetObjectCoarsestResolution(i), 0.0);
    EXPECT_LT(mapper->GetObjectCoarsestResolution(i), 0.2);
    double bounds[6], expected[6];
    mapper->GetObjectBounds(i, bounds);
    data.Leaves[i]->GetBounds(expected);
    for (int k = 0; k < 6; ++k)
    {
      EXPECT_NEAR(bounds[k], expected[k], 1e-6);
    }
    EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(i), 1.0);
    mapper->SetObjectResolution(i, resolutions[i]);
  }

  Scene scene(mapper);
  scene.Render();
  ASSERT_EQ(mapper->GetNumberOfDrawCalls(), 1);

  // The index buffer is the concatenation of every object's traversal, shifted
  // by the object's first point; triangle counts agree with the extraction filter.
  std::vector<uint32_t> expected;
  vtkIdType total = 0;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    const std::vector<uint32_t> triangles = TraversalTriangles(data.Leaves[i], resolutions[i]);
    for (uint32_t v : triangles)
    {
      expected.push_back(v + static_cast<uint32_t>(mapper->GetObjectVertexOffset(i)));
    }
    EXPECT_EQ(
      mapper->GetObjectRenderedTriangles(i), ExtractedTriangles(data.Leaves[i], resolutions[i]))
      << "object " << i;
    EXPECT_EQ(static_cast<size_t>(mapper->GetObjectRenderedTriangles(i)), triangles.size() / 3);
    total += mapper->GetObjectRenderedTriangles(i);
  }
  EXPECT_EQ(mapper->GetRenderedTriangles(), total);
  ASSERT_EQ(mapper->GetLastIndexCount(), static_cast<vtkIdType>(expected.size()));
  const std::vector<uint32_t> drawn(
    mapper->GetLastIndices(), mapper->GetLastIndices() + mapper->GetLastIndexCount());
  EXPECT_EQ(drawn, expected);
  EXPECT_LT(mapper->GetObjectRenderedTriangles(3), mapper->GetObjectNumberOfTriangles(3));

  // Bounds: the union of the leaves (what the actor and ResetCamera see).
  double bounds[6];
  scene.Actor->GetBounds(bounds);
  EXPECT_NEAR(bounds[0], data.Leaves[0]->GetBounds()[0], 1e-6);
  EXPECT_NEAR(bounds[1], data.Leaves[2]->GetBounds()[1], 1e-6);
  EXPECT_NEAR(bounds[3], data.Leaves[3]->GetBounds()[3], 1e-6);
}

TEST(MultiresolutionMapper, ReReadsWhenANestedBlockChanges)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  mapper->SetObjectResolution(0, 0.3);
  mapper->SetObjectResolution(3, 0.6);
  Scene scene(mapper);
  scene.Render();
  // Replace a leaf of the inner multiblock and fill the empty one.
  auto inner = vtkMultiBlockDataSet::SafeDownCast(data.Input->GetBlock(1));
  ASSERT_NE(inner, nullptr);
  auto replacement = MakeTOM(0.35, 36, 24, 0, -1.0, 0);
  auto filled = MakeTOM(0.2, 12, 10, 0.8, 0.8, 0);
  inner->SetBlock(0, replacement);
  inner->SetBlock(2, filled);
  scene.Render();
  // Objects: block 0, inner 0 (replaced), inner 2 (filled), inner 3, block 3.
  ASSERT_EQ(mapper->GetNumberOfObjects(), 5);
  EXPECT_EQ(mapper->GetObjectNumberOfTriangles(1), replacement->GetNumberOfPolys());
  EXPECT_EQ(mapper->GetObjectNumberOfTriangles(2), filled->GetNumberOfPolys());
  EXPECT_EQ(mapper->GetObjectNumberOfTriangles(4), data.Leaves[3]->GetNumberOfPolys());
  // Resolutions stay with object indices; the new index starts at 1.
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(0), 0.3);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(3), 0.6);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(4), 1.0);
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(1), replacement->GetNumberOfPolys());
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
  // A leaf modified in place is read again too.
  auto bigger = MakeTOM(0.2, 20, 16, 0.8, 0.8, 0);
  filled->ShallowCopy(bigger);
  scene.Render();
  EXPECT_EQ(mapper->GetObjectNumberOfTriangles(2), bigger->GetNumberOfPolys());
}

TEST(MultiresolutionMapper, WireframeAndPointIndicesFollowTheTraversal)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.3);
  Scene scene(mapper);
  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  scene.Render();
  EXPECT_EQ(mapper->GetLastIndexCount(), 6 * mapper->GetRenderedTriangles());
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);

  scene.Actor->GetProperty()->SetRepresentationToPoints();
  scene.Render();
  EXPECT_EQ(mapper->GetLastIndexCount(), mapper->GetRenderedVertices());
  // Points are the active vertices [offset, offset + n) of every object.
  std::set<uint32_t> drawn(
    mapper->GetLastIndices(), mapper->GetLastIndices() + mapper->GetLastIndexCount());
  EXPECT_EQ(static_cast<vtkIdType>(drawn.size()), mapper->GetRenderedVertices());
  EXPECT_EQ(*drawn.begin(), 0u);
}

TEST(MultiresolutionMapper, FiftyObjectsInOneDrawCall)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(50);
  for (unsigned int i = 0; i < 50; ++i)
  {
    blocks->SetBlock(i,
      MakeTOM(
        0.15, 10 + (i % 5) * 2, 8 + (i % 3) * 2, 0.4 * (i % 10) - 1.8, 0.4 * (i / 10) - 0.8, 0.0));
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 50);
  for (vtkIdType i = 0; i < 50; ++i)
  {
    mapper->SetObjectResolution(i, 0.02 * static_cast<double>(i + 1));
  }
  Scene scene(mapper);
  scene.SetCamera(0, 0, 6);
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
  EXPECT_GT(mapper->GetRenderedTriangles(), 0);
  EXPECT_GT(scene.CountForeground(), 1000);

  // Everything culled: nothing drawn, no draw call.
  mapper->SetResolution(0.0);
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 0);
  EXPECT_EQ(mapper->GetRenderedTriangles(), 0);
  EXPECT_EQ(scene.CountForeground(), 0);
}

TEST(MultiresolutionMapper, ResolutionChangesRewriteOnlyTheIndexBuffer)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  Scene scene(mapper);
  scene.Render();
  const vtkIdType vertexBuilds = mapper->GetVertexBufferBuildCount();
  const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
  const vtkMTimeType positions = mapper->GetVertexBufferUploadTime("vertexMC");
  const vtkMTimeType normals = mapper->GetVertexBufferUploadTime("normalMC");
  const vtkMTimeType mapperTime = mapper->GetMTime();
  ASSERT_GT(positions, 0u);
  ASSERT_GT(normals, 0u);
  const vtkIdType full = mapper->GetRenderedTriangles();

  // Nothing changed: nothing rebuilt.
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds);
  std::vector<double> same(4, 1.0);
  mapper->SetObjectResolutions(same.data(), 4);
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds);

  for (int frame = 1; frame <= 5; ++frame)
  {
    mapper->SetObjectResolution(frame % 4, 0.1 * frame);
    scene.Render();
    EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds + frame);
    EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
    EXPECT_EQ(mapper->GetVertexBufferUploadTime("vertexMC"), positions);
    EXPECT_EQ(mapper->GetVertexBufferUploadTime("normalMC"), normals);
  }
  EXPECT_LT(mapper->GetRenderedTriangles(), full);
  // Resolutions are render state: they do not modify the mapper.
  EXPECT_EQ(mapper->GetMTime(), mapperTime);

  // A property change goes through the superclass but uploads no vertex data.
  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  scene.Render();
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("vertexMC"), positions);
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("normalMC"), normals);
}

TEST(MultiresolutionMapper, ResolutionChangesDoNotAllocate)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  Scene scene(mapper);
  // Grow every buffer once (the largest index data is at full resolution).
  scene.Render();
  mapper->SetResolution(0.5);
  scene.Render();
  // VTK's own frame may allocate; a resolution change must add nothing to it.
  const std::size_t before = tt::GetAllocationCount();
  scene.Render();
  const std::size_t plainFrame = tt::GetAllocationCount() - before;
  const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
  const std::size_t start = tt::GetAllocationCount();
  mapper->SetObjectResolution(0, 0.3);
  mapper->SetObjectResolution(2, 0.7);
  scene.Render();
  const std::size_t changedFrame = tt::GetAllocationCount() - start;
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds + 1);
  EXPECT_LE(changedFrame, plainFrame);
}

TEST(MultiresolutionMapper, ZeroResolutionCullsAndBadValuesAreErrors)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  mapper->SetObjectResolution(1, 0.0);
  Scene scene(mapper);
  scene.Render();
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(1), 0);
  EXPECT_GT(mapper->GetObjectRenderedTriangles(0), 0);
  const uint32_t begin = static_cast<uint32_t>(mapper->GetObjectVertexOffset(1));
  const uint32_t end = begin + static_cast<uint32_t>(mapper->GetObjectNumberOfVertices(1));
  for (vtkIdType k = 0; k < mapper->GetLastIndexCount(); ++k)
  {
    const uint32_t v = mapper->GetLastIndices()[k];
    ASSERT_FALSE(v >= begin && v < end) << "index " << k << " belongs to the culled object";
  }

  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
  mapper->SetObjectResolution(0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(errors.Count, 1);
  mapper->SetObjectResolution(4, 0.5);
  EXPECT_EQ(errors.Count, 2);
  mapper->SetObjectResolution(-1, 0.5);
  EXPECT_EQ(errors.Count, 3);
  mapper->SetResolution(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(errors.Count, 4);
  std::vector<double> wrongSize(3, 0.5);
  mapper->SetObjectResolutions(wrongSize.data(), 3);
  EXPECT_EQ(errors.Count, 5);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(0), 1.0);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(2), 1.0);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(1), 0.0);
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds);
  // Out of range values are clamped, not errors.
  mapper->SetObjectResolution(0, 7.0);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(0), 1.0);
  EXPECT_EQ(errors.Count, 5);
}

TEST(MultiresolutionMapper, NoInputAndEmptyInput)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EXPECT_EQ(mapper->GetNumberOfObjects(), 0);
  mapper->UpdateObjects();
  EXPECT_EQ(mapper->GetNumberOfObjects(), 0);
  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  {
    Scene scene(mapper);
    scene.Render(); // the renderer culls the actor: it has no bounds
    mapper->RenderPiece(scene.Renderer, scene.Actor);
    EXPECT_EQ(errors.Count, 1); // "no input"
    EXPECT_EQ(mapper->GetRenderedTriangles(), 0);
    double bounds[6];
    mapper->GetBounds(bounds);
    EXPECT_FALSE(vtkMath::AreBoundsInitialized(bounds));
  }
  vtkNew<vtkMultiBlockDataSet> empty;
  empty->SetNumberOfBlocks(2);
  vtkNew<vtkPolyData> nothing;
  empty->SetBlock(0, nothing);
  mapper->SetInputDataObject(empty);
  const int before = errors.Count;
  Scene scene(mapper);
  scene.Render();
  EXPECT_EQ(errors.Count, before);
  EXPECT_EQ(mapper->GetNumberOfObjects(), 0);
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 0);
  EXPECT_EQ(scene.CountForeground(), 0);
}

TEST(MultiresolutionMapper, NonTOMLeafRendersAtFullResolutionWithOneWarning)
{
  vtkNew<vtkSphereSource> plain;
  plain->SetCenter(1.2, 0, 0);
  plain->SetRadius(0.4);
  plain->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, MakeTOM(0.5, 30, 20));
  blocks->SetBlock(1, plain->GetOutput());
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter warnings(mapper, vtkCommand::WarningEvent);
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 2);
  EXPECT_FALSE(mapper->GetObjectIsTOM(1));
  EXPECT_DOUBLE_EQ(mapper->GetObjectCoarsestResolution(1), 1.0);
  mapper->SetResolution(0.1);
  Scene scene(mapper);
  scene.Render();
  scene.Render();
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(1), plain->GetOutput()->GetNumberOfPolys());
  EXPECT_LT(mapper->GetObjectRenderedTriangles(0), mapper->GetObjectNumberOfTriangles(0));
  // A re-read (input modified) does not warn again.
  blocks->Modified();
  scene.Render();
  EXPECT_EQ(warnings.Count, 1);
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(0), 0.1); // kept across the re-read
}

TEST(MultiresolutionMapper, LeavesWithBadPointIdsOrCoordinatesAreErrorsNotCrashes)
{
  // Negative ids once crashed (double free) in the bounds of the leaf and
  // ids past the end were drawn from outside the vertex buffer. Each bad leaf
  // is an error naming the block; the good leaves still draw.
  auto badLeaf = [](vtkIdType id, double coordinate) {
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(2.0, 0.0, 0.0);
    points->InsertNextPoint(3.0, 0.0, 0.0);
    points->InsertNextPoint(2.0, coordinate, 0.0);
    vtkNew<vtkCellArray> polys;
    const vtkIdType ids[3] = { 0, 1, id };
    polys->InsertNextCell(3, ids);
    auto leaf = vtkSmartPointer<vtkPolyData>::New();
    leaf->SetPoints(points);
    leaf->SetPolys(polys);
    return leaf;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case
  {
    vtkSmartPointer<vtkPolyData> Leaf;
    std::string Message;
  };
  const std::vector<Case> cases = { { badLeaf(-5, 1.0), "cell 0 refers to point -5" },
    { badLeaf(3, 1.0), "cell 0 refers to point 3" },
    { badLeaf(100000, 1.0), "cell 0 refers to point 100000" },
    { badLeaf(2, nan), "point 2 has a non-finite" },
    { badLeaf(2, std::numeric_limits<double>::infinity()), "point 2 has a non-finite" } };
  for (const Case& c : cases)
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(2);
    blocks->SetBlock(0, MakeTOM(0.5, 30, 20));
    blocks->SetBlock(1, c.Leaf);
    vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
    vtkNew<vtkTest::ErrorObserver> errors;
    mapper->AddObserver(vtkCommand::ErrorEvent, errors);
    mapper->SetInputDataObject(blocks);
    Scene scene(mapper);
    scene.Render();
    scene.Render();
    ASSERT_TRUE(errors->GetError()) << c.Message;
    EXPECT_NE(errors->GetErrorMessage().find("Block 2 is not drawn: " + c.Message),
      std::string::npos)
      << errors->GetErrorMessage();
    ASSERT_EQ(mapper->GetNumberOfObjects(), 1) << c.Message;
    EXPECT_EQ(mapper->GetObjectRenderedTriangles(0), mapper->GetObjectNumberOfTriangles(0));
    EXPECT_GT(scene.CountForeground(), 0);
  }

  // vtkTOMPolyDataMapper: the same check, nothing drawn.
  vtkNew<vtkTOMPolyDataMapper> single;
  vtkNew<vtkTest::ErrorObserver> errors;
  single->AddObserver(vtkCommand::ErrorEvent, errors);
  single->SetInputData(badLeaf(-1, 1.0));
  Scene scene(single);
  scene.Render();
  ASSERT_TRUE(errors->GetError());
  EXPECT_NE(errors->GetErrorMessage().find("Input is not drawn: cell 0 refers to point -1"),
    std::string::npos)
    << errors->GetErrorMessage();
  EXPECT_EQ(single->GetRenderedTriangles(), 0);
  EXPECT_EQ(scene.CountForeground(), 0);
}

TEST(MultiresolutionMapper, PolyDataAndPartitionedInput)
{
  auto tom = MakeTOM(0.6, 50, 36);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(tom);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 1);
  EXPECT_EQ(mapper->GetObjectFlatIndex(0), 0u);
  mapper->SetResolution(0.25);
  Scene scene(mapper);
  scene.Render();
  EXPECT_EQ(mapper->GetRenderedTriangles(), ExtractedTriangles(tom, 0.25));
  EXPECT_GT(scene.CountForeground(), 1000);

  vtkNew<vtkPartitionedDataSetCollection> collection;
  vtkNew<vtkPartitionedDataSet> first;
  first->SetPartition(0, MakeTOM(0.3, 20, 14, -0.6, 0, 0));
  vtkNew<vtkPartitionedDataSet> second;
  second->SetPartition(0, MakeTOM(0.3, 24, 16, 0.6, 0, 0));
  second->SetPartition(1, MakeTOM(0.3, 28, 18, 0, 0.6, 0));
  collection->SetPartitionedDataSet(0, first);
  collection->SetPartitionedDataSet(1, second);
  vtkNew<vtkMultiresolutionPolyDataMapper> partitioned;
  partitioned->SetInputDataObject(collection);
  partitioned->UpdateObjects();
  ASSERT_EQ(partitioned->GetNumberOfObjects(), 3);
  const double r[3] = { 0.2, 0.5, 1.0 };
  partitioned->SetObjectResolutions(r, 3);
  Scene other(partitioned);
  other.Render();
  EXPECT_EQ(partitioned->GetNumberOfDrawCalls(), 1);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    vtkPolyData* leaf = vtkPolyData::SafeDownCast(
      i == 0 ? first->GetPartition(0) : second->GetPartition(static_cast<unsigned int>(i - 1)));
    EXPECT_EQ(partitioned->GetObjectRenderedTriangles(i), ExtractedTriangles(leaf, r[i]));
  }
  EXPECT_GT(other.CountForeground(), 1000);
}

// A polydata mapper of extracted resolutions (one actor per leaf) against the
// multiresolution mapper of all leaves: same image with the same coloring.
struct ColoringCase
{
  std::vector<vtkSmartPointer<vtkPolyData>> Leaves;
  std::vector<double> Resolutions;
};

void ConfigureColoring(vtkMapper* mapper, bool cells)
{
  // Same vertex values on the GPU for both mappers (no shift and scale from
  // different bounds), so that lines shared by two triangles break their
  // depth ties the same way and take the same cell's color.
  if (auto gl = vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    gl->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::DISABLE_SHIFT_SCALE);
  }
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.0, 0.7);
  lut->Build();
  mapper->SetLookupTable(lut);
  mapper->ScalarVisibilityOn();
  if (cells)
  {
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray("Patch");
    mapper->SetScalarRange(0, 4);
  }
  else
  {
    mapper->SetScalarModeToUsePointFieldData();
    mapper->SelectColorArray("Height");
    mapper->SetScalarRange(-1, 1);
  }
}

void CompareWithExtraction(
  const ColoringCase& input, bool cells, int representation, const std::string& name)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(static_cast<unsigned int>(input.Leaves.size()));
  for (size_t i = 0; i < input.Leaves.size(); ++i)
  {
    blocks->SetBlock(static_cast<unsigned int>(i), input.Leaves[i]);
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  mapper->SetObjectResolutions(
    input.Resolutions.data(), static_cast<vtkIdType>(input.Resolutions.size()));
  ConfigureColoring(mapper, cells);
  Scene scene(mapper);
  scene.SetCamera(0.3, 0.8, 3.2);
  scene.Actor->GetProperty()->SetRepresentation(representation);
  scene.Actor->GetProperty()->SetPointSize(3);
  const std::string image = OutputPath(name + "_multires");
  scene.Save(image);

  Scene reference(nullptr);
  reference.Renderer->RemoveActor(reference.Actor);
  reference.SetCamera(0.3, 0.8, 3.2);
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (size_t i = 0; i < input.Leaves.size(); ++i)
  {
    vtkNew<vtkExtractTOMResolution> extract;
    extract->SetInputData(input.Leaves[i]);
    extract->SetResolution(input.Resolutions[i]);
    extract->Update();
    vtkNew<vtkPolyDataMapper> plain;
    plain->SetInputData(extract->GetOutput());
    ConfigureColoring(plain, cells);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(plain);
    actor->GetProperty()->DeepCopy(scene.Actor->GetProperty());
    reference.Renderer->AddActor(actor);
    actors.push_back(actor);
  }
  const std::string expected = OutputPath(name + "_extracted");
  reference.Save(expected);
  const auto result = tt::CompareImages(image, expected, PixelThreshold);
  EXPECT_TRUE(tt::Passes(result, Tolerance))
    << name << ": " << tt::Describe(result) << " (" << image << " against " << expected << ")";
}

TEST(MultiresolutionMapper, PointAndCellScalarsMatchExtractedResolutions)
{
  ColoringCase input;
  input.Leaves = { MakeTOM(0.55, 48, 32, -0.6, 0, 0), MakeTOM(0.5, 40, 28, 0.6, 0, 0, 6.0) };
  input.Resolutions = { 0.3, 0.7 };
  CompareWithExtraction(input, false, VTK_SURFACE, "PointScalars");
  // Cell colors are looked up by primitive id: rebuilt for the dropped triangles.
  CompareWithExtraction(input, true, VTK_SURFACE, "CellScalars");
  CompareWithExtraction(input, true, VTK_WIREFRAME, "CellScalarsWireframe");
  CompareWithExtraction(input, true, VTK_POINTS, "CellScalarsPoints");
}

TEST(MultiresolutionMapper, WireframeAndPointsRender)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->SetResolution(0.4);
  Scene scene(mapper);
  scene.SetCamera(0, 0.3, 4);
  const std::string surface = OutputPath("Representation_surface");
  scene.Save(surface);
  const int surfacePixels = scene.CountForeground();
  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  const std::string wireframe = OutputPath("Representation_wireframe");
  scene.Save(wireframe);
  const int wirePixels = scene.CountForeground();
  scene.Actor->GetProperty()->SetRepresentationToPoints();
  scene.Actor->GetProperty()->SetPointSize(2);
  scene.Save(OutputPath("Representation_points"));
  const int pointPixels = scene.CountForeground();
  EXPECT_GT(surfacePixels, 5000);
  EXPECT_GT(wirePixels, 1000);
  EXPECT_GT(pointPixels, 500);
  EXPECT_LT(wirePixels, surfacePixels);
  const auto result = tt::CompareImages(wireframe, surface, PixelThreshold);
  ASSERT_TRUE(result.Loaded) << result.Message;
  EXPECT_FALSE(tt::Passes(result, Tolerance)) << tt::Describe(result);
}

TEST(MultiresolutionMapper, GraphicsResourcesFollowTheWindow)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.5);
  {
    Scene first(mapper);
    first.Render();
    EXPECT_GT(first.CountForeground(), 1000);
  } // the window goes first and releases the mapper's buffers
  const vtkIdType builds = mapper->GetVertexBufferBuildCount();
  Scene second(mapper);
  second.Render();
  EXPECT_GT(second.CountForeground(), 1000);
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), builds + 1);
  {
    // Another window while the second lives: buffers move there and back.
    Scene third(mapper);
    third.Render();
    EXPECT_GT(third.CountForeground(), 1000);
    second.Render();
    EXPECT_GT(second.CountForeground(), 1000);
    EXPECT_EQ(mapper->GetVertexBufferBuildCount(), builds + 3);
  }
  // A mapper deleted while its window lives frees its buffers in that window.
  {
    vtkNew<vtkMultiresolutionPolyDataMapper> temporary;
    temporary->SetInputDataObject(data.Input);
    second.Actor->SetMapper(temporary);
    second.Render();
    EXPECT_GT(second.CountForeground(), 1000);
    second.Actor->SetMapper(mapper);
  }
  second.Render();
  EXPECT_GT(second.CountForeground(), 1000);
}

TEST(MultiresolutionMapper, CellPickerReportsFlatIndexAndLeafCell)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 5);
  scene.Render();

  vtkNew<vtkCellPicker> picker;
  picker->SetTolerance(0.0);
  for (vtkIdType object : { vtkIdType(0), vtkIdType(2), vtkIdType(3) })
  {
    // Aim at the centre of the leaf's triangle that faces the camera most directly.
    vtkPolyData* leaf = data.Leaves[object];
    vtkIdType target = -1;
    double best = -1.0, aim[3] = { 0, 0, 0 };
    for (vtkIdType c = 0; c < leaf->GetNumberOfPolys(); ++c)
    {
      vtkIdType npts;
      const vtkIdType* ids;
      leaf->GetPolys()->GetCellAtId(c, npts, ids);
      double p[3][3];
      for (int k = 0; k < 3; ++k)
      {
        leaf->GetPoint(ids[k], p[k]);
      }
      const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
      const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
      const double nz = u[0] * v[1] - u[1] * v[0];
      const double length = std::sqrt(
        std::pow(u[1] * v[2] - u[2] * v[1], 2) + std::pow(u[2] * v[0] - u[0] * v[2], 2) + nz * nz);
      if (length > 0 && nz / length > best)
      {
        best = nz / length;
        target = c;
        for (int k = 0; k < 3; ++k)
        {
          aim[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
        }
      }
    }
    ASSERT_GE(target, 0);
    scene.Renderer->SetWorldPoint(aim[0], aim[1], aim[2], 1.0);
    scene.Renderer->WorldToDisplay();
    double display[3];
    scene.Renderer->GetDisplayPoint(display); // a copy: picking moves the renderer's
    ASSERT_TRUE(picker->Pick(display[0], display[1], 0.0, scene.Renderer));
    EXPECT_EQ(picker->GetActor(), scene.Actor.GetPointer());
    EXPECT_EQ(
      picker->GetFlatBlockIndex(), static_cast<vtkIdType>(mapper->GetObjectFlatIndex(object)));
    EXPECT_EQ(picker->GetDataSet(), leaf);
    // Display coordinates are rounded to pixels: the hit is the aimed cell or
    // lies within a pixel of its centre.
    const double* hit = picker->GetPickPosition();
    EXPECT_NEAR(hit[0], aim[0], 0.02);
    EXPECT_NEAR(hit[1], aim[1], 0.02);
    EXPECT_EQ(picker->GetCellId(), target) << "object " << object;

    // Hardware prop picking (vtkHardwareSelector) finds the actor.
    vtkNew<vtkPropPicker> propPicker;
    ASSERT_TRUE(propPicker->Pick(display[0], display[1], 0.0, scene.Renderer))
      << "object " << object << " at " << display[0] << ", " << display[1];
    EXPECT_EQ(propPicker->GetActor(), scene.Actor.GetPointer());
  }
}

//------------------------------------------------------------------------------
// Image baselines: nine TOMs at pinned resolutions, normal colors and the resolution map.
namespace
{
vtkSmartPointer<vtkMultiBlockDataSet> GridInput()
{
  static vtkSmartPointer<vtkMultiBlockDataSet> grid;
  if (!grid)
  {
    grid = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    grid->SetNumberOfBlocks(9);
    for (unsigned int i = 0; i < 9; ++i)
    {
      const double x = 1.1 * (static_cast<int>(i % 3) - 1);
      const double y = 1.1 * (1 - static_cast<int>(i / 3));
      grid->SetBlock(i, MakeTOM(0.5, 48 + 8 * (i % 3), 32 + 6 * (i / 3), x, y, 0, 6.0 + i));
    }
  }
  return grid;
}

const double GridResolutions[9] = { 1.0, 0.5, 0.25, 0.1, 0.05, 0.75, 0.3, 0.15, 0.02 };

std::string RenderGrid(const double* resolutions, bool map, const std::string& name)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(GridInput());
  mapper->UpdateObjects();
  mapper->SetObjectResolutions(resolutions, 9);
  mapper->SetColorByResolution(map);
  Scene scene(mapper);
  scene.Actor->GetProperty()->SetInterpolationToFlat();
  scene.SetCamera(0.4, 0.5, 7.0);
  const std::string path = OutputPath(name);
  scene.Save(path);
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
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
  const auto result = tt::CompareImages(image, baseline, PixelThreshold);
  EXPECT_TRUE(tt::Passes(result, Tolerance)) << name << ": " << tt::Describe(result) << " (image "
                                             << image << ", baseline " << baseline << ")";
}
}

TEST(MultiresolutionMapperBaseline, GridOfNineObjects)
{
  CheckBaseline(RenderGrid(GridResolutions, false, "Grid"), "Grid");
}

TEST(MultiresolutionMapperBaseline, GridResolutionMap)
{
  CheckBaseline(RenderGrid(GridResolutions, true, "GridResolutionMap"), "GridResolutionMap");
}

TEST(MultiresolutionMapperBaseline, OtherResolutionsFailTheThresholds)
{
  double other[9];
  for (int i = 0; i < 9; ++i)
  {
    other[i] = GridResolutions[(i + 1) % 9];
  }
  const std::string image = RenderGrid(other, false, "GridOtherResolutions");
  const auto result = tt::CompareImages(image, BaselinePath("Grid"), PixelThreshold);
  ASSERT_TRUE(result.Loaded) << result.Message;
  EXPECT_FALSE(tt::Passes(result, Tolerance)) << tt::Describe(result);
  const std::string map = RenderGrid(other, true, "GridOtherResolutionMap");
  const auto mapResult = tt::CompareImages(map, BaselinePath("GridResolutionMap"), PixelThreshold);
  ASSERT_TRUE(mapResult.Loaded) << mapResult.Message;
  EXPECT_FALSE(tt::Passes(mapResult, Tolerance)) << tt::Describe(mapResult);
}

TEST(MultiresolutionMapperBaseline, ResolutionMapFollowsResolutionsAndTurnsOff)
{
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(GridInput());
  mapper->UpdateObjects();
  mapper->SetObjectResolutions(GridResolutions, 9);
  Scene scene(mapper);
  scene.Actor->GetProperty()->SetInterpolationToFlat();
  scene.SetCamera(0.4, 0.5, 7.0);
  const std::string normal = OutputPath("MapToggle_normal");
  scene.Save(normal);

  // Map on with other resolutions first, then the pinned ones: only the
  // colors of changed objects are rewritten, and the result is the baseline.
  double other[9];
  for (int i = 0; i < 9; ++i)
  {
    other[i] = GridResolutions[(i + 4) % 9];
  }
  mapper->SetObjectResolutions(other, 9);
  mapper->ColorByResolutionOn();
  scene.Render();
  const vtkIdType vertexBuilds = mapper->GetVertexBufferBuildCount();
  const vtkMTimeType positions = mapper->GetVertexBufferUploadTime("vertexMC");
  const vtkMTimeType colors = mapper->GetVertexBufferUploadTime("scalarColor");
  ASSERT_GT(colors, 0u);
  mapper->SetObjectResolutions(GridResolutions, 9);
  const std::string map = OutputPath("MapToggle_map");
  scene.Save(map);
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("vertexMC"), positions);
  // Changed objects' colors went in place (glBufferSubData), not as a new upload.
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("scalarColor"), colors);
  const auto mapResult = tt::CompareImages(map, BaselinePath("GridResolutionMap"), PixelThreshold);
  EXPECT_TRUE(tt::Passes(mapResult, Tolerance)) << tt::Describe(mapResult);

  // Off again: normal colors, exactly.
  mapper->ColorByResolutionOff();
  const std::string back = OutputPath("MapToggle_back");
  scene.Save(back);
  const auto backResult = tt::CompareImages(back, normal, 0.0);
  ASSERT_TRUE(backResult.Loaded) << backResult.Message;
  EXPECT_EQ(backResult.MaxError, 0.0) << tt::Describe(backResult);
}

TEST(MultiresolutionMapperBaseline, OneObjectMatchesTheTOMMapper)
{
  auto tom = MakeTOM(1.0, 120, 90);
  for (double r : { 1.0, 0.25, 0.05 })
  {
    vtkNew<vtkMultiresolutionPolyDataMapper> multi;
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(1);
    blocks->SetBlock(0, tom);
    multi->SetInputDataObject(blocks);
    multi->UpdateObjects();
    multi->SetResolution(r);
    Scene multiScene(multi);
    multiScene.Actor->GetProperty()->SetInterpolationToFlat();
    const std::string multiImage =
      OutputPath("OneObject_multires_r" + std::to_string(int(100 * r)));
    multiScene.Save(multiImage);

    vtkNew<vtkTOMPolyDataMapper> single;
    single->SetInputData(tom);
    single->SetResolution(r);
    Scene singleScene(single);
    singleScene.Actor->GetProperty()->SetInterpolationToFlat();
    const std::string singleImage = OutputPath("OneObject_tom_r" + std::to_string(int(100 * r)));
    singleScene.Save(singleImage);

    EXPECT_EQ(multi->GetRenderedTriangles(), single->GetRenderedTriangles());
    const auto result = tt::CompareImages(multiImage, singleImage, PixelThreshold);
    EXPECT_TRUE(tt::Passes(result, Tolerance)) << "r=" << r << ": " << tt::Describe(result);
    EXPECT_EQ(result.MaxError, 0.0) << "r=" << r << ": " << tt::Describe(result);
  }
}

//------------------------------------------------------------------------------
// Index slots: an update rewrites only the objects that changed, in their
// slots, padded with degenerate primitives that draw nothing; the result is
// what a full rebuild without padding draws.
namespace
{
vtkSmartPointer<vtkMultiBlockDataSet> SlotGrid(int count)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(static_cast<unsigned int>(count));
  for (int i = 0; i < count; ++i)
  {
    blocks->SetBlock(static_cast<unsigned int>(i),
      MakeTOM(0.18, 14 + 2 * (i % 4), 10 + 2 * (i % 3), 0.45 * (i % 6) - 1.15,
        0.45 * (i / 6) - 0.7, 0.0, 6.0 + i % 5));
  }
  return blocks;
}

// A reference mapper of the same input, rebuilt in full at every check with
// no slack (no padding at all), in its own window with the same camera.
struct FullRebuild
{
  FullRebuild(vtkDataObject* input, vtkActor* like, bool cells)
    : View(this->Mapper)
  {
    this->Mapper->SetInputDataObject(input);
    this->Mapper->UpdateObjects();
    this->Mapper->SetIndexSlack(0.0);
    if (cells)
    {
      ConfigureColoring(this->Mapper, true);
    }
    this->View.Actor->GetProperty()->DeepCopy(like->GetProperty());
    this->View.SetCamera(0, 0, 3.6);
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> Mapper;
  Scene View;
};

std::vector<uint32_t> LastIndices(vtkMultiresolutionPolyDataMapper* mapper)
{
  return std::vector<uint32_t>(
    mapper->GetLastIndices(), mapper->GetLastIndices() + mapper->GetLastIndexCount());
}

// The mapper's last render against a full rebuild of the same resolutions:
// the same indices per object, the same statistics and (with `image`) the
// same pixels, exactly.
void ExpectSameAsFullRebuild(vtkMultiresolutionPolyDataMapper* mapper, Scene& scene,
  FullRebuild& reference, const std::string& image)
{
  std::vector<double> r(static_cast<size_t>(mapper->GetNumberOfObjects()));
  for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
  {
    r[i] = mapper->GetObjectResolution(i);
  }
  reference.Mapper->SetObjectResolutions(r.data(), static_cast<vtkIdType>(r.size()));
  reference.Mapper->Modified(); // a full rebuild
  reference.View.Render();
  EXPECT_EQ(reference.Mapper->GetNumberOfPaddingPrimitives(), 0);
  EXPECT_EQ(LastIndices(mapper), LastIndices(reference.Mapper));
  EXPECT_EQ(mapper->GetRenderedTriangles(), reference.Mapper->GetRenderedTriangles());
  EXPECT_EQ(mapper->GetRenderedVertices(), reference.Mapper->GetRenderedVertices());
  vtkIdType triangles = 0;
  for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
  {
    triangles += mapper->GetObjectRenderedTriangles(i);
  }
  EXPECT_EQ(mapper->GetRenderedTriangles(), triangles) << "real triangles only";
  if (!image.empty())
  {
    const std::string drawn = OutputPath("Slots_" + image);
    const std::string expected = OutputPath("Slots_" + image + "_rebuilt");
    scene.Save(drawn);
    reference.View.Save(expected);
    const auto result = tt::CompareImages(drawn, expected, 0.0);
    ASSERT_TRUE(result.Loaded) << result.Message;
    EXPECT_EQ(result.MaxError, 0.0) << image << ": " << tt::Describe(result);
  }
}
}

TEST(MultiresolutionMapperSlots, OnlyTheChangedObjectIsRewritten)
{
  auto input = SlotGrid(24);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.3);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 3.6);
  FullRebuild reference(input, scene.Actor, false);
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfRewrittenObjects(), 24);
  EXPECT_GT(mapper->GetNumberOfPaddingPrimitives(), 0);
  ExpectSameAsFullRebuild(mapper, scene, reference, "first");
  const vtkIdType relayouts = mapper->GetIndexBufferRelayoutCount();

  // Nothing changed, or a resolution that keeps the same mesh: nothing written.
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfRewrittenObjects(), 0);
  EXPECT_EQ(mapper->GetIndexBytesUploaded(), 0);
  const vtkIdType builds = mapper->GetIndexBufferBuildCount();
  mapper->SetObjectResolution(7, 0.3 + 1e-9);
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), builds + 1);
  EXPECT_EQ(mapper->GetNumberOfRewrittenObjects(), 0);
  EXPECT_EQ(mapper->GetIndexBytesUploaded(), 0);

  auto onlyObject = [&](vtkIdType changed, const char* step)
  {
    SCOPED_TRACE(step);
    EXPECT_EQ(mapper->GetNumberOfRewrittenObjects(), 1);
    for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
    {
      EXPECT_EQ(mapper->GetObjectRewritten(i), i == changed) << "object " << i;
    }
    EXPECT_EQ(mapper->GetIndexBufferRelayoutCount(), relayouts) << "no relayout";
    EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
    // At most its slot at full resolution (12 bytes a triangle), and a hole
    // of the same size when it moved.
    EXPECT_GT(mapper->GetIndexBytesUploaded(), 0);
    EXPECT_LE(mapper->GetIndexBytesUploaded(), 2 * 12 * mapper->GetObjectNumberOfTriangles(changed));
  };
  // Shrinks in place, grows within its slack, outgrows it (moves), culled, back.
  mapper->SetObjectResolution(7, 0.2);
  scene.Render();
  onlyObject(7, "shrink");
  ExpectSameAsFullRebuild(mapper, scene, reference, "shrink");
  mapper->SetObjectResolution(7, 0.28);
  scene.Render();
  onlyObject(7, "grow in place");
  mapper->SetObjectResolution(7, 0.9);
  scene.Render();
  onlyObject(7, "outgrow");
  ExpectSameAsFullRebuild(mapper, scene, reference, "outgrow");
  mapper->SetObjectResolution(12, 0.0);
  scene.Render();
  onlyObject(12, "cull");
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(12), 0);
  mapper->SetObjectResolution(12, 0.6);
  scene.Render();
  onlyObject(12, "back");
  ExpectSameAsFullRebuild(mapper, scene, reference, "back");
}

TEST(MultiresolutionMapperSlots, PointsHaveNoPadding)
{
  // A degenerate point is still a point: slots fit exactly, culling leaves no
  // hole, and a change of size lays the buffer out again.
  auto input = SlotGrid(12);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.4);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 3.6);
  scene.Actor->GetProperty()->SetRepresentationToPoints();
  scene.Actor->GetProperty()->SetPointSize(2);
  FullRebuild reference(input, scene.Actor, false);
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfPaddingPrimitives(), 0);
  mapper->SetObjectResolution(5, 0.0);
  scene.Render();
  EXPECT_EQ(mapper->GetNumberOfPaddingPrimitives(), 0);
  ExpectSameAsFullRebuild(mapper, scene, reference, "points_cull");
  const vtkIdType relayouts = mapper->GetIndexBufferRelayoutCount();
  mapper->SetObjectResolution(3, 0.8);
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferRelayoutCount(), relayouts + 1);
  EXPECT_EQ(mapper->GetNumberOfPaddingPrimitives(), 0);
  ExpectSameAsFullRebuild(mapper, scene, reference, "points_grow");
}

TEST(MultiresolutionMapperSlots, RandomChangesMatchAFullRebuild)
{
  auto input = SlotGrid(18);
  struct Case
  {
    const char* Name;
    int Representation;
    bool Cells;
    double Slack;
    double LineWidth;
    bool Vertices;
    bool Edges = false;
  };
  // Maximum slack: most of the buffer is padding, which must draw nothing in
  // any representation (wide lines go through a geometry shader).
  const Case cases[] = { { "surface", VTK_SURFACE, false, 0.1, 1.0, false },
    { "surface_cells_padded", VTK_SURFACE, true, 4.0, 1.0, false },
    { "surface_vertices", VTK_SURFACE, false, 0.1, 1.0, true },
    { "wireframe_cells", VTK_WIREFRAME, true, 0.1, 1.0, false },
    { "wide_lines_padded", VTK_WIREFRAME, false, 4.0, 3.0, false },
    { "surface_edges_padded", VTK_SURFACE, false, 4.0, 1.0, false, true },
    { "points_cells", VTK_POINTS, true, 0.1, 1.0, false },
    { "no_slack", VTK_SURFACE, true, 0.0, 1.0, false } };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.Name);
    vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
    mapper->SetInputDataObject(input);
    mapper->UpdateObjects();
    mapper->SetIndexSlack(c.Slack);
    if (c.Cells)
    {
      ConfigureColoring(mapper, true);
    }
    Scene scene(mapper);
    scene.SetCamera(0, 0, 3.6);
    vtkProperty* property = scene.Actor->GetProperty();
    property->SetRepresentation(c.Representation);
    property->SetLineWidth(static_cast<float>(c.LineWidth));
    property->SetPointSize(2);
    property->SetVertexVisibility(c.Vertices);
    property->SetEdgeVisibility(c.Edges);
    property->SetEdgeColor(0.1, 0.9, 0.2);
    FullRebuild reference(input, scene.Actor, c.Cells);
    vtkMath::RandomSeed(42);
    for (int frame = 0; frame < 16; ++frame)
    {
      // A random third of the objects change: culled, full, or anything between.
      for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
      {
        const double u = vtkMath::Random();
        if (frame == 0 || u < 1.0 / 3.0)
        {
          const double v = vtkMath::Random();
          mapper->SetObjectResolution(i, v < 0.1 ? 0.0 : v > 0.9 ? 1.0 : v);
        }
      }
      scene.Render();
      EXPECT_LE(mapper->GetNumberOfDrawCalls(), c.Vertices ? 2 : 1);
      if (c.Representation == VTK_POINTS)
      {
        EXPECT_EQ(mapper->GetNumberOfPaddingPrimitives(), 0) << "no degenerate point exists";
      }
      ExpectSameAsFullRebuild(mapper, scene, reference,
        frame % 2 == 1 ? std::string(c.Name) + "_" + std::to_string(frame) : std::string());
    }
  }
}

TEST(MultiresolutionMapperSlots, RelocationAndCompactionDoNotAllocate)
{
  auto input = SlotGrid(24);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.5);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 3.6);
  scene.Render();
  scene.Render();
  const std::size_t before = tt::GetAllocationCount();
  scene.Render();
  const std::size_t plainFrame = tt::GetAllocationCount() - before;

  // Half the objects to full resolution: they outgrow their slots, the
  // buffer runs out of room and is compacted within the update.
  const vtkIdType relayouts = mapper->GetIndexBufferRelayoutCount();
  std::size_t start = tt::GetAllocationCount();
  for (vtkIdType i = 0; i < 24; i += 2)
  {
    mapper->SetObjectResolution(i, 1.0);
  }
  scene.Render();
  EXPECT_LE(tt::GetAllocationCount() - start, plainFrame);
  EXPECT_GT(mapper->GetIndexBufferRelayoutCount(), relayouts);
  for (vtkIdType i = 0; i < 24; i += 2)
  {
    EXPECT_TRUE(mapper->GetObjectRewritten(i)) << "object " << i;
  }

  // Then most shrink far below their slots: holes, compaction for padding.
  start = tt::GetAllocationCount();
  for (vtkIdType i = 0; i < 20; ++i)
  {
    mapper->SetObjectResolution(i, 0.05);
  }
  scene.Render();
  EXPECT_LE(tt::GetAllocationCount() - start, plainFrame);
  EXPECT_LE(mapper->GetNumberOfPaddingPrimitives(),
    2 * (mapper->GetRenderedTriangles() / 10 + 8 * 24)) << "padding within its limit";
}

TEST(MultiresolutionMapperSlots, MovingFrontsRewriteOnlyTheirSlots)
{
  // Two merge-tree leaves drawn as view-dependent fronts between three TOMs.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(5);
  for (unsigned int i = 0; i < 5; ++i)
  {
    auto surface = tt::MakeBumpySurface(0.35, 36, 24, 0.8 * i - 1.6, 0, 0, 7.0);
    if (i % 2 == 1)
    {
      vtkNew<vtkMergeTreeBuilder> builder;
      builder->SetInputData(surface);
      builder->Update();
      auto tree = vtkSmartPointer<vtkPolyData>::New();
      tree->ShallowCopy(builder->GetOutput());
      blocks->SetBlock(i, tree);
    }
    else
    {
      blocks->SetBlock(i, BuildTOM(surface));
    }
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  mapper->SetResolution(0.4);
  mapper->SetRefinementModeToFixedAccuracy();
  Scene scene(mapper);
  scene.SetCamera(0, 0.5, 4.0);
  scene.Render();
  ASSERT_TRUE(mapper->GetObjectIsViewDependent(1));
  ASSERT_TRUE(mapper->GetObjectIsViewDependent(3));
  int frontChanges = 0;
  for (int frame = 1; frame <= 8; ++frame)
  {
    const vtkIdType relayouts = mapper->GetIndexBufferRelayoutCount();
    scene.SetCamera(0.4 * frame - 1.6, 0.5, 4.0 - 0.3 * frame);
    scene.Render();
    EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
    if (mapper->GetIndexBufferRelayoutCount() != relayouts)
    {
      continue; // compacted: moved slots are rewritten too
    }
    for (vtkIdType i = 0; i < 5; ++i)
    {
      const bool moved = mapper->GetObjectSplits(i) + mapper->GetObjectMerges(i) > 0;
      EXPECT_EQ(mapper->GetObjectRewritten(i), moved) << "frame " << frame << ", object " << i;
      frontChanges += moved ? 1 : 0;
    }
  }
  EXPECT_GE(frontChanges, 4) << "the camera path should move the fronts";
}

//------------------------------------------------------------------------------
// Hardware selection (vtkHardwareSelector on the renderer, as ParaView selects):
// every selected (flat index, cell id) is a leaf cell that the mapper drew, at
// any resolution and for view-dependent fronts, and the cell under a drawn
// triangle's centre is that triangle's own.
namespace
{
// The leaf cells drawn for object i by the last render, each with the drawn
// triangle (its index among the object's drawn triangles) it became: a cell
// is drawn when its corners, moved up the substitution forest to vertices
// that the drawn triangles use, are the corners of a drawn triangle.
struct DrawnCells
{
  std::vector<std::array<uint32_t, 3>> Triangles; // leaf point ids
  std::map<vtkIdType, size_t> CellTriangle;       // drawn cell -> its drawn triangle
  std::set<uint32_t> Vertices;
};

DrawnCells GetDrawnCells(vtkMultiresolutionPolyDataMapper* mapper, vtkIdType object, vtkPolyData* leaf)
{
  DrawnCells drawn;
  const uint32_t* indices = mapper->GetLastIndices();
  size_t start = 0;
  for (vtkIdType i = 0; i < object; ++i)
  {
    start += 3 * static_cast<size_t>(mapper->GetObjectRenderedTriangles(i));
  }
  const auto offset = static_cast<uint32_t>(mapper->GetObjectVertexOffset(object));
  std::map<std::array<uint32_t, 3>, size_t> byCorners;
  for (vtkIdType t = 0; t < mapper->GetObjectRenderedTriangles(object); ++t)
  {
    std::array<uint32_t, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      corners[k] = indices[start + 3 * t + k] - offset;
      drawn.Vertices.insert(corners[k]);
    }
    drawn.Triangles.push_back(corners);
    std::sort(corners.begin(), corners.end());
    byCorners[corners] = static_cast<size_t>(t);
  }
  vtkDataArray* substitution =
    leaf->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName());
  auto up = [&](vtkIdType v)
  {
    while (substitution && !drawn.Vertices.count(static_cast<uint32_t>(v)))
    {
      const auto parent = static_cast<vtkIdType>(substitution->GetComponent(v, 0));
      if (parent == v)
      {
        break;
      }
      v = parent;
    }
    return static_cast<uint32_t>(v);
  };
  for (vtkIdType c = 0; c < leaf->GetNumberOfPolys(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    leaf->GetPolys()->GetCellAtId(c, npts, ids);
    if (npts != 3)
    {
      continue;
    }
    std::array<uint32_t, 3> corners = { up(ids[0]), up(ids[1]), up(ids[2]) };
    std::sort(corners.begin(), corners.end());
    auto found = byCorners.find(corners);
    if (found != byCorners.end())
    {
      EXPECT_EQ(drawn.CellTriangle.count(c), 0u);
      drawn.CellTriangle[c] = found->second;
    }
  }
  // Every drawn triangle comes from exactly one cell.
  EXPECT_EQ(drawn.CellTriangle.size(), drawn.Triangles.size()) << "object " << object;
  return drawn;
}

// (flat index, id) pairs of an area selection of the whole window.
std::set<std::pair<unsigned int, vtkIdType>> SelectArea(Scene& scene, int association)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(scene.Renderer);
  selector->SetFieldAssociation(association);
  const int* size = scene.Window->GetSize();
  selector->SetArea(0, 0, static_cast<unsigned int>(size[0] - 1), static_cast<unsigned int>(size[1] - 1));
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  std::set<std::pair<unsigned int, vtkIdType>> pairs;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    EXPECT_EQ(node->GetProperties()->Get(vtkSelectionNode::PROP()), scene.Actor.GetPointer());
    const auto flat =
      static_cast<unsigned int>(node->GetProperties()->Get(vtkSelectionNode::COMPOSITE_INDEX()));
    auto ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    for (vtkIdType k = 0; ids && k < ids->GetNumberOfTuples(); ++k)
    {
      pairs.emplace(flat, ids->GetValue(k));
    }
  }
  return pairs;
}

// Checks the area selection of cells (and of points) and, for each object, the
// pixel at the centre of its largest drawn triangle facing the camera (+z).
void CheckSelection(vtkMultiresolutionPolyDataMapper* mapper, Scene& scene,
  const std::vector<vtkPolyData*>& leaves, const std::string& what, bool pixels = true)
{
  // What is drawn, from the triangle indices of a surface render.
  vtkProperty* property = scene.Actor->GetProperty();
  const int representation = property->GetRepresentation();
  property->SetRepresentationToSurface();
  scene.Render();
  std::map<unsigned int, vtkIdType> objectOfFlat;
  std::vector<DrawnCells> drawn;
  for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
  {
    objectOfFlat[mapper->GetObjectFlatIndex(i)] = i;
    drawn.push_back(GetDrawnCells(mapper, i, leaves[i]));
  }
  property->SetRepresentation(representation);
  scene.Render();

  // Pairs that are not a drawn cell of an object: counted, the first one shown.
  size_t wrong = 0;
  std::string example;
  auto check = [&](const std::pair<unsigned int, vtkIdType>& pair, bool cell)
  {
    auto object = objectOfFlat.find(pair.first);
    const bool right = object != objectOfFlat.end() &&
      (cell ? drawn[object->second].CellTriangle.count(pair.second)
            : drawn[object->second].Vertices.count(static_cast<uint32_t>(pair.second))) == 1;
    if (!right && wrong++ == 0)
    {
      example = (cell ? "cell " : "point ") + std::to_string(pair.second) + " of flat index " +
        std::to_string(pair.first);
    }
    return right ? object->second : -1;
  };
  const auto cells = SelectArea(scene, vtkDataObject::FIELD_ASSOCIATION_CELLS);
  std::vector<size_t> selected(leaves.size(), 0);
  for (const auto& pair : cells)
  {
    const vtkIdType object = check(pair, true);
    selected[object >= 0 ? object : 0] += object >= 0 ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u) << what << ": " << wrong << " of " << cells.size()
                       << " selected cells not drawn, e.g. " << example;
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    // Every object shows many of its cells (points: those of its visible vertices).
    EXPECT_GE(selected[i], std::min<size_t>(10, drawn[i].Triangles.size() / 8))
      << what << ": object " << i;
  }

  const auto points = SelectArea(scene, vtkDataObject::FIELD_ASSOCIATION_POINTS);
  EXPECT_GT(points.size(), 20u) << what;
  wrong = 0;
  for (const auto& pair : points)
  {
    check(pair, false);
  }
  EXPECT_EQ(wrong, 0u) << what << ": " << wrong << " of " << points.size()
                       << " selected points not drawn, e.g. " << example;
  if (!pixels)
  {
    return;
  }

  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(scene.Renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  const int* size = scene.Window->GetSize();
  selector->SetArea(0, 0, static_cast<unsigned int>(size[0] - 1), static_cast<unsigned int>(size[1] - 1));
  ASSERT_TRUE(selector->CaptureBuffers());
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    double largest = 0.0, aim[3] = { 0, 0, 0 };
    size_t target = 0;
    for (size_t t = 0; t < drawn[i].Triangles.size(); ++t)
    {
      double p[3][3];
      for (int k = 0; k < 3; ++k)
      {
        leaves[i]->GetPoint(drawn[i].Triangles[t][k], p[k]);
      }
      const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
      const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
      double n[3];
      vtkMath::Cross(u, v, n);
      const double area = vtkMath::Norm(n);
      if (area > largest && n[2] > 0.9 * area)
      {
        largest = area;
        target = t;
        for (int k = 0; k < 3; ++k)
        {
          aim[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
        }
      }
    }
    ASSERT_GT(largest, 0.0) << what << ": object " << i;
    vtkIdType cell = -1;
    for (const auto& entry : drawn[i].CellTriangle)
    {
      if (entry.second == target)
      {
        cell = entry.first;
      }
    }
    scene.Renderer->SetWorldPoint(aim[0], aim[1], aim[2], 1.0);
    scene.Renderer->WorldToDisplay();
    double display[3];
    scene.Renderer->GetDisplayPoint(display);
    const unsigned int position[2] = { static_cast<unsigned int>(std::lround(display[0])),
      static_cast<unsigned int>(std::lround(display[1])) };
    const vtkHardwareSelector::PixelInformation info = selector->GetPixelInformation(position);
    ASSERT_TRUE(info.Valid) << what << ": object " << i;
    EXPECT_EQ(info.Prop, scene.Actor.GetPointer());
    EXPECT_EQ(info.CompositeID, mapper->GetObjectFlatIndex(static_cast<vtkIdType>(i)))
      << what << ": object " << i;
    EXPECT_EQ(info.AttributeID, cell) << what << ": object " << i;
  }
}
}

TEST(MultiresolutionMapperSelection, AreaSelectionReportsLeafCellsAtAnyResolution)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  Scene scene(mapper, 500);
  scene.SetCamera(0, 0, 7);
  const std::vector<vtkPolyData*> leaves(data.Leaves.begin(), data.Leaves.end());
  CheckSelection(mapper, scene, leaves, "full resolution");

  const double reduced[4] = { 0.3, 0.5, 0.15, 0.6 };
  mapper->SetObjectResolutions(reduced, 4);
  scene.Render();
  CheckSelection(mapper, scene, leaves, "reduced");
  for (vtkIdType i = 0; i < 4; ++i)
  {
    EXPECT_LT(mapper->GetObjectRenderedTriangles(i), mapper->GetObjectNumberOfTriangles(i));
  }

  // Slots moved by growth and shrinking: ids follow the slots, not object order.
  const double moved[4] = { 0.9, 0.1, 0.7, 0.2 };
  mapper->SetObjectResolutions(moved, 4);
  CheckSelection(mapper, scene, leaves, "moved slots");

  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  CheckSelection(mapper, scene, leaves, "wireframe", false);
  scene.Actor->GetProperty()->SetRepresentationToPoints();
  scene.Actor->GetProperty()->SetPointSize(3);
  CheckSelection(mapper, scene, leaves, "points", false);
}

TEST(MultiresolutionMapperSelection, FrontsAndNonTOMLeaves)
{
  // A view-dependent front, a TOM and a plain (non-TOM) surface.
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetInputData(tt::MakeBumpySurface(0.5, 40, 30, -1.2, 0, 0, 7.0));
  builder->Update();
  auto tree = vtkSmartPointer<vtkPolyData>::New();
  tree->ShallowCopy(builder->GetOutput());
  auto tom = MakeTOM(0.45, 48, 32, 0, 0, 0);
  vtkNew<vtkSphereSource> plain;
  plain->SetCenter(1.2, 0, 0);
  plain->SetRadius(0.4);
  plain->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(3);
  blocks->SetBlock(0, tree);
  blocks->SetBlock(1, tom);
  blocks->SetBlock(2, plain->GetOutput());
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter warnings(mapper, vtkCommand::WarningEvent); // the non-TOM leaf
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  EXPECT_EQ(warnings.Count, 1);
  mapper->SetResolution(0.3);
  Scene scene(mapper, 500);
  scene.SetCamera(0, 0, 7);
  scene.Render();
  ASSERT_TRUE(mapper->GetObjectIsViewDependent(0));
  ASSERT_FALSE(mapper->GetObjectIsTOM(2));
  EXPECT_LT(mapper->GetObjectRenderedTriangles(0), mapper->GetObjectNumberOfTriangles(0));
  const std::vector<vtkPolyData*> leaves = { tree, tom, plain->GetOutput() };
  CheckSelection(mapper, scene, leaves, "front");
  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  CheckSelection(mapper, scene, leaves, "front, wireframe", false);
}

//------------------------------------------------------------------------------
// Memory: the mapper keeps no copy of the leaves' points, arrays or cells; its
// vertex buffers are appended from the leaves themselves.
namespace
{
// Exposes the superclass's input and vertex buffers.
class InspectedMapper : public vtkMultiresolutionPolyDataMapper
{
public:
  static InspectedMapper* New();
  vtkTypeMacro(InspectedMapper, vtkMultiresolutionPolyDataMapper);
  vtkPolyData* GetCurrentInput() { return this->CurrentInput; }
  vtkOpenGLVertexBufferObject* GetVBO(const char* attribute)
  {
    return this->VBOs->GetVBO(attribute);
  }

protected:
  InspectedMapper() = default;
  ~InspectedMapper() override = default;
};
vtkStandardNewMacro(InspectedMapper);

double HeapInUse()
{
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks) + static_cast<double>(info.hblkhd);
}

vtkIdType TotalTriangles(const std::vector<vtkSmartPointer<vtkPolyData>>& leaves)
{
  vtkIdType total = 0;
  for (const auto& leaf : leaves)
  {
    total += leaf->GetNumberOfPolys();
  }
  return total;
}
}

TEST(MultiresolutionMapperMemory, NoCopyOfTheLeaves)
{
  // Eight TOMs (about 150K triangles): what UpdateObjects() keeps is the TOM
  // arrays' copies (3 + 1/T ids per triangle and vertex, 4 bytes each) and
  // little else; a merged copy of the leaves (points, normals, the Height and
  // Patch arrays, polygons) would add more than 30 bytes per triangle.
  std::vector<vtkSmartPointer<vtkPolyData>> leaves;
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(8);
  vtkIdType points = 0;
  for (unsigned int i = 0; i < 8; ++i)
  {
    leaves.push_back(MakeTOM(0.3, 110, 90, 0.7 * (i % 4) - 1.05, i < 4 ? 0.4 : -0.4, 0));
    blocks->SetBlock(i, leaves.back());
    points += leaves.back()->GetNumberOfPoints();
  }
  const vtkIdType triangles = TotalTriangles(leaves);
  ASSERT_GT(triangles, 100000);
  vtkNew<InspectedMapper> mapper;
  mapper->SetInputDataObject(blocks);
  {
    // What reading builds in the leaves themselves (cell maps for their
    // bounds, array ranges) is input memory: built here first.
    vtkNew<vtkMultiresolutionPolyDataMapper> first;
    first->SetInputDataObject(blocks);
    first->UpdateObjects();
  }
  const double before = HeapInUse();
  mapper->UpdateObjects();
  const double kept = HeapInUse() - before;
  // The TOM copies, and the traversal's scratch (one object at full resolution).
  const double copies = 4.0 * (3.0 * static_cast<double>(triangles) + static_cast<double>(points)) +
    12.0 * static_cast<double>(leaves[0]->GetNumberOfPolys());
  EXPECT_LT(kept, copies + 1.0 * static_cast<double>(triangles) + 65536.0)
    << "UpdateObjects() kept " << kept / triangles << " bytes per triangle, "
    << copies / triangles << " of them TOM copies and scratch";

  mapper->SetResolution(0.4);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 4);
  scene.Render();
  EXPECT_GT(scene.CountForeground(), 5000);
  // The GPU timer runs on the leaves' cells (the skeleton has none).
  EXPECT_GT(mapper->GetTimeToDraw(), 0.0);
  // The superclass's input has no points, no polygons and arrays of no tuples.
  vtkPolyData* skeleton = mapper->GetCurrentInput();
  ASSERT_NE(skeleton, nullptr);
  EXPECT_EQ(skeleton->GetNumberOfPoints(), 0);
  EXPECT_EQ(skeleton->GetNumberOfCells(), 0);
  ASSERT_NE(skeleton->GetPointData()->GetNormals(), nullptr); // decides the shaders' normals
  EXPECT_EQ(skeleton->GetPointData()->GetNormals()->GetNumberOfTuples(), 0);
  for (int a = 0; a < skeleton->GetPointData()->GetNumberOfArrays(); ++a)
  {
    EXPECT_EQ(skeleton->GetPointData()->GetAbstractArray(a)->GetNumberOfTuples(), 0);
  }
  // The vertex buffers hold every leaf's vertices, and no CPU packing copy stays.
  for (const char* attribute : { "vertexMC", "normalMC" })
  {
    vtkOpenGLVertexBufferObject* vbo = mapper->GetVBO(attribute);
    ASSERT_NE(vbo, nullptr) << attribute;
    EXPECT_EQ(static_cast<vtkIdType>(vbo->GetNumberOfTuples()), points) << attribute;
    EXPECT_EQ(vbo->GetPackedVBO().capacity(), 0u) << attribute;
  }
}

TEST(MultiresolutionMapperMemory, RebuiltBuffersMatchAFreshMapper)
{
  // Vertex buffers appended from the leaves again after a leaf changed, and
  // colors alone re-uploaded after a scalar range change: the same image as
  // a new mapper of the same input, exactly.
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  const double r[4] = { 1.0, 0.5, 0.3, 0.7 };
  mapper->SetObjectResolutions(r, 4);
  ConfigureColoring(mapper, false);
  Scene scene(mapper);
  scene.SetCamera(0.5, 0.4, 4.5);
  scene.Render();
  auto compare = [&](const std::string& name)
  {
    vtkNew<vtkMultiresolutionPolyDataMapper> fresh;
    fresh->SetInputDataObject(data.Input);
    fresh->UpdateObjects();
    fresh->SetObjectResolutions(r, 4);
    ConfigureColoring(fresh, false);
    fresh->SetScalarRange(mapper->GetScalarRange());
    Scene reference(fresh);
    reference.SetCamera(0.5, 0.4, 4.5);
    const std::string drawn = OutputPath("Rebuilt_" + name);
    const std::string expected = OutputPath("Rebuilt_" + name + "_fresh");
    scene.Save(drawn);
    reference.Save(expected);
    const auto result = tt::CompareImages(drawn, expected, 0.0);
    ASSERT_TRUE(result.Loaded) << result.Message;
    EXPECT_EQ(result.MaxError, 0.0) << name << ": " << tt::Describe(result);
    EXPECT_GT(scene.CountForeground(), 5000) << name;
  };

  // A leaf replaced in place: everything appended again.
  data.Leaves[2]->ShallowCopy(MakeTOM(0.4, 50, 30, 1.2, 0.1, 0));
  const vtkIdType builds = mapper->GetVertexBufferBuildCount();
  compare("leaf");
  EXPECT_GT(mapper->GetVertexBufferBuildCount(), builds);

  // Another scalar range: the colors only.
  const vtkMTimeType positions = mapper->GetVertexBufferUploadTime("vertexMC");
  const vtkMTimeType colors = mapper->GetVertexBufferUploadTime("scalarColor");
  ASSERT_NE(colors, 0u);
  mapper->SetScalarRange(-0.5, 0.5);
  compare("range");
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("vertexMC"), positions);
  EXPECT_GT(mapper->GetVertexBufferUploadTime("scalarColor"), colors);
}

//------------------------------------------------------------------------------
// Vertices, lines, polygons and strips of a non-TOM leaf next to a TOM: drawn
// with cell colors like plain polydata mappers of the leaves draw them, and
// selected with the leaf's own cell ids.
namespace
{
vtkSmartPointer<vtkPolyData> MakeMixedCells()
{
  auto mixed = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  auto add = [&](double x, double y) { return points->InsertNextPoint(x, y, 0.0); };
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  verts->InsertNextCell({ add(1.1, 0.7) });
  verts->InsertNextCell({ add(1.4, 0.7), add(1.7, 0.7) });
  lines->InsertNextCell({ add(1.1, 0.45), add(1.5, 0.55), add(1.9, 0.45) });
  lines->InsertNextCell({ add(1.1, 0.3), add(1.9, 0.3) });
  polys->InsertNextCell({ add(1.1, -0.1), add(1.5, -0.1), add(1.5, 0.2), add(1.1, 0.2) });
  polys->InsertNextCell({ add(1.6, -0.1), add(1.9, -0.1), add(1.75, 0.2) });
  std::vector<vtkIdType> strip;
  for (int k = 0; k < 6; ++k)
  {
    strip.push_back(add(1.1 + 0.16 * k, k % 2 ? -0.7 : -0.4)); // counter-clockwise: lit
  }
  strips->InsertNextCell(static_cast<vtkIdType>(strip.size()), strip.data());
  mixed->SetPoints(points);
  mixed->SetVerts(verts);
  mixed->SetLines(lines);
  mixed->SetPolys(polys);
  mixed->SetStrips(strips);
  // The arrays of the TOM leaves (only arrays common to all leaves color).
  vtkNew<vtkFloatArray> height, normals;
  height->SetName("Height");
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    height->InsertNextValue(static_cast<float>(points->GetPoint(p)[1]));
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
  }
  mixed->GetPointData()->AddArray(height);
  mixed->GetPointData()->SetNormals(normals);
  vtkNew<vtkIntArray> patch;
  patch->SetName("Patch");
  for (vtkIdType c = 0; c < mixed->GetNumberOfCells(); ++c)
  {
    patch->InsertNextValue(static_cast<int>(c % 5));
  }
  mixed->GetCellData()->AddArray(patch);
  return mixed;
}
/// The multiresolution scene's image against a plain VTK scene's (name_multires, name_plain).
void ExpectSameImages(Scene& scene, Scene& reference, const std::string& name)
{
  const std::string image = OutputPath(name + "_multires");
  const std::string expected = OutputPath(name + "_plain");
  scene.Save(image);
  reference.Save(expected);
  const auto result = tt::CompareImages(image, expected, PixelThreshold);
  EXPECT_TRUE(tt::Passes(result, Tolerance))
    << name << ": " << tt::Describe(result) << " (" << image << " against " << expected << ")";
}
}

TEST(MultiresolutionMapper, VerticesLinesAndStripsOfNonTOMLeaves)
{
  auto tom = MakeTOM(0.5, 40, 28, 0, 0, 0);
  auto mixed = MakeMixedCells();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, tom);
  blocks->SetBlock(1, mixed);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter warnings(mapper, vtkCommand::WarningEvent); // the non-TOM leaf
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 2);
  ConfigureColoring(mapper, true);
  Scene scene(mapper);
  scene.SetCamera(0.75, 0, 3.5, 0.75, 0, 0);
  scene.Actor->GetProperty()->SetPointSize(5);
  scene.Actor->GetProperty()->SetLineWidth(3);

  Scene reference(nullptr);
  reference.Renderer->RemoveActor(reference.Actor);
  reference.SetCamera(0.75, 0, 3.5, 0.75, 0, 0);
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (vtkPolyData* leaf : { tom.GetPointer(), mixed.GetPointer() })
  {
    vtkNew<vtkPolyDataMapper> plain;
    plain->SetInputData(leaf);
    ConfigureColoring(plain, true);
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(plain);
    reference.Renderer->AddActor(actor);
    actors.push_back(actor);
  }
  for (int representation : { VTK_SURFACE, VTK_WIREFRAME, VTK_POINTS })
  {
    scene.Actor->GetProperty()->SetRepresentation(representation);
    for (auto& actor : actors)
    {
      actor->GetProperty()->DeepCopy(scene.Actor->GetProperty());
    }
    ExpectSameImages(scene, reference, "MixedCells_" + std::to_string(representation));
  }

  // Cell selection: the mixed leaf's cells of every type, by its own ids.
  scene.Actor->GetProperty()->SetRepresentationToSurface();
  scene.Render();
  std::set<int> types;
  vtkIdType tomCells = 0;
  for (const auto& pair : SelectArea(scene, vtkDataObject::FIELD_ASSOCIATION_CELLS))
  {
    if (pair.first == mapper->GetObjectFlatIndex(1))
    {
      ASSERT_LT(pair.second, mixed->GetNumberOfCells());
      types.insert(mixed->GetCellType(pair.second));
    }
    else
    {
      EXPECT_EQ(pair.first, mapper->GetObjectFlatIndex(0));
      EXPECT_LT(pair.second, tom->GetNumberOfCells());
      ++tomCells;
    }
  }
  EXPECT_EQ(types, (std::set<int>{ VTK_VERTEX, VTK_POLY_VERTEX, VTK_POLY_LINE, VTK_LINE, VTK_QUAD,
                     VTK_TRIANGLE, VTK_TRIANGLE_STRIP }));
  EXPECT_GT(tomCells, 100);
  EXPECT_EQ(warnings.Count, 1);
}

TEST(MultiresolutionMapper, TextureColorsCameraShiftScaleAndTranslucency)
{
  // Interpolated scalars (color texture coordinates mapped per leaf) and
  // camera-based shift and scale (vertex buffers appended again when the
  // shift moves): the same images as plain polydata mappers of the leaves.
  std::vector<vtkSmartPointer<vtkPolyData>> leaves = { MakeTOM(0.5, 40, 28, -0.6, 0, 0),
    MakeTOM(0.45, 36, 24, 0.6, 0, 0, 6.0) };
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, leaves[0]);
  blocks->SetBlock(1, leaves[1]);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(blocks);
  ConfigureColoring(mapper, false);
  mapper->InterpolateScalarsBeforeMappingOn();
  mapper->SetVBOShiftScaleMethod(vtkOpenGLVertexBufferObject::NEAR_PLANE_SHIFT_SCALE);
  Scene scene(mapper);
  Scene reference(nullptr);
  reference.Renderer->RemoveActor(reference.Actor);
  for (const auto& leaf : leaves)
  {
    vtkNew<vtkPolyDataMapper> plain;
    plain->SetInputData(leaf);
    ConfigureColoring(plain, false);
    plain->InterpolateScalarsBeforeMappingOn();
    vtkOpenGLPolyDataMapper::SafeDownCast(plain)->SetVBOShiftScaleMethod(
      vtkOpenGLVertexBufferObject::NEAR_PLANE_SHIFT_SCALE);
    vtkNew<vtkActor> actor;
    actor->SetMapper(plain);
    actor->GetProperty()->DeepCopy(scene.Actor->GetProperty());
    reference.Renderer->AddActor(actor);
  }
  for (int view = 0; view < 2; ++view)
  {
    scene.SetCamera(0.3 + view, 0.6, 3.0 - view);
    reference.SetCamera(0.3 + view, 0.6, 3.0 - view);
    ExpectSameImages(scene, reference, "TextureColors_" + std::to_string(view));
    EXPECT_GT(scene.CountForeground(), 5000);
  }
  EXPECT_GE(mapper->GetVertexBufferBuildCount(), 2) << "the shift moved with the camera";

  // Translucent colors in one leaf make the actor translucent.
  EXPECT_FALSE(mapper->HasTranslucentPolygonalGeometry());
  vtkNew<vtkLookupTable> translucent;
  translucent->SetAlphaRange(0.5, 0.5);
  translucent->Build();
  mapper->SetLookupTable(translucent);
  EXPECT_TRUE(mapper->HasTranslucentPolygonalGeometry());
  EXPECT_TRUE(mapper->HasTranslucentPolygonalGeometry()); // the kept answer
  translucent->SetAlphaRange(1.0, 1.0); // the table changed in place
  translucent->ForceBuild();
  EXPECT_FALSE(mapper->HasTranslucentPolygonalGeometry());
}

TEST(MultiresolutionMapperSelection, IdArraysOfTheLeaves)
{
  // Cell and point id arrays (as ParaView names its original ids) are read
  // from each leaf at the leaf's own ids.
  NestedScene data;
  for (auto& leaf : data.Leaves)
  {
    vtkNew<vtkIdTypeArray> cellIds, pointIds;
    cellIds->SetName("OriginalCellIds");
    pointIds->SetName("OriginalPointIds");
    for (vtkIdType c = 0; c < leaf->GetNumberOfCells(); ++c)
    {
      cellIds->InsertNextValue(50000 + c);
    }
    for (vtkIdType p = 0; p < leaf->GetNumberOfPoints(); ++p)
    {
      pointIds->InsertNextValue(70000 + p);
    }
    leaf->GetCellData()->AddArray(cellIds);
    leaf->GetPointData()->AddArray(pointIds);
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->SetCellIdArrayName("OriginalCellIds");
  mapper->SetPointIdArrayName("OriginalPointIds");
  mapper->UpdateObjects();
  const double r[4] = { 0.4, 0.6, 0.3, 0.5 };
  mapper->SetObjectResolutions(r, 4);
  Scene scene(mapper, 500);
  scene.SetCamera(0, 0, 7);
  scene.Render();
  std::map<unsigned int, vtkIdType> objectOfFlat;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    objectOfFlat[mapper->GetObjectFlatIndex(i)] = i;
  }
  for (const int association :
    { vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkDataObject::FIELD_ASSOCIATION_POINTS })
  {
    const bool cells = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
    const auto pairs = SelectArea(scene, association);
    EXPECT_GT(pairs.size(), 100u);
    size_t wrong = 0;
    for (const auto& pair : pairs)
    {
      auto object = objectOfFlat.find(pair.first);
      const vtkIdType id = pair.second - (cells ? 50000 : 70000);
      // A TOM draws cells [0, drawn triangles) and points [0, drawn vertices).
      const bool right = object != objectOfFlat.end() && id >= 0 &&
        id < (cells ? mapper->GetObjectRenderedTriangles(object->second)
                    : mapper->GetObjectRenderedVertices(object->second));
      wrong += right ? 0 : 1;
    }
    EXPECT_EQ(wrong, 0u) << (cells ? "cells" : "points");
  }
}

TEST(MultiresolutionMapperSelection, SelectionDisplayOutlinesTheLeafCells)
{
  // vtkMapper::SetSelection: the cells selected by a node with a leaf's flat
  // index are outlined over that leaf, and only there.
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.5);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 5);
  scene.Actor->GetProperty()->SetSelectionColor(1.0, 0.0, 1.0, 1.0);
  scene.Render();
  auto pixels = [&]()
  {
    std::vector<unsigned char> rgb(3 * ImageSize * ImageSize);
    unsigned char* read = scene.Window->GetPixelData(0, 0, ImageSize - 1, ImageSize - 1, 0);
    std::copy(read, read + rgb.size(), rgb.begin());
    delete[] read;
    return rgb;
  };
  const std::vector<unsigned char> plain = pixels();

  auto select = [&](unsigned int flat)
  {
    vtkNew<vtkIdTypeArray> ids;
    for (vtkIdType c = 0; c < 40; ++c)
    {
      ids->InsertNextValue(c);
    }
    vtkNew<vtkSelectionNode> node;
    node->SetFieldType(vtkSelectionNode::CELL);
    node->SetContentType(vtkSelectionNode::INDICES);
    node->SetSelectionList(ids);
    node->GetProperties()->Set(vtkSelectionNode::COMPOSITE_INDEX(), static_cast<int>(flat));
    vtkNew<vtkSelection> selection;
    selection->AddNode(node);
    mapper->SetSelection(selection);
    scene.Render();
    return pixels();
  };
  // Leaf 0's display box.
  double box[4] = { 1e9, -1e9, 1e9, -1e9 };
  const double* b = data.Leaves[0]->GetBounds();
  for (int corner = 0; corner < 8; ++corner)
  {
    scene.Renderer->SetWorldPoint(b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + (corner >> 2)], 1);
    scene.Renderer->WorldToDisplay();
    const double* d = scene.Renderer->GetDisplayPoint();
    box[0] = std::min(box[0], d[0]);
    box[1] = std::max(box[1], d[0]);
    box[2] = std::min(box[2], d[1]);
    box[3] = std::max(box[3], d[1]);
  }
  const std::vector<unsigned char> outlined = select(mapper->GetObjectFlatIndex(0));
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 2); // the triangles and the outlines
  int inside = 0, outside = 0;
  for (int y = 0; y < ImageSize; ++y)
  {
    for (int x = 0; x < ImageSize; ++x)
    {
      const size_t k = 3 * (static_cast<size_t>(y) * ImageSize + x);
      if (std::equal(&plain[k], &plain[k] + 3, &outlined[k]))
      {
        continue;
      }
      const bool in = x >= box[0] - 2 && x <= box[1] + 2 && y >= box[2] - 2 && y <= box[3] + 2;
      (in ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 30);
  EXPECT_EQ(outside, 0);
  // A node of no leaf's flat index outlines nothing.
  EXPECT_EQ(select(12345), plain);
}

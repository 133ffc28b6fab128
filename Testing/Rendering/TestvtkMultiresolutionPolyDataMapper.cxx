// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: index data against the traversal core,
// one draw call for many objects, index-only updates, culling, bad input,
// non-TOM leaves, polydata and partitioned input, representations, graphics
// resources, picking and image baselines. The other suites are in
// TestvtkMultiresolutionPolyDataMapper{Colors,IndexBuffer,Selection,VertexBuffers}.cxx.
#include "MultiresolutionMapperTestSupport.h"

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

TEST(MultiresolutionMapper, AReadChecksAgainOnlyTheLeavesModifiedSinceTheLast)
{
  // Reads remember each leaf's verdict and bounds while it is unmodified
  // (finished background builds make the mapper read every leaf again): a
  // leaf moved, or broken, and Modified() is checked again.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  auto still = MakeTOM(0.5, 30, 20);
  auto moving = MakeTOM(0.5, 30, 20, 2.0, 0.0, 0.0);
  blocks->SetBlock(0, still);
  blocks->SetBlock(1, moving);
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  vtkNew<vtkTest::ErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 2);
  double before[6];
  mapper->GetObjectBounds(1, before);

  vtkPoints* points = moving->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double x[3];
    points->GetPoint(p, x);
    points->SetPoint(p, x[0] + 5.0, x[1], x[2]);
  }
  points->Modified();
  mapper->UpdateObjects();
  double after[6];
  mapper->GetObjectBounds(1, after);
  EXPECT_NEAR(after[0], before[0] + 5.0, 1e-6);
  EXPECT_NEAR(after[1], before[1] + 5.0, 1e-6);
  EXPECT_FALSE(errors->GetError());

  points->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  points->Modified();
  mapper->UpdateObjects();
  ASSERT_TRUE(errors->GetError());
  EXPECT_NE(errors->GetErrorMessage().find("Block 2 is not drawn: point 3 has a non-finite"),
    std::string::npos)
    << errors->GetErrorMessage();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 1);
  double kept[6];
  mapper->GetObjectBounds(0, kept);
  EXPECT_DOUBLE_EQ(kept[0], still->GetBounds()[0]);
  EXPECT_DOUBLE_EQ(kept[1], still->GetBounds()[1]);
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
// Image baselines: nine TOMs at pinned resolutions.
TEST(MultiresolutionMapperBaseline, GridOfNineObjects)
{
  CheckBaseline(RenderGrid(GridResolutions, false, "Grid"), "Grid");
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

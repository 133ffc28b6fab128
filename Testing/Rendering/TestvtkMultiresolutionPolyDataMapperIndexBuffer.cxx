// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper index buffer: only changed objects are
// rewritten, padding is invisible, the result is a full rebuild's, and
// relocation and compaction do not allocate.
#include "MultiresolutionMapperTestSupport.h"

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

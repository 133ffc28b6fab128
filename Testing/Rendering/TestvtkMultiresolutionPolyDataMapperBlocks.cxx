// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper block attributes
// (vtkCompositeDataDisplayAttributes): hidden, colored and translucent blocks
// against vtkCompositePolyDataMapper2 with the same attributes and by their
// pixels, inheritance from parent blocks, changes that rewrite one block's
// colors only, hidden blocks in vtkTimeCriticalRenderer, bad values.
#include "MultiresolutionMapperTestSupport.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkTimeCriticalRenderer.h"

namespace
{
// Flat indices: root 0, A 1, inner 2, B 3, C 4, D 5. Four spheres in a row.
struct BlockScene
{
  BlockScene()
  {
    this->Leaves = { MakeTOM(0.42, 40, 30, -1.5, 0, 0), MakeTOM(0.42, 36, 24, -0.5, 0, 0),
      MakeTOM(0.42, 44, 30, 0.5, 0, 0), MakeTOM(0.42, 40, 28, 1.5, 0, 0) };
    vtkNew<vtkMultiBlockDataSet> inner;
    inner->SetNumberOfBlocks(2);
    inner->SetBlock(0, this->Leaves[1]);
    inner->SetBlock(1, this->Leaves[2]);
    this->Input->SetNumberOfBlocks(3);
    this->Input->SetBlock(0, this->Leaves[0]);
    this->Input->SetBlock(1, inner);
    this->Input->SetBlock(2, this->Leaves[3]);
    this->Inner = inner;
  }
  // A hidden; inner red (B inherits it); C's own blue over it; D half opaque.
  void SetAttributes(vtkCompositeDataDisplayAttributes* attributes) const
  {
    const double red[3] = { 1.0, 0.2, 0.2 };
    const double blue[3] = { 0.2, 0.4, 1.0 };
    attributes->SetBlockVisibility(this->Leaves[0], false);
    attributes->SetBlockColor(this->Inner, red);
    attributes->SetBlockColor(this->Leaves[2], blue);
    attributes->SetBlockOpacity(this->Leaves[3], 0.5);
  }
  std::vector<vtkSmartPointer<vtkPolyData>> Leaves;
  vtkNew<vtkMultiBlockDataSet> Input;
  vtkSmartPointer<vtkMultiBlockDataSet> Inner;
};

void PrepareScene(Scene& scene)
{
  scene.SetCamera(0.0, 0.0, 8.0);
  scene.Actor->GetProperty()->SetSpecular(0.0);
}

// RGB of the pixel at the center of the sphere at x (world), camera as in PrepareScene.
std::array<int, 3> PixelAt(Scene& scene, double x)
{
  scene.Renderer->SetWorldPoint(x, 0.0, 0.0, 1.0);
  scene.Renderer->WorldToDisplay();
  const double* display = scene.Renderer->GetDisplayPoint();
  const int px = static_cast<int>(std::lround(display[0]));
  const int py = static_cast<int>(std::lround(display[1]));
  unsigned char* rgb = scene.Window->GetPixelData(px, py, px, py, 0);
  std::array<int, 3> color = { rgb[0], rgb[1], rgb[2] };
  delete[] rgb;
  return color;
}

bool Near(const std::array<int, 3>& a, const std::array<int, 3>& b, int tolerance)
{
  for (int k = 0; k < 3; ++k)
  {
    if (std::abs(a[k] - b[k]) > tolerance)
    {
      return false;
    }
  }
  return true;
}

const std::array<int, 3> Background = { 26, 26, 38 }; // Scene's (0.1, 0.1, 0.15)
}

TEST(MultiresolutionMapperBlocks, MatchCompositePolyDataMapper2)
{
  BlockScene data;
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  data.SetAttributes(attributes);

  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->SetCompositeDataDisplayAttributes(attributes);
  EXPECT_EQ(mapper->GetCompositeDataDisplayAttributes(), attributes.GetPointer());
  Scene scene(mapper);
  PrepareScene(scene);

  vtkNew<vtkCompositePolyDataMapper2> composite;
  composite->SetInputDataObject(data.Input);
  composite->SetCompositeDataDisplayAttributes(attributes);
  Scene reference(composite);
  PrepareScene(reference);
  ExpectSameImages(scene, reference, "Blocks_attributes");

  // Attributes of the parent apply to its children; a child's own wins.
  mapper->UpdateObjects();
  ASSERT_EQ(mapper->GetNumberOfObjects(), 4);
  EXPECT_FALSE(mapper->GetObjectVisibility(0));
  EXPECT_TRUE(mapper->GetObjectVisibility(1));
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(0), 0); // culled, whatever its resolution
  EXPECT_DOUBLE_EQ(mapper->GetObjectResolution(0), 1.0);
  // One draw call per pass: the opaque blocks in the opaque pass, D in the translucent one.
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 1);
  EXPECT_TRUE(mapper->HasOpaqueGeometry());
  EXPECT_TRUE(mapper->HasTranslucentPolygonalGeometry());

  scene.Render();
  EXPECT_TRUE(Near(PixelAt(scene, -1.5), Background, 2)) << "hidden block A drawn";
  const auto b = PixelAt(scene, -0.5);
  EXPECT_GT(b[0], 2 * b[1]);
  EXPECT_GT(b[0], 2 * b[2]);
  const auto c = PixelAt(scene, 0.5);
  EXPECT_GT(c[2], 2 * c[0]);
  EXPECT_GT(c[2], c[1]);
  const auto d = PixelAt(scene, 1.5);
  // D translucent: between the background and D drawn opaque.
  attributes->SetBlockOpacity(data.Leaves[3], 1.0);
  scene.Render();
  const auto opaque = PixelAt(scene, 1.5);
  EXPECT_FALSE(mapper->HasTranslucentPolygonalGeometry());
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_GT(d[k], Background[k] + 10) << k;
    EXPECT_LT(d[k], opaque[k] - 10) << k;
  }
}

TEST(MultiresolutionMapperBlocks, TranslucentBlockInFrontOfOpaqueOne)
{
  // The translucent block comes first in the one index buffer: drawn in the
  // opaque pass it would hide the opaque block behind it.
  vtkNew<vtkMultiBlockDataSet> input;
  input->SetNumberOfBlocks(2);
  input->SetBlock(0, MakeTOM(0.6, 40, 30, 0.0, 0.0, 1.0));
  input->SetBlock(1, MakeTOM(0.5, 40, 30, 0.2, 0.0, 0.0));
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(input);
  mapper->SetBlockOpacity(1, 0.4);
  mapper->SetBlockColor(2, 0.2, 0.4, 1.0);
  Scene scene(mapper);
  PrepareScene(scene);
  vtkNew<vtkCompositePolyDataMapper2> composite;
  composite->SetInputDataObject(input);
  composite->SetCompositeDataDisplayAttributes(mapper->GetCompositeDataDisplayAttributes());
  Scene reference(composite);
  PrepareScene(reference);
  ExpectSameImages(scene, reference, "Blocks_translucent_in_front");
  const auto center = PixelAt(scene, 0.2);
  EXPECT_GT(center[2], center[0] + 40) << "the opaque block is hidden by the translucent one";

  // Over cell scalars (colors per cell: the fragment shader splits the passes).
  mapper->SetBlockColor(2, 1.0, 1.0, 1.0);
  ConfigureColoring(mapper, true);
  ConfigureColoring(composite, true);
  ExpectSameImages(scene, reference, "Blocks_translucent_in_front_cells");
  EXPECT_TRUE(mapper->HasOpaqueGeometry());
  EXPECT_TRUE(mapper->HasTranslucentPolygonalGeometry());
}

TEST(MultiresolutionMapperBlocks, ChangesRewriteOnlyTheirBlock)
{
  BlockScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  Scene scene(mapper);
  PrepareScene(scene);
  // Point scalars under the block colors: uncolored blocks keep them.
  ConfigureColoring(mapper, false);
  mapper->SetBlockColor(3, 1.0, 0.2, 0.2); // B
  scene.Render();
  scene.Render();
  const vtkIdType vertexBuilds = mapper->GetVertexBufferBuildCount();
  const vtkIdType indexBuilds = mapper->GetIndexBufferBuildCount();
  const vtkMTimeType colorUpload = mapper->GetVertexBufferUploadTime("scalarColor");
  ASSERT_NE(colorUpload, 0u);
  const auto a = PixelAt(scene, -1.5);

  // A color change: C's vertices' colors only, nothing rebuilt.
  mapper->SetBlockColor(4, 0.2, 0.4, 1.0);
  std::size_t allocations = tt::GetAllocationCount();
  scene.Render();
  EXPECT_EQ(mapper->GetColorBytesUploaded(), 4 * mapper->GetObjectNumberOfVertices(2));
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds);
  EXPECT_EQ(mapper->GetVertexBufferUploadTime("scalarColor"), colorUpload);
  const auto c = PixelAt(scene, 0.5);
  EXPECT_GT(c[2], 2 * c[0]);
  EXPECT_TRUE(Near(PixelAt(scene, -1.5), a, 1)) << "an unchanged block changed";

  // A steady frame allocates nothing of ours and uploads no colors.
  allocations = tt::GetAllocationCount();
  scene.Render();
  const std::size_t steady = tt::GetAllocationCount() - allocations;
  EXPECT_EQ(mapper->GetColorBytesUploaded(), 0);
  mapper->SetBlockColor(4, 0.3, 0.4, 1.0);
  mapper->UpdateObjects(); // the attribute walk allocates once per change, not per frame
  allocations = tt::GetAllocationCount();
  scene.Render();
  EXPECT_LE(tt::GetAllocationCount() - allocations, steady);

  // Hiding a block culls its index slot (the padding it leaves may compact
  // the others' slots, as a resolution of 0 would) and rebuilds nothing.
  mapper->SetBlockVisibility(1, false);
  scene.Render();
  EXPECT_EQ(mapper->GetIndexBufferBuildCount(), indexBuilds + 1);
  EXPECT_TRUE(mapper->GetObjectRewritten(0));
  EXPECT_EQ(mapper->GetObjectRenderedTriangles(0), 0);
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
  EXPECT_TRUE(Near(PixelAt(scene, -1.5), Background, 2));
  // Bounds leave hidden blocks out, as vtkCompositePolyDataMapper2's.
  EXPECT_NEAR(mapper->GetBounds()[0], -0.92, 0.02);
  mapper->SetBlockVisibility(1, true);
  scene.Render();
  EXPECT_TRUE(Near(PixelAt(scene, -1.5), a, 1));
  EXPECT_NEAR(mapper->GetBounds()[0], -1.92, 0.02);
}

TEST(MultiresolutionMapperBlocks, HiddenBlocksCostTheRendererNothing)
{
  BlockScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->SetBlockVisibility(2, false); // inner: B and C
  vtkNew<vtkTimeCriticalRenderer> renderer;
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->SetPosition(0, 0, 8);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(200, 200);
  window->AddRenderer(renderer);
  window->Render();
  EXPECT_EQ(renderer->GetNumberOfObjects(), 4);
  EXPECT_EQ(renderer->GetNumberOfCulledObjects(), 2);
  EXPECT_EQ(mapper->GetObjectResolution(1), 0.0);
  EXPECT_EQ(mapper->GetObjectResolution(2), 0.0);
  EXPECT_GT(mapper->GetObjectRenderedTriangles(0), 0);
  EXPECT_EQ(mapper->GetRenderedTriangles(),
    mapper->GetObjectRenderedTriangles(0) + mapper->GetObjectRenderedTriangles(3));
}

TEST(MultiresolutionMapperBlocks, LinesOfHiddenBlocksAndCellColors)
{
  // A non-TOM leaf's vertices, lines and strips (VTK's own index buffers)
  // hide with it; block colors over cell scalars are per cell.
  vtkNew<vtkMultiBlockDataSet> input;
  input->SetNumberOfBlocks(2);
  input->SetBlock(0, MakeTOM(0.5, 40, 30, -0.6, 0, 0));
  input->SetBlock(1, MakeMixedCells());
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(input);
  Scene scene(mapper);
  scene.SetCamera(0.6, 0.0, 5.5, 0.6, 0.0, 0.0);
  scene.Actor->GetProperty()->SetLineWidth(3);
  scene.Actor->GetProperty()->SetPointSize(5);
  scene.Render();
  const int all = scene.CountForeground();
  mapper->SetBlockVisibility(1, true); // block mode needs a color, an opacity or hidden lines
  mapper->SetBlockVisibility(2, false);
  scene.Render();
  const int sphereOnly = scene.CountForeground();
  EXPECT_LT(sphereOnly, all - 500);

  vtkNew<vtkMultiresolutionPolyDataMapper> alone;
  vtkNew<vtkMultiBlockDataSet> sphere;
  sphere->SetNumberOfBlocks(1);
  sphere->SetBlock(0, input->GetBlock(0));
  alone->SetInputDataObject(sphere);
  Scene reference(alone);
  reference.SetCamera(0.6, 0.0, 5.5, 0.6, 0.0, 0.0);
  ExpectSameImages(scene, reference, "Blocks_hidden_lines");

  // Cell scalars: the colored block in its color, the other in its scalars.
  mapper->SetBlockVisibility(2, true);
  ConfigureColoring(mapper, true);
  mapper->SetBlockColor(1, 0.2, 0.4, 1.0);
  vtkNew<vtkCompositePolyDataMapper2> composite;
  composite->SetInputDataObject(input);
  ConfigureColoring(composite, true);
  composite->SetCompositeDataDisplayAttributes(mapper->GetCompositeDataDisplayAttributes());
  Scene compositeScene(composite);
  compositeScene.SetCamera(0.6, 0.0, 5.5, 0.6, 0.0, 0.0);
  compositeScene.Actor->GetProperty()->DeepCopy(scene.Actor->GetProperty());
  ExpectSameImages(scene, compositeScene, "Blocks_cell_colors");
  // A change in place: the cell colors' texels, nothing rebuilt.
  const vtkIdType vertexBuilds = mapper->GetVertexBufferBuildCount();
  mapper->SetBlockColor(1, 1.0, 0.8, 0.1);
  mapper->SetBlockOpacity(2, 0.0); // fully transparent: nothing of it drawn
  EXPECT_TRUE(mapper->HasOpaqueGeometry()); // the sphere stays in the opaque pass
  ExpectSameImages(scene, compositeScene, "Blocks_cell_colors_changed");
  EXPECT_EQ(mapper->GetVertexBufferBuildCount(), vertexBuilds);
}

TEST(MultiresolutionMapperBlocks, BadValuesAreErrors)
{
  BlockScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  mapper->SetBlockColor(99, 1.0, 0.0, 0.0);
  EXPECT_EQ(errors.Count, 1);
  mapper->SetBlockOpacity(5, 1.5);
  EXPECT_EQ(errors.Count, 2);
  mapper->SetBlockOpacity(5, std::nan(""));
  EXPECT_EQ(errors.Count, 3);
  mapper->SetBlockColor(5, 1.0, std::nan(""), 0.0);
  EXPECT_EQ(errors.Count, 4);
  EXPECT_EQ(mapper->GetCompositeDataDisplayAttributes(), nullptr); // nothing was set
  vtkNew<vtkMultiresolutionPolyDataMapper> empty;
  EventCounter emptyErrors(empty, vtkCommand::ErrorEvent);
  empty->SetBlockVisibility(1, false); // no input
  EXPECT_EQ(emptyErrors.Count, 1);
  EXPECT_EQ(empty->GetCompositeDataDisplayAttributes(), nullptr);
  // Attributes of objects that are not in the input are ignored.
  vtkNew<vtkCompositeDataDisplayAttributes> foreign;
  vtkNew<vtkPolyData> other;
  foreign->SetBlockVisibility(other, false);
  mapper->SetCompositeDataDisplayAttributes(foreign);
  mapper->UpdateObjects();
  for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
  {
    EXPECT_TRUE(mapper->GetObjectVisibility(i));
  }
  EXPECT_FALSE(mapper->GetObjectVisibility(7)); // out of range: an error
  EXPECT_EQ(errors.Count, 5);
}

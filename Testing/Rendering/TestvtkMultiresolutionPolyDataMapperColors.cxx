// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper colors: point and cell scalars against
// extracted resolutions, the resolution map, cell colors of the vertices,
// lines and strips of non-TOM leaves, texture colors and translucency.
#include "MultiresolutionMapperTestSupport.h"

namespace
{
// A polydata mapper of extracted resolutions (one actor per leaf) against the
// multiresolution mapper of all leaves: same image with the same coloring.
struct ColoringCase
{
  std::vector<vtkSmartPointer<vtkPolyData>> Leaves;
  std::vector<double> Resolutions;
};

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

//------------------------------------------------------------------------------
// The resolution map: baseline, following the resolutions, turned off.
TEST(MultiresolutionMapperBaseline, GridResolutionMap)
{
  CheckBaseline(RenderGrid(GridResolutions, true, "GridResolutionMap"), "GridResolutionMap");
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

//------------------------------------------------------------------------------
// Vertices, lines, polygons and strips of a non-TOM leaf next to a TOM: drawn
// with cell colors like plain polydata mappers of the leaves draw them, and
// selected with the leaf's own cell ids.
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

// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper vertex buffers: no copy of the leaves is
// kept, and rebuilt buffers draw what a fresh mapper draws.
#include "MultiresolutionMapperTestSupport.h"

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

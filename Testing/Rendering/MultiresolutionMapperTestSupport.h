// SPDX-License-Identifier: BSD-3-Clause
// Shared by the tests of vtkMultiresolutionPolyDataMapper (one executable per
// source file of the mapper): TOMs of bumpy spheres, a scene of one actor in an
// offscreen window with a fixed camera, the traversal core's reference
// triangles, nested and grid inputs, coloring set-ups, image comparisons and
// area selection.
//
// Image thresholds are those of TestvtkTOMPolyDataMapper: a channel value
// differing by more than 0.05 fails; at most 0.1% may fail, RMS below 0.005.
#ifndef MultiresolutionMapperTestSupport_h
#define MultiresolutionMapperTestSupport_h

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

inline std::string OutputPath(const std::string& name)
{
  return std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/" + name + ".png";
}

inline std::string BaselinePath(const std::string& name)
{
  return std::string(TIMECRITICAL_BASELINE_DIR) + "/MultiresolutionMapper_" + name + ".png";
}

inline vtkSmartPointer<vtkPolyData> BuildTOM(vtkPolyData* surface)
{
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputData(surface);
  builder->Update();
  auto tom = vtkSmartPointer<vtkPolyData>::New();
  tom->ShallowCopy(builder->GetOutput());
  return tom;
}

inline vtkSmartPointer<vtkPolyData> MakeTOM(double radius, int theta, int phi, double cx = 0,
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
inline std::vector<uint32_t> TraversalTriangles(vtkPolyData* tom, double r)
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

inline vtkIdType ExtractedTriangles(vtkPolyData* tom, double r)
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

inline void ConfigureColoring(vtkMapper* mapper, bool cells)
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

inline vtkSmartPointer<vtkMultiBlockDataSet> GridInput()
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

inline std::string RenderGrid(const double* resolutions, bool map, const std::string& name)
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

inline void CheckBaseline(const std::string& image, const std::string& name)
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

// (flat index, id) pairs of an area selection of the whole window.
inline std::set<std::pair<unsigned int, vtkIdType>> SelectArea(Scene& scene, int association)
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

inline vtkSmartPointer<vtkPolyData> MakeMixedCells()
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
inline void ExpectSameImages(Scene& scene, Scene& reference, const std::string& name)
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

#endif

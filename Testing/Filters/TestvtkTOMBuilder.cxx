// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTOMBuilder: the TOM it builds, its input handling and errors,
// abort, saving and reading back. The collapse settings it shares with
// vtkMergeTreeBuilder are tested in TestvtkCollapseHierarchyBuilder.cxx.
#include "FilterTestSupport.h"
#include "TOMMesh.h"
#include "vtkExtractTOMResolution.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>

namespace
{
namespace tt = timecritical::testing;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;

vtkSmartPointer<vtkPolyData> Build(vtkPolyData* input, vtkTOMBuilder* builder = nullptr)
{
  return tt::RunFilter(input, builder);
}

vtkSmartPointer<vtkPolyData> Triangle()
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  data->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  data->SetPolys(polys);
  return data;
}
}

TEST(vtkTOMBuilder, SphereGivesValidTOM)
{
  auto input = MakeSphere();
  auto tom = Build(input);
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_EQ(tom->GetNumberOfPoints(), input->GetNumberOfPoints());
  EXPECT_EQ(tom->GetNumberOfPolys(), input->GetNumberOfPolys());
  auto* substitution = vtkTypeUInt32Array::SafeDownCast(
    tom->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  ASSERT_NE(substitution, nullptr);
  const vtkIdType base = reader->GetBaseVertexCount();
  EXPECT_GE(base, 4);
  EXPECT_LE(base, 8) << "a closed sphere should reduce to a handful of vertices";
  for (vtkIdType i = 0; i < tom->GetNumberOfPoints(); ++i)
  {
    if (i < base)
    {
      ASSERT_EQ(substitution->GetValue(i), static_cast<uint32_t>(i));
    }
    else
    {
      ASSERT_LT(substitution->GetValue(i), static_cast<uint32_t>(i));
    }
  }
  // Only the substitution is added per point: normals plus TOMSubstitution.
  EXPECT_EQ(tom->GetPointData()->GetNumberOfArrays(), input->GetPointData()->GetNumberOfArrays() + 1);
}

TEST(vtkTOMBuilder, PointAndCellDataTravelWithTheirPointsAndTriangles)
{
  auto input = MakeSphere();
  auto tom = Build(input);
  tt::ExpectDataTravelsWithPointsAndTriangles(input, tom);
}

TEST(vtkTOMBuilder, EmptyInputGivesEmptyOutputQuietly)
{
  // What a parallel reader gives the ranks without data: no message, an empty
  // output that the extraction passes on quietly too.
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(empty, builder);
  EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
  EXPECT_TRUE(log.Warnings.empty());
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);

  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog extractLog(extract);
  extract->SetInputData(out);
  extract->SetResolution(0.5);
  extract->Update();
  EXPECT_TRUE(extractLog.Errors.empty()) << extractLog.AllErrors();
  EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, PointsWithoutCellsAreAnError)
{
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  cloud->SetPoints(points);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(cloud, builder);
  EXPECT_TRUE(log.ErrorContains("no surface cells")) << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkTOMBuilder, LinesOnlyIsAnError)
{
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(tt::LinesOnly(), builder);
  EXPECT_TRUE(log.ErrorContains("no surface cells"));
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, NaNCoordinateIsAnError)
{
  auto input = MakeSphere(10);
  input->GetPoints()->SetPoint(5, std::numeric_limits<double>::quiet_NaN(), 0, 0);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(input, builder);
  EXPECT_TRUE(log.ErrorContains("point 5 has a non-finite"));
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkTOMBuilder, HugeCoordinateIsAnError)
{
  // Finite, but beyond what the cores' float errors and radii hold: the
  // cores' own limit, reported at the filter's entry.
  auto input = MakeSphere(10);
  input->GetPoints()->SetPoint(5, -2.2e38, 0, 0);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto out = Build(input, builder);
  EXPECT_TRUE(log.ErrorContains(
    "point 5 has a coordinate of magnitude 2.2e+38, beyond the supported 1e+28"))
    << log.AllErrors();
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, QuadsAndStripsAreTriangulated)
{
  auto quads = Build(tt::PlaneQuads());
  EXPECT_EQ(quads->GetNumberOfPolys(), 200);

  auto stripped = tt::PlaneStrips();
  ASSERT_GT(stripped->GetNumberOfStrips(), 0);
  auto strips = Build(stripped);
  EXPECT_EQ(strips->GetNumberOfPolys(), 200);
  EXPECT_EQ(strips->GetNumberOfStrips(), 0);
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_TRUE(reader->Read(strips)) << reader->GetErrorMessage();
}

TEST(vtkTOMBuilder, DuplicatePointsAreMergedAndDegenerateCellsDropped)
{
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto tom = Build(tt::DuplicatePointsAndDegenerateCells(), builder);
  EXPECT_TRUE(log.Errors.empty());
  // The line is content lost: a warning. The zero-area triangle is not.
  ASSERT_EQ(log.Warnings.size(), 1u);
  EXPECT_NE(log.Warnings[0].find("vertex and line cells"), std::string::npos) << log.Warnings[0];
  EXPECT_EQ(tom->GetNumberOfPoints(), 4);
  EXPECT_EQ(tom->GetNumberOfPolys(), 2);
  EXPECT_EQ(builder->GetNumberOfMergedPoints(), 2);
  EXPECT_EQ(builder->GetNumberOfDroppedCells(), 2);
}

TEST(vtkTOMBuilder, ZeroAreaTrianglesAreDroppedWithoutAWarning)
{
  auto data = tt::DuplicatePointsAndDegenerateCells();
  data->SetLines(nullptr);
  vtkNew<vtkTOMBuilder> builder;
  MessageLog log(builder);
  auto tom = Build(data, builder);
  EXPECT_TRUE(log.Errors.empty());
  EXPECT_TRUE(log.Warnings.empty()) << log.Warnings[0];
  EXPECT_EQ(tom->GetNumberOfPolys(), 2);
  EXPECT_EQ(builder->GetNumberOfDroppedCells(), 1);
}

TEST(vtkTOMBuilder, OneTriangle)
{
  auto tom = Build(Triangle());
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetNumberOfTriangles(), 1);
  EXPECT_EQ(reader->GetNumberOfVertices(), 3);
}

TEST(vtkTOMBuilder, NonManifoldEdgeBuilds)
{
  // Three triangles on the edge (0,1).
  vtkNew<vtkPolyData> data;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0.5, 1, 0);
  points->InsertNextPoint(0.5, -1, 0);
  points->InsertNextPoint(0.5, 0, 1);
  data->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  polys->InsertNextCell({ 0, 1, 2 });
  polys->InsertNextCell({ 1, 0, 3 });
  polys->InsertNextCell({ 0, 1, 4 });
  data->SetPolys(polys);
  auto tom = Build(data);
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetNumberOfTriangles(), 3);
}

TEST(vtkTOMBuilder, AbortLeavesEmptyOutput)
{
  auto input = MakeSphere(60);
  vtkNew<vtkTOMBuilder> builder;
  tt::AbortPastOneFifth(builder);
  auto out = Build(input, builder);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_EQ(out->GetNumberOfCells(), 0);
}

TEST(vtkTOMBuilder, SavedAndReadBackLosesNothing)
{
  auto tom = Build(MakeSphere());
  const std::string path = std::string(TIMECRITICAL_TEST_OUTPUT_DIR) + "/sphere-tom.vtp";
  vtkSmartPointer<vtkPolyData> back;
  ASSERT_NO_FATAL_FAILURE(tt::WriteAndReadBack(tom, path, back));
  vtkNew<vtkTOMFieldData> before;
  vtkNew<vtkTOMFieldData> after;
  ASSERT_TRUE(before->Read(tom));
  ASSERT_TRUE(after->Read(back)) << after->GetErrorMessage();
  EXPECT_EQ(before->GetMesh().Substitution, after->GetMesh().Substitution);
  EXPECT_EQ(before->GetMesh().Triangles, after->GetMesh().Triangles);
  EXPECT_EQ(before->GetBaseTriangleCount(), after->GetBaseTriangleCount());
  const auto& a = before->GetMesh().ErrorCurve.GetSamples();
  const auto& b = after->GetMesh().ErrorCurve.GetSamples();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_EQ(a[i].Triangles, b[i].Triangles);
    EXPECT_EQ(a[i].Error, b[i].Error);
  }
  for (vtkIdType i = 0; i < tom->GetNumberOfPoints(); ++i)
  {
    ASSERT_EQ(PointKey(tom, i), PointKey(back, i));
  }
  EXPECT_NE(back->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(back->GetCellData()->GetArray("InputCellId"), nullptr);
}

TEST(vtkTOMBuilder, RealMeshWhenAvailable)
{
  const std::string path = std::string(TIMECRITICAL_SHARED_DATA_DIR) + "/cow.obj";
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << path << " not found";
  }
  vtkNew<vtkOBJReader> obj;
  obj->SetFileName(path.c_str());
  vtkNew<vtkTOMBuilder> builder;
  builder->SetInputConnection(obj->GetOutputPort());
  builder->Update();
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(builder->GetOutput())) << reader->GetErrorMessage();
  EXPECT_EQ(reader->GetNumberOfTriangles(), 5804);
  EXPECT_LE(reader->GetBaseVertexCount(), 16);
}

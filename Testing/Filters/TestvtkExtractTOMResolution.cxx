// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkExtractTOMResolution: resolutions as prefixes of the TOM, the
// three selection modes, geomorphing, and the errors on inputs that are not
// (valid) TOMs.
#include "FilterTestSupport.h"
#include "vtkExtractTOMResolution.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace
{
namespace tt = timecritical::testing;
using tt::MakeSphere;
using tt::MessageLog;
using tt::PointKey;

vtkSmartPointer<vtkPolyData> Build(vtkPolyData* input)
{
  return tt::RunFilter<vtkTOMBuilder>(input, nullptr);
}

vtkSmartPointer<vtkPolyData> Extract(vtkPolyData* tom, vtkExtractTOMResolution* filter)
{
  filter->SetInputData(tom);
  filter->Update();
  vtkSmartPointer<vtkPolyData> out = filter->GetOutput();
  return out;
}
}

TEST(vtkExtractTOMResolution, ResolutionsArePrefixes)
{
  auto tom = Build(MakeSphere());
  const vtkIdType full = tom->GetNumberOfPolys();
  vtkIdType previousVertices = 0;
  for (double r : { 0.05, 0.1, 0.25, 0.5, 1.0 })
  {
    vtkNew<vtkExtractTOMResolution> extract;
    extract->SetResolution(r);
    auto out = Extract(tom, extract);
    const vtkIdType target = static_cast<vtkIdType>(std::lround(r * static_cast<double>(full)));
    EXPECT_LE(out->GetNumberOfPolys(), std::max<vtkIdType>(target, 8)) << "r = " << r;
    EXPECT_GE(out->GetNumberOfPolys(), target - 4) << "r = " << r;
    EXPECT_GT(out->GetNumberOfPoints(), previousVertices);
    previousVertices = out->GetNumberOfPoints();
    EXPECT_EQ(out->GetNumberOfPolys(), extract->GetExtractedTriangleCount());
    EXPECT_EQ(out->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()), nullptr);
    EXPECT_NE(out->GetPointData()->GetNormals(), nullptr);
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      ASSERT_EQ(PointKey(out, i), PointKey(tom, i));
    }
    // Cell data is the prefix of the TOM's.
    vtkDataArray* inIds = tom->GetCellData()->GetArray("InputCellId");
    vtkDataArray* outIds = out->GetCellData()->GetArray("InputCellId");
    ASSERT_NE(outIds, nullptr);
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      ASSERT_EQ(outIds->GetTuple1(c), inIds->GetTuple1(c));
    }
  }
  EXPECT_EQ(previousVertices, tom->GetNumberOfPoints());
}

TEST(vtkExtractTOMResolution, TargetTrianglesAndMaximumError)
{
  auto tom = Build(MakeSphere());
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetTargetTriangles(500);
  auto out = Extract(tom, extract);
  EXPECT_LE(out->GetNumberOfPolys(), 500);
  EXPECT_GE(out->GetNumberOfPolys(), 496);
  EXPECT_EQ(extract->GetSelectionMode(), vtkExtractTOMResolution::BY_TRIANGLE_COUNT);

  vtkIdType previous = -1;
  for (double e : { 1.0, 0.1, 0.01, 0.001, 0.0 })
  {
    extract->SetMaximumError(e);
    out = Extract(tom, extract);
    EXPECT_GE(out->GetNumberOfPolys(), previous) << "smaller error must not give fewer triangles";
    EXPECT_LE(extract->GetExtractedError(), e + 1e-6);
    previous = out->GetNumberOfPolys();
  }
  EXPECT_EQ(previous, tom->GetNumberOfPolys());
}

TEST(vtkExtractTOMResolution, GeomorphMovesTheLastVertex)
{
  auto tom = Build(MakeSphere());
  vtkNew<vtkExtractTOMResolution> extract;
  extract->SetResolution(0.5);
  extract->SetGeomorphFactor(1.0);
  auto rest = vtkSmartPointer<vtkPolyData>::New();
  rest->DeepCopy(Extract(tom, extract));
  extract->SetGeomorphFactor(0.0);
  auto morphed = Extract(tom, extract);
  const vtkIdType last = morphed->GetNumberOfPoints() - 1;
  ASSERT_EQ(rest->GetNumberOfPoints(), morphed->GetNumberOfPoints());
  EXPECT_NE(PointKey(rest, last), PointKey(morphed, last));
  // At factor 0 the last vertex sits on another active vertex.
  bool onAnother = false;
  for (vtkIdType i = 0; i < last; ++i)
  {
    onAnother = onAnother || PointKey(morphed, i) == PointKey(morphed, last);
  }
  EXPECT_TRUE(onAnother);
  for (vtkIdType i = 0; i < last; ++i)
  {
    ASSERT_EQ(PointKey(rest, i), PointKey(morphed, i));
  }
}

TEST(vtkExtractTOMResolution, NonTOMInputIsAnError)
{
  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog log(extract);
  auto out = Extract(MakeSphere(), extract);
  EXPECT_TRUE(log.ErrorContains("TOMSubstitution"));
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
}

TEST(vtkExtractTOMResolution, CorruptedTOMIsAnError)
{
  auto tom = Build(MakeSphere());
  // A substitution pointing to a later vertex would make chains cyclic.
  auto corrupted = vtkSmartPointer<vtkPolyData>::New();
  corrupted->DeepCopy(tom);
  auto* substitution = vtkTypeUInt32Array::SafeDownCast(
    corrupted->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  const vtkIdType n = corrupted->GetNumberOfPoints();
  substitution->SetValue(n - 2, static_cast<uint32_t>(n - 1));
  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog log(extract);
  auto out = Extract(corrupted, extract);
  ASSERT_FALSE(log.Errors.empty());
  EXPECT_TRUE(log.ErrorContains("invalid TOM")) << log.Errors[0];
  EXPECT_EQ(out->GetNumberOfPoints(), 0);

  // Counts that disagree with the data.
  corrupted->DeepCopy(tom);
  auto* counts = vtkDataArray::SafeDownCast(
    corrupted->GetFieldData()->GetAbstractArray(vtkTOMFieldData::CountsArrayName()));
  counts->SetTuple1(1, counts->GetTuple1(1) + 1);
  vtkNew<vtkExtractTOMResolution> extract2;
  MessageLog log2(extract2);
  Extract(corrupted, extract2);
  EXPECT_TRUE(log2.ErrorContains("triangles")) << (log2.Errors.empty() ? "" : log2.Errors[0]);

  // Triangles out of prefix order: swap the first and the last triangle.
  corrupted->DeepCopy(tom);
  vtkNew<vtkIdList> first, last;
  corrupted->GetCellPoints(0, first);
  corrupted->GetCellPoints(corrupted->GetNumberOfCells() - 1, last);
  corrupted->ReplaceCell(0, 3, last->GetPointer(0));
  corrupted->ReplaceCell(corrupted->GetNumberOfCells() - 1, 3, first->GetPointer(0));
  vtkNew<vtkExtractTOMResolution> extract3;
  MessageLog log3(extract3);
  Extract(corrupted, extract3);
  EXPECT_TRUE(log3.ErrorContains("invalid TOM"));
}

TEST(vtkExtractTOMResolution, NonFiniteCoordinatesAreAnError)
{
  // Coordinates are checked like the arrays: NaN or infinite points would
  // otherwise come out of every extraction.
  auto tom = Build(MakeSphere());
  for (double bad : { std::numeric_limits<double>::quiet_NaN(),
         -std::numeric_limits<double>::infinity() })
  {
    auto corrupted = vtkSmartPointer<vtkPolyData>::New();
    corrupted->DeepCopy(tom);
    corrupted->GetPoints()->SetPoint(7, 0.0, bad, 0.0);
    vtkNew<vtkExtractTOMResolution> extract;
    MessageLog log(extract);
    auto out = Extract(corrupted, extract);
    EXPECT_TRUE(log.ErrorContains("point 7 has a non-finite")) << log.AllErrors();
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
    EXPECT_EQ(out->GetNumberOfCells(), 0);
  }
}

TEST(vtkExtractTOMResolution, TOMOfNoPointsGivesEmptyOutput)
{
  // Counts 0, 0, 0, 0 and empty arrays but no vtkPoints: a valid TOM of
  // nothing, which once dereferenced the missing points.
  vtkNew<vtkPolyData> nothing;
  vtkNew<vtkTypeUInt32Array> substitution;
  substitution->SetName(vtkTOMFieldData::SubstitutionArrayName());
  nothing->GetPointData()->AddArray(substitution);
  vtkNew<vtkTypeUInt32Array> counts;
  counts->SetName(vtkTOMFieldData::CountsArrayName());
  counts->SetNumberOfValues(4);
  counts->FillValue(0);
  nothing->GetFieldData()->AddArray(counts);
  for (int mode = 0; mode < 3; ++mode)
  {
    vtkNew<vtkExtractTOMResolution> extract;
    MessageLog log(extract);
    if (mode == 0)
    {
      extract->SetResolution(0.5);
    }
    else if (mode == 1)
    {
      extract->SetTargetTriangles(10);
    }
    else
    {
      extract->SetMaximumError(0.1);
    }
    extract->SetInputData(nothing);
    extract->Update();
    EXPECT_TRUE(log.Errors.empty()) << log.AllErrors();
    EXPECT_EQ(extract->GetOutput()->GetNumberOfPoints(), 0);
    EXPECT_EQ(extract->GetOutput()->GetNumberOfCells(), 0);
    EXPECT_EQ(extract->GetExtractedTriangleCount(), 0);
  }
}

TEST(vtkExtractTOMResolution, NaNResolutionIsReported)
{
  vtkNew<vtkExtractTOMResolution> extract;
  MessageLog log(extract);
  extract->SetResolution(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(log.ErrorContains("NaN"));
  EXPECT_EQ(extract->GetResolution(), 0.0);
}

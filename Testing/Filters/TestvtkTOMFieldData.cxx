// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkTOMFieldData: the arrays a TOM carries, Write() and Read() round
// trips, the counts of a read, and the message of each way a vtkPolyData can
// fail to be a valid TOM.
#include "FilterTestSupport.h"
#include "TOMMesh.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTypeUInt32Array.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>

namespace
{
namespace tt = timecritical::testing;

/// A TOM of a small sphere, built by vtkTOMBuilder.
vtkSmartPointer<vtkPolyData> SphereTOM()
{
  return tt::RunFilter<vtkTOMBuilder>(tt::MakeSphere(10), nullptr);
}

/// A deep copy of `tom` to corrupt.
vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* tom)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(tom);
  return copy;
}

/// The message of reading `data`, which must fail.
std::string ReadError(vtkPolyData* data)
{
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_FALSE(reader->Read(data));
  EXPECT_EQ(reader->GetNumberOfVertices(), 0) << "counts of a failed read";
  EXPECT_EQ(reader->GetNumberOfTriangles(), 0);
  return reader->GetErrorMessage();
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
}

TEST(vtkTOMFieldData, ArrayNamesAndHasTOMArrays)
{
  EXPECT_STREQ(vtkTOMFieldData::SubstitutionArrayName(), "TOMSubstitution");
  EXPECT_STREQ(vtkTOMFieldData::CountsArrayName(), "TOMCounts");
  EXPECT_STREQ(vtkTOMFieldData::ErrorCurveArrayName(), "TOMErrorCurve");
  auto tom = SphereTOM();
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(tom));
  EXPECT_FALSE(vtkTOMFieldData::HasTOMArrays(tt::MakeSphere(10)));
  EXPECT_FALSE(vtkTOMFieldData::HasTOMArrays(nullptr));
  // Both arrays are needed, valid or not.
  auto noCounts = Copy(tom);
  noCounts->GetFieldData()->RemoveArray(vtkTOMFieldData::CountsArrayName());
  EXPECT_FALSE(vtkTOMFieldData::HasTOMArrays(noCounts));
  auto badCounts = Copy(tom);
  vtkNew<vtkFloatArray> counts;
  counts->SetName(vtkTOMFieldData::CountsArrayName());
  badCounts->GetFieldData()->AddArray(counts);
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(badCounts));
}

TEST(vtkTOMFieldData, ReadGivesTheCountsAndTheMesh)
{
  auto tom = SphereTOM();
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom)) << reader->GetErrorMessage();
  EXPECT_STREQ(reader->GetErrorMessage(), "");
  const timecritical::TOMMesh& mesh = reader->GetMesh();
  EXPECT_EQ(reader->GetNumberOfVertices(), tom->GetNumberOfPoints());
  EXPECT_EQ(reader->GetNumberOfTriangles(), tom->GetNumberOfPolys());
  EXPECT_EQ(static_cast<vtkIdType>(mesh.GetNumberOfVertices()), tom->GetNumberOfPoints());
  EXPECT_EQ(reader->GetBaseVertexCount(), static_cast<vtkIdType>(mesh.BaseVertexCount));
  EXPECT_EQ(reader->GetBaseTriangleCount(), static_cast<vtkIdType>(mesh.BaseTriangleCount));
  EXPECT_GT(reader->GetBaseVertexCount(), 0);
  EXPECT_LT(reader->GetBaseVertexCount(), reader->GetNumberOfVertices());
  auto* counts = vtkDataArray::SafeDownCast(
    tom->GetFieldData()->GetAbstractArray(vtkTOMFieldData::CountsArrayName()));
  ASSERT_NE(counts, nullptr);
  EXPECT_EQ(counts->GetTuple1(2), static_cast<double>(mesh.BaseVertexCount));
  EXPECT_EQ(counts->GetTuple1(3), static_cast<double>(mesh.BaseTriangleCount));
  // The triangles are the polygons of the data, in order.
  for (vtkIdType c = 0; c < tom->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    tom->GetCellPoints(c, n, ids);
    ASSERT_EQ(n, 3);
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_EQ(static_cast<vtkIdType>(mesh.Triangles[3 * c + k]), ids[k]);
    }
  }
  EXPECT_FALSE(mesh.ErrorCurve.GetSamples().empty());
  std::ostringstream print;
  reader->Print(print);
  EXPECT_TRUE(Contains(print.str(), "Valid: 1")) << print.str();
}

TEST(vtkTOMFieldData, WriteThenReadGivesTheSameMesh)
{
  auto tom = SphereTOM();
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom));
  // The same points and triangles without any TOM array, then Write().
  vtkNew<vtkPolyData> plain;
  plain->SetPoints(tom->GetPoints());
  plain->SetPolys(tom->GetPolys());
  EXPECT_FALSE(vtkTOMFieldData::HasTOMArrays(plain));
  vtkTOMFieldData::Write(reader->GetMesh(), plain);
  EXPECT_TRUE(vtkTOMFieldData::HasTOMArrays(plain));
  EXPECT_NE(vtkTypeUInt32Array::SafeDownCast(
              plain->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName())),
    nullptr);
  auto* curve = vtkDoubleArray::SafeDownCast(
    plain->GetFieldData()->GetAbstractArray(vtkTOMFieldData::ErrorCurveArrayName()));
  ASSERT_NE(curve, nullptr);
  EXPECT_EQ(curve->GetNumberOfComponents(), 2);
  vtkNew<vtkTOMFieldData> back;
  ASSERT_TRUE(back->Read(plain)) << back->GetErrorMessage();
  const timecritical::TOMMesh& a = reader->GetMesh();
  const timecritical::TOMMesh& b = back->GetMesh();
  EXPECT_EQ(a.Substitution, b.Substitution);
  EXPECT_EQ(a.Triangles, b.Triangles);
  EXPECT_EQ(a.BaseVertexCount, b.BaseVertexCount);
  EXPECT_EQ(a.BaseTriangleCount, b.BaseTriangleCount);
  ASSERT_EQ(a.ErrorCurve.GetSamples().size(), b.ErrorCurve.GetSamples().size());
  for (size_t i = 0; i < a.ErrorCurve.GetSamples().size(); ++i)
  {
    EXPECT_EQ(a.ErrorCurve.GetSamples()[i].Triangles, b.ErrorCurve.GetSamples()[i].Triangles);
    EXPECT_EQ(a.ErrorCurve.GetSamples()[i].Error, b.ErrorCurve.GetSamples()[i].Error);
  }
}

TEST(vtkTOMFieldData, MissingOrMalformedArraysAreReported)
{
  auto tom = SphereTOM();
  EXPECT_EQ(ReadError(nullptr), "no input data");
  EXPECT_TRUE(Contains(ReadError(tt::MakeSphere(10)), "not a Totally Ordered Mesh"));

  auto floatSubstitution = Copy(tom);
  vtkNew<vtkFloatArray> floats;
  floats->SetName(vtkTOMFieldData::SubstitutionArrayName());
  floats->SetNumberOfValues(tom->GetNumberOfPoints());
  floats->FillValue(0.0f);
  floatSubstitution->GetPointData()->AddArray(floats);
  EXPECT_EQ(ReadError(floatSubstitution), "TOMSubstitution must be a single-component integer array");

  auto threeCounts = Copy(tom);
  vtkNew<vtkTypeUInt32Array> three;
  three->SetName(vtkTOMFieldData::CountsArrayName());
  three->SetNumberOfValues(3);
  three->FillValue(1);
  threeCounts->GetFieldData()->AddArray(three);
  EXPECT_TRUE(Contains(ReadError(threeCounts), "TOMCounts must hold 4 values"));

  auto fractionalCount = Copy(tom);
  vtkNew<vtkDoubleArray> fractional;
  fractional->SetName(vtkTOMFieldData::CountsArrayName());
  fractional->SetNumberOfValues(4);
  fractional->FillValue(1.5);
  fractionalCount->GetFieldData()->AddArray(fractional);
  EXPECT_TRUE(Contains(ReadError(fractionalCount), "TOMCounts value 0 (1.5) is not a 32-bit count"));

  auto badCurve = Copy(tom);
  vtkNew<vtkDoubleArray> curve;
  curve->SetName(vtkTOMFieldData::ErrorCurveArrayName());
  curve->SetNumberOfComponents(3);
  curve->SetNumberOfTuples(1);
  badCurve->GetFieldData()->AddArray(curve);
  EXPECT_TRUE(Contains(ReadError(badCurve), "TOMErrorCurve must be a numeric array"));

  auto negativeCurve = Copy(tom);
  vtkNew<vtkDoubleArray> negative;
  negative->SetName(vtkTOMFieldData::ErrorCurveArrayName());
  negative->SetNumberOfComponents(2);
  negative->InsertNextTuple2(-4.0, 0.5);
  negativeCurve->GetFieldData()->AddArray(negative);
  EXPECT_EQ(ReadError(negativeCurve), "TOMErrorCurve sample 0 has a bad triangle count");
}

TEST(vtkTOMFieldData, DataThatDisagreesWithTheArraysIsReported)
{
  auto tom = SphereTOM();
  const vtkIdType points = tom->GetNumberOfPoints();

  auto extraPoint = Copy(tom);
  extraPoint->GetPoints()->InsertNextPoint(0, 0, 0);
  EXPECT_TRUE(Contains(ReadError(extraPoint), "TOM vertex counts disagree: TOMCounts says " +
                         std::to_string(points) + ", the data has " + std::to_string(points + 1) +
                         " points"));

  auto nanPoint = Copy(tom);
  nanPoint->GetPoints()->SetPoint(3, 0, std::numeric_limits<double>::quiet_NaN(), 0);
  EXPECT_EQ(ReadError(nanPoint), "point 3 has a non-finite (NaN or infinite) coordinate");

  auto withLine = Copy(tom);
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell({ 0, 1 });
  withLine->SetLines(lines);
  EXPECT_TRUE(Contains(ReadError(withLine), "a TOM holds triangles only"));

  auto missingTriangle = Copy(tom);
  vtkNew<vtkCellArray> fewer;
  for (vtkIdType c = 0; c + 1 < tom->GetNumberOfPolys(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    tom->GetCellPoints(c, n, ids);
    fewer->InsertNextCell(n, ids);
  }
  missingTriangle->SetPolys(fewer);
  EXPECT_TRUE(Contains(ReadError(missingTriangle),
    "TOMCounts says " + std::to_string(tom->GetNumberOfPolys()) + " triangles"));

  auto quad = Copy(tom);
  vtkNew<vtkCellArray> withQuad;
  withQuad->InsertNextCell({ 0, 1, 2, 3 });
  for (vtkIdType c = 1; c < tom->GetNumberOfPolys(); ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    tom->GetCellPoints(c, n, ids);
    withQuad->InsertNextCell(n, ids);
  }
  quad->SetPolys(withQuad);
  EXPECT_EQ(ReadError(quad), "cell 0 has 4 points; a TOM holds triangles only");

  auto outOfRange = Copy(tom);
  const vtkIdType far[3] = { 0, 1, points + 7 };
  outOfRange->ReplaceCell(2, 3, far);
  EXPECT_EQ(ReadError(outOfRange),
    "triangle 2 refers to point " + std::to_string(points + 7) + ", out of range");

  auto laterSubstitution = Copy(tom);
  auto* substitution = vtkTypeUInt32Array::SafeDownCast(
    laterSubstitution->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  ASSERT_NE(substitution, nullptr);
  substitution->SetValue(points - 2, static_cast<uint32_t>(points - 1));
  EXPECT_TRUE(Contains(ReadError(laterSubstitution), "invalid TOM: "));
}

TEST(vtkTOMFieldData, AFailedReadForgetsThePreviousMesh)
{
  auto tom = SphereTOM();
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(tom));
  ASSERT_GT(reader->GetNumberOfTriangles(), 0);
  EXPECT_FALSE(reader->Read(tt::MakeSphere(10)));
  EXPECT_EQ(reader->GetNumberOfVertices(), 0);
  EXPECT_EQ(reader->GetNumberOfTriangles(), 0);
  EXPECT_EQ(reader->GetBaseVertexCount(), 0);
  EXPECT_EQ(reader->GetBaseTriangleCount(), 0);
  EXPECT_TRUE(reader->GetMesh().Substitution.empty());
  // And a good read after it clears the message.
  ASSERT_TRUE(reader->Read(tom));
  EXPECT_STREQ(reader->GetErrorMessage(), "");
}

namespace
{
/// Breaks the TOM order of `tom` in place (a substitution target above its
/// vertex), without telling VTK when `tell` is false.
void BreakTheOrder(vtkPolyData* tom, bool tell)
{
  auto substitution = vtkTypeUInt32Array::SafeDownCast(
    tom->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName()));
  ASSERT_NE(substitution, nullptr);
  const vtkIdType points = tom->GetNumberOfPoints();
  substitution->SetValue(points - 2, static_cast<uint32_t>(points - 1));
  if (tell)
  {
    substitution->Modified();
  }
}
}

TEST(vtkTOMFieldData, RememberedValidationsAreSkippedUntilTheDataChanges)
{
  auto tom = Copy(SphereTOM());
  vtkNew<vtkTOMFieldData> reader;
  EXPECT_FALSE(reader->GetRememberValidated());
  reader->SetRememberValidated(true);
  ASSERT_TRUE(reader->Read(tom));
  const auto triangles = reader->GetNumberOfTriangles();
  // A change VTK is not told of is not seen: the validation is remembered
  // (the contract of every VTK cache keyed by modification times)...
  BreakTheOrder(tom, false);
  ASSERT_TRUE(reader->Read(tom));
  EXPECT_EQ(reader->GetNumberOfTriangles(), triangles);
  // ...while a reader without the memory sees it,
  EXPECT_TRUE(Contains(ReadError(tom), "invalid TOM: "));
  // and so does this one once the array says it was modified.
  BreakTheOrder(tom, true);
  EXPECT_FALSE(reader->Read(tom));
  EXPECT_TRUE(Contains(reader->GetErrorMessage(), "invalid TOM: "));
}

TEST(vtkTOMFieldData, RememberedValidationsLastTwoReadingPasses)
{
  auto tom = Copy(SphereTOM());
  vtkNew<vtkTOMFieldData> reader;
  reader->SetRememberValidated(true);
  ASSERT_TRUE(reader->Read(tom));
  BreakTheOrder(tom, false);
  reader->StartReadingPass(); // read in the previous pass: still remembered
  ASSERT_TRUE(reader->Read(tom));
  reader->StartReadingPass();
  reader->StartReadingPass(); // not read in the previous pass: forgotten
  EXPECT_FALSE(reader->Read(tom));
  // Turning the memory off forgets too.
  auto other = Copy(SphereTOM());
  ASSERT_TRUE(reader->Read(other));
  BreakTheOrder(other, false);
  reader->SetRememberValidated(false);
  reader->SetRememberValidated(true);
  EXPECT_FALSE(reader->Read(other));
}

TEST(vtkTOMFieldData, RememberedValidationsStillCheckTheStructure)
{
  // What the memory skips is the costly part only: a count that no longer
  // matches is reported even for arrays that validated.
  auto tom = Copy(SphereTOM());
  vtkNew<vtkTOMFieldData> reader;
  reader->SetRememberValidated(true);
  ASSERT_TRUE(reader->Read(tom));
  vtkNew<vtkCellArray> fewer;
  fewer->DeepCopy(tom->GetPolys());
  fewer->ResizeExact(fewer->GetNumberOfCells() - 1, 3 * (fewer->GetNumberOfCells() - 1));
  tom->SetPolys(fewer);
  EXPECT_FALSE(reader->Read(tom));
  EXPECT_TRUE(Contains(reader->GetErrorMessage(), "triangles, the data has"));
}

TEST(vtkTOMFieldData, ReleaseMeshEmptiesTheCopy)
{
  vtkNew<vtkTOMFieldData> reader;
  ASSERT_TRUE(reader->Read(SphereTOM()));
  reader->ReleaseMesh();
  EXPECT_TRUE(reader->GetMesh().Triangles.empty());
  EXPECT_EQ(reader->GetNumberOfTriangles(), 0);
}
